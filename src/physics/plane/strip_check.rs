//! The shown model measured against the exact strip model at the same inputs, where that is
//! cheap, and the verdict on an operating point once measured (`judged`): a measurement replaces
//! the study's estimates of `validity` (docs/models.md, "Validity").

use crate::phrase::Phrase;
use crate::physics::SolveError;
use crate::physics::plane::criteria::MU_STAR_FLOOR;
use crate::physics::plane::validity::{Aspect, Deviation, Reason, Validity, estimate, percentages};
use crate::physics::plane::{Model, PlaneSolution, solve_strip_to_check};

/// The largest (a+b)/h at which `against_strip` runs the strip model (about 400 nodes, a few
/// milliseconds).
pub const CHEAP_STRIP_WIDTH: f64 = 90.0;

/// The shown model against the exact strip model, for the status.
#[derive(Clone, Debug, PartialEq)]
pub enum StripCheck {
    /// The strip model is shown: it is the exact model, for any (a+b)/h.
    Exact,
    /// The wide model on a half-plane, where it is exact.
    HalfPlane,
    /// Measured against the strip model at the same inputs.
    Measured(Deviation),
    /// A flat punch with sharp corners measured against the strip model: the contact (the face)
    /// and mu* (= mu) are exact in every model, so the pressure is what differs; its largest
    /// relative gap on the middle half of the face (the corners' layers left out).
    Face {
        /// Largest |q2/q2_strip - 1| over |x| <= c/2.
        pressure: f64,
    },
    /// Not measured: why, and the deviation the study's formulas estimate (`Validity`).
    Estimated {
        /// Why the strip model was not run (too wide to be cheap, or it has no answer).
        why: String,
        /// The estimated deviation; None where the study estimates nothing (a punch or laws it
        /// does not cover, inputs outside it).
        estimate: Option<Deviation>,
    },
}

/// The shown solution against the strip model: measured when the strip model is cheap (a contact
/// at most CHEAP_STRIP_WIDTH thicknesses wide), else estimated by the study's formulas.
pub fn strip_check(sol: &PlaneSolution) -> StripCheck {
    measured_with(sol, || solve_strip_to_check(&sol.inputs))
}

/// Whether `strip_check` runs the strip model for this solution (a wide or narrow model on a
/// strip, a contact at most CHEAP_STRIP_WIDTH thicknesses wide).
fn runs_strip(sol: &PlaneSolution) -> bool {
    let h = sol.inputs.material.thickness;
    sol.model != Model::Strip && h.is_finite() && sol.contact_width() / h <= CHEAP_STRIP_WIDTH
}

/// `strip_check` with the strip solution at the same inputs from `strip` (called only where
/// `runs_strip`).
fn measured_with(
    sol: &PlaneSolution,
    strip: impl FnOnce() -> Result<PlaneSolution, SolveError>,
) -> StripCheck {
    let h = sol.inputs.material.thickness;
    let lambda = sol.contact_width() / h;
    let estimated = |why: String| {
        let study = estimate(sol);
        let unstudied = study.reasons.iter().any(|r| r.aspect == Aspect::Unstudied);
        StripCheck::Estimated {
            why,
            estimate: (!unstudied).then_some(study.estimated_error),
        }
    };
    if sol.model == Model::Strip {
        return StripCheck::Exact;
    }
    if !h.is_finite() {
        return StripCheck::HalfPlane;
    }
    if lambda > CHEAP_STRIP_WIDTH {
        return estimated(format!(
            "the exact strip model is not run beyond (a+b)/h = {CHEAP_STRIP_WIDTH:.0}"
        ));
    }
    let strip = match strip() {
        Ok(strip) => strip,
        Err(e) => return estimated(format!("the exact strip model has no answer here: {e}")),
    };
    if sol.inputs.shape.is_sharp() {
        return StripCheck::Face {
            pressure: face_gap(sol, &strip),
        };
    }
    let mu = sol.inputs.friction.coefficient;
    let floor = MU_STAR_FLOOR * strip.contact_width() / sol.inputs.radius();
    StripCheck::Measured(Deviation {
        contact_width: (sol.contact_width() / strip.contact_width() - 1.0).abs(),
        mu_star_minus_mu: (sol.mu_star - strip.mu_star).abs()
            / (strip.mu_star - mu).abs().max(floor),
    })
}

