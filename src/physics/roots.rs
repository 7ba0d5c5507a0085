//! Bracketing and Brent root finding (the `roots` crate) with a relative tolerance.

use roots::{Convergency, find_root_brent};

struct Relative {
    rtol: f64,
    max_iter: usize,
}

impl Convergency<f64> for Relative {
    fn is_root_found(&mut self, y: f64) -> bool {
        y == 0.0
    }
    fn is_converged(&mut self, a: f64, b: f64) -> bool {
        (a - b).abs() <= self.rtol * a.abs().max(b.abs())
    }
    fn is_iteration_limit_reached(&mut self, iter: usize) -> bool {
        iter > self.max_iter
    }
}

/// The root of f in [lo, hi] (f(lo) and f(hi) of opposite signs) to relative accuracy 1e-15.
pub fn brent(lo: f64, hi: f64, f: impl Fn(f64) -> f64) -> Option<f64> {
    brent_to(lo, hi, 1e-15, f)
}

/// As `brent`, to relative accuracy `rtol`.
pub fn brent_to(lo: f64, hi: f64, rtol: f64, f: impl Fn(f64) -> f64) -> Option<f64> {
    let mut conv = Relative {
        rtol,
        max_iter: 200,
    };
    find_root_brent(lo, hi, &f, &mut conv).ok()
}

/// Widens a bracket around `start` for an increasing f: x goes down by `shrink` (at most
/// `tries_down` times) until f(x) < 0, and up by `grow` (at most `tries_up` times) until
/// f(x) >= 0. Each point is evaluated once. None when no bracket is found (or f is NaN).
pub fn bracket(
    start: f64,
    (shrink, tries_down): (f64, usize),
    (grow, tries_up): (f64, usize),
    f: impl Fn(f64) -> f64,
) -> Option<(f64, f64)> {
    let f_start = f(start);
    let (mut lo, mut f_lo) = (start, f_start);
    for _ in 0..tries_down {
        if f_lo < 0.0 {
            break;
        }
        lo *= shrink;
        f_lo = f(lo);
    }
    let (mut hi, mut f_hi) = (start, f_start);
    for _ in 0..tries_up {
        if f_hi >= 0.0 {
            break;
        }
        hi *= grow;
        f_hi = f(hi);
    }
    (f_lo < 0.0 && f_hi >= 0.0).then_some((lo, hi))
}

/// Marches x up geometrically (factor `growth`) from `start` while f(x) < 0 and x <= `limit`;
/// returns the first bracket [x_k, x_{k+1}] with f(x_k) < 0 <= f(x_{k+1}), or the largest f seen
/// (with its x) when there is none.
pub fn march_up(
    start: f64,
    growth: f64,
    limit: f64,
    f: impl Fn(f64) -> f64,
) -> Result<(f64, f64), (f64, f64)> {
    let mut lo = start;
    let mut f_lo = f(lo);
    let mut best = (lo, f_lo);
    while lo <= limit {
        let hi = lo * growth;
        let f_hi = f(hi);
        if f_lo < 0.0 && f_hi >= 0.0 {
            return Ok((lo, hi));
        }
        if f_hi > best.1 {
            best = (hi, f_hi);
        }
        lo = hi;
        f_lo = f_hi;
    }
    Err(best)
}
