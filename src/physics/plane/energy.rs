//! The energy identity I = J of Soldatenkov (2007) eq. (2.9) and the energy losses of its section 2,
//! evaluated numerically from the solved q1, q2.
//!
//! Per unit sliding speed (N/m: power per unit speed), the work of the tangential force T splits
//! into the friction loss D1/V0 = Q1 + I (2.5) and the wear loss DW/V0 = psi - J (2.7);
//! T = D1/V0 + DW/V0 exactly when I = J (2.8)-(2.9). The wear loss is also the integral of
//! q2 F(q2) (k q2^2 for the linear law; the contact condition, docs/physics/plane.md and
//! docs/physics/plane-general.md section 4), which checks the solution against the contact
//! condition independently of I = J. The shear is q1 = Pi(q2) = min(mu q2 + tau0, tau_max).
//!
//! I = integral of q1 u', J = integral of q2 v' over [-a, b]. The derivatives u', v' come from the
//! kernel of the model, not from the closed-form identity: for the wide strip (4.1),
//!   m u' = -pi chi q2 + H[q1] - chi c12 Q2/h,   m v' = -pi chi q1 - H[q2] - chi c12 Q1/h,
//! with the Hilbert transform H[q](x) = p.v. integral q(s)/(s - x) ds computed by quadrature
//! (singularity subtraction, tanh–sinh on both sides of x, each rule split where the general
//! solver's q2 or q1 has a kink); for the Winkler strip (5.1),
//! u' = alpha q1', v' = -beta q2' with q2' from (5.3); for the strip of any thickness, (3.7) with
//! the tabulated kernels.

use serde::Serialize;

use crate::physics::elastic::chi_c12;
use crate::physics::plane::narrow::{winkler_alpha, winkler_beta};
use crate::physics::plane::strip::kernels_for;
use crate::physics::plane::{Model, PlaneSolution, PressureLaw};
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
    /// Friction loss D1/V0 = Q1 + I [N/m] (2.5): the power dissipated by friction per unit
    /// sliding speed, >= 0.
    pub friction_loss: f64,
    /// Wear loss DW/V0 = psi - J [N/m] (2.7): the power spent on wear per unit sliding speed,
    /// >= 0 (0 without wear).
    pub wear_loss: f64,
    /// External work T [N/m] (3.11): the power of the tangential force per unit sliding speed;
    /// equals friction_loss + wear_loss when I = J.
    pub external: f64,
    /// |psi - J - integral q2 F(q2)| relative to the larger of |T| and the gross work: how well the
    /// solution satisfies the contact condition (the wear loss computed two ways). Dimensionless.
    pub contact_residual: f64,
}

/// What is left of the energy balance where I and J have no number (a punch with sharp corners):
/// written as the `Energy` keys with null for those, and `note` saying why.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Undefined {
    /// External work T [N/m] (3.11), finite.
    pub external: f64,
    /// Wear loss [N/m] where it is finite (the Winkler strip's k int q2^2), else None.
    pub wear_loss: Option<f64>,
    /// Why I, J and the losses have no number.
    pub note: &'static str,
}

/// Why I, J and the losses have no number on the half-plane and the wide strip under sharp
/// corners (docs/physics/plane-general.md section 4).
pub const CORNERS_NOTE: &str = "the pressure is singular at the sharp corners (q2 ~ \
    r^(-1/2-theta) at the trailing corner, r^(-1/2+theta) at the leading one, r the distance to \
    the corner): q1 u' and q2 v' grow like 1/r or faster there, so I, J, the friction loss and \
    the wear loss diverge; T = Q1 and the wear per pass k P stay finite";

/// Why I, J and the friction loss have no number on the Winkler strip under sharp corners.
pub const FACE_NOTE: &str = "the Winkler pressure is bounded but steps from 0 at the sharp \
    corners, and the surface displacements (u' = alpha q1', v' = -beta q2') step with it: I and \
    J would be the work of a stress on a displacement step, which the model leaves undefined, \
    and so is the friction loss Q1 + I; the wear loss is k times the integral of q2^2";

impl Undefined {
    /// The wear loss as a share of T (dimensionless) where the wear loss has a number; None
    /// else, or when T = 0.
    pub fn wear_share(&self) -> Option<f64> {
        let loss = self.wear_loss?;
        (self.external != 0.0).then(|| loss / self.external)
    }
}

