//! The stresses beneath a sliding line contact (src/physics/plane/yield_onset.rs) against the
//! closed forms of a Hertz line contact in Johnson (1985): on the axis of a frictionless contact
//! (section 4.2), on the surface of one with sliding friction (section 7.1), and the largest von
//! Mises stress of a frictionless contact against the axis closed form's maximum and Johnson's
//! "first yield at p0 = 3.1 k".

use crate::common;

use std::f64::consts::PI;

use common::{plane, rel};
use wearlab::physics::plane::yield_onset::{NotJudged, Stress, peak, stress};
use wearlab::physics::plane::{Model, PlaneSolution, Shape, solve};

const E: f64 = 1e10;
const R: f64 = 0.05;
const P: f64 = 1e4;
/// Nearly 1/2 (the solvers take nu < 1/2): chi = 1e-9 shifts the pressure by mu chi ~ 1e-9.
const INCOMPRESSIBLE: f64 = 0.5 - 5e-10;

/// The wide model on a half-plane without wear: Hertz's pressure p0 sqrt(1 - x^2/a^2) (with
/// nu -> 1/2 also under friction: chi -> 0 uncouples the shear from the pressure).
fn hertz(nu: f64, mu: f64) -> (PlaneSolution, f64, f64) {
    let sol = solve(
        &plane(E, nu, f64::INFINITY, mu, 0.0, 0.0, R, P),
        Model::Wide,
    )
    .unwrap();
    // Johnson (1985) eqs 4.43-4.45: a^2 = 4 P R/(pi E*), p0 = 2 P/(pi a), E* = E/(1 - nu^2)
    let a = (4.0 * P * R * (1.0 - nu * nu) / (PI * E)).sqrt();
    (sol, a, 2.0 * P / (PI * a))
}

/// Johnson (1985) section 4.2: on the axis x = 0 of a frictionless line contact,
/// sx = -(p0/a) [(a^2 + 2 z^2)/sqrt(a^2 + z^2) - 2 z], sz = -p0 a/sqrt(a^2 + z^2), txz = 0.
fn axis(a: f64, p0: f64, z: f64) -> Stress {
    let r = (a * a + z * z).sqrt();
    Stress {
        sx: -p0 / a * ((a * a + 2.0 * z * z) / r - 2.0 * z),
        sz: -p0 * a / r,
        txz: 0.0,
    }
}

#[test]
fn stresses_on_the_axis_of_a_frictionless_contact_are_johnsons() {
    let (sol, a, p0) = hertz(0.3, 0.0);
    assert!(rel(sol.a, a) < 1e-9, "a = {} against {a}", sol.a);
    for z in [0.05, 0.3, 0.78, 1.5, 4.0].map(|f| f * a) {
        let (s, want) = (stress(&sol, 0.0, z), axis(a, p0, z));
        for (got, want) in [(s.sx, want.sx), (s.sz, want.sz), (s.txz, want.txz)] {
            assert!(
                (got - want).abs() < 1e-6 * p0,
                "z = {z}: {s:?} against {want:?}"
            );
        }
    }
    // the principal shear (sz - sx)/2 on the axis peaks at 0.30 p0 at z = 0.78 a (Johnson
    // (1985) section 4.2)
    let tau = |z: f64| {
        let s = stress(&sol, 0.0, z);
        0.5 * (s.sx - s.sz).abs()
    };
    let best = (1..200)
        .map(|i| i as f64 * 0.01 * a)
        .max_by(|x, y| tau(*x).total_cmp(&tau(*y)));
    let z = best.unwrap();
    assert!((z / a - 0.78).abs() < 0.015, "z = {} a", z / a);
    assert!((tau(z) / p0 - 0.30).abs() < 0.005, "{}", tau(z) / p0);
}

#[test]
fn surface_stresses_under_sliding_friction_are_johnsons() {
    // Johnson (1985) section 7.1, q = mu p on a Hertz pressure: on the surface
    // sx = -p0 [sqrt(1 - x^2/a^2) + 2 mu x/a] within the contact, and
    // sx = -2 mu p0 [x/a - sign(x) sqrt(x^2/a^2 - 1)] beyond it: a tension 2 mu p0 at the
    // trailing edge x = -a
    let mu = 0.3;
    // the solution's own a (Hertz's to 1e-9, checked above): the surface stress has a square-root
    // cusp at the edge, where 1e-10 of a moves it by 1e-5 p0
    let (sol, _, _) = hertz(INCOMPRESSIBLE, mu);
    let (a, p0) = (sol.a, 2.0 * P / (PI * sol.a));
    let closed = |x: f64| {
        let u = x / a;
        if u.abs() < 1.0 {
            -p0 * ((1.0 - u * u).sqrt() + 2.0 * mu * u)
        } else {
            -2.0 * mu * p0 * (u - u.signum() * (u * u - 1.0).sqrt())
        }
    };
    for u in [-1.6, -0.999, -0.5, 0.0, 0.37, 0.9, 0.999, 1.3] {
        let s = stress(&sol, u * a, 0.0);
        assert!(
            (s.sx - closed(u * a)).abs() < 1e-5 * p0,
            "x = {u} a: {s:?} against {}, b - a = {}",
            closed(u * a),
            sol.b - sol.a
        );
    }
    // at the edges themselves: the solver's a and b differ by ~4e-10 a, and the cusp turns that
    // into ~sqrt(8e-10) 2 mu p0 ~ 2e-5 p0
    let (trailing, leading) = (stress(&sol, -sol.a, 0.0).sx, stress(&sol, sol.b, 0.0).sx);
    assert!((trailing - 2.0 * mu * p0).abs() < 1e-4 * p0, "{trailing}");
    assert!((leading + 2.0 * mu * p0).abs() < 1e-4 * p0, "{leading}");
}

