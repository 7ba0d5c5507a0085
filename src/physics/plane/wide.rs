//! Wide strip ((a+b)/h -> 0) and half-plane (h = inf): Soldatenkov (2007) section 4, docs/physics/plane.md section 3.

use std::f64::consts::PI;

use crate::physics::SolveError;
use crate::physics::elastic::chi_c12;
use crate::physics::plane::{Found, PlaneInputs, PlaneSolution, PressureLaw, exponent};
use crate::physics::roots::{BRENT_ITERATIONS, NoBracket, brent, march_up};

/// The constants of the wide solution that do not depend on the contact width.
#[derive(Clone, Copy, Debug)]
pub struct WideConstants {
    /// m [Pa].
    pub m: f64,
    /// gamma = pi chi mu/m - k [1/Pa] (4.3).
    pub gamma: f64,
    /// theta = arctan(m gamma / pi)/pi (4.5).
    pub theta: f64,
    /// Q2 / L^2 = (1 - 4 theta^2) m / (8 R) [Pa/m] from (4.6).
    pub q2_per_l2: f64,
    /// The part of Phi0 that does not depend on the load: pi chi tau0 / m (dimensionless).
    pub phi0_adhesion: f64,
    /// d Phi0 / d Q1 = chi c12 / (m h) [m/N]; 0 for the half-plane.
    pub phi0_per_q1: f64,
}

impl WideConstants {
    /// The constants for these inputs (the load is not used).
    pub fn new(inputs: &PlaneInputs) -> WideConstants {
        let mat = &inputs.material;
        let (m, gamma, theta) = exponent(inputs);
        let chi = mat.chi();
        let phi0_per_q1 = if mat.is_half_space() {
            0.0
        } else {
            chi_c12(mat.poisson_ratio) / (m * mat.thickness)
        };
        WideConstants {
            m,
            gamma,
            theta,
            q2_per_l2: (1.0 - 4.0 * theta * theta) * m / (8.0 * inputs.radius()),
            phi0_adhesion: PI * chi * inputs.friction.adhesion / m,
            phi0_per_q1,
        }
    }
}

/// Everything the closed form gives at one contact width L.
#[derive(Clone, Copy, Debug)]
pub struct WideState {
    /// Q2 [N/m].
    pub q2: f64,
    /// Q1 [N/m].
    pub q1: f64,
    /// a, b [m].
    pub a: f64,
    /// b [m].
    pub b: f64,
    /// psi [N/m] (4.7).
    pub psi: f64,
    /// Delta_g [m] (4.8).
    pub delta_g: f64,
    /// P [N/m] from (3.11).
    pub load: f64,
}

/// The closed form at contact width `l`: (4.5)-(4.8) and (3.11).
pub fn state(c: &WideConstants, inputs: &PlaneInputs, l: f64) -> WideState {
    let r = inputs.radius();
    let mu = inputs.friction.coefficient;
    let tau0 = inputs.friction.adhesion;
    let q2 = c.q2_per_l2 * l * l;
    let q1 = mu * q2 + tau0 * l;
    let phi0 = c.phi0_adhesion + c.phi0_per_q1 * q1;
    let shift = c.theta * l + r * phi0; // (a - b)/2, (4.5)
    let psi = -(q2 / r) * (4.0 / 3.0 * c.theta * l + r * phi0);
    let delta_g = -(l / r) * shift;
    WideState {
        q2,
        q1,
        a: 0.5 * l + shift,
        b: 0.5 * l - shift,
        psi,
        delta_g,
        load: q2 - mu * psi - tau0 * delta_g,
    }
}

/// Solves for the given load: the smallest positive root L of P(L) = P (a quartic), by a
/// geometric march from a tiny L to the first sign change, then Brent.
pub fn solve(inputs: &PlaneInputs) -> Result<PlaneSolution, SolveError> {
    solve_with(&WideConstants::new(inputs), inputs)
}

/// As `solve`, with the load-independent constants already computed (a load sweep computes them
/// once: chi c12 costs a quadrature).
pub fn solve_with(c: &WideConstants, inputs: &PlaneInputs) -> Result<PlaneSolution, SolveError> {
    let p = inputs.load;
    let hertz = (8.0 * inputs.radius() * p / c.m).sqrt();
    let f = |l: f64| state(c, inputs, l).load - p;
    let (from, to) = (hertz * 1e-4, hertz * 1e6);
    // the first width at which the load is carried: by factors of 2 (about 14 evaluations up to
    // the Hertz width), and where that finds none, by factors of 1.1, which resolves a load
    // carried only over a narrow range of widths (near the most the model carries) and that most
    // for the message
    let coarse = march_up(from, 2.0, to, f);
    let (lo, hi) = coarse
        .or_else(|_| march_up(from, 1.1, to, f))
        .map_err(|why| match why {
            NoBracket::NoPositive { best_x, best_f, .. } => SolveError::NoSolution(format!(
                "the wide-strip model has no contact at P = {p:.4e} N/m: it carries at most \
             P = {:.4e} N/m (contact width {best_x:.4e} m, far outside its range of validity)",
                best_f + p,
            )),
            other => SolveError::NoSolution(format!(
                "the wide-strip model finds no contact width at P = {p:.4e} N/m: {other}"
            )),
        })?;
    let l = brent(lo, hi, f).ok_or_else(|| {
        SolveError::NoSolution(format!(
            "the contact width did not converge at P = {p:.4e} N/m \
             (Brent's method, {BRENT_ITERATIONS} iterations)"
        ))
    })?;
    let s = state(c, inputs, l);
    Ok(PlaneSolution::assemble(
        super::Model::Wide,
        inputs,
        Found {
            a: s.a,
            b: s.b,
            width: l,
            q2: s.q2,
            psi: s.psi,
            delta_g: s.delta_g,
            theta: Some(c.theta),
            gamma: Some(c.gamma),
            friction_integrals: None,
        },
        PressureLaw::Wide {
            c: c.m * (PI * c.theta).cos() / (PI * inputs.radius()),
            theta: c.theta,
        },
    ))
}
