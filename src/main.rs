//! The `wearlab` binary: its command line read and handed to the subcommand (`cli`).

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod cli;

use cli::{Format, check, explorer, fit, solve, sweep};
use wearlab::tui;

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
        /// Output format (default: JSON; with --output, one `KEY = value unit` line each).
        #[arg(long, value_enum)]
        format: Option<Format>,
        /// Print only these quantities, comma-separated (the names of `wearlab sweep --output`,
        /// e.g. mu_star,a,b).
        #[arg(long, value_name = "KEY[,KEY...]", conflicts_with_all = ["points", "probe"])]
        output: Option<String>,
        /// Number of profile points, both ends included (plane; default 201).
        #[arg(long, value_name = "N", allow_hyphen_values = true, value_parser = solve::parse_points)]
        points: Option<usize>,
        /// The instant t [s] to solve at, overriding the preset's spatial.time (spatial).
        #[arg(long, value_name = "T", allow_hyphen_values = true, value_parser = solve::parse_time)]
        time: Option<f64>,
        /// Also report the fields at the point X,Y [m] (spatial; repeatable).
        #[arg(long, value_name = "X,Y", allow_hyphen_values = true, value_parser = solve::parse_probe)]
        probe: Vec<[f64; 2]>,
        /// Set a preset value before solving, e.g. material.thickness=10um (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE", allow_hyphen_values = true)]
        settings: Vec<String>,
        /// Let --set change the keys the preset's lesson locks (the instructor's check).
        #[arg(long)]
        unlock: bool,
        /// Stop after S seconds of wall-clock time with exit code 3 (the solve is not finished).
        #[arg(long, value_name = "S", value_parser = cli::parse_seconds)]
        max_seconds: Option<f64>,
        /// Also write the punch surface at t (a spatial.surface preset) to FILE as a height-map
        /// CSV.
        #[arg(long, value_name = "FILE", conflicts_with = "output")]
        write_surface: Option<PathBuf>,
        /// Also compute mu* against the mean pressure over spatial.sweep (spatial, JSON; on the
        /// period cell a contact solve a point). The plane report always holds its load sweep.
        #[arg(long, conflicts_with = "output")]
        sweep: bool,
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
        /// Let --set change the keys the preset's lesson locks (the instructor's check).
        #[arg(long)]
        unlock: bool,
        /// The quantities to write, comma-separated (default: the scalar keys of `solve`).
        #[arg(long, value_name = "LIST")]
        output: Option<String>,
        /// Output format.
        #[arg(long, value_enum, default_value_t = Format::Csv)]
        format: Format,
        /// Stop after S seconds of wall-clock time with exit code 3, saying how many points
        /// were done.
        #[arg(long, value_name = "S", value_parser = cli::parse_seconds)]
        max_seconds: Option<f64>,
    },
    /// Fit preset values to a data file (weighted least squares) and print estimates, 95 %
    /// intervals and whether the data determine each, as JSON.
    Fit {
        /// The preset file (TOML, schema 1): the model and the starting values.
        preset: PathBuf,
        /// The data file: CSV with a header `quantity [unit],...`, the x axis first; without
        /// it, the file the preset's [explore] section names (`data = "..."`, beside the preset).
        #[arg(long, value_name = "FILE")]
        data: Option<PathBuf>,
        /// The preset keys to fit, comma-separated, e.g. friction.coefficient,wear.coefficient.
        #[arg(long, value_name = "KEY[,KEY...]")]
        free: String,
        /// Set a preset value first, e.g. plane.model=strip (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE", allow_hyphen_values = true)]
        settings: Vec<String>,
        /// Let --set change the keys the preset's lesson locks (the instructor's check).
        #[arg(long)]
        unlock: bool,
        /// Save the fitted preset to this file (atomically).
        #[arg(long, value_name = "OUT.toml")]
        write: Option<PathBuf>,
        /// Stop after S seconds of wall-clock time with exit code 3.
        #[arg(long, value_name = "S", value_parser = cli::parse_seconds)]
        max_seconds: Option<f64>,
    },
    /// Print the answer key of a preset's lesson: each question with the program's answer.
    Check {
        /// The preset file (TOML, schema 1) with a [lesson] section.
        preset: PathBuf,
        /// Output format.
        #[arg(long, value_enum, default_value_t = check::CheckFormat::Text)]
        format: check::CheckFormat,
    },
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
            unlock,
            max_seconds,
            output,
            write_surface,
            sweep,
        }) => solve::run(
            &preset,
            format,
            &solve::Overrides {
                points,
                time,
                probes: probe,
                settings,
                unlock,
                max_seconds,
                output,
                write_surface,
                sweep,
            },
        ),
        Some(Command::Sweep {
            preset,
            vary,
            settings,
            unlock,
            output,
            format,
            max_seconds,
        }) => sweep::run(&sweep::Request {
            path: &preset,
            vary: &vary,
            settings: &settings,
            unlock,
            output: output.as_deref(),
            format,
            max_seconds,
        }),
        Some(Command::Fit {
            preset,
            data,
            free,
            settings,
            unlock,
            write,
            max_seconds,
        }) => fit::run(&fit::Request {
            path: &preset,
            data: data.as_deref(),
            free: &free,
            settings: &settings,
            unlock,
            write: write.as_deref(),
            max_seconds,
        }),
        Some(Command::Check { preset, format }) => check::run(&preset, format),
        None => explorer::run(
            cli.preset,
            tui::Options {
                ascii: cli.ascii,
                mouse: cli.mouse,
            },
        ),
    }
}
