//! The verdict at every point of a one-parameter sweep, as `strip_check::verdict` gives it at each,
//! without a strip solve at every doubted point: the deviations from the strip model vary smoothly
//! along a sweep, so they are measured on a grid of the doubted points and read between its
//! points where the interpolation puts them clearly on one side of the tolerances.

use rayon::prelude::*;

use crate::physics::plane::PlaneSolution;
use crate::physics::plane::strip_check::{StripCheck, holds_measured, measures, strip_check};
use crate::physics::plane::validity::{Passes, passes};

/// Points between two measured points of a run of doubted points.
const SPAN: usize = 8;

/// A point is read from the interpolation only where it puts each deviation at least this far
/// (as a fraction of its tolerance) beyond the interpolation's error bound from the tolerance.
pub(crate) const BAND: f64 = 0.02;

/// A measured point: the verdict, and the two deviations over their tolerances (contact width,
/// mu* - mu) where the strip model answered.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Measured {
    pub ok: bool,
    pub ratios: Option<[f64; 2]>,
}

/// The solution measured against the strip model (`strip_check`), its verdict as
/// `strip_check::judged` gives it: where measured, `holds_measured`; else the study's estimate
/// (`passes`: `estimate` without its words).
pub(crate) fn measure(sol: &PlaneSolution, passes: Passes) -> Measured {
    match strip_check(sol) {
        StripCheck::Measured(d) => Measured {
            ok: holds_measured(passes.assumptions_hold, &d),
            ratios: Some(d.ratios()),
        },
        _ => Measured {
            ok: passes.ok,
            ratios: None,
        },
    }
}

/// Whether the model holds at each point of a one-parameter sweep (its solutions in the sweep's
/// order, evenly spaced in the swept parameter or its logarithm; None where the model has no
/// solution): `verdict(sol).ok` at every point. Where the study's estimate passes a point, that is
/// the verdict. Along a run of doubted points, every SPAN-th point and the run's ends are measured
/// against the strip model (in parallel); between two of them, a point takes the verdict that the
/// deviations interpolated linearly give, where that is certain: each deviation's interpolated
/// value lies beyond the tolerance by more than the interpolation's error bound (half the largest
/// second difference of the grid around it, four times the h^2 f''/8 of a smooth curve) plus
/// BAND; elsewhere the point is measured. Its own assumptions (small slopes, ...) still decide as
/// in `judged`. A run of 100 doubted points costs about 15 strip solves instead of 100.
pub fn holds_along(sols: &[Option<PlaneSolution>]) -> Vec<Option<bool>> {
    let estimates: Vec<Option<Passes>> = sols.iter().map(|s| s.as_ref().map(passes)).collect();
    let doubted: Vec<bool> = (sols.iter().zip(&estimates))
        .map(|(s, e)| matches!((s, e), (Some(s), Some(e)) if measures(s, e.ok)))
        .collect();
    let mut holds: Vec<Option<bool>> = estimates.iter().map(|e| e.map(|e| e.ok)).collect();
    let measure_at = |i: usize| match (&sols[i], estimates[i]) {
        (Some(sol), Some(estimated)) => measure(sol, estimated),
        _ => Measured {
            ok: false,
            ratios: None,
        },
    };
    let mut start = 0;
    while start < sols.len() {
        if !doubted[start] {
            start += 1;
            continue;
        }
        let end = (start..sols.len())
            .take_while(|&i| doubted[i])
            .last()
            .unwrap_or(start);
        let mut grid: Vec<usize> = (start..end).step_by(SPAN).collect();
        grid.push(end);
        let measured: Vec<Measured> = grid.par_iter().map(|&i| measure_at(i)).collect();
        for (&i, m) in grid.iter().zip(&measured) {
            holds[i] = Some(m.ok);
        }
        let ratios: Vec<Option<[f64; 2]>> = measured.iter().map(|m| m.ratios).collect();
        let (grid, ratios) = (&grid, &ratios);
        let between: Vec<(usize, Option<bool>)> = (0..grid.len().saturating_sub(1))
            .flat_map(|g| (grid[g] + 1..grid[g + 1]).map(move |k| (k, read(grid, ratios, g, k))))
            .collect();
        let unread: Vec<usize> = between
            .iter()
            .filter(|(_, r)| r.is_none())
            .map(|(k, _)| *k)
            .collect();
        let exact: Vec<Measured> = unread.par_iter().map(|&k| measure_at(k)).collect();
        for (k, inside) in between {
            if let Some(inside) = inside {
                let own = estimates[k].is_some_and(|e| e.assumptions_hold);
                holds[k] = Some(inside && own);
            }
        }
        for (&k, m) in unread.iter().zip(&exact) {
            holds[k] = Some(m.ok);
        }
        start = end + 1;
    }
    holds
}

