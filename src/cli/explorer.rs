//! `wearlab [PRESET] [--ascii] [--mouse]`: the terminal explorer (`wearlab::tui`) on a preset.

use std::io::{self, IsTerminal};
use std::path::PathBuf;
use std::process::ExitCode;

use wearlab::{preset, tui};

use super::{EXIT_INVALID, load, say};

/// Runs the explorer on the preset at `path` (the built-in default when none is given).
pub fn run(path: Option<PathBuf>, options: tui::Options) -> ExitCode {
    if !(io::stdin().is_terminal() && io::stdout().is_terminal()) {
        say("error: wearlab needs a terminal; use `wearlab solve` for scripts");
        return ExitCode::from(EXIT_INVALID);
    }
    let preset = match &path {
        Some(p) => match load(p) {
            Ok(p) => p,
            Err(code) => return code,
        },
        None => preset::default_preset(),
    };
    match tui::run(preset, path, options) {
        Ok(tui::Ending::Quit) => ExitCode::SUCCESS,
        // the shell's convention for a process ended by a signal
        Ok(tui::Ending::Signal(n)) => ExitCode::from(u8::try_from(128 + n).unwrap_or(u8::MAX)),
        Err(e) => {
            say(&format!("error: the terminal failed: {e}"));
            ExitCode::FAILURE
        }
    }
}
