//! `wearlab solve`, `wearlab sweep`, `wearlab check` and `wearlab fit` as a script sees them: the JSON and CSV contract of
//! `docs/cli.md`, `--set`, exit codes and messages, hostile command lines.

mod check;
mod cli;
mod cli_set;
mod cli_sweep;
mod closed_stdout;
#[path = "../common/mod.rs"]
mod common;
mod fit_cli;
mod hostile_cli;
mod lesson_lock;
mod max_seconds;
mod progress;
mod quantities;
mod run;
mod shapes_cli;
mod solve_output;
mod surface_bad_files;
mod surface_cli;
mod surface_set_cli;
mod surface_statistics_cli;
mod wear_law_cli;
mod yield_cli;