impl Serialize for Undefined {
    fn serialize<S: serde::Serializer>(&self, out: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut map = out.serialize_struct("Energy", 8)?;
        for key in ["I", "J", "residual", "friction_loss"] {
            map.serialize_field(key, &None::<f64>)?;
        }
        map.serialize_field("wear_loss", &self.wear_loss)?;
        map.serialize_field("external", &self.external)?;
        map.serialize_field("contact_residual", &None::<f64>)?;
        map.serialize_field("note", self.note)?;
        map.end()
    }
}

/// `energy`'s answer as `wearlab solve` writes it: the `Energy` keys, null where `Undefined`.
pub fn serialize_balance<S: serde::Serializer>(
    balance: &Result<Energy, Undefined>,
    out: S,
) -> Result<S::Ok, S::Error> {
    match balance {
        Ok(energy) => energy.serialize(out),
        Err(undefined) => undefined.serialize(out),
    }
}

impl Energy {
    /// The friction loss as a share of the external work T (dimensionless); None when T = 0
    /// (neither friction nor wear: nothing is dissipated).
    pub fn friction_share(&self) -> Option<f64> {
        (self.external != 0.0).then(|| self.friction_loss / self.external)
    }

    /// The wear loss as a share of T (dimensionless); None when T = 0.
    pub fn wear_share(&self) -> Option<f64> {
        (self.external != 0.0).then(|| self.wear_loss / self.external)
    }
}

/// The residual's round-off floor (dimensionless): I and J are sums of some hundreds of
/// quadrature terms, each exact to about 1.1e-16 (f64's unit round-off), so a residual below this
/// says I = J to the precision of the arithmetic and its digits carry no information (they move
/// with the last bits of the solution).
pub const RESIDUAL_ROUND_OFF: f64 = 1e-14;

/// p.v. integral of q(s)/(s - x) over [lo, hi] for lo < x < hi, the regular part's rule split at
/// `kinks` (points where q has a kink).
fn hilbert(
    rule: &GaussRule,
    (lo, hi): (f64, f64),
    x: f64,
    q: &impl Fn(f64) -> f64,
    kinks: &[f64],
) -> f64 {
    let qx = q(x);
    let regular = |s: f64| {
        let ds = s - x;
        if ds == 0.0 { 0.0 } else { (q(s) - qx) / ds }
    };
    pieces(lo, x, kinks)
        .chain(pieces(x, hi, kinks))
        .map(|(a, b)| rule.integrate(a, b, regular))
        .sum::<f64>()
        + qx * ((hi - x) / (x - lo)).ln()
}

/// [lo, hi] cut at the `kinks` inside it (increasing), as consecutive pieces.
fn pieces(lo: f64, hi: f64, kinks: &[f64]) -> impl Iterator<Item = (f64, f64)> {
    let mut ends = vec![lo];
    ends.extend(kinks.iter().copied().filter(|&k| k > lo && k < hi));
    ends.push(hi);
    (0..ends.len() - 1).map(move |i| (ends[i], ends[i + 1]))
}

/// The tanh-sinh step of the energy integrals: 1/16 for the closed forms; for the general
/// solver's polynomial of N nodes 2/N within [1/64, 1/32], so that the rule's nodes away from
/// the ends (spaced some pi h/2 in t) follow a polynomial of degree N (the energies of 128 nodes
/// moved by up to 1.3e-6 of T from 1/32 to 1/64 on a power punch, n = 1.5).
fn step(sol: &PlaneSolution) -> f64 {
    match &sol.law {
        PressureLaw::General { pressure, .. } => {
            (2.0 / pressure.nodes().len() as f64).clamp(1.0 / 64.0, 1.0 / 32.0)
        }
        _ => 1.0 / 16.0,
    }
}