/// The largest relative gap between the pressures of two solutions on the middle half of a face
/// (21 points over |x| <= c/2).
fn face_gap(sol: &PlaneSolution, strip: &PlaneSolution) -> f64 {
    let l = sol.contact_width();
    (0..=20)
        .map(|i| l * (0.25 + 0.025 * i as f64))
        .map(|u| {
            let exact = strip.pressure_from_trailing_edge(u);
            (sol.pressure_from_trailing_edge(u) / exact - 1.0).abs()
        })
        .fold(0.0, f64::max)
}

/// The shown wide or narrow solution against the strip model at the same inputs, measured: None
/// for the strip model itself, a half-plane, a contact wider than CHEAP_STRIP_WIDTH thicknesses,
/// or where the strip model has no answer.
pub fn against_strip(sol: &PlaneSolution) -> Option<Deviation> {
    match strip_check(sol) {
        StripCheck::Measured(deviation) => Some(deviation),
        _ => None,
    }
}

/// A relative deviation in percent, rounded up to 0.1 % (so that "within" stays true).
fn within(x: f64) -> String {
    format!("{:.1} %", (1000.0 * x).ceil() / 10.0)
}

impl StripCheck {
    /// One line for the status: "wide: contact width within 0.1 %, mu* - mu within 0.4 % of the
    /// exact strip solution"; "off by" where a deviation is outside the tolerances.
    pub fn describe(&self, model: Model) -> Phrase {
        let name = format!("{}:", model.name());
        let lead = Phrase::whole(name);
        match self {
            StripCheck::Exact => lead.then_words("the exact model of the bonded strip"),
            StripCheck::HalfPlane => lead.then_words("exact on a half-plane"),
            StripCheck::Measured(d) if d.within_tolerance() => lead
                .then_words("contact width within")
                .then(format!("{},", within(d.contact_width)))
                .then_words("mu* - mu within")
                .then(within(d.mu_star_minus_mu))
                .then_words("of the exact strip solution"),
            StripCheck::Measured(d) => lead
                .then_words("off the exact strip solution by")
                .then_phrase(percentages(d)),
            StripCheck::Estimated {
                why,
                estimate: None,
            } => lead
                .then_words(
                    "not measured against the exact strip solution, nor estimated for these inputs",
                )
                .then_words(&format!("({why})")),
            StripCheck::Estimated {
                why,
                estimate: Some(estimate),
            } if estimate.within_tolerance() => lead
                .then_words("estimated to match the exact strip solution within")
                .then_phrase(percentages(estimate))
                .then_words(&format!("({why})")),
            StripCheck::Face { pressure } => lead
                .then_words("contact and mu* exact at sharp corners, pressure within")
                .then(within(*pressure))
                .then_words("of the exact strip solution (middle half of the face)"),
            StripCheck::Estimated {
                why,
                estimate: Some(estimate),
            } => lead
                .then_words("estimated off by")
                .then_phrase(percentages(estimate))
                .then_words(&format!("({why})")),
        }
    }

    /// The same in at most 46 columns, for a status too small for the long line: "off exact
    /// strip: width 227 %, mu*-mu 12 %" outside the tolerances ("est. off ..." for an estimate),
    /// "within 0.1 % of the exact strip solution" (the larger of the two deviations) inside
    /// them ("est. within ..." for an estimate): an agreement never reads as "off";
    /// "pressure within 2.1 % of the exact strip" for sharp corners. None where `describe` is
    /// the only form.
    pub fn describe_short(&self) -> Option<Phrase> {
        let short = |x: f64| {
            let percent = 100.0 * x;
            if percent >= 10.0 {
                format!("{percent:.0} %")
            } else {
                format!("{percent:.1} %")
            }
        };
        let agreement = |lead: &str, d: &Deviation| {
            let larger = d.contact_width.max(d.mu_star_minus_mu);
            Some(
                Phrase::words(lead)
                    .then(within(larger))
                    .then_words("of the exact strip solution"),
            )
        };
        let (lead, d) = match self {
            StripCheck::Measured(d) if d.within_tolerance() => return agreement("within", d),
            StripCheck::Estimated { estimate: None, .. } => {
                return Some(Phrase::words("not measured against the exact strip"));
            }
            StripCheck::Estimated {
                estimate: Some(estimate),
                ..
            } if estimate.within_tolerance() => {
                return agreement("est. within", estimate);
            }
            StripCheck::Measured(d) if !d.within_tolerance() => ("off exact strip", d),
            StripCheck::Face { pressure } => {
                return Some(
                    Phrase::words("pressure within")
                        .then(within(*pressure))
                        .then_words("of the exact strip"),
                );
            }
            StripCheck::Estimated {
                estimate: Some(estimate),
                ..
            } => ("est. off exact strip", estimate),
            _ => return None,
        };
        Some(
            Phrase::words(&format!("{lead}: width"))
                .then(format!("{},", short(d.contact_width)))
                .then("mu*-mu")
                .then(short(d.mu_star_minus_mu)),
        )
    }
}

