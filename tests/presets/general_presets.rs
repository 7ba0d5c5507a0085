//! The presets of the general plane problem (a measured profile, a wear law with n = 2, a shear
//! cap, the energy split against k) show what their descriptions say: each number of a
//! description is recomputed here from the solver, within the digits the description gives.

use wearlab::physics::plane::energy::energy;
use wearlab::physics::plane::{PlaneSolution, Shape, solve};
use wearlab::preset::{self, Preset};

fn preset(file: &str) -> Preset {
    preset::bundled(file).unwrap().unwrap()
}

fn at(p: &Preset, load: f64) -> PlaneSolution {
    solve(&p.plane_inputs().with_load(load), p.plane.model).unwrap()
}

/// The largest pressure over 2001 points of the contact.
fn peak(s: &PlaneSolution) -> f64 {
    (0..=2000)
        .map(|i| s.pressure(-s.a + (s.a + s.b) * i as f64 / 2000.0))
        .fold(0.0, f64::max)
}

fn near(value: f64, said: f64, within: f64) -> bool {
    (value - said).abs() <= within
}

#[test]
fn the_worn_pin_spreads_the_load_over_its_flattened_tip() {
    let p = preset("worn-pin-profile.toml");
    assert!(matches!(p.plane.shape, Some(Shape::Table(_))));
    let worn = at(&p, 2e4);
    // "[-0.343, 0.332] mm"; "peak pressure 36.4 MPa"
    assert!(near(worn.a, 0.343e-3, 0.5e-6) && near(worn.b, 0.332e-3, 0.5e-6));
    assert!(near(peak(&worn), 36.4e6, 0.05e6), "{}", peak(&worn));
    // "against [-0.279, 0.267] mm under the unworn cylinder ... 46.6 MPa": R = 10 mm, the
    // cylinder the profile's header names
    let mut new = p.clone();
    new.plane.shape = None;
    new.plane.radius = 0.01;
    let new = at(&new, 2e4);
    assert!(near(new.a, 0.279e-3, 0.5e-6) && near(new.b, 0.267e-3, 0.5e-6));
    assert!(near(peak(&new), 46.6e6, 0.05e6), "{}", peak(&new));
    // "0.19 um deep at the tip after one pass": k times the integral of q2 from the tip to b
    let op =
        wearlab::physics::plane::operating_point(&p.plane_inputs(), p.plane.model, 2001).unwrap();
    let tip = op.profile.x.iter().position(|x| *x >= 0.0).unwrap();
    assert!(
        near(op.profile.wear[tip], 0.19e-6, 0.005e-6),
        "{}",
        op.profile.wear[tip]
    );
}

#[test]
fn the_squared_wear_law_tips_the_balance_towards_wear() {
    let p = preset("wear-law-squared.toml");
    assert_eq!((p.wear_exponent, p.reference_pressure), (2.0, Some(2e6)));
    let s = at(&p, p.plane.load);
    // "a = 0.293 mm < b = 0.320 mm", "mu* = 0.3005", "the 10.4 MPa peak", "5 times faster"
    assert!(
        near(s.a, 0.293e-3, 0.5e-6) && near(s.b, 0.320e-3, 0.5e-6),
        "{} {}",
        s.a,
        s.b
    );
    assert!(near(s.mu_star, 0.3005, 0.00005), "{}", s.mu_star);
    let q = peak(&s);
    assert!(near(q, 10.4e6, 0.05e6) && near(q / 2e6, 5.0, 0.3), "{q}");
    // "theta = arctan(chi mu)/pi = 0.022"
    let chi = p.material.chi();
    let theta = (chi * 0.3_f64).atan() / std::f64::consts::PI;
    assert!(near(theta, 0.022, 0.0005) && near(s.theta.unwrap(), theta, 1e-9));
    // the linear law: "a = 0.312 mm > b = 0.298 mm, mu* = 0.2998", theta 0.011
    let mut linear = p.clone();
    linear.wear_exponent = 1.0;
    let l = at(&linear, p.plane.load);
    assert!(
        near(l.a, 0.312e-3, 0.5e-6) && near(l.b, 0.298e-3, 0.5e-6),
        "{} {}",
        l.a,
        l.b
    );
    assert!(near(l.mu_star, 0.2998, 0.00005), "{}", l.mu_star);
    assert!(near(l.theta.unwrap(), 0.011, 0.0005));
}

#[test]
fn the_shear_cap_holds_mu_star_below_mu() {
    let p = preset("polymer-shear-strength.toml");
    assert_eq!(p.shear_strength, 4e6);
    // "at P = 2e4 N/m (peak pressure 27.5 MPa) mu* = 0.180, less than half of mu"
    let s = at(&p, 2e4);
    assert!(near(peak(&s), 27.5e6, 0.05e6) && near(s.mu_star, 0.180, 0.0005));
    assert!(s.mu_star < p.friction.coefficient / 2.0);
    // "mu* = 0.399 at 1e3 N/m, where the peak pressure is 6.2 MPa and nothing is capped"
    let light = at(&p, 1e3);
    assert!(near(light.mu_star, 0.399, 0.0005) && near(peak(&light), 6.2e6, 0.05e6));
    assert!(peak(&light) * p.friction.coefficient < p.shear_strength);
    // "0.248 at 1e4 N/m"
    assert!(near(at(&p, 1e4).mu_star, 0.248, 0.0005));
    // "the shear q1 is flat at 4 MPa over the middle of the contact"
    assert_eq!(s.shear(0.0), 4e6);
}