#[test]
fn the_largest_von_mises_stress_of_a_frictionless_contact_is_on_its_axis() {
    let nu = 0.3;
    let (sol, a, p0) = hertz(nu, 0.0);
    let found = peak(&sol).unwrap();
    // the closed form's maximum on the axis, by a fine scan
    let on_axis = (1..4000)
        .map(|i| i as f64 * 5e-4 * a)
        .map(|z| (axis(a, p0, z).von_mises(nu), z))
        .max_by(|x, y| x.0.total_cmp(&y.0))
        .unwrap();
    assert!(
        rel(found.stress, on_axis.0) < 1e-5,
        "{found:?} against {on_axis:?}"
    );
    assert!(found.x.abs() < 1e-3 * a, "{found:?}");
    assert!((found.depth - on_axis.1).abs() < 0.01 * a, "{found:?}");
    // Johnson (1985) section 4.2: first yield (von Mises) at p0 = 3.1 k, k = Y/sqrt(3), so the
    // largest von Mises stress is sqrt(3)/3.1 p0 = 0.559 p0 (rounded to two figures there)
    assert!(
        (found.stress / p0 - 3f64.sqrt() / 3.1).abs() < 0.01,
        "{}",
        found.stress / p0
    );
}

#[test]
fn with_strong_friction_the_largest_stress_is_at_the_trailing_edge_on_the_surface() {
    // Johnson (1985) section 7.2: from mu of about 0.3 the surface yields first, at the
    // trailing edge where the tension is 2 mu p0
    let (sol, a, p0) = hertz(INCOMPRESSIBLE, 0.5);
    let found = peak(&sol).unwrap();
    assert!(found.depth < 0.02 * a, "{found:?}");
    assert!((found.x + a).abs() < 0.05 * a, "{found:?}");
    // at the edge itself sz = txz = 0, sx = 2 mu p0, sy = nu sx: von Mises sx sqrt(1 - nu + nu^2)
    let edge = 2.0 * 0.5 * p0 * (1.0 - 0.5 + 0.25f64).sqrt();
    assert!(
        found.stress >= edge * (1.0 - 1e-6),
        "{found:?} against {edge}"
    );
}

#[test]
fn sharp_corners_and_thin_layers_are_not_judged() {
    let mut sharp = plane(E, 0.3, f64::INFINITY, 0.3, 0.0, 0.0, R, P);
    sharp.shape = Shape::Flat {
        half_width: 1e-3,
        edge_radius: 0.0,
    };
    let sol = solve(&sharp, Model::Wide).unwrap();
    assert_eq!(peak(&sol), Err(NotJudged::SharpCorners));
    let thin = plane(E, 0.3, 1e-5, 0.3, 0.0, 1e-11, R, P);
    let sol = solve(&thin, Model::Narrow).unwrap();
    assert_eq!(peak(&sol), Err(NotJudged::ThinLayer));
}

#[test]
fn a_peak_below_the_layer_is_not_judged() {
    use wearlab::physics::plane::yield_onset::{Strength, judge};
    let y = Strength {
        yield_strength: Some(1e8),
        hardness: None,
    };
    // frictionless, so that the largest stress lies beneath the surface: on a half-plane at
    // about 0.70 a (`the_largest_von_mises_stress_of_a_frictionless_contact_is_on_its_axis`);
    // a = 0.24 mm here (Johnson (1985) eq. 4.43)
    let (_, a, _) = hertz(0.3, 0.0);
    for (h, below) in [(0.1 * a, true), (0.3 * a, true), (10.0 * a, false)] {
        let sol = solve(&plane(E, 0.3, h, 0.0, 0.0, 0.0, R, P), Model::Strip).unwrap();
        let found = peak(&sol).unwrap();
        let check = judge(&sol, y).unwrap();
        assert_eq!(found.depth > h, below, "h = {h}: {found:?}");
        if below {
            assert_eq!(
                check.note,
                Some(NotJudged::BelowLayer {
                    depth: found.depth,
                    thickness: h
                })
            );
            assert_eq!(
                (check.yields, check.ratio, check.von_mises_max),
                (None, None, None)
            );
            let words = check.describe();
            assert!(
                words
                    .starts_with("yield not judged: the peak stress of a half-plane lies at depth")
                    && words.contains("below the layer (h = "),
                "{words}"
            );
        } else {
            assert_eq!(check.note, None);
            assert_eq!(check.depth, Some(found.depth));
        }
    }
}
