//! Bracketing and Brent root finding (the `roots` crate) with a relative tolerance. Every search
//! here has a bound on its steps, and a failed one says which bound it hit.

use std::fmt;

use roots::{Convergency, find_root_brent};

/// Brent's iteration limit.
pub const BRENT_ITERATIONS: usize = 200;
/// The most steps a geometric march takes, whatever its range.
pub const MARCH_STEPS: usize = 10_000;

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

/// The root of f in [lo, hi] (f(lo) and f(hi) of opposite signs) to relative accuracy 1e-15;
/// None when f(lo) and f(hi) have the same sign, f is NaN, or `BRENT_ITERATIONS` pass.
pub fn brent(lo: f64, hi: f64, f: impl Fn(f64) -> f64) -> Option<f64> {
    brent_to(lo, hi, 1e-15, f)
}

/// As `brent`, to relative accuracy `rtol`. The `roots` crate evaluates f again at an end it
/// already knows once per iteration; the last few values are remembered, so each new point costs
/// one evaluation.
pub fn brent_to(lo: f64, hi: f64, rtol: f64, f: impl Fn(f64) -> f64) -> Option<f64> {
    let mut conv = Relative {
        rtol,
        max_iter: BRENT_ITERATIONS,
    };
    let mut seen = [(f64::NAN, f64::NAN); 4];
    let mut next = 0;
    let remembered = |x: f64| {
        if let Some(&(_, y)) = seen.iter().find(|(sx, _)| *sx == x) {
            return y;
        }
        let y = f(x);
        seen[next] = (x, y);
        next = (next + 1) % seen.len();
        y
    };
    find_root_brent(lo, hi, remembered, &mut conv).ok()
}

/// Why a search for a sign change of an increasing f failed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NoBracket {
    /// The start (or the growth factor) cannot drive a geometric search: 0, negative or not
    /// finite.
    BadStart(f64),
    /// f is not a number at x.
    NotANumber(f64),
    /// f stayed >= 0 down to x after the allowed number of steps.
    NoNegative {
        /// The smallest x tried.
        x: f64,
        /// Steps taken.
        steps: usize,
    },
    /// f stayed < 0 up to x after the allowed number of steps; the largest f seen was
    /// `best_f` at `best_x`.
    NoPositive {
        /// The largest x tried.
        x: f64,
        /// Steps taken.
        steps: usize,
        /// Where f was largest.
        best_x: f64,
        /// The largest f.
        best_f: f64,
    },
}

impl fmt::Display for NoBracket {
    fn fmt(&self, out: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NoBracket::BadStart(x) => write!(
                out,
                "the search cannot start from {x:e} (it must be positive and finite)"
            ),
            NoBracket::NotANumber(x) => write!(out, "the equation is not a number at {x:.4e}"),
            NoBracket::NoNegative { x, steps } => write!(
                out,
                "no sign change down to {x:.4e} (search limit: {steps} steps)"
            ),
            NoBracket::NoPositive { x, steps, .. } => write!(
                out,
                "no sign change up to {x:.4e} (search limit: {steps} steps)"
            ),
        }
    }
}

fn usable(x: f64) -> bool {
    x > 0.0 && x.is_finite()
}

/// Evaluates f, turning NaN into the error that names x.
fn eval(f: &impl Fn(f64) -> f64, x: f64) -> Result<f64, NoBracket> {
    let y = f(x);
    if y.is_nan() {
        Err(NoBracket::NotANumber(x))
    } else {
        Ok(y)
    }
}

/// Widens a bracket around `start` for an increasing f: x goes down by `shrink` (at most
/// `tries_down` times) until f(x) < 0, and up by `grow` (at most `tries_up` times) until
/// f(x) >= 0. Each point is evaluated once.
pub fn bracket_or_why(
    start: f64,
    (shrink, tries_down): (f64, usize),
    (grow, tries_up): (f64, usize),
    f: impl Fn(f64) -> f64,
) -> Result<(f64, f64), NoBracket> {
    if !usable(start) {
        return Err(NoBracket::BadStart(start));
    }
    let f_start = eval(&f, start)?;
    let (mut lo, mut f_lo, mut down) = (start, f_start, 0);
    while f_lo >= 0.0 {
        if down == tries_down || !usable(lo * shrink) {
            return Err(NoBracket::NoNegative { x: lo, steps: down });
        }
        lo *= shrink;
        f_lo = eval(&f, lo)?;
        down += 1;
    }
    let (mut hi, mut f_hi, mut up) = (start, f_start, 0);
    let (mut best_x, mut best_f) = (start, f_start);
    while f_hi < 0.0 {
        if up == tries_up || !usable(hi * grow) {
            return Err(NoBracket::NoPositive {
                x: hi,
                steps: up,
                best_x,
                best_f,
            });
        }
        hi *= grow;
        f_hi = eval(&f, hi)?;
        if f_hi > best_f {
            (best_x, best_f) = (hi, f_hi);
        }
        up += 1;
    }
    Ok((lo, hi))
}

/// As `bracket_or_why`, without the reason.
pub fn bracket(
    start: f64,
    down: (f64, usize),
    up: (f64, usize),
    f: impl Fn(f64) -> f64,
) -> Option<(f64, f64)> {
    bracket_or_why(start, down, up, f).ok()
}

