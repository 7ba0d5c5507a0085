//! The complete-contact check p > 0 (1.3), docs/physics/spatial.md section 4.

use serde::Serialize;

use crate::physics::roots::brent;
use crate::physics::spatial::field::{Term, pressure_terms, synthesize};
use crate::physics::spatial::{COMMENSURATE_ULPS, Cell, PERIOD_SEARCH, Period, SpatialSolution};

/// What the check found.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Contact {
    /// The smallest contact pressure [Pa]: the certified cell minimum when `exact`, else the bound.
    pub min_pressure: f64,
    /// Where the minimum is, [x, y] [m] (null when only the bound is known).
    pub at: Option<[f64; 2]>,
    /// pbar - sum A_n/M_n [Pa]: a lower bound of p everywhere.
    pub lower_bound: f64,
    /// True when p > 0 everywhere (certified: by the cell minimum or by the bound).
    pub complete: bool,
    /// True when `min_pressure` is the certified cell minimum (a period was found and the grid
    /// decided), false when it is only the bound.
    pub exact: bool,
    /// Why the cell minimum was not certified (null when it was).
    pub not_certified: Option<NotCertified>,
    /// The time [s] after which the bound guarantees complete contact (0 if it already does; null
    /// without wear). Indicative only: partial-contact wear differs.
    pub complete_after: Option<f64>,
}

/// Why the search for the certified cell minimum gave up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NotCertified {
    /// No common period was found along this axis ('x' or 'y').
    NoPeriod(char),
    /// Deciding would need a grid of `side` points per side, more than `MAX_SIDE`.
    GridLimit {
        /// Points per side the grid would need.
        side: f64,
    },
}

impl std::fmt::Display for NotCertified {
    fn fmt(&self, out: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            NotCertified::NoPeriod(axis) => write!(
                out,
                "no common period along {axis} was found: no base w_min/q (q <= {PERIOD_SEARCH}) \
                 divides every wavenumber to within the precision of the numbers \
                 ({COMMENSURATE_ULPS} units in the last place)"
            ),
            NotCertified::GridLimit { side } => write!(
                out,
                "the period cell needs a grid of {side:.0} points per side to decide (limit \
                 {MAX_SIDE})"
            ),
        }
    }
}

