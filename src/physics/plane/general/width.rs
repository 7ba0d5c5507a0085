//! The contact width of the general solver: the root of P(L) = Q2 - phi = P, phi = integral of
//! Pi(q2) g' (2.1), each P(L) a Newton solve of the collocation (`system`) started from the
//! solution at the nearest width already solved. First guess: the width at which
//! m L (g'(L/2) - g'(-L/2))/8 = P, which is Q2 exactly for a parabola without friction or wear,
//! or a coarser solution's width. From there secant steps on ln P against ln L (`secant_log`),
//! the first one with the slope d ln P/d ln L of the first guess's formula or of the coarser
//! solution: P(L) is smooth and grows like a power of L, and some four widths from a coarser
//! solution reach the root. Should they not converge (a width whose collocation fails, P not
//! increasing), a geometric bracket and Brent's method.

use std::cell::RefCell;
use std::sync::Arc;

use crate::physics::SolveError;
use crate::physics::plane::general::Problem;
use crate::physics::plane::general::pressure::Pressure;
use crate::physics::plane::general::system::{Discretisation, Unknowns, solve_at};
use crate::physics::plane::strip::collocation::Rules;
use crate::physics::roots::{
    BRENT_ITERATIONS, NoBracket, bracket_or_why, brent, brent_to, march_up, secant_log,
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
/// Widths the secant steps try before the bracket takes over.
const SECANT_EVALS: usize = 16;

/// A solved width: L [m], the load it carries, the collocation there, d ln P/d ln L at it
/// (dimensionless), and the rules of its nodes; a finer discretisation, or the same at another
/// load, starts from it.
pub struct Width {
    /// Contact width L = a + b [m].
    pub l: f64,
    /// The load P = Q2 - phi [N/m] it carries.
    pub load: f64,
    /// The collocation's unknowns at L.
    pub unknowns: Unknowns,
    /// d ln P/d ln L at L, from the last secant step or the bracket's ends.
    pub log_slope: f64,
    rules: Arc<Rules>,
}

impl Width {
    /// The width of the pressure `p`, which carries `load` [N/m] in `problem` (at another load
    /// than the problem's); d ln P/d ln L taken from the first guess's formula.
    pub fn of(problem: &Problem, p: &Pressure, load: f64) -> Width {
        let rules = p.rules();
        let m = problem.m();
        let y = p.phi.iter().zip(rules.weights()).map(|(f, w)| w * f / m);
        Width {
            l: p.l,
            load,
            unknowns: Unknowns {
                y: nalgebra::DVector::from_iterator(rules.len(), y),
                s: 2.0 * p.c / p.l,
            },
            log_slope: guess_log_slope(problem, p.l),
            rules: Arc::clone(rules),
        }
    }

    /// Whether its unknowns are on the nodes of `d`.
    fn on(&self, d: &Discretisation) -> bool {
        let rules = d.rules();
        rules.len() == self.rules.len() && rules.theta().to_bits() == self.rules.theta().to_bits()
    }

    /// The unknowns on the nodes of `d` (same theta): phi = m y/W interpolated through this
    /// width's nodes, y = W phi/m on the new ones.
    fn start_on(&self, d: &Discretisation) -> Unknowns {
        let (nodes, bary, weights) = (self.rules.nodes(), self.rules.bary(), self.rules.weights());
        let ratio: Vec<f64> = self
            .unknowns
            .y
            .iter()
            .zip(weights)
            .map(|(y, w)| y / w)
            .collect();
        let rules = d.rules();
        let y = rules.nodes().iter().zip(rules.weights()).map(|(&t, w)| {
            let (mut num, mut den) = (0.0, 0.0);
            for ((x, b), r) in nodes.iter().zip(bary).zip(&ratio) {
                if t == *x {
                    return w * r;
                }
                num += b * r / (t - x);
                den += b / (t - x);
            }
            w * num / den
        });
        Unknowns {
            y: nalgebra::DVector::from_iterator(rules.len(), y),
            s: self.unknowns.s,
        }
    }
}

/// The solutions at the widths tried, for warm starts.
struct Tried<'a> {
    problem: &'a Problem<'a>,
    d: &'a Discretisation,
    solved: RefCell<Vec<(f64, Unknowns)>>,
    /// A coarser solution on these nodes, the start while no width is solved.
    seed: Option<(f64, Unknowns)>,
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
                .or(self.seed.as_ref())
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

    /// The collocation at a width already solved, else solved now (`at`).
    fn solution(&self, l: f64) -> Option<Unknowns> {
        let known = (self.solved.borrow().iter())
            .find(|(w, _)| *w == l)
            .map(|(_, u)| u.clone());
        known.or_else(|| self.at(l))
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

/// d ln f/d ln L of the first guess's f(L) = m L (g'(L/2) - g'(-L/2))/8 at L (a central
/// difference over 1 %): 2 for a parabola, n for a power punch; 2 where it is not a number.
fn guess_log_slope(problem: &Problem, l: f64) -> f64 {
    let shape = problem.shape;
    let f = |l: f64| l * (shape.slope(0.5 * l) - shape.slope(-0.5 * l));
    let k = (f(1.01 * l) / f(l / 1.01)).ln() / (2.0 * 1.01f64.ln());
    if k.is_finite() && k > 0.0 { k } else { 2.0 }
}

/// The width L [m] and the collocation that carry the problem's load, from the first guess or
/// from `near` (the bracket then starts with small steps): a coarser solution, or one on these
/// nodes at another load, whose value of P(L) is known.
pub fn solve(
    problem: &Problem,
    d: &Discretisation,
    near: Option<&Width>,
) -> Result<Width, SolveError> {
    let p = problem.load;
    let same = near.filter(|w| w.on(d));
    let tried = Tried {
        problem,
        d,
        solved: RefCell::new(
            same.map(|w| (w.l, w.unknowns.clone()))
                .into_iter()
                .collect(),
        ),
        seed: near.filter(|w| !w.on(d)).map(|w| (w.l, w.start_on(d))),
        values: RefCell::new(same.map(|w| (w.l, w.load - p)).into_iter().collect()),
    };
    let f = |l: f64| tried.excess_load(l);
    let (start, log_slope, down, up) = match near {
        Some(w) => (w.l, w.log_slope, NEAR_DOWN, NEAR_UP),
        None => {
            let l = first_guess(problem)?;
            (l, guess_log_slope(problem, l), BRACKET_DOWN, BRACKET_UP)
        }
    };
    let carried = |l: f64| Some(f(l) + p).filter(|v| v.is_finite());
    let found = secant_log(carried, p, start, log_slope, WIDTH_TOLERANCE, SECANT_EVALS);
    let (l, log_slope) = match found {
        Some(found) => found,
        None => bracketed(start, (down, up), p, f)?,
    };
    let unknowns = tried.solution(l).ok_or_else(|| {
        SolveError::NoSolution(format!(
            "the collocation did not converge at the contact width {l:.4e} m (P = {p:.4e} N/m)"
        ))
    })?;
    Ok(Width {
        l,
        load: p,
        unknowns,
        log_slope,
        rules: Arc::clone(d.rules()),
    })
}

/// The root of the increasing `f` = P(L) - P by a geometric bracket from `start` and Brent's
/// method, and d ln P/d ln L across the bracket.
fn bracketed(
    start: f64,
    (down, up): ((f64, usize), (f64, usize)),
    p: f64,
    f: impl Fn(f64) -> f64,
) -> Result<(f64, f64), SolveError> {
    let (lo, hi) = bracket_or_why(start, down, up, &f).map_err(|why| {
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
    let log_slope = (f(hi) - f(lo)) / (hi / lo).ln() / p;
    let l = brent_to(lo, hi, WIDTH_TOLERANCE, &f).ok_or_else(|| {
        SolveError::NoSolution(format!(
            "the contact width did not converge at P = {p:.4e} N/m (Brent's method, \
             {BRENT_ITERATIONS} iterations, or a collocation that did not converge)"
        ))
    })?;
    Ok((l, log_slope))
}