/// Marches x up geometrically (factor `growth` > 1) from `start` to at most `limit`, and at most
/// `MARCH_STEPS` steps; returns the first bracket [x_k, x_{k+1}] with f(x_k) < 0 <= f(x_{k+1}).
pub fn march_up(
    start: f64,
    growth: f64,
    limit: f64,
    f: impl Fn(f64) -> f64,
) -> Result<(f64, f64), NoBracket> {
    if !(usable(start) && usable(limit) && growth > 1.0 && growth.is_finite()) {
        return Err(NoBracket::BadStart(start));
    }
    let steps = ((limit / start).ln() / growth.ln())
        .ceil()
        .clamp(0.0, MARCH_STEPS as f64) as usize;
    let mut lo = start;
    let mut f_lo = eval(&f, lo)?;
    let (mut best_x, mut best_f) = (lo, f_lo);
    for _ in 0..steps {
        let hi = lo * growth;
        let f_hi = eval(&f, hi)?;
        if f_lo < 0.0 && f_hi >= 0.0 {
            return Ok((lo, hi));
        }
        if f_hi > best_f {
            (best_x, best_f) = (hi, f_hi);
        }
        lo = hi;
        f_lo = f_hi;
    }
    Err(NoBracket::NoPositive {
        x: lo,
        steps,
        best_x,
        best_f,
    })
}

/// The root of f(x) = target for a positive f that grows like a power of x, by the secant method
/// on ln f against ln x from x0, the first step taken with `slope` (d ln f/d ln x) and each step
/// at most a factor e. Stops when the step is below `rtol` relative, or below 1e-12 and no longer
/// halving (round-off), after at most `max_evals` evaluations. Returns the root and the last slope;
/// None when f fails (returns None, or a value that is not positive and finite), when the slope
/// leaves [0.2, 20] (f not increasing like a power), or when it does not converge.
pub fn secant_log(
    mut f: impl FnMut(f64) -> Option<f64>,
    target: f64,
    x0: f64,
    slope: f64,
    rtol: f64,
    max_evals: usize,
) -> Option<(f64, f64)> {
    let log = |v: f64| (v > 0.0 && v.is_finite()).then(|| v.ln());
    let ln_target = log(target)?;
    let (mut x, mut lf) = (x0, log(f(x0)?)?);
    let (mut slope, mut last_step) = (slope, f64::INFINITY);
    for _ in 1..max_evals {
        let step = ((ln_target - lf) / slope).clamp(-1.0, 1.0);
        if step.abs() <= rtol || (step.abs() <= 1e-12 && step.abs() > 0.5 * last_step) {
            return Some((x * step.exp(), slope));
        }
        let x_new = x * step.exp();
        let lf_new = log(f(x_new)?)?;
        if step.abs() > 1e-8 {
            slope = (lf_new - lf) / step;
        }
        if !(0.2..=20.0).contains(&slope) {
            return None;
        }
        (x, lf, last_step) = (x_new, lf_new, step.abs());
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_search_ends_and_says_why() {
        let never = |_: f64| -1.0;
        for start in [0.0, f64::INFINITY, f64::NAN, -1.0] {
            assert!(matches!(
                march_up(start, 1.1, 1e6, never),
                Err(NoBracket::BadStart(_))
            ));
            assert!(matches!(
                bracket_or_why(start, (0.5, 60), (2.0, 60), never),
                Err(NoBracket::BadStart(_))
            ));
        }
        let steps = match march_up(1e-300, 1.0 + 1e-15, 1e300, never) {
            Err(NoBracket::NoPositive { steps, .. }) => steps,
            other => panic!("{other:?}"),
        };
        assert_eq!(steps, MARCH_STEPS);
        assert!(matches!(
            march_up(1.0, 2.0, 8.0, |_| f64::NAN),
            Err(NoBracket::NotANumber(x)) if x == 1.0
        ));
        assert!(matches!(
            bracket_or_why(1.0, (0.5, 3), (2.0, 3), |_| 1.0),
            Err(NoBracket::NoNegative { steps: 3, .. })
        ));
        assert!(matches!(
            bracket_or_why(1.0, (0.0, 3), (2.0, 3), |_| 1.0),
            Err(NoBracket::NoNegative { steps: 0, .. })
        ));
        assert_eq!(
            bracket_or_why(1.0, (0.5, 60), (2.0, 60), |x| x - 5.0),
            Ok((1.0, 8.0))
        );
        assert_eq!(march_up(1.0, 2.0, 100.0, |x| x - 5.0), Ok((4.0, 8.0)));
    }

    #[test]
    fn brent_evaluates_each_point_once() {
        let calls = std::cell::Cell::new(0);
        let root = brent(0.0, 3.0, |x| {
            calls.set(calls.get() + 1);
            x * x * x - 2.0
        })
        .unwrap();
        assert!((root - 2f64.cbrt()).abs() < 1e-15);
        let points = std::cell::RefCell::new(Vec::new());
        let distinct = brent(0.0, 3.0, |x| {
            let mut points = points.borrow_mut();
            if !points.contains(&x.to_bits()) {
                points.push(x.to_bits());
            }
            x * x * x - 2.0
        });
        assert_eq!(distinct, Some(root));
        assert_eq!(
            calls.get(),
            points.borrow().len(),
            "one evaluation per distinct point"
        );
    }
}
