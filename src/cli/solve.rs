//! `wearlab solve PRESET [--format json|csv] [--points N] [--time T] [--probe X,Y] [--set ...]`:
//! the library's report of one preset (`report::plane_report`, `spatial_report`) on stdout, or with
//! `--output KEY[,KEY...]` chosen quantities of it (`solve_output`).

use std::io::{self, IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use wearlab::physics::limits::{self, Limit};
use wearlab::physics::spatial::partial::running_in::Stopped;
use wearlab::physics::spatial::result::SpatialResult;
use wearlab::physics::stop::Stop;
use wearlab::preset::{Links, Preset, Problem, write_atomically};
use wearlab::{finite, report, spatial_report};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use super::{
    EXIT_INVALID, EXIT_OUTPUT, Format, SOLVE_NOT_FINISHED, finished, load_with, print_streamed,
    say, solve_output, solver_failure, within,
};

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

/// Reads `--points N`.
pub fn parse_points(text: &str) -> Result<usize, String> {
    number(text, "--points", &limits::PROFILE_POINTS).map(|n| n as usize)
}

/// Reads `--time T` [s].
pub fn parse_time(text: &str) -> Result<f64, String> {
    number(text, "--time", &limits::TIME)
}

/// Reads `--probe X,Y` [m].
pub fn parse_probe(text: &str) -> Result<[f64; 2], String> {
    match text.split(',').collect::<Vec<_>>().as_slice() {
        [x, y] => Ok([
            number(x, "x", &limits::PROBE)?,
            number(y, "y", &limits::PROBE)?,
        ]),
        _ => Err(format!("'{text}' is not a point X,Y in metres")),
    }
}

/// The options of `solve` that apply to one problem only, and its time bound.
pub struct Overrides {
    pub points: Option<usize>,
    pub time: Option<f64>,
    pub probes: Vec<[f64; 2]>,
    /// `--set KEY=VALUE`, in order.
    pub settings: Vec<String>,
    /// `--unlock`: `--set` may change the keys the lesson locks.
    pub unlock: bool,
    /// `--max-seconds`: the bound on the solve's wall-clock time [s].
    pub max_seconds: Option<f64>,
    /// `--output KEY[,KEY...]`: print these quantities instead of the report.
    pub output: Option<String>,
    /// `--write-surface FILE`: also write the punch surface at t as a height-map CSV.
    pub write_surface: Option<PathBuf>,
    /// `--sweep`: also compute mu* against the mean pressure (spatial, JSON); the plane report
    /// always holds its load sweep.
    pub sweep: bool,
}

impl Overrides {
    /// An option given for the other problem is an error: a script that asks for `--time` on a
    /// plane preset expects an answer that depends on it, and would silently get one that does not.
    fn check(&self, problem: Problem) -> Result<(), String> {
        let (misplaced, this, other) = match problem {
            Problem::Plane if self.time.is_some() => ("--time", "plane", "spatial"),
            Problem::Plane if self.write_surface.is_some() => {
                ("--write-surface", "plane", "spatial")
            }
            Problem::Plane if !self.probes.is_empty() => ("--probe", "plane", "spatial"),
            Problem::Spatial if self.points.is_some() => ("--points", "spatial", "plane"),
            _ => return Ok(()),
        };
        Err(format!(
            "{misplaced} applies to {other} presets only; this preset solves problem = \"{this}\""
        ))
    }
}

/// Runs `wearlab solve`.
/// `format` is None when `--format` is not given: the report is then JSON, `--output` lines.
pub fn run(path: &Path, format: Option<Format>, options: &Overrides) -> ExitCode {
    let mut preset = match load_with(path, &options.settings, options.unlock) {
        Ok(p) => p,
        Err(code) => return code,
    };
    if let Err(why) = options.check(preset.problem) {
        say(&format!("error: {why}"));
        return ExitCode::from(EXIT_INVALID);
    }
    let spinner = ProgressBar::hidden();
    let start = Instant::now();
    let tick = || show_after_a_second(&spinner, start);
    if let Some(list) = options.output.clone() {
        if let Some(t) = options.time {
            preset.spatial.time = t;
        }
        let bounded = within(
            options.max_seconds,
            |stop| solve_output::answer(&preset, &list, format, stop),
            &tick,
        );
        spinner.finish_and_clear();
        return finished(bounded);
    }
    if options.write_surface.is_some() && preset.spatial.surface.is_none() {
        say(
            "error: --write-surface writes a height-map punch (spatial.surface); this preset's \
             punch is [[spatial.harmonics]]",
        );
        return ExitCode::from(EXIT_INVALID);
    }
    if options.sweep && format == Some(Format::Csv) {
        say("error: --sweep adds the mu* curve to the JSON report; the CSV is the field alone");
        return ExitCode::from(EXIT_INVALID);
    }
    let asked = Asked {
        format: format.unwrap_or(Format::Json),
        points: options.points.unwrap_or(DEFAULT_POINTS),
        time: options.time,
        probes: &options.probes,
        write_surface: options.write_surface.as_deref(),
        sweep: options.sweep,
    };
    let bounded = within(
        options.max_seconds,
        |stop| answer(&preset, &asked, stop),
        &tick,
    );
    spinner.finish_and_clear();
    finished(bounded)
}

/// A spinner with the time so far on stderr when it is a terminal (never in a pipe), drawn
/// once the solve has taken a second.
fn show_after_a_second(spinner: &ProgressBar, start: Instant) {
    if spinner.is_hidden() {
        if start.elapsed().as_secs_f64() < 1.0 || !io::stderr().is_terminal() {
            return;
        }
        spinner.set_draw_target(ProgressDrawTarget::stderr());
        if let Ok(style) = ProgressStyle::with_template("{spinner} solving, {elapsed} so far") {
            spinner.set_style(style);
        }
    }
    spinner.tick();
}

/// What a solve prints and writes.
struct Asked<'a> {
    format: Format,
    points: usize,
    time: Option<f64>,
    probes: &'a [[f64; 2]],
    write_surface: Option<&'a Path>,
    sweep: bool,
}

