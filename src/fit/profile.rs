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
/// Bisections of the step in which the profile crosses the threshold: the end to 1/256 of it.
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
    let m = lm::minimize(&f, others.clone(), REFIT_ITERATIONS)?;
    Ok((m.sum_of_squares, m.x))
}

/// The profile range of parameter `j` about the minimum `best`: steps of `step` times `OFFSETS`
/// outwards on each side until the sum of squares exceeds its minimum by `threshold`, the
/// crossing then bisected. A step where the model has no answer (a value outside the
/// parameter's range) ends the scan on that side, open. The two sides are scanned in parallel
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
    let mut inside = centre;
    let mut end = (inside, true);
    for offset in OFFSETS {
        let at = centre + step * offset;
        match rise(at, &others) {
            Err(_) => break,
            Ok((r, _)) if r > threshold => {
                let mut outside = at;
                for _ in 0..BISECTIONS {
                    let mid = 0.5 * (inside + outside);
                    match rise(mid, &others) {
                        Ok((r, fitted)) if r <= threshold => (inside, others) = (mid, fitted),
                        _ => outside = mid,
                    }
                }
                end = (0.5 * (inside + outside), false);
                break;
            }
            Ok((_, fitted)) => {
                (inside, others) = (at, fitted);
                end = (inside, true);
            }
        }
    }
    end
}
