//! `wearlab sweep PRESET --vary KEY=FROM:TO[:N][:log] [--vary ...] [--set ...] [--output LIST]
//! [--format csv|json]`: the library's sweep (`wearlab::sweeps::sweep`) with a progress bar on
//! a terminal, its rows on stdout as they are solved, and the exit codes of `solve`.

use std::io::{self, BufWriter, IsTerminal, Write};
use std::path::Path;
use std::process::ExitCode;

use indicatif::{ProgressBar, ProgressStyle};

use wearlab::physics::stop::Stop;
use wearlab::preset::Preset;
use wearlab::sweeps::axis::{Axis, CURVE_POINTS, GRID_POINTS};
use wearlab::sweeps::quantity::{self, QuantityKey};
use wearlab::sweeps::{output, sweep};

use super::{
    EXIT_INVALID, EXIT_OUTPUT, EXIT_UNSOLVABLE, Format, finished, load_with, say, stdout_at_start,
    within,
};

/// What `wearlab sweep` was asked.
pub struct Request<'a> {
    /// The preset file.
    pub path: &'a Path,
    /// `--vary`, in order.
    pub vary: &'a [String],
    /// `--set`, in order.
    pub settings: &'a [String],
    /// `--unlock`: `--set` may change the keys the lesson locks.
    pub unlock: bool,
    /// `--output`, a comma-separated list.
    pub output: Option<&'a str>,
    /// `--format`.
    pub format: Format,
    /// `--max-seconds`: the bound on the sweep's wall-clock time [s].
    pub max_seconds: Option<f64>,
}

fn invalid(why: &str) -> ExitCode {
    say(&format!("error: {why}"));
    ExitCode::from(EXIT_INVALID)
}

fn axes(preset: &Preset, vary: &[String]) -> Result<Vec<Axis>, String> {
    let points = match vary.len() {
        0 => {
            let Some(e) = &preset.explore else {
                return Err(
                    "give --vary KEY=FROM:TO[:N][:log] (one for a curve, two for a \
                     grid); this preset has no [explore] section to sweep"
                        .into(),
                );
            };
            e.check(preset)
                .map_err(|why| format!("the preset's [explore] section: {why}"))?;
            return Ok(e.axes.clone());
        }
        1 => CURVE_POINTS,
        2 => GRID_POINTS,
        n => {
            return Err(format!(
                "{n} --vary given: at most two (one gives a curve, two a grid)"
            ));
        }
    };
    let axes = vary
        .iter()
        .map(|v| Axis::parse(preset, v, points).map_err(|why| format!("--vary {why}")))
        .collect::<Result<Vec<_>, _>>()?;
    if let [a, b] = axes.as_slice()
        && a.key == b.key
    {
        return Err(format!(
            "--vary {} given twice: vary two different parameters",
            a.key
        ));
    }
    Ok(axes)
}

fn outputs(preset: &Preset, list: Option<&str>) -> Result<Vec<QuantityKey>, String> {
    match list {
        None => {
            let mut outputs = quantity::defaults(preset);
            if let Some(q) = preset.explore.as_ref().map(|e| e.quantity)
                && !outputs.contains(&q)
            {
                outputs.push(q);
            }
            Ok(outputs)
        }
        Some(list) => list
            .split(',')
            .map(|name| QuantityKey::parse(name, preset).map_err(|why| format!("--output {why}")))
            .collect(),
    }
}

/// A bar on stderr when it is a terminal and the rows go elsewhere (rows written to the same
/// screen show their own progress and would tear the bar).
fn progress(points: usize) -> ProgressBar {
    if !io::stderr().is_terminal() || io::stdout().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(points as u64);
    if let Ok(style) = ProgressStyle::with_template("{bar:40} {pos}/{len} points, {eta} left") {
        bar.set_style(style);
    }
    bar
}

/// Runs `wearlab sweep`.
pub fn run(request: &Request) -> ExitCode {
    let preset = match load_with(request.path, request.settings, request.unlock) {
        Ok(p) => p,
        Err(code) => return code,
    };
    let axes = match axes(&preset, request.vary) {
        Ok(a) => a,
        Err(why) => return invalid(&why),
    };
    let outputs = match outputs(&preset, request.output) {
        Ok(o) => o,
        Err(why) => return invalid(&why),
    };
    if stdout_at_start::closed() {
        say("error: cannot write the result to stdout: it is closed");
        return ExitCode::from(EXIT_OUTPUT);
    }
    let bar = progress(axes.iter().map(|a| a.range.points).product());
    let format = request.format;
    let bounded = within(
        request.max_seconds,
        |stop| answer(&preset, &axes, &outputs, format, &|| bar.inc(1), stop),
        &|| {},
    );
    bar.finish_and_clear();
    finished(bounded)
}

/// Sweeps and writes each row on stdout as it is solved. Err, saying how many rows were written,
/// when `stop` stopped the sweep (the text on stdout is then cut short where it stopped).
fn answer(
    preset: &Preset,
    axes: &[Axis],
    outputs: &[QuantityKey],
    format: Format,
    point_done: &(dyn Fn() + Sync),
    stop: Stop,
) -> Result<ExitCode, String> {
    let mut first_failure: Option<String> = None;
    let mut all_failed = true;
    let mut written_rows = 0;
    let rows = sweep::rows(preset, axes, outputs, point_done, stop).inspect(|row| {
        let Ok(row) = row else { return };
        written_rows += 1;
        match &row.failure {
            Some(why) if first_failure.is_none() => first_failure = Some(why.clone()),
            Some(_) => {}
            None => all_failed = false,
        }
    });
    let mut out = BufWriter::new(io::stdout().lock());
    let written = match format {
        Format::Csv => output::write_csv(&mut out, axes, outputs, rows),
        Format::Json => output::write_json(&mut out, preset, axes, outputs, rows),
    }
    .and_then(|()| out.flush());
    if let Err(e) = written {
        if stop.now() {
            let _ = out.flush();
            let points: usize = axes.iter().map(|a| a.range.points).product();
            return Err(format!("{written_rows} of {points} points done"));
        }
        say(&format!("error: cannot write the result to stdout: {e}"));
        return Ok(ExitCode::from(EXIT_OUTPUT));
    }
    Ok(match first_failure {
        Some(why) if all_failed => {
            say(&format!(
                "error: no point of the sweep has an answer; the first: {why}"
            ));
            ExitCode::from(EXIT_UNSOLVABLE)
        }
        _ => ExitCode::SUCCESS,
    })
}
