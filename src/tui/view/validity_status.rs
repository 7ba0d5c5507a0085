//! The validity part of the plane status: whether the shown model holds (the reasons in a few
//! words when it does not), and how far it is from the exact strip model, measured by the engine
//! after the operating point (`plane::validity::StripCheck`). Every word and number comes from
//! the library; this module only lays them out.

use ratatui::text::Line;
use wearlab::physics::plane::OperatingPoint;
use wearlab::physics::plane::validity::StripCheck;

use crate::tui::view::status::prose;
use crate::tui::view::theme::RenderOptions;

/// The validity lines of a plane operating point, wrapped to `width`: the verdict when the model
/// holds, the check against the strip model once it has come (how far off), then the reasons it
/// does not hold and the other warnings (why), each after "! ".
pub fn lines(
    p: &OperatingPoint,
    check: Option<&StripCheck>,
    style: RenderOptions,
    width: usize,
) -> Vec<Line<'static>> {
    let v = &p.validity;
    let model = p.solution.model;
    let mut texts = Vec::new();
    if v.ok {
        texts.push((
            format!(
                "valid: (a+b)/h = {:.3}; {} model holds",
                v.contact_width_over_thickness,
                model.name()
            ),
            style.ok(),
        ));
    }
    // how far off, then why: the failed criteria in a few words, the other warnings
    if let Some(check) = check {
        let off = matches!(check, StripCheck::Measured(d) if !d.within_tolerance());
        let look = if off { style.error() } else { style.ok() };
        texts.push((check.describe(model), look));
    }
    // an estimate the measurement refutes is not shown beside it
    let measured = match check {
        Some(StripCheck::Measured(d)) => Some(d),
        _ => None,
    };
    let reasons = v
        .reasons
        .iter()
        .filter(|r| !measured.is_some_and(|d| r.refuted_by(d)))
        .map(|r| &r.text);
    let others = v.warnings.iter().filter(|w| !v.failed_criteria.contains(w));
    for w in reasons.chain(others) {
        texts.push((format!("! {w}"), style.error()));
    }
    texts
        .into_iter()
        .flat_map(|(text, look)| prose(&text, width, look))
        .collect()
}