/// Solves the preset, writes the surface when asked and prints its report. Err (nothing written)
/// when `stop` said so before the answer was ready: a spatial solve asks it inside its work, a
/// plane solve (within its solvers' own bounds) at its end.
fn answer(preset: &Preset, asked: &Asked, stop: Stop) -> Result<ExitCode, String> {
    let (format, points, time, probes) = (asked.format, asked.points, asked.time, asked.probes);
    // an answer ready only after the bound is not printed either
    let in_time = || {
        if stop.now() {
            Err(SOLVE_NOT_FINISHED.to_string())
        } else {
            Ok(())
        }
    };
    match preset.problem {
        Problem::Plane => match report::plane_report(preset, points) {
            Ok(r) => {
                in_time()?;
                if let Some(y) = r.yield_check.as_ref().filter(|y| y.yields == Some(true)) {
                    say(&format!("warning: {}", y.describe()));
                }
                Ok(match format {
                    Format::Json => print_streamed(finite::check(&r), |out| json(out, &r)),
                    Format::Csv => print_streamed(report::check_profile_csv(&r.profile), |out| {
                        report::write_profile_csv(out, &r.profile)
                    }),
                })
            }
            Err(e) => in_time().map(|()| solver_failure(e)),
        },
        Problem::Spatial => {
            match spatial_report::spatial_report_until(preset, time, probes, asked.sweep, stop) {
                Ok(r) => {
                    in_time()?;
                    if asked
                        .write_surface
                        .is_some_and(|path| !write_surface(path, &r))
                    {
                        return Ok(ExitCode::from(EXIT_OUTPUT));
                    }
                    Ok(match format {
                        Format::Json => print_streamed(finite::check(&r), |out| json(out, &r)),
                        Format::Csv => print_streamed(spatial_report::check_field_csv(&r), |out| {
                            spatial_report::write_field_csv(out, &r)
                        }),
                    })
                }
                Err(Stopped::Cancelled) => Err(SOLVE_NOT_FINISHED.into()),
                Err(Stopped::Failed(e)) => in_time().map(|()| solver_failure(e)),
            }
        }
    }
}

/// Writes `report` as `report::to_json` and a newline, as it is serialised.
fn json(out: &mut dyn Write, report: &impl serde::Serialize) -> io::Result<()> {
    report::write_json(out, report)?;
    out.write_all(b"\n")
}

/// Writes the surface at t of `result` to `path` atomically (the save of a preset's way); false,
/// having said why, when it cannot be written.
fn write_surface(path: &Path, result: &SpatialResult) -> bool {
    let Some(text) = spatial_report::surface_csv(result) else {
        return true;
    };
    match write_atomically(path, Links::Follow, |f| f.write_all(text.as_bytes())) {
        Ok(_) => true,
        Err(e) => {
            say(&format!(
                "error: cannot write the surface to {}: {e}",
                path.display()
            ));
            false
        }
    }
}
