//! `wearlab solve`, `wearlab sweep` and `wearlab check` as a script sees them: the JSON and CSV contract of
//! `docs/cli.md`, `--set`, exit codes and messages, hostile command lines.

mod check;
mod cli;
mod cli_set;
mod cli_sweep;
mod closed_stdout;
#[path = "../common/mod.rs"]
mod common;
mod hostile_cli;
mod quantities;
mod shapes_cli;
mod solve_output;
