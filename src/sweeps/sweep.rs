//! Sweeps of any parameter (`wearlab sweep`): the preset solved at every point of one axis (a
//! curve) or of two (a grid), in parallel, in a fixed order that does not depend on the number of
//! threads: the first axis varies slowest. `rows` hands the rows on as they are solved, a chunk at
//! a time, so a sweep's memory does not grow with its number of points. Each point goes through
//! `point::solve`, so each is bit for bit what `wearlab solve --set` prints at that value; a point
//! that cannot be solved says why in its row.

use rayon::prelude::*;

use crate::physics::spatial::partial::running_in::Stopped;
use crate::physics::stop::Stop;
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

/// A point's failure, if any, and each output's value or why it has none.
pub type Evaluated = (Option<String>, Vec<Result<f64, String>>);

/// The outputs at one point; the failure, if any, first.
pub fn evaluate(preset: &Preset, outputs: &[QuantityKey]) -> Evaluated {
    match point::solve(preset) {
        Ok(p) => (None, values(&p, outputs)),
        Err(e) => failed(e.to_string(), outputs),
    }
}

/// As [`evaluate`], told to stop by `stop` (`point::solve_until`): Err when it did.
fn evaluate_until(
    preset: &Preset,
    outputs: &[QuantityKey],
    stop: Stop,
) -> Result<Evaluated, Stopped> {
    match point::solve_until(preset, stop) {
        Ok(p) => Ok((None, values(&p, outputs))),
        Err(Stopped::Cancelled) => Err(Stopped::Cancelled),
        Err(Stopped::Failed(e)) => Ok(failed(e.to_string(), outputs)),
    }
}

/// A point without an answer: `why` as its failure and as every output's reason.
fn failed(why: String, outputs: &[QuantityKey]) -> Evaluated {
    let values = outputs.iter().map(|_| Err(why.clone())).collect();
    (Some(why), values)
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

/// Points solved together before their rows are handed on: enough to keep every thread busy, few
/// enough that a sweep of millions of points holds a few megabytes of rows at a time.
pub const CHUNK: usize = 4096;

/// The point at `index` of the axes' values, the first axis varying slowest.
fn point_at(values: &[Vec<f64>], mut index: usize) -> Vec<f64> {
    let mut at = vec![0.0; values.len()];
    for (slot, axis) in at.iter_mut().zip(values).rev() {
        *slot = axis[index % axis.len()];
        index /= axis.len();
    }
    at
}

/// The row at `at`, or Err when `stop` stopped its point (a point not started asks once).
fn solve_at(
    base: &Preset,
    axes: &[Axis],
    outputs: &[QuantityKey],
    at: Vec<f64>,
    stop: Stop,
) -> Result<Row, Stopped> {
    if stop.now() {
        return Err(Stopped::Cancelled);
    }
    let (failure, values) = match preset_at(base, axes, &at) {
        Ok(preset) => evaluate_until(&preset, outputs, stop)?,
        Err(why) => failed(format!("invalid input: {why}"), outputs),
    };
    Ok(Row {
        at,
        failure,
        values,
    })
}

/// The rows of a sweep, the first axis varying slowest, solved `CHUNK` points at a time in parallel
/// (rayon) as they are asked for, so that only one chunk is held at once. Once `stop` has stopped
/// a point, the rows before it are handed on, then one `Err(Stopped::Cancelled)`, then nothing:
/// a writer fails there, so a stopped sweep never reads as a whole one.
pub struct Rows<'a> {
    base: &'a Preset,
    axes: &'a [Axis],
    outputs: &'a [QuantityKey],
    tick: &'a (dyn Fn() + Sync),
    stop: Stop<'a>,
    values: Vec<Vec<f64>>,
    next: usize,
    count: usize,
    chunk: std::vec::IntoIter<Result<Row, Stopped>>,
}

impl Iterator for Rows<'_> {
    type Item = Result<Row, Stopped>;

    fn next(&mut self) -> Option<Result<Row, Stopped>> {
        if let Some(row) = self.chunk.next() {
            return Some(row);
        }
        if self.next >= self.count {
            return None;
        }
        let end = self.count.min(self.next + CHUNK);
        let (base, axes, outputs, tick, stop, values) = (
            self.base,
            self.axes,
            self.outputs,
            self.tick,
            self.stop,
            &self.values,
        );
        let mut rows: Vec<Result<Row, Stopped>> = (self.next..end)
            .into_par_iter()
            .map(|i| {
                let row = solve_at(base, axes, outputs, point_at(values, i), stop);
                if row.is_ok() {
                    tick();
                }
                row
            })
            .collect();
        self.next = end;
        if let Some(first) = rows.iter().position(Result::is_err) {
            rows.truncate(first + 1);
            self.next = self.count;
        }
        self.chunk = rows.into_iter();
        self.chunk.next()
    }
}

/// Solves `base` at every point of the axes in parallel, chunk by chunk as the rows are read, the
/// first axis varying slowest; `tick` is called once per finished point (from any thread), `stop`
/// is asked before every point and inside a spatial one (`point::solve_until`).
pub fn rows<'a>(
    base: &'a Preset,
    axes: &'a [Axis],
    outputs: &'a [QuantityKey],
    tick: &'a (dyn Fn() + Sync),
    stop: Stop<'a>,
) -> Rows<'a> {
    let values: Vec<Vec<f64>> = axes.iter().map(Axis::values).collect();
    Rows {
        base,
        axes,
        outputs,
        tick,
        stop,
        count: values.iter().map(Vec::len).product(),
        values,
        next: 0,
        chunk: Vec::new().into_iter(),
    }
}

/// Solves `base` at every point of the axes in parallel (rayon) and returns all the rows, the first
/// axis varying slowest; `tick` is called once per finished point (from any thread).
pub fn run(
    base: &Preset,
    axes: &[Axis],
    outputs: &[QuantityKey],
    tick: &(dyn Fn() + Sync),
) -> Vec<Row> {
    rows(base, axes, outputs, tick, Stop::Never)
        .filter_map(Result::ok)
        .collect()
}
