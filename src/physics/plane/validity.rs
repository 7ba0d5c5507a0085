//! Whether an operating point lies where its model holds, in words (docs/physics/plane.md sections 3,
//! 4, 6). The wide and narrow models are judged by how far they are from the strip model of any
//! thickness, with the formulas of `criteria` (derived from a study against the strip model);
//! `against_strip` measures it exactly when the strip model is cheap.

use serde::Serialize;

use crate::physics::plane::criteria::{
    self, MU_STAR_FLOOR, MU_STAR_TOLERANCE, STUDIED_KM, STUDIED_MU, STUDIED_NU, WIDTH_TOLERANCE,
};
use crate::physics::plane::{Model, PlaneSolution, solve};

/// How far a model is from the strip model of any thickness, relative.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Deviation {
    /// |L_model/L_strip - 1|, dimensionless.
    pub contact_width: f64,
    /// |mu*_model - mu*_strip| / max(|mu*_strip - mu|, 0.01 (a+b)/R), dimensionless.
    pub mu_star_minus_mu: f64,
}

impl Deviation {
    /// No deviation (the strip model itself, or the wide model on a half-plane, where it is exact).
    pub const NONE: Deviation = Deviation {
        contact_width: 0.0,
        mu_star_minus_mu: 0.0,
    };

    /// Within the tolerances (2 % in contact width, 5 % in mu* - mu).
    pub fn within_tolerance(&self) -> bool {
        self.contact_width <= WIDTH_TOLERANCE && self.mu_star_minus_mu <= MU_STAR_TOLERANCE
    }
}

/// The validity verdict reported with every plane solution.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Validity {
    /// True when no warning applies.
    pub ok: bool,
    /// (a + b)/h, dimensionless; 0 for the half-plane.
    pub contact_width_over_thickness: f64,
    /// What is questionable and why, one sentence each (the failed criteria first).
    pub warnings: Vec<String>,
    /// The shown model's deviation from the strip model, estimated by the formulas of the study
    /// (at most 100 each; 0 for the strip model and for the wide model on a half-plane).
    pub estimated_error: Deviation,
    /// The criteria of the study the model fails, in words; empty when it holds.
    pub failed_criteria: Vec<String>,
}

/// Checks the operating point against the model's assumptions and the study's criteria.
pub fn check(sol: &PlaneSolution) -> Validity {
    let inputs = &sol.inputs;
    let h = inputs.material.thickness;
    let l = sol.contact_width();
    let l_over_h = if h.is_finite() { l / h } else { 0.0 };
    let (estimated_error, failed_criteria) = match sol.model {
        _ if !h.is_finite() => (Deviation::NONE, Vec::new()),
        Model::Strip => (Deviation::NONE, Vec::new()),
        Model::Wide | Model::Narrow => criteria_of(sol, l_over_h),
    };
    let mut warnings = failed_criteria.clone();
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
        estimated_error,
        failed_criteria,
    }
}

