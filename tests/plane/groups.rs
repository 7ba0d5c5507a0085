//! The dimensionless groups of the explorer's dimensionless view (`sweeps::groups`) against
//! classical closed forms at points of their own.

use crate::common;

use std::f64::consts::PI;

use common::{cosine, layer, plane, rel, spatial};
use wearlab::physics::plane::validity::estimate;
use wearlab::physics::plane::{Model, solve};
use wearlab::sweeps::groups::{self, Group};

fn value(groups: &[Group], name: &str) -> f64 {
    groups.iter().find(|g| g.name == name).unwrap().value
}

#[test]
fn hertz_width_and_load_groups() {
    // Johnson, Contact Mechanics (1985) eq. 4.45: a = sqrt(4 R P/(pi E*)), E* = E/(1 - nu^2); the
    // plane modulus m = pi E*/2 (Soldatenkov (2007), after eq. (3.1)), so (a+b)/R = 2a/R = sqrt(8 P/(m R))
    let (e, nu, r, p) = (2.1e11, 0.3, 0.05, 1e4);
    let sol = solve(
        &plane(e, nu, f64::INFINITY, 0.0, 0.0, 0.0, r, p),
        Model::Wide,
    )
    .unwrap();
    let g = groups::plane(&sol, &estimate(&sol));
    let e_star = e / (1.0 - nu * nu);
    let a = (4.0 * r * p / (PI * e_star)).sqrt();
    let load_number = p / (PI * e_star / 2.0 * r);
    assert!(rel(value(&g, "width_over_radius"), 2.0 * a / r) < 1e-13);
    assert!(rel(value(&g, "load_number"), load_number) < 1e-14);
    assert!(rel(value(&g, "width_over_radius"), (8.0 * load_number).sqrt()) < 1e-13);
    // a half-plane: (a+b)/h = 0; no friction or wear: k m = mu chi = theta = mu* = mu* - mu = 0
    for name in [
        "validity.contact_width_over_thickness",
        "wear_number",
        "friction_number",
        "theta",
        "mu_star",
        "mu_star_minus_mu",
    ] {
        assert_eq!(value(&g, name), 0.0, "{name}");
    }
    let symbols: Vec<&str> = g.iter().map(|g| g.symbol).collect();
    assert_eq!(
        symbols,
        [
            "(a+b)/h", "(a+b)/R", "P/(m R)", "k m", "mu chi", "theta", "mu*", "mu*-mu"
        ]
    );
}

#[test]
fn theta_vanishes_where_friction_and_wear_groups_balance() {
    // (4.3), (4.5): tan(pi theta) = m gamma/pi = mu chi - k m/pi; chi = (1 - 2 nu)/(2(1 - nu))
    // and m = pi E/(2(1 - nu^2)) written out here
    let (e, nu, mu, r, p, h) = (3e9, 0.35, 0.4, 0.01, 1e3, 2e-3);
    let chi = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));
    let m = PI * e / (2.0 * (1.0 - nu * nu));
    for k in [
        0.0,
        0.5 * PI * mu * chi / m,
        PI * mu * chi / m,
        3.0 * PI * mu * chi / m,
    ] {
        let sol = solve(&plane(e, nu, h, mu, 0.0, k, r, p), Model::Wide).unwrap();
        let g = groups::plane(&sol, &estimate(&sol));
        assert!(rel(value(&g, "wear_number"), k * m) < 1e-14 || k == 0.0);
        assert!(rel(value(&g, "friction_number"), mu * chi) < 1e-14);
        let tan = (PI * value(&g, "theta")).tan();
        assert!((tan - (mu * chi - k * m / PI)).abs() < 1e-12, "k = {k}");
        // (a+b)/h is the contact width over the thickness
        let width = value(&g, "validity.contact_width_over_thickness");
        assert!(rel(width, sol.contact_width() / h) < 1e-14);
    }
}

#[test]
fn harmonic_groups_of_a_frictionless_wavy_half_space_and_layer() {
    // Johnson, Contact Mechanics (1985) sec. 13.2: a wavy surface Delta cos(2 pi x/l) pressed flat
    // on a half-space needs the pressure amplitude p* = pi E* Delta/l; without friction the wear
    // decays the wave at beta = k V (p*/Delta) (docs/physics/spatial.md: beta = k V A_c/M^2, M = A_c)
    let (e, nu, delta, l, k, pbar, t) = (1e9, 0.3, 1e-6, 1e-3, 1e-12, 2e6, 50.0);
    let e_star = e / (1.0 - nu * nu);
    let p_star = PI * e_star * delta / l;
    let inputs = spatial(
        layer(e, nu, f64::INFINITY),
        0.0,
        0.0,
        k,
        pbar,
        vec![cosine(delta, l)],
    );
    let sol = wearlab::physics::spatial::solve(&inputs, t).unwrap();
    let g = groups::harmonic(&sol, &sol.harmonics[0]);
    let beta = k * p_star / delta;
    assert!(rel(value(&g, "harmonics.N.decay_exponent"), beta * t) < 1e-12);
    // at t the amplitude is Delta e^(-beta t), so the pressure ratio is p* e^(-beta t)/pbar
    let ratio = p_star * (-beta * t).exp() / pbar;
    assert!(rel(value(&g, "harmonics.N.pressure_ratio"), ratio) < 1e-12);
    let whole = groups::spatial(&sol);
    assert!(rel(value(&whole, "pressure_ratio_sum"), ratio) < 1e-12);
    // no friction: no deformation part of friction, mu* - mu = 0
    assert_eq!(value(&whole, "mu_star_minus_mu"), 0.0);
    // no friction: the pressure is in phase with the shape
    assert_eq!(value(&g, "harmonics.N.phase_lead"), 0.0);
    assert_eq!(value(&g, "harmonics.N.kh"), f64::INFINITY);
    // on a layer 0.2 mm thick: kh = 2 pi h/l
    let inputs = spatial(
        layer(e, nu, 2e-4),
        0.0,
        0.0,
        k,
        pbar,
        vec![cosine(delta, l)],
    );
    let sol = wearlab::physics::spatial::solve(&inputs, t).unwrap();
    let g = groups::harmonic(&sol, &sol.harmonics[0]);
    assert!(rel(value(&g, "harmonics.N.kh"), 2.0 * PI * 2e-4 / l) < 1e-14);
}
