//! The `wearlab` binary: the command line around the library.

use std::io::{self, IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};

mod cli;

use wearlab::physics::SolveError;
use wearlab::physics::limits::{self, Limit};
use wearlab::preset::{self, Preset, Problem};
use wearlab::{finite, report, spatial_report, tui};

/// Exit code when the result could not be written (closed pipe, full disk).
const EXIT_OUTPUT: u8 = 1;
/// Exit code for invalid input (bad file, bad value, bad arguments).
const EXIT_INVALID: u8 = 2;
/// Exit code when the solver cannot answer.
const EXIT_UNSOLVABLE: u8 = 3;

#[derive(Parser)]
#[command(
    name = "wearlab",
    version,
    about = "Sliding contact with friction and wear"
)]
#[command(args_conflicts_with_subcommands = true)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    /// Preset file to open (default: the built-in default preset).
    preset: Option<PathBuf>,
    /// Draw the whole screen in ASCII: borders, axes, curves, marks and keys (for terminals
    /// without Unicode).
    #[arg(long)]
    ascii: bool,
    /// Capture the mouse (off by default, so the terminal's own selection keeps working).
    #[arg(long)]
    mouse: bool,
}

#[derive(Subcommand)]
enum Command {
    /// Solve a preset and print the result (JSON or CSV) on stdout.
    Solve {
        /// The preset file (TOML, schema 1).
        preset: PathBuf,
        /// Output format.
        #[arg(long, value_enum, default_value_t = Format::Json)]
        format: Format,
        /// Number of profile points, both ends included (plane; default 201).
        #[arg(long, value_name = "N", allow_hyphen_values = true, value_parser = parse_points)]
        points: Option<usize>,
        /// The instant t [s] to solve at, overriding the preset's spatial.time (spatial).
        #[arg(long, value_name = "T", allow_hyphen_values = true, value_parser = parse_time)]
        time: Option<f64>,
        /// Also report the fields at the point X,Y [m] (spatial; repeatable).
        #[arg(long, value_name = "X,Y", allow_hyphen_values = true, value_parser = parse_probe)]
        probe: Vec<[f64; 2]>,
        /// Set a preset value before solving, e.g. material.thickness=10um (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE", allow_hyphen_values = true)]
        settings: Vec<String>,
    },
    /// Solve a preset over a range of one parameter (a curve) or two (a grid); rows on stdout.
    Sweep {
        /// The preset file (TOML, schema 1).
        preset: PathBuf,
        /// The parameter and its range, e.g. material.thickness=1um:10mm:40:log (one for a
        /// curve, two for a grid; N defaults to 50 for a curve, 20 per side for a grid).
        #[arg(long, value_name = "KEY=FROM:TO[:N][:log]", allow_hyphen_values = true)]
        vary: Vec<String>,
        /// Set a preset value first, e.g. plane.model=strip (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE", allow_hyphen_values = true)]
        settings: Vec<String>,
        /// The quantities to write, comma-separated (default: the scalar keys of `solve`).
        #[arg(long, value_name = "LIST")]
        output: Option<String>,
        /// Output format.
        #[arg(long, value_enum, default_value_t = Format::Csv)]
        format: Format,
    },
}

#[derive(Clone, Copy, ValueEnum)]
enum Format {
    Json,
    Csv,
}

/// Profile points when `--points` is not given.
const DEFAULT_POINTS: usize = 201;

fn number(text: &str, name: &str, limit: &Limit) -> Result<f64, String> {
    let v: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("'{text}' is not a number (allowed {})", limit.allowed))?;
    limit.check(name, v)?;
    Ok(v)
}

fn parse_points(text: &str) -> Result<usize, String> {
    number(text, "--points", &limits::PROFILE_POINTS).map(|n| n as usize)
}

fn parse_time(text: &str) -> Result<f64, String> {
    number(text, "--time", &limits::TIME)
}

fn parse_probe(text: &str) -> Result<[f64; 2], String> {
    match text.split(',').collect::<Vec<_>>().as_slice() {
        [x, y] => Ok([
            number(x, "x", &limits::PROBE)?,
            number(y, "y", &limits::PROBE)?,
        ]),
        _ => Err(format!("'{text}' is not a point X,Y in metres")),
    }
}

