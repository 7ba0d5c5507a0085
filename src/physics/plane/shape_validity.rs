//! The punch shape's own assumptions judged on a solved contact [-a, b], for `validity::estimate`:
//! small slopes over the contact (every model is linear elasticity with the boundary conditions
//! put on the undeformed, flat surface: |g'| << 1), and for a measured profile enough knots under
//! the contact and enough beyond it (docs/physics/plane-general.md section 1).

use crate::phrase::Phrase;
use crate::physics::limits::show;
use crate::physics::plane::shape::Shape;
use crate::physics::plane::{PlaneSolution, spline::Spline};

/// The largest slope |g'| (dimensionless) over the contact that counts as small: 0.05, the
/// parabola's (a+b)/R = 0.1 (its largest slope is about half (a+b)/R).
pub const SLOPE_BOUND: f64 = 0.05;
/// Fewest knots of a measured profile strictly inside the contact: with fewer the knot spacing
/// exceeds a tenth of the contact width, and the curvature g'' that the pressure follows is, over
/// most of the contact, the spline's interpolation between the points rather than the
/// measurement.
pub const MIN_KNOTS: usize = 10;
/// Fewest knots of a measured profile beyond each end of the contact: the natural spline's
/// g'' = 0 at the profile's ends reaches into it by a factor 2 - sqrt 3 = 0.27 per knot (Press et
/// al., Numerical Recipes, section 3.3), so 4 knots leave 0.5 % of it at the contact.
pub const END_KNOTS: usize = 4;
/// Points at which the slope is sampled over the contact, besides its ends and the knots.
const SLOPE_SAMPLES: usize = 400;

/// The warnings about the punch shape at the solution: each at length and in a few words. The
/// parabola's slope is judged by (a+b)/R in `validity`; sharp corners have g' = 0 on the face.
pub(crate) fn warnings(sol: &PlaneSolution) -> Vec<(String, Phrase)> {
    let shape = &sol.inputs.shape;
    let mut out = Vec::new();
    if shape.parabola_radius().is_some() || shape.is_sharp() {
        return out;
    }
    let (slope, at) = steepest(shape, -sol.a, sol.b);
    if slope > SLOPE_BOUND {
        out.push((
            format!(
                "the punch slope reaches |g'| = {slope:.3} at x = {} m on the contact, above \
                 {SLOPE_BOUND}: every model is linear elasticity with small slopes |g'| << 1 (the \
                 contact conditions put on the flat, undeformed surface), which the punch does \
                 not have here",
                show(at)
            ),
            Phrase::whole(format!("|g'| = {slope:.3} > {SLOPE_BOUND}:"))
                .then_words("slopes not small"),
        ));
    }
    if let Shape::Table(table) = shape {
        out.extend(knots(&table.spline, &table.file, -sol.a, sol.b));
    }
    out
}

/// The largest |g'| on [lo, hi] and where: at the ends, the shape's kinks and knots inside, and
/// `SLOPE_SAMPLES` points between.
fn steepest(shape: &Shape, lo: f64, hi: f64) -> (f64, f64) {
    let mut xs: Vec<f64> = (0..=SLOPE_SAMPLES)
        .map(|i| lo + (hi - lo) * i as f64 / SLOPE_SAMPLES as f64)
        .collect();
    xs.extend(shape.kinks());
    if let Shape::Table(t) = shape {
        xs.extend(t.spline.knots());
    }
    xs.into_iter()
        .filter(|x| (lo..=hi).contains(x))
        .map(|x| (shape.slope(x).abs(), x))
        .fold((0.0, 0.0), |best, s| if s.0 > best.0 { s } else { best })
}

/// A measured profile too coarse under the contact [lo, hi], or too short beyond it.
fn knots(spline: &Spline, file: &str, lo: f64, hi: f64) -> Vec<(String, Phrase)> {
    let x = spline.knots();
    let inside = x.iter().filter(|&&k| k > lo && k < hi).count();
    let (before, after) = (
        x.iter().filter(|&&k| k < lo).count(),
        x.iter().filter(|&&k| k > hi).count(),
    );
    let mut out = Vec::new();
    if inside < MIN_KNOTS {
        out.push((
            format!(
                "the contact [{}, {}] m holds {inside} of the points of {file}, fewer than \
                 {MIN_KNOTS}: the pressure follows the profile's curvature, which between so few \
                 points is the spline's interpolation, not the measurement; give a finer profile",
                show(lo),
                show(hi)
            ),
            Phrase::words(&format!(
                "profile too coarse: {inside} points under the contact"
            )),
        ));
    }
    let margin = before.min(after);
    if margin < END_KNOTS {
        let end = if before <= after { "first" } else { "last" };
        out.push((
            format!(
                "the contact [{}, {}] m ends {margin} point(s) from the {end} point of {file}, \
                 fewer than {END_KNOTS}: the spline's zero curvature at the profile's ends \
                 reaches the contact (a factor 0.27 per point); give a profile that extends \
                 further",
                show(lo),
                show(hi)
            ),
            Phrase::words(&format!(
                "profile too short: contact {margin} points from its end"
            )),
        ));
    }
    out
}
