//! The subcommands of the binary, one file each, and what they share: the exit codes, the
//! output format, reading a preset and writing the result.

use std::io::{self, Write};
use std::path::Path;
use std::process::ExitCode;
use std::sync::mpsc;
use std::time::{Duration, Instant};

use clap::ValueEnum;

use wearlab::finite;
use wearlab::physics::SolveError;
use wearlab::physics::stop::Stop;
use wearlab::preset::{self, Preset};
use wearlab::units::format_si;

pub mod check;
pub mod explorer;
pub mod fit;
pub mod solve;
pub mod solve_output;
pub mod stdout_at_start;
pub mod sweep;

/// Exit code when the result could not be written (closed pipe, full disk).
pub const EXIT_OUTPUT: u8 = 1;
/// Exit code for invalid input (bad file, bad value, bad arguments).
pub const EXIT_INVALID: u8 = 2;
/// Exit code when the solver cannot answer.
pub const EXIT_UNSOLVABLE: u8 = 3;

/// How far a solve stopped by `--max-seconds` got.
pub const SOLVE_NOT_FINISHED: &str = "the solve had not finished";

/// The text format of a result on stdout.
#[derive(Clone, Copy, PartialEq, ValueEnum)]
pub enum Format {
    Json,
    Csv,
}

/// Writes a line on stderr; a closed or full stderr cannot be told, so its error is dropped.
pub fn say(message: &str) {
    let _ = writeln!(io::stderr(), "{message}");
}

/// A solver's refusal said on stderr, as exit 2 (invalid input) or 3 (no solution).
pub fn solver_failure(e: SolveError) -> ExitCode {
    say(&format!("error: {e}"));
    match e {
        SolveError::InvalidInput(_) => ExitCode::from(EXIT_INVALID),
        SolveError::NoSolution(_) => ExitCode::from(EXIT_UNSOLVABLE),
    }
}

/// The preset at `path`, or exit 2 with the file's error said; the warnings of a valid file
/// (`preset::load_with_warnings`) go to stderr.
pub fn load(path: &Path) -> Result<Preset, ExitCode> {
    let (preset, warnings) = preset::load_with_warnings(path).map_err(|e| {
        say(&format!("error: {e}"));
        ExitCode::from(EXIT_INVALID)
    })?;
    for w in warnings {
        say(&format!("warning: {w}"));
    }
    Ok(preset)
}

/// The preset at `path` with the `--set` values applied; a value that changes a key the
/// preset's lesson locks is refused (exit 2) unless `unlock` (`--unlock`, the instructor's).
pub fn load_with(path: &Path, settings: &[String], unlock: bool) -> Result<Preset, ExitCode> {
    settled(path, &load(path)?, settings, unlock)
}

/// `preset`, read from `path`, with the `--set` values applied, as `load_with` gives it.
pub fn settled(
    path: &Path,
    preset: &Preset,
    settings: &[String],
    unlock: bool,
) -> Result<Preset, ExitCode> {
    let invalid = |why: String| {
        say(&format!("error: {why}"));
        ExitCode::from(EXIT_INVALID)
    };
    let next = preset.with_settings(settings).map_err(invalid)?;
    for w in preset::settings_warnings(&next, settings) {
        say(&format!("warning: {w}"));
    }
    match preset.locked_change(&next) {
        Some(key) if !unlock => Err(invalid(format!(
            "--set {key}: {key} is locked by the lesson of {}, whose questions are asked at {} = \
             {}; add --unlock to set it anyway (the instructor's check of another value)",
            path.display(),
            key.symbol(),
            preset
                .get(key)
                .map_or_else(|e| e, |v| format_si(v, key.param().unit)),
        ))),
        _ => Ok(next),
    }
}

/// Prints the result, after the last check that it holds only finite numbers.
pub fn print(text: &str, guard: Result<(), finite::NonFinite>) -> ExitCode {
    print_streamed(guard, |out| out.write_all(text.as_bytes()))
}

/// Writes the result through `write` as it is produced, after the last check that it holds only
/// finite numbers (`guard`, run on the result before any text): the output of [`print`] without
/// the whole text in memory.
pub fn print_streamed(
    guard: Result<(), finite::NonFinite>,
    write: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> ExitCode {
    if let Err(e) = guard {
        say(&format!("error: {e}"));
        return ExitCode::from(EXIT_UNSOLVABLE);
    }
    if stdout_at_start::closed() {
        say("error: cannot write the result to stdout: it is closed");
        return ExitCode::from(EXIT_OUTPUT);
    }
    let mut out = io::BufWriter::new(io::stdout().lock());
    match write(&mut out).and_then(|()| out.flush()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            say(&format!("error: cannot write the result to stdout: {e}"));
            ExitCode::from(EXIT_OUTPUT)
        }
    }
}

/// Reads `--max-seconds S`: a bound on the work's wall-clock time, above 0.
pub fn parse_seconds(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(s) if s > 0.0 && s <= 1e9 => Ok(s),
        _ => Err(format!("'{text}' is not a number of seconds in (0, 1e9]")),
    }
}

/// What became of work run under a time bound.
pub enum Bounded<T> {
    /// It finished with this.
    Done(T),
    /// The bound stopped it after this many seconds, saying how far it got.
    Stopped(f64, String),
    /// The work panicked (its message is on stderr already).
    Panicked,
}

/// Runs `work` on a thread of its own, handing it a `Stop` that says so once `limit` seconds
/// have passed (never when None): the work asks it between its steps (and inside its contact
/// solves) and returns Err, saying how far it got, when it stopped. Meanwhile `tick` is called
/// every tenth of a second (a progress display). The work's thread has ended when this returns:
/// nothing is left running.
pub fn within<T: Send>(
    limit: Option<f64>,
    work: impl FnOnce(Stop) -> Result<T, String> + Send,
    tick: &dyn Fn(),
) -> Bounded<T> {
    let start = Instant::now();
    let bound = limit.map(Duration::from_secs_f64);
    let passed = || bound.is_some_and(|b| start.elapsed() >= b);
    std::thread::scope(|scope| {
        let (tx, rx) = mpsc::channel();
        let worker = scope.spawn(move || {
            let _ = tx.send(work(Stop::Asked(&passed)));
        });
        let outcome = loop {
            match rx.recv_timeout(Duration::from_millis(100)) {
                Ok(outcome) => break Some(outcome),
                Err(mpsc::RecvTimeoutError::Disconnected) => break None,
                Err(mpsc::RecvTimeoutError::Timeout) => tick(),
            }
        };
        let joined = worker.join();
        match (outcome, joined) {
            (Some(Ok(done)), Ok(())) => Bounded::Done(done),
            (Some(Err(what)), Ok(())) => Bounded::Stopped(start.elapsed().as_secs_f64(), what),
            _ => Bounded::Panicked,
        }
    })
}

/// The exit code of bounded work: its own when it finished; 3 with the reason when the bound
/// stopped it ("stopped after S s (--max-seconds): " and how far it got).
pub fn finished(bounded: Bounded<ExitCode>) -> ExitCode {
    match bounded {
        Bounded::Done(code) => code,
        Bounded::Stopped(seconds, what) => {
            say(&format!(
                "error: stopped after {seconds:.1} s (--max-seconds): {what}"
            ));
            ExitCode::from(EXIT_UNSOLVABLE)
        }
        // the exit code of a panic in Rust's runtime
        Bounded::Panicked => ExitCode::from(101),
    }
}