/// I, J and the residual for a solved operating point. The quadrature runs in u = x + a in
/// [0, a + b], the distance from the trailing edge, so both edges keep full precision. Undefined
/// for a punch with sharp corners, where I and J have no number.
pub fn energy(sol: &PlaneSolution) -> Result<Energy, Undefined> {
    match sol.law {
        PressureLaw::Corners { .. } | PressureLaw::StripCorners(_) | PressureLaw::Face { .. } => {
            return Err(undefined_at(sol));
        }
        _ => {}
    }
    let rule = tanh_sinh(step(sol));
    let inputs = &sol.inputs;
    let (mu, tau0) = (inputs.friction.coefficient, inputs.friction.adhesion);
    let l = sol.contact_width();
    let q2 = |u: f64| sol.pressure_from_trailing_edge(u);
    let q1 = |u: f64| inputs.shear_at(q2(u));
    // where q2 or q1 has kinks: the general solver's (the shape's and the cap's), else the shape's
    let all_kinks: Vec<f64> = match &sol.law {
        PressureLaw::General { kinks, .. } => kinks.to_vec(),
        _ => kinks_within(sol),
    };
    let kinks: &[f64] = &all_kinks;
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
            let pi_chi = std::f64::consts::PI * chi;
            let rule = &rule;
            Box::new(move |u| {
                let du = -pi_chi * q2(u) + hilbert(rule, (0.0, l), u, &q1, kinks) - c * big_q2;
                let dv = -pi_chi * q1(u) - hilbert(rule, (0.0, l), u, &q2, kinks) - c * big_q1;
                (du / m, dv / m)
            })
        }
        Model::Strip => {
            // (3.7) with the exact kernels: A_j = 1/z + R_j, so the Hilbert part is as above and
            // the rest is regular. H[q1] = mu H[q2] + tau0 ln((l - u)/u) exactly, and the regular
            // integrals sample q2 at the same nodes for every u: evaluate them once.
            let mat = &inputs.material;
            let m = mat.plane_modulus();
            let pi_chi = std::f64::consts::PI * mat.chi();
            let h = mat.thickness;
            let k = kernels_for(mat.poisson_ratio);
            let rule = &rule;
            let half = 0.5 * l;
            let samples: Vec<(f64, f64, f64)> = rule
                .nodes
                .iter()
                .zip(&rule.weights)
                .map(|(t, w)| {
                    let s = half + half * t;
                    (s, half * w, q2(s))
                })
                .collect();
            Box::new(move |u| {
                let (mut r1, mut r2, mut b1, mut b2) = (0.0, 0.0, 0.0, 0.0);
                for &(s, w, q) in &samples {
                    let z = (s - u) / h;
                    let (wq2, wq1, b) = (w * q, w * (mu * q + tau0), k.chi_b12(z));
                    r1 += wq1 * k.r1(z);
                    r2 += wq2 * k.r2(z);
                    b1 += wq1 * b;
                    b2 += wq2 * b;
                }
                let h2 = hilbert(rule, (0.0, l), u, &q2, &[]);
                let h1 = mu * h2 + tau0 * ((l - u) / u).ln();
                let du = -pi_chi * q2(u) + h1 + (r1 - b2) / h;
                let dv = -pi_chi * q1(u) - h2 - (r2 + b1) / h;
                (du / m, dv / m)
            })
        }
        Model::Narrow if !inputs.is_classical() => {
            let (alpha, beta, a) = (winkler_alpha(inputs), winkler_beta(inputs), sol.a);
            Box::new(move |u| {
                let q = q2(u);
                // (5.3) with the wear law F and the shape's slope g'
                let dq2 = (inputs.wear.rate(q) - inputs.shape.slope(u - a)) / beta;
                let dq1 = inputs.friction_law().shear_slope(q) * dq2;
                (alpha * dq1, -beta * dq2)
            })
        }
        Model::Narrow => {
            let alpha = winkler_alpha(inputs);
            let beta = winkler_beta(inputs);
            let lambda = inputs.wear.coefficient / beta;
            let (r, a) = (inputs.radius(), sol.a);
            Box::new(move |u| {
                let dq2 = lambda * q2(u) - (u - a) / (r * beta); // (5.3), g'(x) = x/R
                (alpha * mu * dq2, -beta * dq2)
            })
        }
    };
    // the linear law's k q2^2 integrates q2^2 and scales by k after, as it always has
    let linear = inputs.wear.is_linear();
    let wear_of = |q: f64| if linear { q } else { inputs.wear.rate(q) };
    let (mut i, mut j, mut gross, mut q2_wear) = (0.0, 0.0, 0.0, 0.0);
    // the rule runs piecewise between the kinks inside the contact
    for (lo, hi) in pieces(0.0, l, kinks) {
        let half = 0.5 * (hi - lo);
        for (t, w) in rule.nodes.iter().zip(&rule.weights) {
            let u = if *t < 0.0 {
                lo + half * (1.0 + t)
            } else {
                hi - half * (1.0 - t)
            };
            // in a piece thinner than some 1e-2 of l (a cap reached near an edge) the outermost
            // nodes round onto the contact's edge, where q2 = 0 and the p.v. integrals' log term
            // has no value; their weights are below 1e-14 of the piece's
            if u <= 0.0 || u >= l {
                continue;
            }
            let (du, dv) = derivatives(u);
            let (a, b) = (q1(u) * du, q2(u) * dv);
            i += w * half * a;
            j += w * half * b;
            gross += w * half * (a.abs() + b.abs());
            q2_wear += w * half * q2(u) * wear_of(q2(u));
        }
    }
    let scale = i.abs().max(j.abs()).max(gross).max(f64::MIN_POSITIVE);
    let wear_loss = sol.psi - j;
    let direct_wear_loss = if linear {
        inputs.wear.coefficient * q2_wear
    } else {
        q2_wear
    };
    let contact_scale = sol.tangential_force.abs().max(gross).max(f64::MIN_POSITIVE);
    Ok(Energy {
        i,
        j,
        residual: (i - j).abs() / scale,
        friction_loss: sol.friction_force + i,
        wear_loss,
        external: sol.tangential_force,
        contact_residual: (wear_loss - direct_wear_loss).abs() / contact_scale,
    })
}