#[test]
fn the_wear_share_of_the_energy_grows_with_k() {
    let p = preset("energy-split.toml");
    let share = |k: f64| {
        let mut q = p.clone();
        q.wear = k;
        energy(&at(&q, q.plane.load)).unwrap().wear_share().unwrap()
    };
    // "climbs from 3e-5 to 0.24"; "at the preset's k ... (k m = 0.11) it is 6e-4"; "at 1e-9
    // (k m = 5.4) still 0.024"
    assert!(near(share(1e-12), 3e-5, 0.05e-5));
    assert!(near(share(1e-7), 0.24, 0.005));
    let m = p.material.plane_modulus();
    assert!(near(p.wear * m, 0.11, 0.005) && near(share(p.wear), 6e-4, 0.1e-4));
    assert!(near(share(1e-9), 0.024, 0.0005) && near(1e-9 * m, 5.4, 0.05));
    // "k m from 0.005 to 540"
    assert!(near(1e-12 * m, 0.005, 0.0005) && near(1e-7 * m, 540.0, 5.0));
    let mut last = 0.0;
    for i in 0..=10 {
        let s = share(1e-12 * 10f64.powf(i as f64 / 2.0));
        assert!(s > last, "{i}: {s}");
        last = s;
    }
}

#[test]
fn the_sharp_flat_punch_is_singular_at_both_corners() {
    let p = preset("sharp-flat-punch.toml");
    assert!(matches!(
        p.plane.shape,
        Some(Shape::Flat { half_width, edge_radius }) if half_width == 1e-3 && edge_radius == 0.0
    ));
    let s = at(&p, p.plane.load);
    // "theta = 0.011 > 0"; "k m = 0.11"
    assert!(near(s.theta.unwrap(), 0.011, 0.0005), "{:?}", s.theta);
    let m = p.material.plane_modulus();
    assert!(near(p.wear * m, 0.11, 0.005));
    // "3.18 MPa at the middle (0.64 of the mean 5 MPa)"
    let mean = p.plane.load / 2e-3;
    assert!(near(mean, 5e6, 1e-6));
    assert!(
        near(s.pressure(0.0), 3.18e6, 0.005e6),
        "{}",
        s.pressure(0.0)
    );
    assert!(near(s.pressure(0.0) / mean, 0.64, 0.005));
    // "23.9 MPa 10 um from the trailing corner, 21.3 MPa 10 um from the leading one"
    let trailing = s.pressure(-1e-3 + 1e-5);
    let leading = s.pressure(1e-3 - 1e-5);
    assert!(near(trailing, 23.9e6, 0.05e6), "{trailing}");
    assert!(near(leading, 21.3e6, 0.05e6), "{leading}");
    // "infinite at both corners": it grows without bound towards each
    assert!(s.pressure(-1e-3 + 1e-9) > 10.0 * trailing);
    assert!(s.pressure(1e-3 - 1e-9) > 10.0 * leading);
    // "a = b = 1 mm and mu* = mu = 0.3 at every load"; "psi = 0"; "T = Q1 = 3000 N/m"
    for load in [p.plane.sweep.min, p.plane.load, p.plane.sweep.max] {
        let s = at(&p, load);
        assert_eq!((s.a, s.b, s.psi), (1e-3, 1e-3, 0.0));
        assert!(near(s.mu_star, 0.3, 1e-12), "{}", s.mu_star);
    }
    assert!(near(s.tangential_force, 3000.0, 1e-9));
    // "I, J, the friction loss and the wear loss diverge ... T stays finite"
    let undefined = energy(&s).unwrap_err();
    assert!(undefined.note.contains("diverge"), "{}", undefined.note);
    assert!(near(undefined.external, 3000.0, 1e-9));
    // "raise k past pi chi mu/m = 4.05e-11 1/Pa: theta turns negative"
    let threshold = std::f64::consts::PI * p.material.chi() * p.friction.coefficient / m;
    assert!(near(threshold, 4.05e-11, 0.005e-11), "{threshold}");
    let theta = |k: f64| {
        let mut q = p.clone();
        q.wear = k;
        at(&q, q.plane.load).theta.unwrap()
    };
    assert!(theta(0.99 * threshold) > 0.0 && theta(1.01 * threshold) < 0.0);
    let strong = {
        let mut q = p.clone();
        q.wear = 1.01 * threshold;
        at(&q, q.plane.load)
    };
    assert!(strong.pressure(1e-3 - 1e-5) > strong.pressure(-1e-3 + 1e-5));
}
