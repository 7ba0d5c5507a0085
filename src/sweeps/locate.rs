//! Where a verdict changes: bisection between two parameter values (in the axis's own spacing, so
//! a log axis is bisected in the logarithm), and the contour of a verdict on a grid of computed
//! points (marching squares on the cells, each crossing located on its edge).

use std::collections::HashMap;

use rayon::prelude::*;

use crate::physics::Spacing;

/// The value a fraction `u` in [0, 1] of the way from `from` to `to` along a `spacing` axis.
pub fn between(spacing: Spacing, from: f64, to: f64, u: f64) -> f64 {
    match spacing {
        Spacing::Log => (from.ln() + u * (to / from).ln()).exp(),
        Spacing::Linear => from + u * (to - from),
    }
}

/// The fraction u in (0, 1) of the way from `from` (where `side` is `start`) to `to` (where it is
/// not) at which `side` changes, to 2^-steps; None when `side` has no verdict somewhere inside.
pub fn bisect(steps: usize, start: bool, side: impl Fn(f64) -> Option<bool>) -> Option<f64> {
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..steps {
        let mid = 0.5 * (lo + hi);
        if side(mid)? == start {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// What a side function gives at a point: the side, and the smooth quantity that decides it where
/// there is one (a margin: positive on the `true` side, negative on the other).
pub type Probe = (bool, Option<f64>);

/// As [`bisect`], with the same guarantee: the middle of a bracket at most 2^-steps wide with
/// `start` at its lower end and the other side at its upper end. Where both ends carry a margin,
/// the next point is where the chord between them crosses zero (regula falsi with the Illinois
/// rule: the margin of an end kept twice in a row is halved), else the middle; a step that leaves
/// more than half of the bracket is followed by a bisection, so at most 2 steps + 1 probes. A
/// smooth margin narrows the bracket in a handful of probes instead of `steps`. A margin whose
/// sign disagrees with its side is not used.
pub fn locate_change(
    steps: usize,
    start: bool,
    probe: impl Fn(f64) -> Option<Probe>,
) -> Option<f64> {
    let tolerance = 0.5f64.powi(i32::try_from(steps).unwrap_or(i32::MAX));
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    let (mut f_lo, mut f_hi): (Option<f64>, Option<f64>) = (None, None);
    let mut last_moved_lo: Option<bool> = None;
    let mut halve_next = false;
    for _ in 0..=2 * steps {
        let width = hi - lo;
        if width <= tolerance {
            break;
        }
        let chord = match (f_lo, f_hi) {
            (Some(a), Some(b)) if !halve_next => Some(lo + width * a / (a - b)),
            _ => None,
        };
        // a chord point next to an end moves in by less than the tolerance, so that a converged
        // chord closes the bracket on the root's other side
        let inset = 0.4 * tolerance;
        let u = chord
            .filter(|u| u.is_finite())
            .map(|u| u.clamp(lo + inset, hi - inset))
            .unwrap_or(0.5 * (lo + hi));
        let (side, margin) = probe(u)?;
        let margin = margin.filter(|m| (*m > 0.0) == side);
        let moved_lo = side == start;
        if moved_lo {
            lo = u;
            f_lo = margin;
        } else {
            hi = u;
            f_hi = margin;
        }
        if last_moved_lo == Some(moved_lo) {
            let kept = if moved_lo { &mut f_hi } else { &mut f_lo };
            *kept = kept.map(|f| 0.5 * f);
        }
        last_moved_lo = Some(moved_lo);
        halve_next = hi - lo > 0.5 * width;
    }
    Some(0.5 * (lo + hi))
}

/// A node of a grid of computed points: (column, row) in the grid's own numbering.
pub type Node = (usize, usize);

/// A segment of a contour, two points (x, y) in the parameters' units.
pub type Segment = [[f64; 2]; 2];

/// The contour where `side` changes on an `nx` x `ny` grid of nodes: for every edge between two
/// nodes with different verdicts, `locate` gives the crossing (in parallel); each cell joins the
/// crossings on its edges into segments (two crossings: one segment; four, a saddle: two).
pub fn contour(
    nx: usize,
    ny: usize,
    side: &(dyn Fn(Node) -> Option<bool> + Sync),
    locate: &(dyn Fn(Node, Node) -> Option<[f64; 2]> + Sync),
) -> Vec<Segment> {
    let mut edges: Vec<(Node, Node)> = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            for next in [(i + 1, j), (i, j + 1)] {
                if next.0 < nx && next.1 < ny {
                    if let (Some(a), Some(b)) = (side((i, j)), side(next)) {
                        if a != b {
                            edges.push(((i, j), next));
                        }
                    }
                }
            }
        }
    }
    let found: HashMap<(Node, Node), [f64; 2]> = edges
        .into_par_iter()
        .filter_map(|e| locate(e.0, e.1).map(|p| (e, p)))
        .collect();
    let mut segments = Vec::new();
    for j in 0..ny.saturating_sub(1) {
        for i in 0..nx.saturating_sub(1) {
            // bottom, right, top, left
            let around = [
                ((i, j), (i + 1, j)),
                ((i + 1, j), (i + 1, j + 1)),
                ((i, j + 1), (i + 1, j + 1)),
                ((i, j), (i, j + 1)),
            ];
            let cross: Vec<Option<[f64; 2]>> =
                around.iter().map(|e| found.get(e).copied()).collect();
            match cross.iter().flatten().collect::<Vec<_>>().as_slice() {
                [a, b] => segments.push([**a, **b]),
                [_, _, _, _] => {
                    // a saddle: pair each crossing with its neighbour around the cell
                    let c: Vec<[f64; 2]> = cross.iter().flatten().copied().collect();
                    segments.push([c[0], c[3]]);
                    segments.push([c[1], c[2]]);
                }
                _ => {}
            }
        }
    }
    segments
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    /// The side of x < root and a margin root - x, counting the probes.
    fn straight(root: f64, count: &Cell<usize>) -> impl Fn(f64) -> Option<Probe> + '_ {
        move |u| {
            count.set(count.get() + 1);
            Some((u < root, Some(root - u)))
        }
    }

    #[test]
    fn a_margin_finds_the_change_that_bisection_finds_in_fewer_probes() {
        for root in [0.013, 0.37, 0.5, 0.91] {
            let count = Cell::new(0);
            let u = locate_change(30, true, straight(root, &count)).unwrap();
            let halved = bisect(30, true, |u| Some(u < root)).unwrap();
            // both within 2^-30 of the root: bisect's own bound
            assert!((u - root).abs() <= 0.5f64.powi(30), "{root}: {u}");
            assert!((halved - root).abs() <= 0.5f64.powi(30), "{root}: {halved}");
            // halvings until both ends of the bracket carry a margin (the root's distance d
            // from the nearer end needs about log2(1/d) of them), then the chord, which lands on
            // a straight margin's root, a bisection and the closing step: bisect needs 30
            let halvings = (1.0 / root.min(1.0 - root)).log2().ceil() as usize;
            assert!(
                count.get() <= halvings + 5,
                "{root}: {} probes",
                count.get()
            );
        }
    }

    #[test]
    fn without_a_margin_it_bisects_and_a_curved_margin_stays_bounded() {
        let count = Cell::new(0);
        let side = |u: f64| {
            count.set(count.get() + 1);
            Some((u < 0.3, None))
        };
        let u = locate_change(20, true, side).unwrap();
        assert!((u - 0.3).abs() <= 0.5f64.powi(20));
        assert_eq!(count.get(), 20);
        // a margin that is flat on one side (x^9): the chord crawls, the halving keeps the bound
        let count = Cell::new(0);
        let flat = |u: f64| {
            count.set(count.get() + 1);
            let m = (0.8 - u).powi(9);
            Some((u < 0.8, Some(m)))
        };
        let u = locate_change(20, true, flat).unwrap();
        assert!((u - 0.8).abs() <= 0.5f64.powi(20));
        assert!(count.get() <= 41);
        // a margin of the wrong sign is not used
        let wrong = |u: f64| Some((u < 0.6, Some(u - 0.6)));
        let u = locate_change(20, true, wrong).unwrap();
        assert!((u - 0.6).abs() <= 0.5f64.powi(20));
    }
}
