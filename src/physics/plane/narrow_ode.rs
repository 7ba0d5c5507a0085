//! The narrow strip (Winkler foundation, Soldatenkov (2007) eq. (5.1)) for any punch shape, wear
//! law and capped friction (`docs/physics/plane.md`, "General shapes and laws"): v = -beta (q2 -
//! q2(0)) turns the contact condition into the nonlinear first-order ODE
//!   q2'(x) = (F(q2) - g'(x))/beta,   q2(-a) = q2(b) = 0.
//! It is shot backward from the leading end b (stable: wear damps the backward march) by the
//! classical fourth-order Runge-Kutta method, steps landing on the shape's kinks, the trailing
//! end found where q2 returns to zero; b is set by the load P = Q2 - phi (2.1), phi = int Pi(q2)
//! g' dx. Q2, psi, Q1, phi and int q2 F(q2) are integrated with q2 as extra components.

use std::sync::Arc;

use crate::physics::SolveError;
use crate::physics::plane::narrow::winkler_beta;
use crate::physics::plane::{Found, Model, PlaneInputs, PlaneSolution, PressureLaw, Shape};
use crate::physics::roots::{BRENT_ITERATIONS, bracket_or_why, brent, brent_to, secant_log};

/// Runge-Kutta steps across the contact (the step is also kept below the inverse stiffness
/// beta/F'(q2)): an error of order (1/STEPS)^4 ~ 2e-12 of the contact's scales.
const STEPS: f64 = 800.0;
/// The most steps one shot takes before it gives up.
const MAX_STEPS: usize = 200_000;
/// Relative accuracy of the leading end's distance d from the tip (or the face's end).
const ROOT_TOLERANCE: f64 = 1e-14;
/// Leading ends the secant steps try before the bracket takes over.
const SECANT_EVALS: usize = 16;

/// q2 at the nodes of the shot, ascending in x: (x [m], q2 [Pa], q2' [Pa/m]); q2 between two
/// nodes is their cubic Hermite interpolant (fourth order, as the steps).
#[derive(Clone, Debug, PartialEq)]
pub struct Nodes {
    nodes: Vec<(f64, f64, f64)>,
}

impl Nodes {
    /// q2 [Pa] at x [m]; 0 outside the nodes.
    pub fn pressure(&self, x: f64) -> f64 {
        let n = &self.nodes;
        let (first, last) = (n[0].0, n[n.len() - 1].0);
        if !(x > first && x < last) {
            return 0.0;
        }
        let i = n.partition_point(|p| p.0 <= x).clamp(1, n.len() - 1) - 1;
        let ((x0, q0, d0), (x1, q1, d1)) = (n[i], n[i + 1]);
        let h = x1 - x0;
        let t = (x - x0) / h;
        let (t2, t3) = (t * t, t * t * t);
        let q = (2.0 * t3 - 3.0 * t2 + 1.0) * q0
            + (t3 - 2.0 * t2 + t) * h * d0
            + (-2.0 * t3 + 3.0 * t2) * q1
            + (t3 - t2) * h * d1;
        q.max(0.0)
    }
}

/// The state marched: q2, and the integrals from x to b of q2, q2 g', Pi(q2), Pi(q2) g',
/// q2 F(q2), each accumulated with the sign of dx (negative backward).
type State = [f64; 6];

struct Shooter<'a> {
    inputs: &'a PlaneInputs,
    beta: f64,
    /// The shape's kinks, descending.
    kinks: Vec<f64>,
    /// A power punch with n < 2, whose curvature is infinite at the tip.
    blunt_tip: bool,
    /// How many times finer than `STEPS` (and the stiffness bound) the steps are, >= 1.
    refine: f64,
}

/// One shot from b: the trailing end, the integrals over [-a, b] and the nodes.
struct Shot {
    a: f64,
    totals: State,
    nodes: Vec<(f64, f64, f64)>,
}

