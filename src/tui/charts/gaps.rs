//! Where a sweep has no value or its model fails: the shaded x ranges of a chart without
//! values, a curve's points without an answer in words, and the dim runs where its model fails.

use crate::tui::charts::{Axis, Series, Shade, Unanswered};
use crate::units::format_si;

/// The x ranges where a sweep has no value, each from the last point with a value before it to
/// the first after it (or the sweep's end).
pub(super) fn gaps(x: &[f64], values: &[Option<f64>], label: &str) -> Vec<Shade> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < values.len() {
        if values[i].is_some() {
            i += 1;
            continue;
        }
        let j = (i..values.len())
            .find(|&j| values[j].is_some())
            .unwrap_or(values.len());
        out.push(Shade {
            from: x[i.saturating_sub(1)],
            to: x[j.min(values.len() - 1)],
            label: label.into(),
        });
        i = j;
    }
    out
}

/// Where curve `curve`, computed at `x` (increasing or decreasing), has no value (None in
/// `values`): the range of x on the `axis` where they are one run at an end or in the middle,
/// counted among the points, which are `noun` ("no answer at P >= 1.70 kN/m (11 of 40
/// loads)"); None where every point has a value.
pub(super) fn unanswered(
    curve: usize,
    x: &[f64],
    values: &[Option<f64>],
    axis: &Axis,
    noun: &str,
) -> Option<Unanswered> {
    let missing: Vec<usize> = (0..values.len()).filter(|&k| values[k].is_none()).collect();
    let (&first, &last) = (missing.first()?, missing.last()?);
    let (n, m) = (values.len(), missing.len());
    let at = |k: usize| format_si(x[k], axis.unit);
    let rising = x[n - 1] >= x[0];
    let (to_end, from_start) = if rising { (">=", "<=") } else { ("<=", ">=") };
    let name = &axis.label;
    let words = match (first, last) {
        _ if last - first + 1 != m => format!("no answer at {m} of {n} {noun}"),
        (0, l) if l == n - 1 => format!("no answer at any of the {n} {noun}"),
        (f, l) if l == n - 1 => {
            format!("no answer at {name} {to_end} {} ({m} of {n} {noun})", at(f))
        }
        (0, l) => format!(
            "no answer at {name} {from_start} {} ({m} of {n} {noun})",
            at(l)
        ),
        (f, l) => format!(
            "no answer at {name} = {} to {} ({m} of {n} {noun})",
            at(f),
            at(l)
        ),
    };
    Some(Unanswered {
        curve,
        words,
        at: missing.iter().map(|&k| x[k]).collect(),
    })
}

/// The runs of consecutive points where the model of curve `curve` fails (`holds` false), each a
/// dim piece named `name` (the legend's name of the curve's dim parts where curves have marks);
/// `point(k)` is the k-th point as drawn, None where it is not (no value there ends a run).
pub(super) fn failing_runs(
    curve: usize,
    name: &str,
    holds: &[Option<bool>],
    point: impl Fn(usize) -> Option<(f64, f64)>,
) -> Vec<(usize, Series)> {
    let mut runs = Vec::new();
    let mut run: Vec<(f64, f64)> = Vec::new();
    for k in 0..=holds.len() {
        let failing = k < holds.len() && holds[k] == Some(false);
        match (failing, point(k.min(holds.len().saturating_sub(1)))) {
            (true, Some(p)) => run.push(p),
            _ if !run.is_empty() => runs.push((
                curve,
                Series {
                    name: name.to_string(),
                    points: std::mem::take(&mut run),
                },
            )),
            _ => {}
        }
    }
    runs
}

/// What a curve's legend adds while its verdicts are still being computed (the curve is drawn
/// before them): nothing once `judged`; for a plane model the validity being measured against the
/// strip model, for the spatial problem where its contact turns partial being located.
pub(super) fn pending(judged: bool, plane: bool) -> &'static str {
    match (judged, plane) {
        (true, _) => "",
        (false, true) => " (validity: measuring)",
        (false, false) => " (contact: locating changes)",
    }
}
