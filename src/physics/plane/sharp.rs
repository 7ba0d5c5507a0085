//! The flat punch with sharp corners (`edge_radius = 0`): the contact is the face [-c, c] whatever
//! the load, with the linear wear law (or none) and no shear cap (`PlaneInputs::validate` refuses
//! the rest). The derivation is in docs/physics/plane-general.md section 3.
//!
//! On the face g' = 0, phi = psi = Delta_g = 0, so P = Q2, T = Q1 = mu P + 2 c tau0 and mu* = mu.
//!
//! Half-plane and wide strip: the contact condition (E) on the face is
//! gamma q2 + H[q2]/m + f0 = 0, gamma = pi chi mu/m - k (4.3), f0 = pi chi tau0/m + chi c12 Q1/(m h)
//! (0 for h = inf), whose solution singular at both corners is q2 = Z (A + B (c + x)),
//! Z = (c+x)^(-1/2-theta) (c-x)^(-1/2+theta), theta of (4.5), B = -f0 m cos(pi theta)/pi and
//! A = P cos(pi theta)/pi - 2c (1/2 - theta) B (Q2 = P by the Beta integrals of Z and Z (c+x)).
//!
//! Strip of any thickness: the collocation of `sharp_strip` (the half-plane's corner exponents,
//! the exact kernels' regular part, the load as the last equation).
//!
//! Narrow strip (Winkler (5.1)): (5.3) with g' = 0 is q2' = k q2/beta on the face; the pressure is
//! bounded, q2 = P lambda e^(lambda (x - c))/(1 - e^(-2 lambda c)), lambda = k/beta (P/(2c)
//! without wear), largest at the leading corner, and steps from 0 to it at both corners.

use std::f64::consts::PI;
use std::sync::Arc;

use crate::physics::SolveError;
use crate::physics::elastic::chi_c12;
use crate::physics::plane::narrow::winkler_beta;
use crate::physics::plane::sharp_strip;
use crate::physics::plane::strip::kernels_for;
use crate::physics::plane::{Found, Model, PlaneInputs, PlaneSolution, PressureLaw, exponent};

/// The solution for a sharp flat of half-width `half_width` c [m] in each model.
pub fn solve(
    inputs: &PlaneInputs,
    model: Model,
    half_width: f64,
) -> Result<PlaneSolution, SolveError> {
    solve_refined(inputs, model, half_width, 1)
}

/// `solve` with the strip model's node count multiplied by `factor` >= 1 (the other models are
/// closed forms): the difference from `solve`'s answer measures the discretisation error.
pub fn solve_refined(
    inputs: &PlaneInputs,
    model: Model,
    half_width: f64,
    factor: usize,
) -> Result<PlaneSolution, SolveError> {
    let width = 2.0 * half_width;
    let (law, theta, gamma) = match model {
        Model::Narrow => (narrow_law(inputs, width)?, None, None),
        Model::Wide => {
            let (law, theta, gamma) = wide_law(inputs, width);
            (law, Some(theta), Some(gamma))
        }
        Model::Strip => {
            let (law, theta, gamma) = strip_law(inputs, width, factor)?;
            (law, Some(theta), Some(gamma))
        }
    };
    // Q2 = P: the closed forms by their Beta integrals, the strip's collocation by its last
    // equation
    let found = Found {
        a: half_width,
        b: half_width,
        width,
        q2: inputs.load,
        psi: 0.0,
        delta_g: 0.0,
        theta,
        gamma,
        friction_integrals: None,
    };
    Ok(PlaneSolution::assemble(model, inputs, found, law))
}

/// The strip's collocation on the face (`sharp_strip`), and theta, gamma.
fn strip_law(
    inputs: &PlaneInputs,
    width: f64,
    factor: usize,
) -> Result<(PressureLaw, f64, f64), SolveError> {
    let mat = &inputs.material;
    if mat.is_half_space() {
        return Err(SolveError::InvalidInput(
            "the strip model needs a finite thickness h; a half-plane is the wide model's".into(),
        ));
    }
    let (_, gamma, theta) = exponent(inputs);
    let nodes = sharp_strip::node_count(width / mat.thickness, factor)?;
    let kernels = kernels_for(mat.poisson_ratio);
    let pressure = sharp_strip::solve(inputs, kernels.as_ref(), 0.5 * width, nodes)?;
    Ok((PressureLaw::StripCorners(Arc::new(pressure)), theta, gamma))
}

/// The half-plane's and the wide strip's q2 = Z (A + B u), u = c + x, and theta, gamma.
fn wide_law(inputs: &PlaneInputs, width: f64) -> (PressureLaw, f64, f64) {
    let (m, gamma, theta) = exponent(inputs);
    let mat = &inputs.material;
    let (mu, tau0, p) = (
        inputs.friction.coefficient,
        inputs.friction.adhesion,
        inputs.load,
    );
    let thickness = if mat.is_half_space() {
        0.0
    } else {
        // chi c12 Q1/(m h) with Q1 = mu P + tau0 (a + b)
        chi_c12(mat.poisson_ratio) * (mu * p + tau0 * width) / (m * mat.thickness)
    };
    let f0 = PI * mat.chi() * tau0 / m + thickness;
    let cos = (PI * theta).cos();
    let slope = -f0 * m * cos / PI;
    let constant = p * cos / PI - width * (0.5 - theta) * slope;
    let law = PressureLaw::Corners {
        theta,
        constant,
        slope,
        width,
    };
    (law, theta, gamma)
}

/// The Winkler strip's exponential pressure on the face, given by its value at the leading corner.
fn narrow_law(inputs: &PlaneInputs, width: f64) -> Result<PressureLaw, SolveError> {
    if inputs.material.is_half_space() {
        return Err(SolveError::InvalidInput(
            "the narrow (Winkler) model needs a finite thickness h; a half-plane is a wide strip"
                .into(),
        ));
    }
    let lambda = inputs.wear.coefficient / winkler_beta(inputs);
    let leading = if lambda > 0.0 {
        // P lambda/(1 - e^(-lambda L)), exact for small lambda L through expm1
        inputs.load * lambda / -(-lambda * width).exp_m1()
    } else {
        inputs.load / width
    };
    Ok(PressureLaw::Face { leading, lambda })
}

/// q2 [Pa] of `Corners` at the distance u [m] from the trailing corner, 0 < u < L.
pub(crate) fn corners_pressure(theta: f64, constant: f64, slope: f64, width: f64, u: f64) -> f64 {
    let z = ((-0.5 - theta) * u.ln() + (-0.5 + theta) * (width - u).ln()).exp();
    z * (constant + slope * u)
}

/// q2 [Pa] of `Face` at the distance `to_leading` [m] from the leading corner.
pub(crate) fn face_pressure(leading: f64, lambda: f64, to_leading: f64) -> f64 {
    leading * (-lambda * to_leading).exp()
}
