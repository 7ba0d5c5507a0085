//! The profile of the sum of squares along one free parameter (Seber & Wild (1989)
//! chapter 5): the parameter held at values stepped away from its estimate, the others fitted again
//! at each, until the sum of squares has risen by the 95 % threshold or the scan ends. A flat
//! profile over decades, or one that runs into the parameter's allowed range, says that the data
//! do not determine the parameter.

use nalgebra::DVector;

use super::lm::{self, Minimum};
use super::model::Model;

/// The offsets of the scan on each side of the estimate, in steps: evenly to 4 steps, then wider,
/// to 64 steps (16 decades of a logarithmic coordinate at a quarter decade a step), so that a
/// parameter whose best value ran towards zero (a wear coefficient the data hardly feel) still
/// finds where the data start to feel it.
pub const OFFSETS: [f64; 17] = [
    1.0, 2.0, 3.0, 4.0, 6.0, 8.0, 10.0, 12.0, 16.0, 20.0, 24.0, 28.0, 32.0, 40.0, 48.0, 56.0, 64.0,
];
/// The step of a logarithmic coordinate at most: a quarter decade.
pub const LOG_STEP: f64 = std::f64::consts::LN_10 / 4.0;
/// The end is found to 2^-BISECTIONS = 1/256 of the step in which the profile crosses the
/// threshold (as this many bisections of it would give it; `crossing`).
const BISECTIONS: usize = 8;
/// Iterations of the fit of the other parameters at each step (warm-started from the last).
const REFIT_ITERATIONS: usize = 50;

/// Where the profile stays within the threshold, in the fitting coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range {
    /// The low end.
    pub low: f64,
    /// The high end.
    pub high: f64,
    /// True when the low end is where the scan or the allowed values stopped, not a crossing.
    pub low_open: bool,
    /// True when the high end is so.
    pub high_open: bool,
}

fn with(theta: &DVector<f64>, j: usize, value: f64) -> DVector<f64> {
    let mut all = DVector::zeros(theta.len() + 1);
    let mut k = 0;
    for i in 0..all.len() {
        if i == j {
            all[i] = value;
        } else {
            all[i] = theta[k];
            k += 1;
        }
    }
    all
}

/// The sum of squares with parameter `j` at `value` and the others fitted from `others`.
fn profiled(
    model: &Model,
    j: usize,
    value: f64,
    others: &DVector<f64>,
) -> Result<(f64, DVector<f64>), String> {
    if others.is_empty() {
        let r = model.residuals(&with(others, j, value))?;
        return Ok((r.norm_squared(), others.clone()));
    }
    let f = |o: &DVector<f64>| model.residuals(&with(o, j, value));
    let (x, s) = lm::minimize_point(&f, others.clone(), REFIT_ITERATIONS)?;
    Ok((s, x))
}

/// The profile range of parameter `j` about the minimum `best`: steps of `step` times `OFFSETS`
/// outwards on each side until the sum of squares exceeds its minimum by `threshold`, the
/// crossing then found to 1/256 of the step (`crossing`). A step where the model has no answer
/// (a value outside the parameter's range) ends the scan on that side, open. The two sides are scanned in parallel
/// (rayon): each starts from the minimum and reads nothing of the other.
pub fn range(model: &Model, best: &Minimum, j: usize, step: f64, threshold: f64) -> Range {
    let scan = |sign: f64| side(model, best, j, sign * step, threshold);
    let ((low, low_open), (high, high_open)) = rayon::join(|| scan(-1.0), || scan(1.0));
    Range {
        low,
        high,
        low_open,
        high_open,
    }
}

/// One side of the profile range: the end in the fitting coordinate, stepping by `step` (its
/// sign the side), and true when the end is where the scan stopped, not a crossing.
fn side(model: &Model, best: &Minimum, j: usize, step: f64, threshold: f64) -> (f64, bool) {
    let centre = best.x[j];
    let rise = |at: f64, others: &DVector<f64>| {
        profiled(model, j, at, others)
            .map(|(s, fitted)| ((s - best.sum_of_squares).max(0.0), fitted))
    };
    let mut others: DVector<f64> = best.x.clone().remove_row(j);
    let mut inside = (centre, 0.0);
    let mut before = 0.0;
    for offset in OFFSETS {
        let at = centre + step * offset;
        match rise(at, &others) {
            Err(_) => break,
            Ok((r, _)) if r > threshold => {
                let width = (step * (offset - before)).abs() / f64::from(1u32 << BISECTIONS);
                let mut within = |x: f64| match rise(x, &others) {
                    Ok((r, fitted)) if r <= threshold => {
                        others = fitted;
                        Some(r)
                    }
                    Ok((r, _)) => Some(r),
                    Err(_) => None,
                };
                return (
                    crossing(inside, (at, r), threshold, width, &mut within),
                    false,
                );
            }
            Ok((r, fitted)) => (inside, others) = ((at, r), fitted),
        }
        before = offset;
    }
    (inside.0, true)
}

/// Where the rise crosses `threshold` between `inside` and `outside` (each a coordinate and its
/// rise, the first within the threshold, the second above it), to `width`: the middle of a
/// bracket at most `width` wide, as `BISECTIONS` halvings of the step give it, in fewer solves.
/// The square root of the rise is close to linear in the coordinate (the sum of squares close
/// to quadratic about its minimum): a secant of it lands next to the crossing, and a point
/// `width` beyond closes the bracket; each third try halves the bracket, so that the loop ends
/// as bisection would at the latest. `rise` is None where the model has no answer (counted as
/// above the threshold).
fn crossing(
    mut inside: (f64, f64),
    mut outside: (f64, f64),
    threshold: f64,
    width: f64,
    rise: &mut dyn FnMut(f64) -> Option<f64>,
) -> f64 {
    let g = |r: f64| r.sqrt() - threshold.sqrt();
    // which end the last secant point became (true: the inside one)
    let mut secant_moved: Option<bool> = None;
    for attempt in 0..3 * BISECTIONS {
        let (a, b) = (inside.0, outside.0);
        if (b - a).abs() <= width {
            break;
        }
        let towards = (b - a).signum();
        let x = match (secant_moved.take(), attempt % 3) {
            (Some(true), _) => a + 0.99 * width * towards,
            (Some(false), _) => b - 0.99 * width * towards,
            (None, 2) => 0.5 * (a + b),
            (None, _) if !outside.1.is_finite() => 0.5 * (a + b),
            (None, _) => {
                let (ga, gb) = (g(inside.1), g(outside.1));
                let t = (-ga / (gb - ga)).clamp(0.01, 0.99);
                a + t * (b - a)
            }
        };
        let secant = attempt % 3 == 0 && outside.1.is_finite();
        match rise(x) {
            Some(r) if r <= threshold => {
                inside = (x, r);
                secant_moved = secant.then_some(true);
            }
            r => {
                outside = (x, r.unwrap_or(f64::INFINITY));
                secant_moved = secant.then_some(false);
            }
        }
    }
    0.5 * (inside.0 + outside.0)
}