/// The verdict on a solution, the same wherever it is given (`wearlab solve`, its sweep, `wearlab
/// sweep`, the explorer): the study's estimate where it says the model holds (the study found no
/// case it passes that the strip model puts outside the tolerances: docs/models.md), else the
/// measurement against the strip model where that is cheap (`judged`), else the estimate. Only
/// the parabola with the linear law and no cap is measured: its strip solve takes milliseconds,
/// the general strip solver's (other shapes and laws) up to seconds.
pub fn verdict(sol: &PlaneSolution) -> Validity {
    let estimated = estimate(sol);
    if !measures(sol, estimated.ok) {
        return estimated;
    }
    judged(&estimated, &strip_check(sol), sol.model)
}

/// Whether `verdict` measures the solution against the strip model: the estimate doubts it
/// (`estimated_ok` false), the inputs are the parabola's with the linear laws, and the strip model
/// is cheap there.
pub(crate) fn measures(sol: &PlaneSolution, estimated_ok: bool) -> bool {
    !estimated_ok && sol.inputs.is_classical() && runs_strip(sol)
}

/// Whether a model measured against the strip model holds: its assumptions (small slopes, ...)
/// hold and the measured deviation is within the tolerances (2 % in contact width, 5 % in
/// mu* - mu: docs/models.md, "Validity").
pub(crate) fn holds_measured(assumptions_hold: bool, d: &Deviation) -> bool {
    assumptions_hold && d.within_tolerance()
}

/// The verdict on an operating point whose model was checked against the strip model (`check`
/// from `strip_check` of the same solution): where it was measured, the measurement replaces the
/// study's estimates (their warnings about the contact width, mu* - mu and inputs outside the
/// study are dropped) and, outside the tolerances, one warning says by how much and that the
/// strip model holds; the assumptions of every model (small slopes, ...) stay. Unmeasured, the
/// estimate is the verdict.
pub fn judged(estimated: &Validity, check: &StripCheck, model: Model) -> Validity {
    let StripCheck::Measured(d) = check else {
        return estimated.clone();
    };
    let kept: Vec<usize> = (estimated.reasons.iter().enumerate())
        .filter(|(_, r)| r.aspect == Aspect::Assumption)
        .map(|(i, _)| i)
        .collect();
    let mut warnings: Vec<String> = kept
        .iter()
        .map(|&i| estimated.warnings[i].clone())
        .collect();
    let mut reasons: Vec<Reason> = kept.iter().map(|&i| estimated.reasons[i].clone()).collect();
    let mut failed_criteria = Vec::new();
    if !d.within_tolerance() {
        let long = format!(
            "the {} model is off the exact strip solution by {} (measured; it holds within 2 % \
             in contact width and 5 % in mu* - mu): use the strip model",
            model.name(),
            percentages(d)
        );
        failed_criteria.push(long.clone());
        warnings.insert(0, long);
        reasons.insert(
            0,
            Reason {
                aspect: Aspect::Both,
                text: Phrase::words("outside the tolerances: use the strip model"),
            },
        );
    }
    Validity {
        ok: holds_measured(kept.is_empty(), d),
        contact_width_over_thickness: estimated.contact_width_over_thickness,
        warnings,
        estimated_error: estimated.estimated_error,
        measured_error: Some(*d),
        failed_criteria,
        reasons,
    }
}
