//! Whether an operating point lies where its model holds, in words (docs/physics/plane.md sections 3,
//! 4, 6). The wide and narrow models are judged by how far they are from the strip model of any
//! thickness, with the formulas of `criteria` (derived from a study against the strip model);
//! `strip_check` measures it exactly when the strip model is cheap.

use serde::Serialize;

use crate::phrase::Phrase;
use crate::physics::plane::criteria::{
    self, MU_STAR_TOLERANCE, STUDIED_KM, STUDIED_MU, STUDIED_NU, WIDTH_TOLERANCE,
};
use crate::physics::plane::{Model, PlaneSolution, shape_validity};

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

    /// Each deviation over its tolerance (contact width, mu* - mu), dimensionless: both at most 1
    /// where `within_tolerance`.
    pub fn ratios(&self) -> [f64; 2] {
        [
            self.contact_width / WIDTH_TOLERANCE,
            self.mu_star_minus_mu / MU_STAR_TOLERANCE,
        ]
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
    /// The deviation measured against the strip model at the same inputs, where it was
    /// (`strip_check::judged`: then it, not the estimate, decides `ok`); None where not measured.
    pub measured_error: Option<Deviation>,
    /// The criteria of the study the model fails, in words; empty when it holds.
    pub failed_criteria: Vec<String>,
    /// Every warning in a few words, in the order of `warnings`, for the explorer's status
    /// ("Winkler needs (a+b)/h > 312 here, not 8.3"; the form beside it shows nu, mu and k), not
    /// reported by `wearlab solve`, where `warnings` says the same at length.
    #[serde(skip)]
    pub reasons: Vec<Reason>,
}

/// Which tolerance a failed criterion is about: a measurement against the strip model
/// (`StripCheck::Measured`) settles the first two, not the third.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Aspect {
    /// The contact width (2 %).
    ContactWidth,
    /// mu* - mu (5 %).
    MuStarMinusMu,
    /// Both at once (the wide model's limit on (a+b)/h).
    Both,
    /// Inputs outside the study: nothing was estimated.
    Unstudied,
    /// An assumption of every model (small slopes, a contact around the tip, an integrable
    /// pressure): not a comparison with the strip model.
    Assumption,
}

/// A failed criterion in a few words, and what it is about.
#[derive(Clone, Debug, PartialEq)]
pub struct Reason {
    /// What the criterion judges.
    pub aspect: Aspect,
    /// "Winkler needs (a+b)/h > 312 here, not 8.3", its values kept whole.
    pub text: Phrase,
}

/// A criterion of the study the solution fails, with the numbers its words need.
enum Failed {
    /// Not the parabola with the linear laws and no cap: the study's formulas do not apply.
    Unjudged,
    /// Inputs outside the study: which of nu, mu, k m, tau0.
    Outside([bool; 4]),
    /// The wide model beyond its limit on (a+b)/h.
    WideLimit(f64),
    /// The Winkler model's contact width: the (a+b)/h it needs.
    WinklerWidth(f64),
    /// The Winkler model lacks the friction part of mu* - mu.
    WinklerMu,
}

/// An assumption of every model the solution breaks, with its number (the punch shape's own
/// assumptions are `shape_validity`'s).
enum Broken {
    /// theta close to +-1/2.
    Theta(f64),
    /// The parabola's (a+b)/R above 0.1.
    Slopes(f64),
}

/// The inputs the study's criteria are functions of.
struct Studied {
    /// Poisson's ratio nu [-].
    nu: f64,
    /// The friction coefficient mu [-].
    mu: f64,
    /// The wear coefficient times the plane modulus, k m [-].
    km: f64,
}

/// What the study's criteria and the models' assumptions find at a solution, before words.
struct Findings {
    studied: Studied,
    lambda: f64,
    error: Deviation,
    failed: Vec<Failed>,
    broken: Vec<Broken>,
}

fn findings(sol: &PlaneSolution) -> Findings {
    let inputs = &sol.inputs;
    let h = inputs.material.thickness;
    let l = sol.contact_width();
    let lambda = if h.is_finite() { l / h } else { 0.0 };
    let studied = Studied {
        nu: inputs.material.poisson_ratio,
        mu: inputs.friction.coefficient,
        km: inputs.wear.coefficient * inputs.material.plane_modulus(),
    };
    let (error, failed) = match sol.model {
        _ if !h.is_finite() => (Deviation::NONE, Vec::new()),
        Model::Strip => (Deviation::NONE, Vec::new()),
        Model::Wide | Model::Narrow => criteria_of(sol, &studied, lambda),
    };
    let mut broken = Vec::new();
    if let Some(theta) = sol.theta
        && theta.abs() > 0.45
    {
        broken.push(Broken::Theta(theta));
    }
    let l_over_r = l / inputs.radius();
    if inputs.shape.parabola_radius().is_some() && l_over_r > 0.1 {
        broken.push(Broken::Slopes(l_over_r));
    }
    Findings {
        studied,
        lambda,
        error,
        failed,
        broken,
    }
}

