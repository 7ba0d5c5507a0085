//! The contact width of the general solver: the root of P(L) = Q2 - phi = P, phi = integral of
//! Pi(q2) g' (2.1), each P(L) a Newton solve of the collocation (`system`) started from the
//! solution at the nearest width already solved. First guess: the width at which
//! m L (g'(L/2) - g'(-L/2))/8 = P, which is Q2 exactly for a parabola without friction or wear;
//! then a geometric bracket and Brent's method.

use std::cell::RefCell;

use crate::physics::SolveError;
use crate::physics::plane::general::Problem;
use crate::physics::plane::general::pressure::Pressure;
use crate::physics::plane::general::system::{Discretisation, Unknowns, solve_at};
use crate::physics::roots::{
    BRENT_ITERATIONS, NoBracket, bracket_or_why, brent, brent_to, march_up,
};

/// Smallest and largest width of the first guess's march [m], and its factor.
const GUESS_FROM: f64 = 1e-12;
const GUESS_TO: f64 = 1e6;
/// The first guess's factor on a measured profile (some 450 steps from `GUESS_FROM` to 1 m).
const TABLE_GROWTH: f64 = 1.05;
/// Bracket steps from the first guess: factors and counts down and up.
const BRACKET_DOWN: (f64, usize) = (0.8, 80);
const BRACKET_UP: (f64, usize) = (1.25, 80);
/// Bracket steps from a coarser solution's width, which is close.
const NEAR_DOWN: (f64, usize) = (0.99, 400);
const NEAR_UP: (f64, usize) = (1.01, 400);
/// Relative accuracy of the width: P(L) carries the Newton solves' round-off (some 1e-14 of P,
/// depending on the start), which near the root can flip its sign and stall Brent's method at
/// tighter tolerances.
const WIDTH_TOLERANCE: f64 = 1e-13;

/// The solutions at the widths tried, for warm starts.
struct Tried<'a> {
    problem: &'a Problem<'a>,
    d: &'a Discretisation,
    solved: RefCell<Vec<(f64, Unknowns)>>,
    /// P(L) - P at each width tried.
    values: RefCell<Vec<(f64, f64)>>,
}

impl Tried<'_> {
    /// The collocation at width l, from the nearest width solved (its y scaled by the ratio of
    /// the widths: q2 grows like L on a parabola), else from zero.
    fn at(&self, l: f64) -> Option<Unknowns> {
        let start = {
            let solved = self.solved.borrow();
            solved
                .iter()
                .min_by(|x, y| (x.0 / l).ln().abs().total_cmp(&(y.0 / l).ln().abs()))
                .map(|(w, u)| Unknowns {
                    y: &u.y * (l / w),
                    s: u.s,
                })
        };
        let u = start
            .and_then(|s| solve_at(self.d, self.problem, l, &s))
            .or_else(|| solve_at(self.d, self.problem, l, &Unknowns::zero(self.d.len())))?;
        self.solved.borrow_mut().push((l, u.clone()));
        Some(u)
    }

    /// P(L) - P [N/m], NaN where the collocation does not converge. Each width is solved once
    /// and its value kept: solved again from another start, P(L) would differ in its last
    /// digits, and a root finder that sees two signs at one point stalls.
    fn excess_load(&self, l: f64) -> f64 {
        if let Some(&(_, v)) = self.values.borrow().iter().find(|(x, _)| *x == l) {
            return v;
        }
        let v = self.at(l).map_or(f64::NAN, |u| {
            let p = u.pressure(self.d, self.problem, l);
            carried_load(self.problem, &p) - self.problem.load
        });
        self.values.borrow_mut().push((l, v));
        v
    }
}

/// P = Q2 - phi [N/m] that the pressure `p` carries.
pub fn carried_load(problem: &Problem, p: &Pressure) -> f64 {
    let rule = Pressure::rule(&problem.splits(p));
    let (f, shape) = (&problem.friction, problem.shape);
    p.normal_force() - p.integrate(&rule, |x, q| f.shear(q) * shape.slope(x))
}

/// The first guess of the width [m] (module note). On a measured profile the march stays within
/// the widest contact centred on the tip that the profile covers, in steps of `TABLE_GROWTH`:
/// beyond its ends the spline's end cubic bends g' back down, and doubling steps can pass over a
/// window of widths that carry the load before the profile ends.
pub fn first_guess(problem: &Problem) -> Result<f64, SolveError> {
    let (m, p, shape) = (problem.m(), problem.load, problem.shape);
    let f = |l: f64| m * l * (shape.slope(0.5 * l) - shape.slope(-0.5 * l)) / 8.0 - p;
    let (limit, growth) = match shape.known_range() {
        Some((lo, hi)) if (-lo).min(hi) > GUESS_FROM => (2.0 * (-lo).min(hi), TABLE_GROWTH),
        _ => (GUESS_TO, 2.0),
    };
    march_up(GUESS_FROM, growth, limit, f)
        .ok()
        .and_then(|(lo, hi)| brent(lo, hi, f))
        .ok_or_else(|| {
            SolveError::NoSolution(format!(
                "the punch carries no load P = {p:.4e} N/m on any contact width from \
                 {GUESS_FROM:e} m to {GUESS_TO:e} m (is its profile flat?)"
            ))
        })
}

/// The width L [m] and the collocation that carry the problem's load; `near` is the width of a
/// coarser solution, if any, from which the bracket starts.
pub fn solve(
    problem: &Problem,
    d: &Discretisation,
    near: Option<f64>,
) -> Result<(f64, Unknowns), SolveError> {
    let p = problem.load;
    let tried = Tried {
        problem,
        d,
        solved: RefCell::new(Vec::new()),
        values: RefCell::new(Vec::new()),
    };
    let f = |l: f64| tried.excess_load(l);
    let (start, down, up) = match near {
        Some(l) => (l, NEAR_DOWN, NEAR_UP),
        None => (first_guess(problem)?, BRACKET_DOWN, BRACKET_UP),
    };
    let (lo, hi) = bracket_or_why(start, down, up, f).map_err(|why| {
        SolveError::NoSolution(match why {
            NoBracket::NotANumber(l) => format!(
                "the general plane solver's collocation did not converge at contact width \
                 {l:.4e} m (P = {p:.4e} N/m): no bounded pressure found there"
            ),
            other => format!(
                "the general plane solver finds no contact width at P = {p:.4e} N/m: {other}"
            ),
        })
    })?;
    let l = brent_to(lo, hi, WIDTH_TOLERANCE, f).ok_or_else(|| {
        SolveError::NoSolution(format!(
            "the contact width did not converge at P = {p:.4e} N/m (Brent's method, \
             {BRENT_ITERATIONS} iterations, or a collocation that did not converge)"
        ))
    })?;
    let u = tried.at(l).ok_or_else(|| {
        SolveError::NoSolution(format!(
            "the collocation did not converge at the contact width {l:.4e} m (P = {p:.4e} N/m)"
        ))
    })?;
    Ok((l, u))
}
