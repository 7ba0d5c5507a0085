//! The explorer: its engine's stages, the sweep worker, curves and maps, and the real binary in
//! tmux and in a pty.

mod engine;
mod explore_cancel;
mod explore_curve;
mod explore_map;
mod map_yield;
mod tui_monkey;
mod tui_signals;
mod tui_tmux;