/// What decides the verdict at a solution, without its words (for the verdicts along a sweep):
/// whether the study's estimate passes it (`estimate(sol).ok`) and whether the assumptions of
/// every model hold there (no warning of `Aspect::Assumption`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Passes {
    pub ok: bool,
    pub assumptions_hold: bool,
}

/// `estimate` without the words: the same findings.
pub(crate) fn passes(sol: &PlaneSolution) -> Passes {
    let found = findings(sol);
    let assumptions_hold = found.broken.is_empty() && shape_validity::warnings(sol).is_empty();
    Passes {
        ok: found.failed.is_empty() && assumptions_hold,
        assumptions_hold,
    }
}

/// Checks the operating point against the model's assumptions and the study's criteria: the
/// study's estimate of its deviation from the strip model, not measured (`strip_check::judged`
/// measures it where that is cheap).
pub fn estimate(sol: &PlaneSolution) -> Validity {
    let found = findings(sol);
    let (reasons, failed_criteria): (Vec<Reason>, Vec<String>) = found
        .failed
        .iter()
        .map(|f| {
            let (aspect, text, long) = failed_words(sol, &found, f);
            (Reason { aspect, text }, long)
        })
        .unzip();
    let mut warnings = failed_criteria.clone();
    let mut reasons = reasons;
    let mut assumption = |long: String, short: Phrase| {
        warnings.push(long);
        reasons.push(Reason {
            aspect: Aspect::Assumption,
            text: short,
        });
    };
    for broken in &found.broken {
        match *broken {
            Broken::Theta(theta) => {
                let edge = if theta > 0.0 { "trailing" } else { "leading" };
                assumption(
                    format!(
                        "theta = {theta:.3} is close to +-1/2: the pressure is nearly singular at \
                         the {edge} edge"
                    ),
                    Phrase::whole(format!("theta = {theta:.3}")).then_words(&format!(
                        "near +-1/2: pressure nearly singular at the {edge} edge"
                    )),
                );
            }
            Broken::Slopes(l_over_r) => assumption(
                format!(
                    "contact width/radius (a+b)/R = {l_over_r:.3} > 0.1: the punch slopes are not \
                     small"
                ),
                Phrase::whole(format!("(a+b)/R = {l_over_r:.3} > 0.1:"))
                    .then_words("slopes not small"),
            ),
        }
    }
    for (long, short) in shape_validity::warnings(sol) {
        assumption(long, short);
    }
    Validity {
        ok: warnings.is_empty(),
        contact_width_over_thickness: found.lambda,
        warnings,
        estimated_error: found.error,
        measured_error: None,
        failed_criteria,
        reasons,
    }
}

