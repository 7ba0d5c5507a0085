//! wearlab: sliding contact with friction and wear — the physics, the preset files and the
//! reports, and (with the default feature `explorer`) the terminal explorer in [`tui`]. Nothing
//! outside `tui` uses terminal code: without the feature the library builds without ratatui and
//! crossterm.

pub mod data;
pub mod engine;
pub mod finite;
pub mod fit;
pub mod materials;
pub mod phrase;
pub mod physics;
pub mod preset;
pub mod report;
pub mod spatial_report;
pub mod sweeps;
#[cfg(feature = "explorer")]
pub mod tui;
pub mod units;
pub mod views;