impl Serialize for NotCertified {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

impl Contact {
    /// The sentence to show when contact is not complete (lost, or not certified).
    pub fn failure(&self) -> Option<String> {
        if self.complete {
            return None;
        }
        let units = crate::units::format_si;
        let after = match self.complete_after {
            Some(t) => format!("; it holds after t = {}", units(t, "s")),
            None => String::new(),
        };
        Some(match (self.at, self.not_certified) {
            (Some([x, y]), _) => format!(
                "complete contact lost: p_min = {} at x = {}, y = {}{after}",
                units(self.min_pressure, "Pa"),
                units(x, "m"),
                units(y, "m")
            ),
            (None, why) => format!(
                "complete contact not certified: the lower bound pbar - sum A/M = {} is not \
                 positive, and the cell minimum is unknown: {}{after}",
                units(self.lower_bound, "Pa"),
                why.map_or_else(|| "not searched".to_string(), |w| w.to_string())
            ),
        })
    }
}

/// Largest grid side used for the certified minimum.
pub const MAX_SIDE: usize = 1024;

fn value_and_derivatives(terms: &[Term], pbar: f64, x: f64, y: f64) -> (f64, [f64; 2], [f64; 3]) {
    let (mut p, mut g, mut h) = (pbar, [0.0; 2], [0.0; 3]);
    for t in terms {
        let (sx, cx) = (t.wx * x + t.px).sin_cos();
        let (sy, cy) = (t.wy * y + t.py).sin_cos();
        p += t.c * sx * sy;
        g[0] += t.c * t.wx * cx * sy;
        g[1] += t.c * t.wy * sx * cy;
        h[0] -= t.c * t.wx * t.wx * sx * sy;
        h[1] += t.c * t.wx * t.wy * cx * cy;
        h[2] -= t.c * t.wy * t.wy * sx * sy;
    }
    (p, g, h)
}

/// Newton from (x, y) towards a local minimum of p, moving only along the axes that vary
/// (`vary` = [x, y]); never returns a higher value.
fn polish(terms: &[Term], pbar: f64, vary: [bool; 2], mut x: f64, mut y: f64) -> (f64, f64, f64) {
    let (mut p, mut g, mut h) = value_and_derivatives(terms, pbar, x, y);
    for _ in 0..30 {
        let (dx, dy) = match vary {
            [true, true] => {
                let det = h[0] * h[2] - h[1] * h[1];
                if !(det > 0.0 && h[0] > 0.0) {
                    break;
                }
                (
                    -(h[2] * g[0] - h[1] * g[1]) / det,
                    -(h[0] * g[1] - h[1] * g[0]) / det,
                )
            }
            [true, false] if h[0] > 0.0 => (-g[0] / h[0], 0.0),
            [false, true] if h[2] > 0.0 => (0.0, -g[1] / h[2]),
            _ => break,
        };
        let (nx, ny) = (x + dx, y + dy);
        let (np, ng, nh) = value_and_derivatives(terms, pbar, nx, ny);
        if np > p {
            break;
        }
        let done = np == p;
        (x, y, p, g, h) = (nx, ny, np, ng, nh);
        if done {
            break;
        }
    }
    (p, x, y)
}

/// The time after which pbar > sum |A_n(0)| e^{-beta_n t}/M_n, by Brent (the sum decreases).
fn time_to_bound(sol: &SpatialSolution) -> Option<f64> {
    let pbar = sol.inputs.mean_pressure;
    let excess = |t: f64| {
        sol.harmonics
            .iter()
            .map(|h| h.initial.amplitude * (-h.evolution.decay_rate * t).exp() / h.evolution.m)
            .sum::<f64>()
            - pbar
    };
    if excess(0.0) < 0.0 {
        return Some(0.0);
    }
    let beta_max = sol
        .harmonics
        .iter()
        .map(|h| h.evolution.decay_rate)
        .fold(0.0, f64::max);
    if beta_max <= 0.0 {
        return None;
    }
    let mut hi = 1.0 / beta_max;
    for _ in 0..200 {
        if excess(hi) < 0.0 {
            return brent(0.0, hi, excess);
        }
        hi *= 2.0;
    }
    None
}

/// Checks complete contact: the cheap bound always; the certified minimum over the cell when a
/// period was found (grid of >= 16 points per shortest wavelength, doubled until decided or
/// `MAX_SIDE`; Newton polish of the lowest points; certificate p_min >= grid_min - H delta^2/2
/// with H = sum k^2 A/M, docs/physics/spatial.md section 4).
pub fn check(sol: &SpatialSolution, cell: &Cell) -> Contact {
    let pbar = sol.inputs.mean_pressure;
    let terms = pressure_terms(sol);
    let lower_bound = pbar - terms.iter().map(|t| t.c.abs()).sum::<f64>();
    let complete_after = time_to_bound(sol);
    let bound_only = |why: NotCertified| Contact {
        min_pressure: lower_bound,
        at: None,
        lower_bound,
        complete: lower_bound > 0.0,
        exact: false,
        not_certified: Some(why),
        complete_after,
    };
    for (axis, period) in [('x', cell.period_x), ('y', cell.period_y)] {
        if period == Period::NotFound {
            return bound_only(NotCertified::NoPeriod(axis));
        }
    }
    let k_max = sol
        .harmonics
        .iter()
        .map(|h| h.initial.wavenumber())
        .fold(0.0, f64::max);
    let side = |period: Period, extent: f64| match period {
        Period::Constant => 1.0,
        _ => (16.0 * extent * k_max / (2.0 * std::f64::consts::PI))
            .ceil()
            .max(16.0),
    };
    let (side_x, side_y) = (side(cell.period_x, cell.lx), side(cell.period_y, cell.ly));
    if side_x.max(side_y) > MAX_SIDE as f64 {
        return bound_only(NotCertified::GridLimit {
            side: side_x.max(side_y),
        });
    }
    let (mut nx, mut ny) = (side_x as usize, side_y as usize);
    let vary = [nx > 1, ny > 1];
    let hessian_bound: f64 = sol
        .harmonics
        .iter()
        .map(|h| h.initial.wavenumber().powi(2) * h.state.amplitude / h.evolution.m)
        .sum();
    // each pass doubles the varying sides, from >= 16 to at most MAX_SIDE points
    for _ in 0..=(MAX_SIDE / 16).ilog2() {
        if nx.max(ny) > MAX_SIDE {
            break;
        }
        let xs: Vec<f64> = (0..nx).map(|i| i as f64 * cell.lx / nx as f64).collect();
        let ys: Vec<f64> = (0..ny).map(|j| j as f64 * cell.ly / ny as f64).collect();
        let grid = synthesize(&terms, pbar, &xs, &ys);
        // the eight lowest grid points start the Newton polish
        let mut order: Vec<usize> = (0..grid.len()).collect();
        let last = 7.min(grid.len() - 1);
        order.select_nth_unstable_by(last, |a, b| grid[*a].total_cmp(&grid[*b]));
        order.truncate(last + 1);
        let grid_min = order.iter().map(|&i| grid[i]).fold(f64::INFINITY, f64::min);
        let (p_min, x_min, y_min) = order
            .iter()
            .map(|&i| polish(&terms, pbar, vary, xs[i % nx], ys[i / nx]))
            .fold((f64::INFINITY, 0.0, 0.0), |best, c| {
                if c.0 < best.0 { c } else { best }
            });
        let dx = if nx > 1 { cell.lx / nx as f64 } else { 0.0 };
        let dy = if ny > 1 { cell.ly / ny as f64 } else { 0.0 };
        let delta = 0.5 * dx.hypot(dy);
        let certified = grid_min - 0.5 * hessian_bound * delta * delta;
        // Decided: either a point with p <= 0 exists, or the certificate proves p > 0.
        if p_min <= 0.0 || certified > 0.0 {
            let wrap = |v: f64, l: f64| v.rem_euclid(l);
            return Contact {
                min_pressure: p_min,
                at: Some([wrap(x_min, cell.lx), wrap(y_min, cell.ly)]),
                lower_bound,
                complete: p_min > 0.0,
                exact: true,
                not_certified: None,
                complete_after,
            };
        }
        nx *= if vary[0] { 2 } else { 1 };
        ny *= if vary[1] { 2 } else { 1 };
    }
    bound_only(NotCertified::GridLimit {
        side: nx.max(ny) as f64,
    })
}
