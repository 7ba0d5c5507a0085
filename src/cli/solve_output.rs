//! `wearlab solve PRESET --output KEY[,KEY...]`: chosen scalars of the solved preset, named as
//! `wearlab sweep --output` names them (`sweeps::quantity`): one `KEY = value unit` line each,
//! or with `--format json` one object `{"KEY": value, ...}` (units are those of `wearlab sweep
//! --format json`'s `outputs`), or with `--format csv` a header and one row. Numbers are the
//! shortest text that reads back to the same bits; flags are true/false.

use std::process::ExitCode;

use wearlab::finite;
use wearlab::physics::spatial::partial::running_in::Stopped;
use wearlab::physics::stop::Stop;
use wearlab::preset::Preset;
use wearlab::sweeps::QuantityKey;
use wearlab::sweeps::point;

use super::{
    EXIT_INVALID, EXIT_UNSOLVABLE, Format, SOLVE_NOT_FINISHED, print, say, solver_failure,
};

/// Reads `--output`: names of the preset's quantities, separated by commas. Err names the
/// quantities there are.
pub fn parse(preset: &Preset, list: &str) -> Result<Vec<QuantityKey>, String> {
    list.split(',')
        .map(|name| QuantityKey::parse(name, preset).map_err(|why| format!("--output {why}")))
        .collect()
}

/// A number as text: plain between 1e-3 and 1e6, in exponent form outside (both the shortest
/// that reads back to the same f64).
pub fn number(v: f64) -> String {
    if v == 0.0 || (1e-3..1e6).contains(&v.abs()) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// Solves the preset and prints the chosen quantities; a quantity without a value at the
/// preset's point is exit 3 with the reason. Err (nothing printed) when `stop` said so before
/// the values were ready.
pub fn answer(
    preset: &Preset,
    list: &str,
    format: Option<Format>,
    stop: Stop,
) -> Result<ExitCode, String> {
    let outputs = match parse(preset, list) {
        Ok(o) => o,
        Err(why) => {
            say(&format!("error: {why}"));
            return Ok(ExitCode::from(EXIT_INVALID));
        }
    };
    let point = match point::solve_until(preset, stop) {
        Ok(p) => p,
        Err(Stopped::Cancelled) => return Err(SOLVE_NOT_FINISHED.into()),
        Err(Stopped::Failed(e)) => return Ok(solver_failure(e)),
    };
    let mut values = Vec::new();
    for q in &outputs {
        match q.value(&point) {
            Ok(v) => values.push(v),
            Err(why) => {
                say(&format!("error: {q} has no value here: {why}"));
                return Ok(ExitCode::from(EXIT_UNSOLVABLE));
            }
        }
    }
    if stop.now() {
        return Err(SOLVE_NOT_FINISHED.into());
    }
    let guard = finite::check(&values);
    let text = |q: &QuantityKey, v: f64| {
        if q.quantity().flag {
            (v != 0.0).to_string()
        } else {
            number(v)
        }
    };
    let out = match format {
        None => outputs
            .iter()
            .zip(&values)
            .map(|(q, &v)| match q.quantity().unit {
                unit if unit.is_empty() || q.quantity().flag => format!("{q} = {}\n", text(q, v)),
                unit => format!("{q} = {} {unit}\n", text(q, v)),
            })
            .collect(),
        Some(Format::Json) => {
            // in the order asked for (serde_json's own map would sort the keys)
            let fields: Vec<String> = outputs
                .iter()
                .zip(&values)
                .map(|(q, &v)| {
                    let value = if q.quantity().flag {
                        serde_json::Value::Bool(v != 0.0)
                    } else {
                        serde_json::json!(v)
                    };
                    format!("{}: {value}", serde_json::Value::String(q.to_string()))
                })
                .collect();
            format!("{{{}}}\n", fields.join(", "))
        }
        Some(Format::Csv) => {
            let names: Vec<String> = outputs.iter().map(|q| q.to_string()).collect();
            let row: Vec<String> = outputs
                .iter()
                .zip(&values)
                .map(|(q, &v)| {
                    if q.quantity().flag {
                        text(q, v)
                    } else {
                        format!("{v:e}")
                    }
                })
                .collect();
            format!("{}\n{}\n", names.join(","), row.join(","))
        }
    };
    Ok(print(&out, guard))
}