/// The wear loss DW/V0 [N/m] as the integral of q2 F(q2) over the contact (Soldatenkov (2007)
/// eq. 2.7 with the contact condition: psi - J = int q2 F(q2) dx), by the tanh-sinh rule split at
/// the kinks of q2: one pass over the contact, without the Hilbert transforms of I and J, so that
/// a curve of many loads costs what one `energy` does. `energy` computes it too, beside psi - J
/// (its `contact_residual` compares the two). Under sharp corners the answer is `energy`'s.
pub fn wear_loss(sol: &PlaneSolution) -> Result<f64, Undefined> {
    if let PressureLaw::Corners { .. } | PressureLaw::StripCorners(_) | PressureLaw::Face { .. } =
        sol.law
    {
        return Err(undefined_at(sol));
    }
    let rule = tanh_sinh(step(sol));
    let kinks: Vec<f64> = match &sol.law {
        PressureLaw::General { kinks, .. } => kinks.to_vec(),
        _ => kinks_within(sol),
    };
    let law = &sol.inputs.wear;
    let mut total = 0.0;
    for (lo, hi) in pieces(0.0, sol.contact_width(), &kinks) {
        let half = 0.5 * (hi - lo);
        for (t, w) in rule.nodes.iter().zip(&rule.weights) {
            // from the nearer end, so that both ends keep full precision
            let u = if *t < 0.0 {
                lo + half * (1.0 + t)
            } else {
                hi - half * (1.0 - t)
            };
            let q = sol.pressure_from_trailing_edge(u);
            total += w * half * q * law.rate(q);
        }
    }
    Ok(total)
}

/// The energy balance of a punch with sharp corners: only T, and the wear loss on the Winkler
/// face, have a number (docs/physics/plane-general.md section 4).
fn undefined_at(sol: &PlaneSolution) -> Undefined {
    let (wear_loss, note) = match sol.law {
        PressureLaw::Face { leading, lambda } => {
            // k times the integral over the face of (q_b e^(-lambda (L - u)))^2
            let l = sol.contact_width();
            let squared = if lambda > 0.0 {
                -(-2.0 * lambda * l).exp_m1() / (2.0 * lambda)
            } else {
                l
            };
            let loss = sol.inputs.wear.coefficient * leading * leading * squared;
            (Some(loss), FACE_NOTE)
        }
        _ => (None, CORNERS_NOTE),
    };
    Undefined {
        external: sol.tangential_force,
        wear_loss,
        note,
    }
}

/// The shape's kinks strictly inside the contact, as distances u from the trailing edge,
/// ascending: none for the parabola.
fn kinks_within(sol: &PlaneSolution) -> Vec<f64> {
    let mut out: Vec<f64> = sol
        .inputs
        .shape
        .kinks()
        .into_iter()
        .filter(|x| *x > -sol.a && *x < sol.b)
        .map(|x| x + sol.a)
        .collect();
    out.sort_by(f64::total_cmp);
    out
}
