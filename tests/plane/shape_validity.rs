//! The punch shape's validity messages (physics::plane::shape_validity through
//! validity::estimate): the largest slope over the contact against its bound, and a measured
//! profile too coarse under the contact or too short beyond it.

use std::sync::Arc;

use wearlab::physics::plane::shape::Table;
use wearlab::physics::plane::shape_validity::{END_KNOTS, MIN_KNOTS, SLOPE_BOUND};
use wearlab::physics::plane::spline::Spline;
use wearlab::physics::plane::validity::estimate;
use wearlab::physics::plane::{Model, PlaneSolution, Shape, solve};

use super::plane_general::{laws, plane_inputs};

/// The half-plane under the punch at the load, friction mu and no wear (the wide model).
fn solved(shape: Shape, load: f64, mu: f64) -> PlaneSolution {
    let inputs = plane_inputs(
        shape,
        f64::INFINITY,
        laws(mu, 0.0, f64::INFINITY, 0.0, 1.0),
        load,
    );
    solve(&inputs, Model::Wide).unwrap_or_else(|e| panic!("{e}"))
}

fn warnings(sol: &PlaneSolution) -> Vec<String> {
    estimate(sol).warnings
}

#[test]
fn a_steep_power_punch_is_told_its_largest_slope_on_the_contact() {
    // g' = (|x|/R)^(n-1) sign x grows away from the tip: its largest |g'| is at a contact end
    let (radius, n) = (1e-3, 4.0);
    let sol = solved(
        Shape::Power {
            radius,
            exponent: n,
        },
        3e5,
        0.3,
    );
    let steepest = (sol.a.max(sol.b) / radius).powf(n - 1.0);
    assert!(steepest > SLOPE_BOUND, "{steepest}");
    let said = format!("|g'| = {steepest:.3} at x = ");
    let w = warnings(&sol);
    assert!(
        w.iter()
            .any(|w| w.contains(&said) && w.contains("small slopes")),
        "{said}: {w:?}"
    );
    let gentle = solved(
        Shape::Power {
            radius: 0.05,
            exponent: n,
        },
        1e3,
        0.3,
    );
    assert!(warnings(&gentle).iter().all(|w| !w.contains("|g'|")));
}

/// A table through the parabola x^2/(2R), R = 5 cm, with `points` knots spread over
/// [-half, half] [m].
fn parabola_table(half: f64, points: usize) -> Shape {
    let x: Vec<f64> = (0..points)
        .map(|i| -half + 2.0 * half * i as f64 / (points - 1) as f64)
        .collect();
    let g = x.iter().map(|v| v * v / 0.1).collect();
    Shape::Table(Arc::new(Table {
        file: "p.csv".into(),
        spline: Spline::new(x, g).unwrap(),
    }))
}

#[test]
fn a_measured_profile_too_coarse_or_too_short_for_the_contact_says_so() {
    // without friction the contact is [-L/2, L/2]
    let load = 1e4;
    let reference = solved(Shape::Parabola { radius: 0.05 }, load, 0.0);
    let l = reference.contact_width();
    let shape_warnings = |shape: Shape| -> Vec<String> {
        warnings(&solved(shape, load, 0.0))
            .into_iter()
            .filter(|w| w.contains("p.csv"))
            .collect()
    };
    // 401 points over [-2L, 2L]: some 100 under the contact, 150 beyond each end
    assert_eq!(
        shape_warnings(parabola_table(2.0 * l, 401)),
        Vec::<String>::new()
    );
    // 21 points over [-2L, 2L]: about 5 under the contact
    let coarse = shape_warnings(parabola_table(2.0 * l, 21));
    assert!(
        coarse.len() == 1 && coarse[0].contains(&format!("fewer than {MIN_KNOTS}")),
        "{coarse:?}"
    );
    // 201 points over [-0.52 L, 0.52 L], spaced 0.0052 L: 4 beyond each end, enough; the
    // contact nearly fills the profile, which the first guess of the width finds by marching
    // within the profile
    assert_eq!(
        shape_warnings(parabola_table(0.52 * l, 201)),
        Vec::<String>::new()
    );
    // 31 points over [-0.6 L, 0.6 L], spaced 0.04 L: 3 beyond each end of the contact
    let short = shape_warnings(parabola_table(0.6 * l, 31));
    assert!(
        short.len() == 1 && short[0].contains(&format!("fewer than {END_KNOTS}")),
        "{short:?}"
    );
}