/// Writes a line on stderr; a closed or full stderr cannot be told, so its error is dropped.
fn say(message: &str) {
    let _ = writeln!(io::stderr(), "{message}");
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Some(Command::Solve {
            preset,
            format,
            points,
            time,
            probe,
            settings,
        }) => solve(
            &preset,
            format,
            &Overrides {
                points,
                time,
                probes: probe,
                settings,
            },
        ),
        Some(Command::Sweep {
            preset,
            vary,
            settings,
            output,
            format,
        }) => cli::sweep::run(&cli::sweep::Request {
            path: &preset,
            vary: &vary,
            settings: &settings,
            output: output.as_deref(),
            format,
        }),
        None => explore(
            cli.preset,
            tui::Options {
                ascii: cli.ascii,
                mouse: cli.mouse,
            },
        ),
    }
}

fn load(path: &Path) -> Result<Preset, ExitCode> {
    preset::load(path).map_err(|e| {
        say(&format!("error: {e}"));
        ExitCode::from(EXIT_INVALID)
    })
}

fn solver_failure(e: SolveError) -> ExitCode {
    say(&format!("error: {e}"));
    match e {
        SolveError::InvalidInput(_) => ExitCode::from(EXIT_INVALID),
        SolveError::NoSolution(_) => ExitCode::from(EXIT_UNSOLVABLE),
    }
}

/// The options of `solve` that apply to one problem only.
struct Overrides {
    points: Option<usize>,
    time: Option<f64>,
    probes: Vec<[f64; 2]>,
    /// `--set KEY=VALUE`, in order.
    settings: Vec<String>,
}

impl Overrides {
    /// An option given for the other problem is an error: a script that asks for `--time` on a
    /// plane preset expects an answer that depends on it, and would silently get one that does not.
    fn check(&self, problem: Problem) -> Result<(), String> {
        let (misplaced, this, other) = match problem {
            Problem::Plane if self.time.is_some() => ("--time", "plane", "spatial"),
            Problem::Plane if !self.probes.is_empty() => ("--probe", "plane", "spatial"),
            Problem::Spatial if self.points.is_some() => ("--points", "spatial", "plane"),
            _ => return Ok(()),
        };
        Err(format!(
            "{misplaced} applies to {other} presets only; this preset solves problem = \"{this}\""
        ))
    }
}

/// Prints the result, after the last check that it holds only finite numbers.
fn print(text: &str, guard: Result<(), finite::NonFinite>) -> ExitCode {
    if let Err(e) = guard {
        say(&format!("error: {e}"));
        return ExitCode::from(EXIT_UNSOLVABLE);
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

/// The preset at `path` with the `--set` values applied.
fn load_with(path: &Path, settings: &[String]) -> Result<Preset, ExitCode> {
    load(path)?.with_settings(settings).map_err(|why| {
        say(&format!("error: {why}"));
        ExitCode::from(EXIT_INVALID)
    })
}

fn solve(path: &Path, format: Format, options: &Overrides) -> ExitCode {
    let preset = match load_with(path, &options.settings) {
        Ok(p) => p,
        Err(code) => return code,
    };
    if let Err(why) = options.check(preset.problem) {
        say(&format!("error: {why}"));
        return ExitCode::from(EXIT_INVALID);
    }
    match preset.problem {
        Problem::Plane => {
            let points = options.points.unwrap_or(DEFAULT_POINTS);
            match report::plane_report(&preset, points) {
                Ok(r) => match format {
                    Format::Json => print(&(report::to_json(&r) + "\n"), finite::check(&r)),
                    Format::Csv => {
                        let csv = report::profile_csv(&r.profile);
                        let guard = finite::check_csv(&csv);
                        print(&csv, guard)
                    }
                },
                Err(e) => solver_failure(e),
            }
        }
        Problem::Spatial => {
            match spatial_report::spatial_report(&preset, options.time, &options.probes) {
                Ok(r) => match format {
                    Format::Json => print(&(report::to_json(&r) + "\n"), finite::check(&r)),
                    Format::Csv => {
                        let csv = spatial_report::field_csv(&r);
                        let guard = finite::check_csv(&csv);
                        print(&csv, guard)
                    }
                },
                Err(e) => solver_failure(e),
            }
        }
    }
}

fn explore(path: Option<PathBuf>, options: tui::Options) -> ExitCode {
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
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            say(&format!("error: the terminal failed: {e}"));
            ExitCode::FAILURE
        }
    }
}
