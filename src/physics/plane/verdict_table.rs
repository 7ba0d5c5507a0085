//! The verdicts of many points of one map, from measurements shared between them. For the
//! parabola with the linear laws the model and the strip model are, in the variables
//! x/h and q2 R/(m h), one problem in (a+b)/h with the groups nu, mu, gamma m and the adhesion
//! group tau0 R/(m h) (docs/physics/plane.md section 6, the equation divided by h/R); mu* - mu
//! scales as h/R in both, so the relative deviations (`Deviation`) are functions of (a+b)/h
//! alone once the groups are fixed. A map over the load and the thickness, say, has one such
//! function per model: it is measured at a few widths and read between them where that is
//! certain, instead of a strip solve at every doubted point.

use std::collections::HashMap;
use std::sync::Mutex;

use crate::physics::plane::strip_check::measures;
use crate::physics::plane::sweep_verdicts::{BAND, Measured, combined, measure};
use crate::physics::plane::validity::passes;
use crate::physics::plane::{Model, PlaneSolution, exponent};

/// The largest step in ln((a+b)/h) between two measurements read across.
const MAX_STEP: f64 = 0.1;

/// The groups that, with (a+b)/h, fix the deviations (as bits, for exact equality).
type Groups = (Model, [u64; 4]);

/// Measured deviations over their tolerances (contact width, mu* - mu) at ln((a+b)/h), sorted.
type Measurements = Vec<(f64, [f64; 2])>;

/// Measurements of the deviations from the strip model, by groups, each list sorted by
/// ln((a+b)/h).
#[derive(Debug, Default)]
pub struct VerdictTable {
    measured: Mutex<HashMap<Groups, Measurements>>,
}

impl VerdictTable {
    /// An empty table.
    pub fn new() -> VerdictTable {
        VerdictTable::default()
    }

    /// Whether the model holds at the solution: `strip_check::verdict(sol).ok`, read from the
    /// deviations measured at neighbouring widths with the same groups where their linear
    /// interpolation in ln((a+b)/h) is certain (beyond the tolerance by more than four times the
    /// interpolation's error h^2 |f''|/8, f'' the largest second divided difference around, plus
    /// BAND), else measured and kept.
    pub fn holds(&self, sol: &PlaneSolution) -> bool {
        let estimated = passes(sol);
        if !measures(sol, estimated.ok) {
            return estimated.ok;
        }
        let inputs = &sol.inputs;
        let (m, gamma, _) = exponent(inputs);
        let h = inputs.material.thickness;
        let groups = (
            sol.model,
            [
                inputs.material.poisson_ratio.to_bits(),
                inputs.friction.coefficient.to_bits(),
                (gamma * m).to_bits(),
                (inputs.friction.adhesion * inputs.radius() / (m * h)).to_bits(),
            ],
        );
        let x = (sol.contact_width() / h).ln();
        let read = self
            .measured
            .lock()
            .ok()
            .and_then(|t| t.get(&groups).and_then(|list| read(list, x)));
        if let Some(inside) = read {
            return inside && estimated.assumptions_hold;
        }
        let Measured { ok, ratios } = measure(sol, estimated);
        if let (Some(ratios), Ok(mut table)) = (ratios, self.measured.lock()) {
            let list = table.entry(groups).or_default();
            let at = list.partition_point(|(y, _)| *y < x);
            list.insert(at, (x, ratios));
        }
        ok
    }
}

/// Whether the deviations at ln((a+b)/h) = x are within the tolerances, read from the list:
/// false where one is certainly beyond, true where both are certainly within, None where not
/// certain (no measurement on either side within MAX_STEP, or within the bound of the tolerance).
fn read(list: &[(f64, [f64; 2])], x: f64) -> Option<bool> {
    let j = list.partition_point(|(y, _)| *y < x);
    let (lo, hi) = (list.get(j.checked_sub(1)?)?, list.get(j)?);
    let step = hi.0 - lo.0;
    if step > MAX_STEP || step <= 0.0 {
        return None;
    }
    let t = (x - lo.0) / step;
    // the largest |f''| of the triples of neighbours around the step
    let curvature = |c: usize| -> Option<f64> {
        let triples = [j.checked_sub(2), Some(j - 1)];
        triples
            .into_iter()
            .flatten()
            .filter_map(|i| {
                let (a, b, d) = (list.get(i)?, list.get(i + 1)?, list.get(i + 2)?);
                let slope =
                    |p: &(f64, [f64; 2]), q: &(f64, [f64; 2])| (q.1[c] - p.1[c]) / (q.0 - p.0);
                (d.0 - a.0 > 0.0).then(|| (2.0 * (slope(b, d) - slope(a, b)) / (d.0 - a.0)).abs())
            })
            .reduce(f64::max)
    };
    let sides = [0, 1].map(|c| {
        // four times the h^2 |f''|/8 of linear interpolation
        let bound = 0.5 * curvature(c)? * step * step;
        let value = lo.1[c] + t * (hi.1[c] - lo.1[c]);
        ((value - 1.0).abs() > bound + BAND).then_some(value < 1.0)
    });
    combined(sides)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Measurements of a deviation in contact width f(x) at the given x (mu* - mu well inside).
    fn list(xs: &[f64], f: impl Fn(f64) -> f64) -> Vec<(f64, [f64; 2])> {
        xs.iter().map(|&x| (x, [f(x), 0.1])).collect()
    }

    #[test]
    fn a_straight_deviation_is_read_except_near_its_tolerance() {
        // ratio 1 at x = 0.5
        let l = list(&[0.0, 0.05, 0.1, 0.15, 0.2, 0.6, 0.65, 0.7], |x| 0.5 + x);
        assert_eq!(read(&l, 0.025), Some(true));
        assert_eq!(read(&l, 0.675), Some(false));
        // the step from 0.2 to 0.6 is wider than MAX_STEP: measured
        assert_eq!(read(&l, 0.4), None);
        // outside the measurements: measured
        assert_eq!(read(&l, 0.8), None);
        assert_eq!(read(&l, -0.1), None);
    }
}
