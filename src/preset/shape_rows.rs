//! The punch shape as parameters of the registry (`params::PARAMS`): the kind as a choice
//! (`plane.shape.kind`), each kind's numbers (`plane.radius` for the parabola,
//! `plane.shape.radius` and `plane.shape.exponent` for the power punch, `plane.shape.half_width`
//! and `plane.shape.edge_radius` for the flat one), and a measured profile's file and x range,
//! which are read from the preset's folder and cannot be set. A number belongs to one kind: for
//! another it reads 0 and is not offered (`applies`).

use std::sync::Arc;

use crate::physics::limits;
use crate::physics::plane::Shape;
use crate::preset::Preset;
use crate::units::format_si;

/// The kinds, as `plane.shape.kind` names them.
pub(super) const KINDS: &[&str] = &["parabola", "power", "flat", "table"];

/// The kind of the preset's punch, as an index into `KINDS`.
pub(super) fn kind(p: &Preset) -> usize {
    let name = p.plane.shape.as_ref().map_or("parabola", Shape::kind);
    KINDS.iter().position(|k| *k == name).unwrap_or(0)
}

/// The radius of the parabola that stands in for the current punch when the kind changes: the
/// parabola's and the power punch's R, the flat's edge radius, a measured profile's
/// `table_radius` (the parabola's radius when the flat's corners are sharp, or when the profile
/// does not rise at its ends).
fn stand_in_radius(p: &Preset) -> f64 {
    match &p.plane.shape {
        Some(Shape::Power { radius, .. }) => *radius,
        Some(Shape::Flat { edge_radius, .. }) if *edge_radius > 0.0 => *edge_radius,
        Some(table @ Shape::Table(_)) => table_radius(table).unwrap_or(p.plane.radius),
        _ => p.plane.radius,
    }
}

/// The radius [m] of the parabola g = x^2/(2R) through a measured profile's two ends (R =
/// x^2/(2 g(x)) at each, averaged; within `limits::RADIUS`): the profile's size, which its tip
/// alone (worn flat, say) does not give, and not the preset's parabola radius, which a table
/// leaves unused at its default. None when the profile does not rise at both ends.
fn table_radius(table: &Shape) -> Option<f64> {
    let (lo, hi) = table.range()?;
    let at = |x: f64| {
        let g = table.g(x);
        (g > 0.0).then(|| x * x / (2.0 * g))
    };
    let r = 0.5 * (at(lo)? + at(hi)?);
    Some(r.clamp(limits::RADIUS.min, limits::RADIUS.max))
}

/// Changes the punch's kind, keeping its size: the power punch starts at n = 2 (the same
/// parabola), the flat one has the stand-in parabola's radius at its edges and a face half as
/// wide as that parabola's contact on a half-plane at the preset's load (Hertz: a = sqrt(2 P R/m)),
/// so that the face and the rounded edges both carry load; back to a measured profile only when
/// the preset was opened with one.
pub(super) fn set_kind(p: &mut Preset, index: usize) -> Result<(), String> {
    if index == kind(p) {
        return Ok(());
    }
    let radius = stand_in_radius(p);
    let hertz = (2.0 * p.plane.load * radius / p.material.plane_modulus()).sqrt();
    let shape = match KINDS[index] {
        "parabola" => {
            p.plane.radius = radius;
            None
        }
        "power" => Some(Shape::Power {
            radius,
            exponent: 2.0,
        }),
        "flat" => Some(Shape::Flat {
            half_width: (hertz / 2.0).clamp(limits::HALF_WIDTH.min, limits::HALF_WIDTH.max),
            edge_radius: radius,
        }),
        _ => match &p.plane.measured {
            Some(table) => Some(Shape::Table(Arc::clone(table))),
            None => {
                return Err(
                    "plane.shape.kind = table needs a measured profile, which only a preset file \
                     gives: plane.shape = { kind = \"table\", file = \"profile.csv\" } (columns \
                     x [m],g [m], beside the preset)"
                        .into(),
                );
            }
        },
    };
    p.plane.shape = shape;
    Ok(())
}

/// The parameters of one kind of shape (`plane.shape.*`, and `plane.radius` for the parabola).
fn kind_of(key: &str) -> Option<&'static str> {
    match key {
        "plane.radius" => Some("parabola"),
        "plane.shape.radius" | "plane.shape.exponent" => Some("power"),
        "plane.shape.half_width" | "plane.shape.edge_radius" => Some("flat"),
        "plane.shape.file" | "plane.shape.range" => Some("table"),
        _ => None,
    }
}

/// Ok when the parameter `key` belongs to the preset's punch (or to no shape); else why not.
pub(super) fn applies(p: &Preset, key: &str) -> Result<(), String> {
    let now = KINDS[kind(p)];
    match kind_of(key) {
        Some(k) if k != now => Err(format!(
            "{key} belongs to a {k} punch; this preset's punch is a {now} shape (set \
             plane.shape.kind = {k} first)"
        )),
        _ => Ok(()),
    }
}

/// The power punch's R and n, the flat's c and r, read (0 for another kind).
pub(super) fn power_radius(p: &Preset) -> f64 {
    match &p.plane.shape {
        Some(Shape::Power { radius, .. }) => *radius,
        _ => 0.0,
    }
}

pub(super) fn power_exponent(p: &Preset) -> f64 {
    match &p.plane.shape {
        Some(Shape::Power { exponent, .. }) => *exponent,
        _ => 0.0,
    }
}

pub(super) fn half_width(p: &Preset) -> f64 {
    match &p.plane.shape {
        Some(Shape::Flat { half_width, .. }) => *half_width,
        _ => 0.0,
    }
}

pub(super) fn edge_radius(p: &Preset) -> f64 {
    match &p.plane.shape {
        Some(Shape::Flat { edge_radius, .. }) => *edge_radius,
        _ => 0.0,
    }
}

/// Writes the power punch's R and n, the flat's c and r (nothing for another kind).
pub(super) fn set_power_radius(p: &mut Preset, v: f64) {
    if let Some(Shape::Power { radius, .. }) = &mut p.plane.shape {
        *radius = v;
    }
}

pub(super) fn set_power_exponent(p: &mut Preset, v: f64) {
    if let Some(Shape::Power { exponent, .. }) = &mut p.plane.shape {
        *exponent = v;
    }
}

pub(super) fn set_half_width(p: &mut Preset, v: f64) {
    if let Some(Shape::Flat { half_width, .. }) = &mut p.plane.shape {
        *half_width = v;
    }
}

pub(super) fn set_edge_radius(p: &mut Preset, v: f64) {
    if let Some(Shape::Flat { edge_radius, .. }) = &mut p.plane.shape {
        *edge_radius = v;
    }
}

/// A measured profile's file, as the preset names it ("" for another kind).
pub(super) fn file(p: &Preset) -> String {
    match &p.plane.shape {
        Some(Shape::Table(t)) => t.file.clone(),
        _ => String::new(),
    }
}

/// A measured profile's x range, "-2.00 .. 2.00 mm", the unit written once where both ends
/// share it, so that the row fits the form ("" for another kind).
pub(super) fn range(p: &Preset) -> String {
    let Some((lo, hi)) = p.plane.shape.as_ref().and_then(Shape::range) else {
        return String::new();
    };
    let (lo, hi) = (format_si(lo, "m"), format_si(hi, "m"));
    match (lo.rsplit_once(' '), hi.rsplit_once(' ')) {
        (Some((number, unit)), Some((_, same))) if unit == same => format!("{number} .. {hi}"),
        _ => format!("{lo} .. {hi}"),
    }
}
