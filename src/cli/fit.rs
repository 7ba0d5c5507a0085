//! `wearlab fit PRESET [--data FILE] --free KEY[,KEY...] [--set ...] [--write OUT.toml]`: the
//! library's fit (`wearlab::fit`) of the free parameters to a data file (`wearlab::data`; without
//! `--data`, the one the preset's `[explore]` section names), as JSON
//! on stdout: estimates, 95 % intervals, whether each is determined and why not, the residuals;
//! `--write` saves the fitted preset atomically, as the explorer saves an edited preset: the
//! preset file's text kept (comments, units, key order), only the values that changed rewritten.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use serde_json::{Map, Value, json};

use wearlab::data::{self, DataSet};
use wearlab::finite;
use wearlab::fit::{self, Fit, FitError};
use wearlab::physics::stop::Stop;
use wearlab::preset::{self, Key, Links, Origin, Preset};

use super::{
    EXIT_INVALID, EXIT_OUTPUT, EXIT_UNSOLVABLE, finished, load, print, say, settled, within,
};

/// What `wearlab fit` was asked.
pub struct Request<'a> {
    /// The preset file.
    pub path: &'a Path,
    /// `--data`; None for the file the preset's `[explore]` section names.
    pub data: Option<&'a Path>,
    /// `--free`, a comma-separated list of preset keys.
    pub free: &'a str,
    /// `--set`, in order.
    pub settings: &'a [String],
    /// `--unlock`: `--set` may change the keys the lesson locks.
    pub unlock: bool,
    /// `--write`: where to save the fitted preset.
    pub write: Option<&'a Path>,
    /// `--max-seconds`: the bound on the fit's wall-clock time [s].
    pub max_seconds: Option<f64>,
}

fn invalid(why: &str) -> ExitCode {
    say(&format!("error: {why}"));
    ExitCode::from(EXIT_INVALID)
}

fn keys(preset: &Preset, list: &str) -> Result<Vec<Key>, String> {
    list.split(',')
        .filter(|k| !k.trim().is_empty())
        .map(|k| preset.key(k).map_err(|why| format!("--free {why}")))
        .collect()
}

/// The data file to fit: `--data`, else the one the preset's `[explore]` section names (`data`,
/// as the explorer opens it: relative to the preset's folder).
fn data_file(request: &Request, preset: &Preset) -> Result<PathBuf, String> {
    if let Some(path) = request.data {
        return Ok(path.to_path_buf());
    }
    let named = preset.explore.as_ref().and_then(|e| e.data.as_deref());
    let Some(named) = named else {
        return Err(format!(
            "no data to fit: {} names no data file (its [explore] section has no `data = \"...\"`); \
             give one with --data FILE",
            request.path.display()
        ));
    };
    let folder = request.path.parent().unwrap_or(Path::new(""));
    Ok(folder.join(named))
}

/// Runs `wearlab fit`.
pub fn run(request: &Request) -> ExitCode {
    let read = match load(request.path) {
        Ok(p) => p,
        Err(code) => return code,
    };
    let preset = match settled(request.path, &read, request.settings, request.unlock) {
        Ok(p) => p,
        Err(code) => return code,
    };
    let data_path = match data_file(request, &preset) {
        Ok(p) => p,
        Err(why) => return invalid(&why),
    };
    let data = match data::read(&data_path, &preset) {
        Ok(d) => d,
        Err(e) => return invalid(&e.to_string()),
    };
    let keys = match keys(&preset, request.free) {
        Ok(k) => k,
        Err(why) => return invalid(&why),
    };
    // the file the preset was read from, whose text the written preset keeps
    let origin = Origin {
        path: request.path.to_path_buf(),
        preset: read,
    };
    let write = request.write.map(|out| (out, &origin));
    let bounded = within(
        request.max_seconds,
        |stop| answer(&preset, &data, &keys, write, stop),
        &|| {},
    );
    finished(bounded)
}

/// Fits and prints the report; Err (nothing written) when `stop` said so before the fit was done.
fn answer(
    preset: &Preset,
    data: &DataSet,
    keys: &[Key],
    write: Option<(&Path, &Origin)>,
    stop: Stop,
) -> Result<ExitCode, String> {
    let fitted = fit::fit_until(preset, data, keys, stop);
    if stop.now() {
        return Err("the fit was not finished".into());
    }
    let fitted = match fitted {
        Ok(f) => f,
        Err(FitError::Invalid(why)) => return Ok(invalid(&why)),
        Err(FitError::NoFit(why)) => {
            say(&format!("error: {why}"));
            return Ok(ExitCode::from(EXIT_UNSOLVABLE));
        }
    };
    let report = json(data, &fitted, write.map(|w| w.0));
    if let Some((out, origin)) = write
        && let Err(e) = preset::save_edited(&fitted.preset, Some(origin), out, Links::Follow)
    {
        say(&format!("error: cannot write {}: {e}", out.display()));
        return Ok(ExitCode::from(EXIT_OUTPUT));
    }
    let text = serde_json::to_string_pretty(&report).unwrap_or_default() + "\n";
    Ok(print(&text, finite::check(&report)))
}

/// The JSON report of a fit (keys of docs/cli.md).
fn json(data: &DataSet, f: &Fit, write: Option<&Path>) -> Value {
    let mut estimates = Map::new();
    let mut intervals = Map::new();
    let mut profiles = Map::new();
    let mut determined = Map::new();
    let mut reasons = Map::new();
    let mut units_of = Map::new();
    for e in &f.estimates {
        let key = e.key.to_string();
        estimates.insert(key.clone(), json!(e.value));
        intervals.insert(key.clone(), json!(e.interval));
        profiles.insert(key.clone(), json!(e.profile));
        determined.insert(key.clone(), json!(e.determined));
        units_of.insert(key.clone(), json!(e.key.param().unit));
        if let Some(why) = &e.reason {
            reasons.insert(key, json!(why));
        }
    }
    let summary: Vec<String> = f
        .estimates
        .iter()
        .map(|e| {
            let (value, [low, high]) = e.texts();
            e.undetermined_words(&e.key.to_string())
                .unwrap_or_else(|| format!("{} = {value} (95 %: {low} .. {high})", e.key))
        })
        .collect();
    json!({
        "data": data.path,
        "x": data.x.key.to_string(),
        "measured": data.measured.iter().map(|m| m.quantity.to_string()).collect::<Vec<_>>(),
        "points": data.len(),
        "notes": data.notes,
        "estimates": estimates,
        "intervals": intervals,
        "profile_ranges": profiles,
        "determined": determined,
        "reasons": reasons,
        "units": units_of,
        "summary": summary,
        "residuals": f.residuals,
        "sum_of_squares": f.sum_of_squares,
        "weighted": f.weighted,
        "residual_sd": (!f.weighted).then(|| f.residual_variance.sqrt()),
        "reduced_chi_square": f.sum_of_squares / f.degrees_of_freedom as f64,
        "degrees_of_freedom": f.degrees_of_freedom,
        "iterations": f.iterations,
        "written": write.map(|p| p.display().to_string()),
    })
}
