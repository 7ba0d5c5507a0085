//! The energy losses of Soldatenkov (2007) section 2 for every plane model: the external work T
//! splits into the friction loss Q1 + I (2.5) and the wear loss psi - J (2.7), T = sum when
//! I = J (2.9); the wear loss equals the integral of q2 F(q2) = k q2^2 (the contact condition),
//! checked by an independent quadrature of the solved pressure; and on the frictionless half-plane
//! with a vanishing wear rate, the wear loss per unit k tends to Hertz's integral of p^2.

use crate::common;

use std::f64::consts::PI;

use common::{integrate_cos, plane, rel};
use wearlab::physics::elastic::plane_modulus;
use wearlab::physics::plane::energy::energy;
use wearlab::physics::plane::{Model, PlaneInputs, solve};

/// Smooth cases of every model: friction only, wear only, both with adhesion, on a half-plane and
/// on strips in each model's range.
fn cases() -> Vec<(PlaneInputs, Model)> {
    let m = plane_modulus(1e10, 0.3);
    vec![
        (
            plane(1e10, 0.3, f64::INFINITY, 0.3, 0.0, 0.0, 0.05, 1e4),
            Model::Wide,
        ),
        (
            plane(1e10, 0.3, f64::INFINITY, 0.0, 0.0, 0.5 / m, 0.05, 1e4),
            Model::Wide,
        ),
        (
            plane(1e10, 0.3, 1e-2, 0.3, 1e5, 0.5 / m, 0.05, 1e4),
            Model::Wide,
        ),
        (
            plane(1e10, 0.3, 1e-5, 0.3, 1e5, 0.5 / m, 0.05, 1e4),
            Model::Narrow,
        ),
        (
            plane(1e10, 0.3, 1e-5, 0.3, 0.0, 5.0 / m, 0.05, 1e4),
            Model::Narrow,
        ),
        (
            plane(1e10, 0.3, 1e-3, 0.3, 1e5, 0.5 / m, 0.05, 3e4),
            Model::Strip,
        ),
    ]
}

#[test]
fn external_work_is_friction_loss_plus_wear_loss() {
    for (inp, model) in cases() {
        let sol = solve(&inp, model).unwrap();
        let en = energy(&sol).unwrap();
        assert_eq!(en.external, sol.tangential_force);
        let sum = en.friction_loss + en.wear_loss;
        assert!(rel(sum, en.external) < 1e-8, "{model:?}: {en:?}");
        assert!(
            en.friction_loss > 0.0 || inp.friction.coefficient == 0.0,
            "{en:?}"
        );
        assert!(en.wear_loss >= -1e-9 * en.external.abs(), "{en:?}");
    }
}

#[test]
fn wear_loss_is_the_integral_of_k_q2_squared() {
    // psi - J from the model's kernels against k int q2^2 by a quadrature of its own.
    for (inp, model) in cases() {
        let sol = solve(&inp, model).unwrap();
        let en = energy(&sol).unwrap();
        let direct =
            inp.wear.coefficient * integrate_cos(-sol.a, sol.b, 100, |x| sol.pressure(x).powi(2));
        assert!(
            (en.wear_loss - direct).abs() <= 1e-8 * sol.tangential_force,
            "{model:?}: psi - J = {} against k int q2^2 = {direct}",
            en.wear_loss
        );
        assert!(en.contact_residual < 1e-8, "{model:?}: {en:?}");
    }
}

#[test]
fn without_wear_all_the_work_goes_to_friction() {
    let (inp, model) = cases()[0].clone();
    let en = energy(&solve(&inp, model).unwrap()).unwrap();
    assert!(en.wear_loss.abs() < 1e-9 * en.external, "{en:?}");
}

#[test]
fn wear_loss_per_unit_wear_rate_tends_to_hertz() {
    // Hertz's line contact (Johnson, Contact Mechanics, 1985, eq. 4.43-4.45): a = sqrt(4 P R /(pi E*)),
    // p(x) = (2P/(pi a)) sqrt(1 - x^2/a^2), so int p^2 dx = 16 P^2/(3 pi^2 a). With m = pi E*/2 and a
    // wear rate small enough that the pressure is Hertz's to 1e-7, the wear loss per unit k is that
    // integral to O(theta): gamma = -k without friction, theta = arctan(m gamma/pi)/pi, about
    // -1e-7 here (docs/physics/plane.md section 4).
    let (e, nu, r, p) = (1e10, 0.3, 0.05, 1e4);
    let m = plane_modulus(e, nu);
    let k = 1e-6 / m;
    let sol = solve(&plane(e, nu, f64::INFINITY, 0.0, 0.0, k, r, p), Model::Wide).unwrap();
    let e_star = e / (1.0 - nu * nu);
    let a = (4.0 * p * r / (PI * e_star)).sqrt();
    let hertz = 16.0 * p * p / (3.0 * PI * PI * a);
    let en = energy(&sol).unwrap();
    assert!(
        rel(en.wear_loss / k, hertz) < 1e-5,
        "{} vs {hertz}",
        en.wear_loss / k
    );
}
