//! The subcommands of the binary, one file each, and what they share: the exit codes, the
//! output format, reading a preset and writing the result.

use std::io::{self, Write};
use std::path::Path;
use std::process::ExitCode;

use clap::ValueEnum;

use wearlab::finite;
use wearlab::preset::{self, Preset};

pub mod explorer;
pub mod solve;
pub mod stdout_at_start;
pub mod sweep;

/// Exit code when the result could not be written (closed pipe, full disk).
pub const EXIT_OUTPUT: u8 = 1;
/// Exit code for invalid input (bad file, bad value, bad arguments).
pub const EXIT_INVALID: u8 = 2;
/// Exit code when the solver cannot answer.
pub const EXIT_UNSOLVABLE: u8 = 3;

/// The text format of a result on stdout.
#[derive(Clone, Copy, ValueEnum)]
pub enum Format {
    Json,
    Csv,
}

/// Writes a line on stderr; a closed or full stderr cannot be told, so its error is dropped.
pub fn say(message: &str) {
    let _ = writeln!(io::stderr(), "{message}");
}

/// The preset at `path`, or exit 2 with the file's error said.
pub fn load(path: &Path) -> Result<Preset, ExitCode> {
    preset::load(path).map_err(|e| {
        say(&format!("error: {e}"));
        ExitCode::from(EXIT_INVALID)
    })
}

/// The preset at `path` with the `--set` values applied.
pub fn load_with(path: &Path, settings: &[String]) -> Result<Preset, ExitCode> {
    load(path)?.with_settings(settings).map_err(|why| {
        say(&format!("error: {why}"));
        ExitCode::from(EXIT_INVALID)
    })
}

/// Prints the result, after the last check that it holds only finite numbers.
pub fn print(text: &str, guard: Result<(), finite::NonFinite>) -> ExitCode {
    if let Err(e) = guard {
        say(&format!("error: {e}"));
        return ExitCode::from(EXIT_UNSOLVABLE);
    }
    if stdout_at_start::closed() {
        say("error: cannot write the result to stdout: it is closed");
        return ExitCode::from(EXIT_OUTPUT);
    }
    let mut out = io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            say(&format!("error: cannot write the result to stdout: {e}"));
            ExitCode::from(EXIT_OUTPUT)
        }
    }
}
