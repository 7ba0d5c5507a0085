//! mu > 0 on the 1-D half-plane (docs/physics/spatial-partial.md section 6, route 6): the FFT
//! active-set solver against the singular integral equation of `sie_reference.rs`, which shares
//! none of the solver's code. `cargo run --release --example sie_convergence` prints the FFT
//! solver's convergence in N against it.

use std::f64::consts::PI;

use crate::sie_reference::{Sie, fft, solve_sie, wave};
use wearlab::physics::quadrature::tanh_sinh;

#[test]
fn frictionless_collocation_reproduces_westergaard() {
    // mu = 0: alpha = beta = 1/2, and pbar/p* = sin^2(pi a/l) (docs/physics/spatial-partial.md
    // section 6, route 2), p(0) = 2 pbar/sin(pi a/l): the collocation itself is right.
    let wv = wave(0.0);
    let e = 0.2 * wv.l;
    let sie = solve_sie(&wv, e, 40);
    let e_star = 2.0 * wv.g * (1.0 + wv.nu) / (1.0 - wv.nu * wv.nu);
    let p_star = PI * e_star * wv.delta / wv.l;
    let s = (PI * e / wv.l).sin();
    assert!(sie.c.abs() < 1e-15 * wv.l, "symmetric: c = {}", sie.c);
    assert!(
        (sie.pbar / p_star - s * s).abs() < 1e-13,
        "{}",
        sie.pbar / p_star
    );
    assert!((sie.pressure(0.0) / (2.0 * sie.pbar / s) - 1.0).abs() < 1e-12);
}

#[test]
fn friction_on_the_half_plane_against_the_singular_integral_equation() {
    let wv = wave(0.5);
    let e = 0.2 * wv.l;
    let sie = solve_sie(&wv, e, 40);
    let [fraction, p_max, psi, mean_gap, closure] = sie.outputs(&wv);
    // the SIE is converged in N (40 against 30 nodes) and its gap closes over the gap region
    let coarse = solve_sie(&wv, e, 30).outputs(&wv);
    for (a, b) in [(p_max, coarse[1]), (psi, coarse[2]), (mean_gap, coarse[3])] {
        assert!((a / b - 1.0).abs() < 1e-9, "{a} vs {b}");
    }
    assert!(closure.abs() < 1e-12 * mean_gap, "{closure}");
    // friction with B > 0 (section 1.2): the contact moves backwards, psi < 0
    assert!(sie.c < 0.0 && psi < 0.0);
    let mut previous = [f64::INFINITY; 4];
    for n in [1024, 4096] {
        let got = fft(&wv, sie.pbar, n);
        let err = [
            (got[0] - fraction).abs(),
            (got[1] / p_max - 1.0).abs(),
            (got[2] / psi - 1.0).abs(),
            (got[3] / mean_gap - 1.0).abs(),
        ];
        println!(
            "N = {n}: |fraction error| {:.2e}, p_max {:.2e}, psi {:.2e}, mean gap {:.2e}",
            err[0], err[1], err[2], err[3]
        );
        // the contact fraction is a node count: first order, erratic sign (section 2)
        assert!(err[0] <= 2.0 / n as f64);
        // p_max, a nodal maximum next to the smooth peak: section 2 expects ~1e-3 at 64 nodes
        // per wavelength; measured 5.8e-7 (N = 1024) and 1.4e-6 (4096)
        assert!(err[1] < 1e-5);
        // the integrals converge at second order, faster than the contact fraction (section 2);
        // measured N^2 err = 2.6 and 1.4 (psi), 3.1 and 3.1 (mean gap) at N = 1024 and 4096
        assert!(err[2] < 10.0 / (n * n) as f64 && err[2] < previous[2]);
        assert!(err[3] < 10.0 / (n * n) as f64 && err[3] < previous[3]);
        // mu* < mu for B > 0
        assert!(got[4] < wv.mu);
        previous = err;
    }
}

#[test]
fn the_closed_form_cauchy_integral_of_the_weight_is_right() {
    // tanh-sinh quadrature of (1 - t)^alpha (1 + t)^beta/(z - t), away from the interval
    let sie = Sie {
        c: 0.0,
        e: 1.0,
        alpha: 0.62,
        beta: 0.38,
        t: vec![],
        w: vec![],
        psi: vec![],
        bary: vec![],
        pbar: 0.0,
    };
    let rule = tanh_sinh(1.0 / 64.0);
    for z in [1.3, 2.0, 5.0, -1.3, -3.0] {
        let direct = rule.integrate(-1.0, 1.0, |t| {
            (1.0 - t).powf(0.62) * (1.0 + t).powf(0.38) / (z - t)
        });
        assert!((sie.cauchy_weight(z) - direct).abs() < 1e-12, "z = {z}");
    }
}
