//! The values a fit writes into the preset (the explorer's form, `wearlab fit --write`): a
//! parameter the data do not determine keeps the preset's value where that fits within the
//! noise, else takes the end of the range that fits nearest to it, never the round-off value the
//! minimisation ran off to along a direction the data do not feel; the determined ones are then
//! fitted again with those held, and each is written to the digits its 95 % interval supports
//! (`units::supported`: two significant digits of the half-width).

use nalgebra::DVector;

use super::lm::{self, Minimum};
use super::model::{Free, Model};
use super::profile::Range;
use super::{Estimate, FitError};
use crate::units::{CLEAN_DIGITS, significant, supported};

/// The value an undetermined parameter keeps [SI]: `start` (the preset's) where it lies within
/// the range that fits within the noise (an open end of the range bounds nothing), else the
/// range's end nearest to it, with the fewest significant digits (two at least) that keep it
/// within the range.
pub fn kept(fr: Free, start: f64, range: &Range) -> f64 {
    let low = if range.low_open {
        f64::NEG_INFINITY
    } else {
        fr.value(range.low)
    };
    let high = if range.high_open {
        f64::INFINITY
    } else {
        fr.value(range.high)
    };
    let end = start.clamp(low, high);
    if end == start {
        return start;
    }
    (2..=CLEAN_DIGITS)
        .map(|digits| significant(end, digits))
        .find(|v| (low..=high).contains(v))
        .unwrap_or(end)
}

/// The values to write, one per free parameter [SI]. Where some parameter is not determined, the
/// determined ones are fitted again (from `best`) with the others held at their kept values, and
/// their estimates and intervals move there (each interval keeps its width in the fitting
/// coordinate, `standard` its standard errors at the minimum); then every determined value is
/// rounded to its interval's digits.
pub fn values(
    model: &Model,
    best: &Minimum,
    estimates: &mut [Estimate],
    standard: &[Option<f64>],
    quantile: f64,
) -> Result<Vec<f64>, FitError> {
    let free = model.free;
    let determined: Vec<usize> = (0..free.len())
        .filter(|j| estimates[*j].determined)
        .collect();
    if determined.len() < free.len() && !determined.is_empty() {
        let mut held = best.x.clone();
        for (j, e) in estimates.iter().enumerate() {
            if !e.determined {
                held[j] = free[j].coordinate(e.value);
            }
        }
        let whole = |d: &DVector<f64>| {
            let mut theta = held.clone();
            for (k, j) in determined.iter().enumerate() {
                theta[*j] = d[k];
            }
            theta
        };
        let f = |d: &DVector<f64>| model.residuals(&whole(d));
        let from = DVector::from_iterator(determined.len(), determined.iter().map(|j| best.x[*j]));
        let (refit, _) = lm::minimize_point(&f, from, lm::MAX_ITERATIONS).map_err(|why| {
            FitError::NoFit(format!(
                "the fit with the undetermined parameters held cannot be done: {why}"
            ))
        })?;
        for (k, j) in determined.iter().enumerate() {
            let (fr, c) = (free[*j], refit[k]);
            let e = &mut estimates[*j];
            e.value = fr.value(c);
            if let Some(se) = standard[*j] {
                e.interval = super::within_limit(
                    fr.key,
                    [fr.value(c - quantile * se), fr.value(c + quantile * se)],
                );
            }
        }
    }
    for j in determined {
        let e = &mut estimates[j];
        e.value = supported(e.value, 0.5 * (e.interval[1] - e.interval[0]));
    }
    Ok(estimates.iter().map(|e| e.value).collect())
}
