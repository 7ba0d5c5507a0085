//! The `wearlab` binary: the command line around the library.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};

mod tui;

use wearlab::physics::SolveError;
use wearlab::preset::{self, Preset, Problem};
use wearlab::report;

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
    /// Draw charts with ASCII dots instead of Braille (for terminals without Braille glyphs).
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
        /// Number of profile points, both ends included (plane).
        #[arg(long, default_value_t = 201, value_parser = clap::value_parser!(u32).range(2..=100_000))]
        points: u32,
        /// The instant t [s] to solve at, overriding the preset's spatial.time (spatial).
        #[arg(long, value_parser = parse_time)]
        time: Option<f64>,
        /// Also report the fields at the point X,Y [m] (spatial; repeatable).
        #[arg(long, value_name = "X,Y", value_parser = parse_probe)]
        probe: Vec<[f64; 2]>,
    },
}

#[derive(Clone, Copy, ValueEnum)]
enum Format {
    Json,
    Csv,
}

fn parse_time(text: &str) -> Result<f64, String> {
    let t: f64 = text
        .parse()
        .map_err(|_| format!("'{text}' is not a number of seconds"))?;
    wearlab::physics::limits::TIME.check("--time", t)?;
    Ok(t)
}

fn parse_probe(text: &str) -> Result<[f64; 2], String> {
    let parts: Vec<&str> = text.split(',').collect();
    match parts.as_slice() {
        [x, y] => match (x.trim().parse::<f64>(), y.trim().parse::<f64>()) {
            (Ok(x), Ok(y)) if x.is_finite() && y.is_finite() => Ok([x, y]),
            _ => Err(format!("'{text}' is not two numbers X,Y in metres")),
        },
        _ => Err(format!("'{text}' is not a point X,Y in metres")),
    }
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
        }) => solve(&preset, format, points as usize, time, &probe),
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
        eprintln!("error: {e}");
        ExitCode::from(EXIT_INVALID)
    })
}

fn solver_failure(e: SolveError) -> ExitCode {
    eprintln!("error: {e}");
    match e {
        SolveError::InvalidInput(_) => ExitCode::from(EXIT_INVALID),
        SolveError::NoSolution(_) => ExitCode::from(EXIT_UNSOLVABLE),
    }
}

fn solve(
    path: &Path,
    format: Format,
    points: usize,
    time: Option<f64>,
    probes: &[[f64; 2]],
) -> ExitCode {
    let preset = match load(path) {
        Ok(p) => p,
        Err(code) => return code,
    };
    match preset.problem {
        Problem::Plane => match report::plane_report(&preset, points) {
            Ok(r) => {
                match format {
                    Format::Json => println!("{}", report::to_json(&r)),
                    Format::Csv => print!("{}", report::profile_csv(&r.profile)),
                }
                ExitCode::SUCCESS
            }
            Err(e) => solver_failure(e),
        },
        Problem::Spatial => match report::spatial_report(&preset, time, probes) {
            Ok(r) => {
                match format {
                    Format::Json => println!("{}", report::to_json(&r)),
                    Format::Csv => print!("{}", report::field_csv(&r, &preset.friction)),
                }
                match r.contact.failure() {
                    // The complete-contact solution does not hold: the numbers are printed for
                    // inspection, but the solver has no answer.
                    Some(why) => {
                        eprintln!("error: {why}");
                        ExitCode::from(EXIT_UNSOLVABLE)
                    }
                    None => ExitCode::SUCCESS,
                }
            }
            Err(e) => solver_failure(e),
        },
    }
}

fn explore(path: Option<PathBuf>, options: tui::Options) -> ExitCode {
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
            eprintln!("error: the terminal failed: {e}");
            ExitCode::FAILURE
        }
    }
}