/// The estimated deviation of a wide or narrow solution on a finite strip, and the criteria it
/// fails.
fn criteria_of(sol: &PlaneSolution, studied: &Studied, lambda: f64) -> (Deviation, Vec<Failed>) {
    let inputs = &sol.inputs;
    let &Studied { nu, mu, km } = studied;
    let h_over_r = inputs.material.thickness / inputs.radius();
    if !inputs.is_classical() {
        // the study's formulas are fits to the parabola with the linear law and no cap
        return (Deviation::NONE, vec![Failed::Unjudged]);
    }
    let mut failed = Vec::new();
    let outside = [
        nu > STUDIED_NU,
        mu > STUDIED_MU,
        km > STUDIED_KM,
        inputs.friction.adhesion != 0.0,
    ];
    if outside.contains(&true) {
        failed.push(Failed::Outside(outside));
    }
    let error = if sol.model == Model::Wide {
        let error = Deviation {
            contact_width: criteria::wide_width_error(nu, lambda),
            mu_star_minus_mu: criteria::wide_mu_star_error(nu, lambda).min(100.0),
        };
        let limit = criteria::wide_mu_star_limit(nu)
            .min((WIDTH_TOLERANCE / criteria::wide_width_error(nu, 1.0)).sqrt());
        if lambda > limit {
            failed.push(Failed::WideLimit(limit));
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
        if error.contact_width > WIDTH_TOLERANCE {
            failed.push(Failed::WinklerWidth(criteria::narrow_width_limit(
                nu, mu, km,
            )));
        }
        if error.mu_star_minus_mu > MU_STAR_TOLERANCE {
            failed.push(Failed::WinklerMu);
        }
        error
    };
    (error, failed)
}

/// A failed criterion: what it is about, in a few words and at length.
fn failed_words(
    sol: &PlaneSolution,
    found: &Findings,
    failed: &Failed,
) -> (Aspect, Phrase, String) {
    let inputs = &sol.inputs;
    let Studied { nu, mu, km } = found.studied;
    let (lambda, error) = (found.lambda, &found.error);
    let name = if sol.model == Model::Wide {
        "the wide model"
    } else {
        "the Winkler (narrow) model"
    };
    match failed {
        Failed::Unjudged => {
            let kind = inputs.shape.kind();
            let holds = if sol.model == Model::Wide {
                "where the contact is narrow against the thickness ((a+b)/h small)"
            } else {
                "where the contact is many thicknesses wide ((a+b)/h large)"
            };
            (
                Aspect::Unstudied,
                Phrase::words(&format!("not judged for this punch and laws ({kind})")),
                format!(
                    "{name} is judged against the strip model only for the parabolic punch with \
                     the linear wear law and no shear cap (the validity study); its error for a \
                     {kind} punch with these laws is not estimated: it holds {holds}"
                ),
            )
        }
        Failed::Outside(which) => {
            let outside: Vec<String> = [
                format!("nu = {nu}"),
                format!("mu = {mu}"),
                format!("k m = {km:.3}"),
                format!("tau0 = {:.3e} Pa", inputs.friction.adhesion),
            ]
            .into_iter()
            .zip(which)
            .filter_map(|(what, out)| out.then_some(what))
            .collect();
            (
                Aspect::Unstudied,
                outside
                    .iter()
                    .enumerate()
                    .fold(Phrase::words("not judged at"), |p, (i, what)| {
                        let end = if i + 1 == outside.len() { ":" } else { "," };
                        p.then(format!("{what}{end}"))
                    })
                    .then_words("use the strip model"),
                format!(
                    "{name} is judged against the strip model only where that was studied (nu \
                     <= 0.499, mu <= 1, k m <= 3, no adhesion); here {}: use the strip model",
                    outside.join(", ")
                ),
            )
        }
        Failed::WideLimit(limit) => (
            Aspect::Both,
            Phrase::words("wide needs")
                .then(format!("(a+b)/h < {limit:.2}"))
                .then_words(&format!("here, not {lambda:.3}")),
            format!(
                "the wide model needs (a+b)/h < {limit:.2} at nu = {nu} (contact width within 2 \
                 %, mu* - mu within 5 % of the exact strip solution); here (a+b)/h = \
                 {lambda:.3}, estimated error {}: use the strip model",
                percentages(error)
            ),
        ),
        Failed::WinklerWidth(needed) => (
            Aspect::ContactWidth,
            Phrase::words("Winkler needs")
                .then(format!("(a+b)/h > {needed:.0}"))
                .then_words(&format!("here, not {lambda:.1}")),
            format!(
                "Winkler needs (a+b)/h > {needed:.0} at nu = {nu}, mu = {mu}, k m = {km:.3} for \
                 its contact width within 2 % of the exact strip solution; here (a+b)/h = \
                 {lambda:.3}, estimated error {:.1} %: use the strip model",
                100.0 * error.contact_width
            ),
        ),
        Failed::WinklerMu if km == 0.0 => (
            Aspect::MuStarMinusMu,
            Phrase::words("Winkler lacks the friction part of mu* - mu")
                .then("(mu* = mu without wear)"),
            "without wear the Winkler model gives mu* = mu exactly, while friction alone makes \
             the strip's mu* - mu nonzero: use the strip model"
                .to_string(),
        ),
        Failed::WinklerMu => {
            let part = 100.0 * error.mu_star_minus_mu;
            (
                Aspect::MuStarMinusMu,
                Phrase::words("Winkler lacks the friction part of mu* - mu, estimated up to")
                    .then(format!("{part:.0} %"))
                    .then_words("of it"),
                format!(
                    "the Winkler model lacks the friction-induced part of mu* - mu, estimated \
                     {part:.0} % of what it gives (at most 5 %: wear must dominate): use the \
                     strip model"
                ),
            )
        }
    }
}

/// "1.2 % in contact width, 3.4 % in mu* - mu".
pub(super) fn percentages(d: &Deviation) -> Phrase {
    Phrase::whole(format!("{:.1} %", 100.0 * d.contact_width))
        .then_words("in contact width,")
        .then(format!("{:.1} %", 100.0 * d.mu_star_minus_mu))
        .then_words("in mu* - mu")
}
