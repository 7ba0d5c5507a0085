//! The energy identity I = J of paper 001 (2.9), evaluated numerically from the solved q1, q2.
//!
//! I = integral of q1 u', J = integral of q2 v' over [-a, b]. The derivatives u', v' come from the
//! kernel of the model, not from the closed-form identity: for the wide strip (4.1),
//!   m u' = -pi chi q2 + H[q1] - chi c12 Q2/h,   m v' = -pi chi q1 - H[q2] - chi c12 Q1/h,
//! with the Hilbert transform H[q](x) = p.v. integral q(s)/(s - x) ds computed by quadrature
//! (singularity subtraction, tanh–sinh on both sides of x); for the Winkler strip (5.1),
//! u' = alpha q1', v' = -beta q2' with q2' from (5.3).

use serde::Serialize;

use crate::physics::elastic::chi_c12;
use crate::physics::plane::narrow::{winkler_alpha, winkler_beta};
use crate::physics::plane::{Model, PlaneSolution};
use crate::physics::quadrature::{GaussRule, tanh_sinh};

/// The two sides of (2.9) and how well they agree.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Energy {
    /// I = integral q1 u' dx [N/m] (work of the shear on the tangential strain).
    #[serde(rename = "I")]
    pub i: f64,
    /// J = integral q2 v' dx [N/m].
    #[serde(rename = "J")]
    pub j: f64,
    /// |I - J| / max(|I|, |J|, W), with W = integral (|q1 u'| + |q2 v'|) dx the gross work, so that
    /// the Winkler case I = J = 0 reads as a small number rather than 0/0. Dimensionless.
    pub residual: f64,
}

/// p.v. integral of q(s)/(s - x) over [lo, hi] for lo < x < hi.
fn hilbert(rule: &GaussRule, lo: f64, hi: f64, x: f64, q: &impl Fn(f64) -> f64) -> f64 {
    let qx = q(x);
    let regular = |s: f64| {
        let ds = s - x;
        if ds == 0.0 { 0.0 } else { (q(s) - qx) / ds }
    };
    rule.integrate(lo, x, regular)
        + rule.integrate(x, hi, regular)
        + qx * ((hi - x) / (x - lo)).ln()
}

/// I, J and the residual for a solved operating point.
pub fn energy(sol: &PlaneSolution) -> Energy {
    let rule = tanh_sinh(1.0 / 16.0);
    let inputs = &sol.inputs;
    let (lo, hi) = (-sol.a, sol.b);
    let q2 = |x: f64| sol.pressure(x);
    let q1 = |x: f64| sol.shear(x);
    let derivatives: Box<dyn Fn(f64) -> (f64, f64)> = match sol.model {
        Model::Wide => {
            let mat = &inputs.material;
            let m = mat.plane_modulus();
            let chi = mat.chi();
            let c = if mat.is_half_space() {
                0.0
            } else {
                chi_c12(mat.poisson_ratio) / mat.thickness
            };
            let (big_q1, big_q2) = (sol.friction_force, sol.normal_force);
            Box::new(move |x| {
                let du = -std::f64::consts::PI * chi * q2(x) + hilbert(&rule, lo, hi, x, &q1)
                    - c * big_q2;
                let dv = -std::f64::consts::PI * chi * q1(x)
                    - hilbert(&rule, lo, hi, x, &q2)
                    - c * big_q1;
                (du / m, dv / m)
            })
        }
        Model::Narrow => {
            let alpha = winkler_alpha(inputs);
            let beta = winkler_beta(inputs);
            let lambda = inputs.wear / beta;
            let mu = inputs.friction.coefficient;
            let r = inputs.radius;
            Box::new(move |x| {
                let dq2 = lambda * q2(x) - x / (r * beta); // (5.3)
                (alpha * mu * dq2, -beta * dq2)
            })
        }
    };
    let (mut i, mut j, mut gross) = (0.0, 0.0, 0.0);
    let half = 0.5 * (hi - lo);
    let rule = tanh_sinh(1.0 / 16.0);
    for (t, w) in rule.nodes.iter().zip(&rule.weights) {
        let x = lo + half * (1.0 + t);
        let (du, dv) = derivatives(x);
        let (a, b) = (q1(x) * du, q2(x) * dv);
        i += w * half * a;
        j += w * half * b;
        gross += w * half * (a.abs() + b.abs());
    }
    let scale = i.abs().max(j.abs()).max(gross).max(f64::MIN_POSITIVE);
    Energy {
        i,
        j,
        residual: (i - j).abs() / scale,
    }
}