impl Shooter<'_> {
    fn rate(&self, x: f64, y: &State) -> State {
        let law = &self.inputs.wear;
        let q = y[0];
        let slope = self.inputs.shape.slope(x);
        let shear = self.inputs.shear_at(q);
        [
            (law.rate(q) - slope) / self.beta,
            q,
            q * slope,
            shear,
            shear * slope,
            q * law.rate(q),
        ]
    }

    fn step(&self, x: f64, y: &State, h: f64) -> State {
        let add =
            |y: &State, k: &State, f: f64| -> State { std::array::from_fn(|i| y[i] + f * k[i]) };
        let k1 = self.rate(x, y);
        let k2 = self.rate(x + h / 2.0, &add(y, &k1, h / 2.0));
        let k3 = self.rate(x + h / 2.0, &add(y, &k2, h / 2.0));
        let k4 = self.rate(x + h, &add(y, &k3, h));
        std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
    }

    /// Shoots from b backward with steps of at most `h`; None when q2 does not enter the contact
    /// at b (g'(b) <= 0: no contact ends there).
    fn shoot(&self, b: f64, h: f64) -> Result<Option<Shot>, SolveError> {
        if self.inputs.shape.slope(b) <= 0.0 {
            return Ok(None);
        }
        let stiffness = |q: f64| self.inputs.wear.rate_slope(q) / self.beta;
        let (mut x, mut y) = (b, [0.0; 6]);
        let mut nodes = vec![(b, 0.0, self.rate(b, &y)[0])];
        let range = self.inputs.shape.range();
        for _ in 0..MAX_STEPS {
            let mut size = h.min(0.5 / self.refine / stiffness(y[0]).max(f64::MIN_POSITIVE));
            if self.blunt_tip {
                // g' ~ |x|^(n-1) with n < 2: steps graded geometrically towards the tip keep the
                // fourth order that a uniform step loses there
                size = size.min((0.25 * x.abs()).max(h / 1024.0));
            }
            let mut next = x - size;
            if let Some(k) = self.kinks.iter().copied().find(|&k| k < x && k > next) {
                next = k;
            }
            if let Some((lo, _)) = range {
                if x <= lo {
                    return Err(SolveError::NoSolution(format!(
                        "the contact runs off the measured profile: the pressure is still {:.4e} \
                         Pa at its first point x = {} m; give a profile that covers the contact",
                        y[0],
                        crate::physics::limits::show(lo)
                    )));
                }
                next = next.max(lo);
            }
            let y1 = self.step(x, &y, next - x);
            if y1[0] <= 0.0 {
                let t = brent(0.0, x - next, |t| self.step(x, &y, -t)[0]).ok_or_else(|| {
                    SolveError::NoSolution(format!(
                        "the narrow model's trailing end did not converge (Brent's method, \
                         {BRENT_ITERATIONS} iterations)"
                    ))
                })?;
                let end = self.step(x, &y, -t);
                nodes.push((x - t, 0.0, self.rate(x - t, &end)[0]));
                nodes.reverse();
                return Ok(Some(Shot {
                    a: t - x,
                    totals: end.map(|v| -v),
                    nodes,
                }));
            }
            x = next;
            y = y1;
            nodes.push((x, y[0], self.rate(x, &y)[0]));
        }
        Err(SolveError::NoSolution(format!(
            "the narrow model's pressure did not return to zero within {MAX_STEPS} steps"
        )))
    }

    /// The shot from b with about STEPS (times `refine`) steps across its contact: a first shot
    /// sized by b, then one sized by the contact it found.
    fn settled(&self, b: f64, scale: f64) -> Result<Option<Shot>, SolveError> {
        let steps = STEPS * self.refine;
        let Some(first) = self.shoot(b, scale / steps)? else {
            return Ok(None);
        };
        self.shoot(b, (first.a + b) / steps)
    }

    /// P(b) - P: the load the shot from b carries (0 without contact), less the inputs' load.
    fn excess(&self, b: f64, scale: f64) -> Result<f64, SolveError> {
        if self.inputs.shape.range().is_some_and(|(_, hi)| b >= hi) {
            // beyond the profile: more than any load, so that the root stays inside it
            return Ok(1e6 * self.inputs.load);
        }
        let carried = self
            .settled(b, scale)?
            .map_or(0.0, |s| s.totals[1] - s.totals[4]);
        Ok(carried - self.inputs.load)
    }
}

/// The root of the increasing `f` = P(d) - P by a geometric bracket from `start` and Brent's
/// method; the first error a shot reported into `failure`, if any.
fn bracketed(
    start: f64,
    p: f64,
    f: impl Fn(f64) -> f64,
    failure: &std::cell::RefCell<Option<SolveError>>,
) -> Result<f64, SolveError> {
    let bracket = bracket_or_why(start, (0.5, 60), (2.0, 200), &f);
    if let Some(e) = failure.borrow_mut().take() {
        return Err(e);
    }
    let (lo, hi) = bracket.map_err(|why| {
        SolveError::NoSolution(format!(
            "the narrow-strip model finds no contact for P = {p:.4e} N/m: {why}"
        ))
    })?;
    let d = brent_to(lo, hi, ROOT_TOLERANCE, &f).ok_or_else(|| {
        SolveError::NoSolution(format!(
            "the contact did not converge at P = {p:.4e} N/m (Brent's method, \
             {BRENT_ITERATIONS} iterations)"
        ))
    })?;
    match failure.borrow_mut().take() {
        Some(e) => Err(e),
        None => Ok(d),
    }
}

