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

/// The energy chart's curve (`sweep::energy_sweep`: the wear loss as the integral of q2 F(q2), the
/// friction loss as T less it) against the full route of `energy` (Q1 + I and psi - J, each
/// from the kernels' u' and v') at the same loads: a parabola with wear on a strip (closed form)
/// and the bundled general-solver presets (a measured profile, n = 2, a shear cap).
#[test]
fn the_energy_sweep_agrees_with_the_full_energy_at_its_loads() {
    use wearlab::physics::SweepRange;
    use wearlab::physics::plane::sweep::energy_sweep;
    let m = plane_modulus(1e10, 0.3);
    let mut cases = vec![(
        plane(1e10, 0.3, 1e-2, 0.3, 1e5, 0.5 / m, 0.05, 1e4),
        Model::Wide,
    )];
    for file in [
        "worn-pin-profile.toml",
        "wear-law-squared.toml",
        "polymer-shear-strength.toml",
    ] {
        let p = wearlab::preset::bundled(file).unwrap().unwrap();
        cases.push((p.plane_inputs(), p.plane.model));
    }
    for (inputs, model) in cases {
        let loads = SweepRange {
            min: inputs.load / 4.0,
            max: inputs.load,
            points: 3,
            spacing: wearlab::physics::Spacing::Log,
        };
        let e = energy_sweep(&inputs, model, &loads);
        assert_eq!(e.load.len(), 3);
        for (i, load) in e.load.iter().enumerate() {
            let full = energy(&solve(&inputs.with_load(*load), model).unwrap()).unwrap();
            let (f, w) = (e.friction_share[i].unwrap(), e.wear_share[i].unwrap());
            assert!(
                (f - full.friction_share().unwrap()).abs() < 1e-6
                    && (w - full.wear_share().unwrap()).abs() < 1e-6,
                "{model:?} P = {load}: {f} {w} against {full:?}"
            );
        }
    }
}

#[test]
fn the_energy_identity_holds_where_a_measured_profile_has_knots_inside_the_contact() {
    // worn-pin-profile: a natural cubic spline through a point every 40 um (presets/worn-pin.csv);
    // g'' and so the slope of q2 kink at each knot inside the contact [-0.343, 0.332] mm
    use wearlab::physics::plane::Shape;
    let p = wearlab::preset::bundled("worn-pin-profile.toml")
        .unwrap()
        .unwrap();
    let Some(Shape::Table(table)) = &p.plane.shape else {
        panic!("worn-pin-profile has a table shape");
    };
    let sol = solve(&p.plane_inputs(), p.plane.model).unwrap();
    let inside: Vec<f64> = table
        .spline
        .knots()
        .iter()
        .copied()
        .filter(|x| *x > -sol.a && *x < sol.b)
        .collect();
    assert!(inside.len() >= 10, "{} knots inside", inside.len());
    let en = energy(&sol).unwrap();
    // (2.9): I = J to 1e-6 of the gross work, the bound plane-general.md section 5 sets where q2
    // has interior kinks (observed 7.8e-11, printed below)
    assert!(
        en.residual < 1e-6,
        "I = {} J = {} residual {}",
        en.i,
        en.j,
        en.residual
    );
    assert!(
        (en.external - en.friction_loss - en.wear_loss).abs() <= 1e-6 * en.external,
        "{en:?}"
    );
    // the wear loss psi - J from the kernels against k int q2^2 by a quadrature of this test's
    // own, split at the knots so that each piece is smooth (observed 4.3e-9 of T)
    let mut ends = vec![-sol.a];
    ends.extend(&inside);
    ends.push(sol.b);
    let k = p.plane_inputs().wear.coefficient;
    let direct: f64 = ends
        .windows(2)
        .map(|w| k * integrate_cos(w[0], w[1], 4, |x| sol.pressure(x).powi(2)))
        .sum();
    println!(
        "{} knots inside; I = J to {:.1e}; psi - J against k int q2^2 to {:.1e} of T",
        inside.len(),
        en.residual,
        (en.wear_loss - direct).abs() / en.external
    );
    assert!(
        (en.wear_loss - direct).abs() <= 1e-6 * en.external,
        "psi - J = {} against k int q2^2 = {direct}",
        en.wear_loss
    );
}
