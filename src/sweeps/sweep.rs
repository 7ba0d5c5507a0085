//! Sweeps of any parameter (`wearlab sweep`): the preset solved at every point of one axis (a
//! curve) or of two (a grid), in parallel, in a fixed order that does not depend on the number of
//! threads: the first axis varies slowest. Each point goes through `point::solve`, so each is bit
//! for bit what `wearlab solve --set` prints at that value; a point that cannot be solved says why
//! in its row.

use rayon::prelude::*;

use crate::preset::Preset;
use crate::sweeps::axis::Axis;
use crate::sweeps::point::{self, Point};
use crate::sweeps::quantity::QuantityKey;

/// One point of a sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The values of the varied parameters, in the order of the axes.
    pub at: Vec<f64>,
    /// Why the point has no answer (a value the rules between fields refuse, or the solver's
    /// reason, the one `wearlab solve` exits 3 with), or None.
    pub failure: Option<String>,
    /// Each output's value, or why it has none at this point.
    pub values: Vec<Result<f64, String>>,
}

impl Row {
    /// "ok" when every output has a value; otherwise why the empty ones are empty.
    pub fn status(&self) -> String {
        if let Some(why) = &self.failure {
            return why.clone();
        }
        let mut reasons: Vec<&str> = Vec::new();
        for why in self.values.iter().filter_map(|v| v.as_ref().err()) {
            if !reasons.contains(&why.as_str()) {
                reasons.push(why);
            }
        }
        if reasons.is_empty() {
            "ok".into()
        } else {
            reasons.join("; ")
        }
    }
}

/// The preset at one point: `base` with each axis's parameter set to its value (limits, then the
/// rules between fields).
pub fn preset_at(base: &Preset, axes: &[Axis], values: &[f64]) -> Result<Preset, String> {
    let mut preset = base.clone();
    for (axis, v) in axes.iter().zip(values) {
        preset.assign(axis.key, *v)?;
    }
    preset.check_rules()?;
    Ok(preset)
}

/// The outputs at one point; the failure, if any, first.
pub fn evaluate(
    preset: &Preset,
    outputs: &[QuantityKey],
) -> (Option<String>, Vec<Result<f64, String>>) {
    match point::solve(preset) {
        Ok(p) => (None, values(&p, outputs)),
        Err(e) => {
            let why = e.to_string();
            (
                Some(why.clone()),
                outputs.iter().map(|_| Err(why.clone())).collect(),
            )
        }
    }
}

fn values(point: &Point, outputs: &[QuantityKey]) -> Vec<Result<f64, String>> {
    outputs
        .iter()
        .map(|q| match q.value(point) {
            Ok(v) if !v.is_finite() => Err(format!("{q} is not a finite number here ({v})")),
            v => v.map_err(|why| format!("{q}: {why}")),
        })
        .collect()
}

/// The points of one or two axes, the first varying slowest.
pub fn points(axes: &[Axis]) -> Vec<Vec<f64>> {
    let mut rows: Vec<Vec<f64>> = vec![Vec::new()];
    for axis in axes {
        let values = axis.values();
        rows = rows
            .iter()
            .flat_map(|r| {
                values.iter().map(move |v| {
                    let mut r = r.clone();
                    r.push(*v);
                    r
                })
            })
            .collect();
    }
    rows
}

/// Solves `base` at every point of the axes in parallel (rayon) and returns the rows in the order
/// of `points`; `tick` is called once per finished point (from any thread).
pub fn run(
    base: &Preset,
    axes: &[Axis],
    outputs: &[QuantityKey],
    tick: &(dyn Fn() + Sync),
) -> Vec<Row> {
    points(axes)
        .into_par_iter()
        .map(|at| {
            let (failure, values) = match preset_at(base, axes, &at) {
                Ok(preset) => evaluate(&preset, outputs),
                Err(why) => {
                    let why = format!("invalid input: {why}");
                    (
                        Some(why.clone()),
                        outputs.iter().map(|_| Err(why.clone())).collect(),
                    )
                }
            };
            tick();
            Row {
                at,
                failure,
                values,
            }
        })
        .collect()
}