/// The estimated deviation of a wide or narrow solution on a finite strip, and the criteria it
/// fails in words.
fn criteria_of(sol: &PlaneSolution, lambda: f64) -> (Deviation, Vec<String>) {
    let inputs = &sol.inputs;
    let nu = inputs.material.poisson_ratio;
    let mu = inputs.friction.coefficient;
    let km = inputs.wear * inputs.material.plane_modulus();
    let h_over_r = inputs.material.thickness / inputs.radius;
    let mut failed = Vec::new();
    let name = if sol.model == Model::Wide {
        "the wide model"
    } else {
        "the Winkler (narrow) model"
    };
    let outside: Vec<String> = [
        (nu > STUDIED_NU, format!("nu = {nu}")),
        (mu > STUDIED_MU, format!("mu = {mu}")),
        (km > STUDIED_KM, format!("k m = {km:.3}")),
        (
            inputs.friction.adhesion != 0.0,
            format!("tau0 = {:.3e} Pa", inputs.friction.adhesion),
        ),
    ]
    .into_iter()
    .filter_map(|(out, what)| out.then_some(what))
    .collect();
    if !outside.is_empty() {
        failed.push(format!(
            "{name} is judged against the strip model only where that was studied (nu <= 0.499, \
             mu <= 1, k m <= 3, no adhesion); here {}: use the strip model",
            outside.join(", ")
        ));
    }
    let error = if sol.model == Model::Wide {
        let error = Deviation {
            contact_width: criteria::wide_width_error(nu, lambda),
            mu_star_minus_mu: criteria::wide_mu_star_error(nu, lambda).min(100.0),
        };
        let limit = criteria::wide_mu_star_limit(nu)
            .min((WIDTH_TOLERANCE / criteria::wide_width_error(nu, 1.0)).sqrt());
        if lambda > limit {
            failed.push(format!(
                "the wide model needs (a+b)/h < {limit:.2} at nu = {nu} (contact width within 2 %, \
                 mu* - mu within 5 % of the exact strip solution); here (a+b)/h = {lambda:.3}, \
                 estimated error {}: use the strip model",
                percentages(&error)
            ));
        }
        error
    } else {
        let w_minus_mu = sol.mu_star - mu;
        let error = Deviation {
            contact_width: criteria::narrow_width_error(nu, mu, km, lambda).min(100.0),
            mu_star_minus_mu: criteria::narrow_mu_star_error(
                nu,
                mu,
                h_over_r,
                w_minus_mu,
                lambda * h_over_r,
            ),
        };
        let needed = criteria::narrow_width_limit(nu, mu, km);
        if error.contact_width > WIDTH_TOLERANCE {
            failed.push(format!(
                "Winkler needs (a+b)/h > {needed:.0} at nu = {nu}, mu = {mu}, k m = {km:.3} for \
                 its contact width within 2 % of the exact strip solution; here (a+b)/h = \
                 {lambda:.3}, estimated error {:.1} %: use the strip model",
                100.0 * error.contact_width
            ));
        }
        if error.mu_star_minus_mu > MU_STAR_TOLERANCE {
            failed.push(if km == 0.0 {
                "without wear the Winkler model gives mu* = mu exactly, while friction alone \
                 makes the strip's mu* - mu nonzero: use the strip model"
                    .to_string()
            } else {
                format!(
                    "the Winkler model lacks the friction-induced part of mu* - mu, estimated \
                     {:.0} % of what it gives (at most 5 %: wear must dominate): use the strip \
                     model",
                    100.0 * error.mu_star_minus_mu
                )
            });
        }
        error
    };
    (error, failed)
}

/// "1.2 % in contact width, 3.4 % in mu* - mu".
fn percentages(d: &Deviation) -> String {
    format!(
        "{:.1} % in contact width, {:.1} % in mu* - mu",
        100.0 * d.contact_width,
        100.0 * d.mu_star_minus_mu
    )
}

/// The largest (a+b)/h at which `against_strip` runs the strip model (about 400 nodes, a few
/// milliseconds).
pub const CHEAP_STRIP_WIDTH: f64 = 90.0;

/// The shown wide or narrow solution against the strip model at the same inputs, measured: None
/// for the strip model itself, a half-plane, a contact wider than CHEAP_STRIP_WIDTH thicknesses,
/// or where the strip model has no answer.
pub fn against_strip(sol: &PlaneSolution) -> Option<Deviation> {
    let h = sol.inputs.material.thickness;
    if sol.model == Model::Strip || !h.is_finite() || sol.contact_width() / h > CHEAP_STRIP_WIDTH {
        return None;
    }
    let strip = solve(&sol.inputs, Model::Strip).ok()?;
    let mu = sol.inputs.friction.coefficient;
    let floor = MU_STAR_FLOOR * strip.contact_width() / sol.inputs.radius;
    Some(Deviation {
        contact_width: (sol.contact_width() / strip.contact_width() - 1.0).abs(),
        mu_star_minus_mu: (sol.mu_star - strip.mu_star).abs()
            / (strip.mu_star - mu).abs().max(floor),
    })
}

/// One line for the status: "wide: contact width within 0.1 %, mu* - mu within 0.4 % of the exact
/// strip solution".
pub fn describe(model: Model, deviation: &Deviation) -> String {
    format!(
        "{}: contact width within {:.1} %, mu* - mu within {:.1} % of the exact strip solution",
        model.name(),
        100.0 * deviation.contact_width,
        100.0 * deviation.mu_star_minus_mu
    )
}
