//! Whether an operating point lies where its model holds, in words (docs/physics/plane.md sections 3, 4).

use serde::Serialize;

use crate::physics::plane::narrow::winkler_beta;
use crate::physics::plane::{Model, PlaneSolution};

/// The validity verdict reported with every plane solution.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Validity {
    /// True when no warning applies.
    pub ok: bool,
    /// (a + b)/h, dimensionless; 0 for the half-plane.
    pub contact_width_over_thickness: f64,
    /// What is questionable and why, one sentence each.
    pub warnings: Vec<String>,
}

/// Checks the operating point against the model's assumptions.
pub fn check(sol: &PlaneSolution) -> Validity {
    let inputs = &sol.inputs;
    let h = inputs.material.thickness;
    let l = sol.contact_width();
    let l_over_h = if h.is_finite() { l / h } else { 0.0 };
    let mut warnings = Vec::new();
    match sol.model {
        // the strip model resolves every width it answers for (wider ones are an error)
        Model::Strip => {}
        Model::Wide => {
            if l_over_h > 1.0 {
                warnings.push(format!(
                    "contact width/thickness (a+b)/h = {l_over_h:.3}: far outside the wide-strip \
                     model's range ((a+b)/h << 1); use the strip model"
                ));
            } else if l_over_h > 0.1 {
                warnings.push(format!(
                    "contact width/thickness (a+b)/h = {l_over_h:.3} > 0.1: the wide-strip model's \
                     error in mu* - mu is about 0.09 (L/h)^2 = {:.1} %; use the strip model",
                    9.0 * l_over_h * l_over_h
                ));
            }
        }
        Model::Narrow => {
            if l_over_h < 10.0 {
                warnings.push(format!(
                    "contact width/thickness (a+b)/h = {l_over_h:.3} < 10: the Winkler model needs \
                     a contact much wider than the strip; use the strip model"
                ));
            }
            let lambda_h = inputs.wear / winkler_beta(inputs) * h;
            if lambda_h > 0.3 {
                warnings.push(format!(
                    "wear length lambda h = {lambda_h:.3} > 0.3: the pressure changes over a length \
                     comparable to h, where the Winkler relations do not hold; use the strip model"
                ));
            }
        }
    }
    if let Some(theta) = sol.theta
        && theta.abs() > 0.45
    {
        warnings.push(format!(
            "theta = {theta:.3} is close to +-1/2: the pressure is nearly singular at the {} edge",
            if theta > 0.0 { "trailing" } else { "leading" }
        ));
    }
    let l_over_r = l / inputs.radius;
    if l_over_r > 0.1 {
        warnings.push(format!(
            "contact width/radius (a+b)/R = {l_over_r:.3} > 0.1: the punch slopes are not small"
        ));
    }
    if sol.a < 0.0 || sol.b < 0.0 {
        warnings.push(format!(
            "the contact zone [-a, b] = [{:.4e}, {:.4e}] m does not contain the punch tip",
            -sol.a, sol.b
        ));
    }
    Validity {
        ok: warnings.is_empty(),
        contact_width_over_thickness: l_over_h,
        warnings,
    }
}