/// Why the root search's contact carries `carried` [N/m] and not the load `p` [N/m], in words for
/// the shape: a measured profile ends before the contact does; any other shape has no end, and
/// the search stopped where P(b) jumps.
fn load_mismatch(shape: &Shape, carried: f64, p: f64) -> SolveError {
    SolveError::NoSolution(if shape.range().is_some() {
        format!(
            "the narrow model carries {carried:.4e} N/m at most within the measured profile, not \
             P = {p:.4e} N/m: the contact runs off the measured profile; give a profile that \
             covers it"
        )
    } else {
        format!(
            "the narrow model's root search ended on a contact that carries {carried:.4e} N/m, \
             not P = {p:.4e} N/m: the load jumps there as the leading end moves (no contact \
             carries P on this shape by the shooting)"
        )
    })
}

/// Solves the Winkler problem for any shape and law at the inputs' load.
pub fn solve(inputs: &PlaneInputs) -> Result<PlaneSolution, SolveError> {
    solve_refined(inputs, 1)
}

/// `solve` with `factor` >= 1 times `STEPS` Runge-Kutta steps across the contact: the
/// discretisation error is the difference from `solve`'s answer.
pub fn solve_refined(inputs: &PlaneInputs, factor: usize) -> Result<PlaneSolution, SolveError> {
    if inputs.shape.is_sharp() {
        return Err(SolveError::InvalidInput(
            "the narrow model's shooting needs a rounded edge (edge_radius > 0): on sharp corners \
             the contact is the face and its pressure is plane::sharp's"
                .into(),
        ));
    }
    let beta = winkler_beta(inputs);
    let shooter = Shooter {
        inputs,
        beta,
        kinks: {
            let mut k = inputs.shape.kinks();
            k.sort_by(|p, q| q.total_cmp(p));
            k
        },
        blunt_tip: matches!(inputs.shape, Shape::Power { exponent, .. } if exponent < 2.0),
        refine: factor.max(1) as f64,
    };
    let p = inputs.load;
    let radius = inputs.shape.radius();
    // where the leading end may lie: beyond the flat's face, else beyond the tip
    let start = match &inputs.shape {
        Shape::Flat { half_width, .. } => *half_width,
        _ => 0.0,
    };
    let width0 = (12.0 * beta * radius * p).cbrt();
    let scale = 2.0 * start + width0;
    let failure = std::cell::RefCell::new(None);
    let f = |d: f64| match shooter.excess(start + d, scale) {
        Ok(v) => v,
        Err(e) => {
            failure.borrow_mut().get_or_insert(e);
            f64::NAN
        }
    };
    // secant steps on ln P against ln d (P grows like d^3 on a parabola), else a bracket and
    // Brent's method
    let carried = |d: f64| Some(f(d) + p).filter(|v| v.is_finite());
    let d = match secant_log(carried, p, width0 / 2.0, 3.0, ROOT_TOLERANCE, SECANT_EVALS) {
        Some((d, _)) => d,
        None => {
            failure.borrow_mut().take();
            bracketed(width0 / 2.0, p, f, &failure)?
        }
    };
    let b = start + d;
    let shot = shooter.settled(b, scale)?.ok_or_else(|| {
        SolveError::NoSolution(format!(
            "the narrow model finds no contact at P = {p:.4e} N/m"
        ))
    })?;
    let [_, q2, psi, q1, phi, _] = shot.totals;
    if (q2 - phi - p).abs() > 1e-6 * p {
        return Err(load_mismatch(&inputs.shape, q2 - phi, p));
    }
    Ok(PlaneSolution::assemble(
        Model::Narrow,
        inputs,
        Found {
            a: shot.a,
            b,
            width: shot.a + b,
            q2,
            psi,
            delta_g: inputs.shape.g(b) - inputs.shape.g(-shot.a),
            theta: None,
            gamma: None,
            friction_integrals: Some((q1, phi)),
        },
        PressureLaw::Shooting(Arc::new(Nodes { nodes: shot.nodes })),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_load_mismatch_names_the_measured_profile_only_for_a_table() {
        let table = Shape::Table(Arc::new(crate::physics::plane::shape::Table {
            file: "profile.csv".into(),
            spline: crate::physics::plane::spline::Spline::new(
                vec![-1e-3, 0.0, 1e-3],
                vec![1e-5, 0.0, 1e-5],
            )
            .unwrap(),
        }));
        let power = Shape::Power {
            radius: 0.05,
            exponent: 3.0,
        };
        let said = |shape: &Shape| load_mismatch(shape, 5e3, 1e4).to_string();
        assert!(
            said(&table).contains("runs off the measured profile"),
            "{}",
            said(&table)
        );
        let other = said(&power);
        assert!(!other.contains("profile"), "{other}");
        assert!(
            other.contains("5.0000e3 N/m") && other.contains("P = 1.0000e4"),
            "{other}"
        );
    }
}
