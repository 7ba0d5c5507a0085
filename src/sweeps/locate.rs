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