/// Whether point k, between grid points g and g + 1, is within the tolerances according to the
/// deviations interpolated from the grid: false where one deviation is certainly beyond its
/// tolerance, true where both are certainly within, None where that is not certain (a grid point
/// without a measurement nearby, or a deviation within the error bound plus BAND of its
/// tolerance).
fn read(grid: &[usize], ratios: &[Option<[f64; 2]>], g: usize, k: usize) -> Option<bool> {
    let (lo, hi) = (ratios[g]?, ratios[g + 1]?);
    // second differences over the grid triples around the interval, where the spacing is even
    let second = |c: usize, m: usize| -> Option<f64> {
        let (a, b, d) = (
            ratios.get(m.checked_sub(1)?)?.as_ref()?,
            ratios[m]?,
            ratios.get(m + 1)?.as_ref()?,
        );
        let even = grid[m] - grid[m - 1] == grid[m + 1] - grid[m];
        even.then(|| (a[c] - 2.0 * b[c] + d[c]).abs())
    };
    let t = (k - grid[g]) as f64 / (grid[g + 1] - grid[g]) as f64;
    // each deviation certainly within (true) or beyond (false) its tolerance, or uncertain (None)
    let sides = [0, 1].map(|c| {
        let bound = second(c, g)
            .into_iter()
            .chain(second(c, g + 1))
            .reduce(f64::max)?;
        let value = lo[c] + t * (hi[c] - lo[c]);
        ((value - 1.0).abs() > 0.5 * bound + BAND).then_some(value < 1.0)
    });
    combined(sides)
}

/// The verdict from each deviation's side of its tolerance (true within, false beyond, None
/// uncertain): false where one is beyond, true where both are within, else None.
pub(crate) fn combined(sides: [Option<bool>; 2]) -> Option<bool> {
    if sides.contains(&Some(false)) {
        Some(false)
    } else if sides.iter().all(|s| *s == Some(true)) {
        Some(true)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The grid of a run of 33 points (every SPAN-th and the end) and the ratios of a deviation
    /// f(i) in contact width (mu* - mu held at 0.1, well inside).
    fn grid_of(f: impl Fn(f64) -> f64) -> (Vec<usize>, Vec<Option<[f64; 2]>>) {
        let grid: Vec<usize> = (0..=32).step_by(SPAN).collect();
        let ratios = grid.iter().map(|&i| Some([f(i as f64), 0.1])).collect();
        (grid, ratios)
    }

    #[test]
    fn a_straight_deviation_is_read_except_within_the_band_of_its_tolerance() {
        // crosses the tolerance (ratio 1) at i = 16: the second differences vanish, so only
        // the points within BAND of it (|i - 16| * 0.02 <= 0.02) are left to measure
        let (grid, ratios) = grid_of(|i| 1.32 - 0.02 * i);
        let read_at = |k: usize| read(&grid, &ratios, k / SPAN, k);
        assert_eq!(read_at(3), Some(false));
        assert_eq!(read_at(15), None);
        assert_eq!(read_at(17), None);
        assert_eq!(read_at(18), Some(true));
        assert_eq!(read_at(30), Some(true));
    }

    #[test]
    fn a_curved_deviation_widens_the_band_by_its_second_differences() {
        // f = 1 + (i - 16)^2/256 - 0.05: second difference over the grid 2 * 64/256 = 0.5,
        // so the bound 0.25 + BAND keeps every point near the dip unread
        let (grid, ratios) = grid_of(|i| 0.95 + (i - 16.0).powi(2) / 256.0);
        for k in 9..24 {
            assert_eq!(read(&grid, &ratios, k / SPAN, k), None, "{k}");
        }
    }

    #[test]
    fn one_deviation_certainly_beyond_decides_whatever_the_other() {
        let grid = vec![0, SPAN, 2 * SPAN];
        let ratios = vec![Some([5.0, 1.0]), Some([5.0, 1.0]), Some([5.0, 1.0])];
        assert_eq!(read(&grid, &ratios, 0, 3), Some(false));
        let unmeasured = vec![Some([5.0, 1.0]), None, Some([5.0, 1.0])];
        assert_eq!(read(&grid, &unmeasured, 0, 3), None);
    }
}
