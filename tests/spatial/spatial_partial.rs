//! Partial contact on the period cell (docs/physics/spatial-partial.md) against classical
//! closed forms, the closed form of complete contact and the second algorithm.

use crate::common;

use std::f64::consts::PI;

use common::{cosine, harmonic as wave, layer};

use wearlab::physics::Material;
use wearlab::physics::spatial::harmonic::Harmonic;
use wearlab::physics::spatial::partial::Setup;
use wearlab::physics::spatial::partial::fixed_point;
use wearlab::physics::spatial::partial::state::State;
use wearlab::physics::spatial::{PunchShape, SpatialInputs, solve};
use wearlab::physics::stop::Stop;

fn inputs(material: Material, mu: f64, tau0: f64, pbar: f64, h: Vec<Harmonic>) -> SpatialInputs {
    common::spatial(material, mu, tau0, 0.0, pbar, h)
}

fn state(inputs: &SpatialInputs, n: usize) -> (Setup, State) {
    let setup = Setup::new(inputs, n).unwrap();
    let s = setup.initial_state().unwrap();
    (setup, s)
}

/// The amplitude of p_cc - pbar: max over the nodes of (K^-1 U).
fn oscillation(inputs: &SpatialInputs, n: usize) -> f64 {
    let setup = Setup::new(inputs, n).unwrap();
    let mut p = vec![0.0; setup.grid.len()];
    setup.operator().inverse(&setup.initial_shape, &mut p, 0.0);
    p.iter().copied().fold(0.0, f64::max)
}

/// Least-squares slope of ln(err) against ln(N).
fn order(ns: &[usize], errs: &[f64]) -> f64 {
    let xs: Vec<f64> = ns.iter().map(|n| (*n as f64).ln()).collect();
    let ys: Vec<f64> = errs.iter().map(|e| e.ln()).collect();
    let (mx, my) = (
        xs.iter().sum::<f64>() / xs.len() as f64,
        ys.iter().sum::<f64>() / ys.len() as f64,
    );
    let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    -sxy / sxx
}

#[test]
fn westergaard_wave_on_a_half_space() {
    // route 2: mu = 0, g = Delta cos(2 pi x/l), p* = pi E* Delta/l, pbar/p* = sin^2(pi a/l),
    // p(x) = (2 pbar cos(pi x/l)/sin^2(pi a/l)) sqrt(sin^2(pi a/l) - sin^2(pi x/l)).
    let (e, nu, delta, l) = (2e11, 0.3, 1e-6, 1e-3);
    let p_star = PI * e / (1.0 - nu * nu) * delta / l;
    let pbar = 0.3 * p_star;
    let s2 = 0.3;
    let half_width = l / PI * f64::asin(f64::sqrt(s2));
    let exact = |x: f64| {
        let x = (x + l / 2.0).rem_euclid(l) - l / 2.0;
        let s = (PI * x / l).sin().powi(2);
        if s < s2 {
            2.0 * pbar * (PI * x / l).cos() / s2 * (s2 - s).sqrt()
        } else {
            0.0
        }
    };
    let ns = [256, 512, 1024, 2048, 4096];
    let (mut peak, mut rms) = (vec![], vec![]);
    for n in ns {
        let input = inputs(
            layer(e, nu, f64::INFINITY),
            0.0,
            0.0,
            pbar,
            vec![cosine(delta, l)],
        );
        let (setup, s) = state(&input, n);
        let err: Vec<f64> = (0..n)
            .map(|i| s.pressure[i] - exact(setup.grid.x(i)))
            .collect();
        let fraction = s.outputs.contact_fraction - 2.0 * half_width / l;
        // node 0 is the crest x = 0, where p is largest
        peak.push((s.outputs.max_pressure - exact(0.0)).abs() / p_star);
        rms.push((err.iter().map(|e| e * e).sum::<f64>() / n as f64).sqrt() / p_star);
        println!(
            "N = {n}: fraction {fraction:+.2e}, p_max {:.2e} p*, rms {:.2e} p*",
            peak.last().unwrap(),
            rms.last().unwrap()
        );
        assert!(fraction.abs() <= 2.0 / n as f64);
        if n == 1024 {
            // the figures route 2 expects at N = 1024 per wavelength
            assert!(*peak.last().unwrap() < 3e-6 && *rms.last().unwrap() < 5e-4);
        }
    }
    // measured orders: 1.9 (p_max: the interior converges faster than the edges) and 1.3 (rms,
    // dominated by the nodes next to the square-root edges, erratic in N)
    let (peak_order, rms_order) = (order(&ns, &peak), order(&ns, &rms));
    println!("orders: p_max {peak_order:.2}, rms {rms_order:.2}");
    assert!(peak_order > 1.5 && rms_order > 1.0);
}

/// The egg-box of Johnson, Greenwood and Higginson (route 3): g = Delta cos(2 pi x/l) cos(2 pi y/l)
/// on a frictionless half-space, p* = sqrt(2) pi E* Delta/l. The contact fraction at pbar/p* = r.
fn egg_box(r: f64, n: usize) -> f64 {
    let (e, nu, delta, l) = (2e11, 0.3, 1e-7, 1e-3);
    let p_star = 2f64.sqrt() * PI * e / (1.0 - nu * nu) * delta / l;
    let w = 2.0 * PI / l;
    let h = vec![wave(delta, w, w, PI / 2.0, PI / 2.0)];
    state(
        &inputs(layer(e, nu, f64::INFINITY), 0.0, 0.0, r * p_star, h),
        n,
    )
    .1
    .outputs
    .contact_fraction
}

#[test]
fn egg_box_near_complete_contact() {
    // route 3: 1 - A/l^2 -> (3/(2 pi))(1 - pbar/p*) within ~2.5 % at pbar/p* = 0.9 ... 0.98
    for r in [0.9, 0.95] {
        let gap_area = 1.0 - egg_box(r, 128);
        let ratio = gap_area / (3.0 / (2.0 * PI) * (1.0 - r));
        println!("pbar/p* = {r}: (1 - A)/asymptote = {ratio:.4}");
        assert!((ratio - 1.0).abs() < 0.025);
    }
    // complete contact from pbar = p* on
    assert_eq!(egg_box(1.0, 64), 1.0);
}

#[test]
#[ignore]
fn egg_box_both_asymptotes_on_fine_grids() {
    // route 3 at the stated grids (run by hand, release, ~1 s): small load A/l^2 ->
    // pi (3/(8 pi))^(2/3) (pbar/p*)^(2/3) "within ~1 %" at 0.001, N = 512 (measured 1.0108; 1.0120
    // at N = 1024, so the remaining 1.2 % is the asymptote's, not the grid's); near complete at
    // 0.98 (measured 0.9747, 0.9883, 0.9981 at N = 256, 512, 1024).
    let small =
        egg_box(0.001, 512) / (PI * (3.0 / (8.0 * PI)).powf(2.0 / 3.0) * 0.001f64.powf(2.0 / 3.0));
    let near = (1.0 - egg_box(0.98, 512)) / (3.0 / (2.0 * PI) * 0.02);
    println!("small load: A/asymptote = {small:.4}; near complete: (1 - A)/asymptote = {near:.4}");
    assert!((small - 1.0).abs() < 0.015 && (near - 1.0).abs() < 0.025);
}

/// A 2-D shape with B < 0 for its long waves: the "dispersion" preset's harmonics on a 0.5 mm
/// layer with nu = 0.45 (X* = 2.78; kh = 1.6 and 2.2 below it).
fn dispersion_shape() -> Vec<Harmonic> {
    let w = 3141.592653589793;
    vec![
        wave(1e-5, w, 0.0, 0.0, PI / 2.0),
        wave(3e-6, 4.0 * w, 0.0, 1.0, PI / 2.0),
        wave(5e-6, w, w, 0.5, 0.3),
        wave(2e-6, 2.0 * w, 3.0 * w, 2.0, 1.0),
    ]
}

#[test]
fn complete_contact_returns_the_closed_form() {
    // route 1: when min p_cc >= 0 the partial solver returns p_cc (docs/physics/spatial.md
    // section 3) to 1e-12 pbar, contact fraction 1, mean gap 0; with and without tau0; 1-D on a
    // half-space and 2-D with B < 0.
    let cases = [
        (
            layer(3e9, 0.3, f64::INFINITY),
            0.3,
            vec![cosine(1e-6, 1e-3)],
            64,
            2e7,
        ),
        (layer(1e7, 0.45, 5e-4), 0.8, dispersion_shape(), 64, 3e6),
    ];
    for (material, mu, h, n, pbar) in cases {
        for tau0 in [0.0, 0.1 * pbar] {
            let input = inputs(material, mu, tau0, pbar, h.clone());
            let (setup, s) = state(&input, n);
            let closed = solve(&input, 0.0).unwrap();
            let o = s.outputs;
            assert!(o.complete && o.contact_fraction == 1.0 && o.mean_gap.abs() <= 1e-20);
            for j in 0..setup.grid.ny {
                for i in 0..setup.grid.nx {
                    let p = s.pressure[j * setup.grid.nx + i];
                    let expected = closed.pressure(setup.grid.x(i), setup.grid.y(j));
                    assert!((p - expected).abs() < 1e-12 * pbar, "{p} vs {expected}");
                }
            }
            assert!((o.psi / closed.psi - 1.0).abs() < 1e-12);
            assert!((o.normal_force / closed.load - 1.0).abs() < 1e-14);
            assert!((o.holding_force / closed.tangential - 1.0).abs() < 1e-14);
            assert!((o.mu_star - closed.mu_star).abs() < 1e-14);
        }
    }
}

#[test]
fn a_wave_across_the_sliding_line_solves_like_one_along_it_without_friction() {
    // mu = 0 has no preferred direction: the wave along y (solved on 1 x N) and the same wave
    // along x (N x 1) give the same pressures
    let material = layer(1e7, 0.45, 5e-4);
    let along_x = inputs(material, 0.0, 0.0, 1e5, vec![cosine(1e-5, 2e-3)]);
    let mut along_y = along_x.clone();
    let PunchShape::Harmonics(waves) = &mut along_y.shape else {
        panic!("harmonics")
    };
    let h = &mut waves[0];
    (h.wavenumber_x, h.wavenumber_y, h.phase_x) = (0.0, h.wavenumber_x, PI / 2.0);
    let (sx, a) = state(&along_x, 128);
    let (sy, b) = state(&along_y, 128);
    assert_eq!(
        (sx.grid.nx, sx.grid.ny, sy.grid.nx, sy.grid.ny),
        (128, 1, 1, 128)
    );
    assert!(!a.outputs.complete);
    let diff = a
        .pressure
        .iter()
        .zip(&b.pressure)
        .map(|(p, q)| (p - q).abs())
        .fold(0.0, f64::max);
    assert!(diff < 1e-12 * 1e5, "{diff:e}");
}

#[test]
fn the_two_algorithms_agree() {
    // route 5: the active set (production) and the S-metric projected fixed point (convergence
    // proof for tau0 = 0) agree to 1e-9 pbar, up to phi_max = 1.2 rad.
    let two = vec![
        cosine(1e-6, 1e-3),
        wave(4e-7, 6.0 * PI / 1e-3, 0.0, 0.4, PI / 2.0),
    ];
    let cases = [
        (layer(1e7, 0.3, f64::INFINITY), 0.5, two.clone(), 256),
        (layer(1e7, 0.49, 2e-4), 3.5, two, 256),
        (layer(1e7, 0.45, 5e-4), 0.8, dispersion_shape(), 64),
        (layer(1e7, 0.49, 1.5e-4), 1.2, dispersion_shape(), 64),
    ];
    let mut largest_phi: f64 = 0.0;
    for (material, mu, h, n) in cases {
        let mut input = inputs(material, mu, 0.0, 1.0, h);
        input.mean_pressure = 0.4 * oscillation(&input, n);
        let (setup, s) = state(&input, n);
        assert!(!s.outputs.complete);
        let phi = setup.multipliers.tan_phi_max().atan();
        largest_phi = largest_phi.max(phi);
        let pbar = input.mean_pressure;
        let (p, iterations) = fixed_point::solve(
            &mut setup.operator(),
            &setup.initial_shape,
            pbar,
            1e-11,
            5000,
        )
        .unwrap();
        let diff = p
            .iter()
            .zip(&s.pressure)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        println!(
            "phi_max = {phi:.3}: fraction {:.3}, {} active-set and {iterations} fixed-point \
             iterations, max |dp| = {:.1e} pbar",
            s.outputs.contact_fraction,
            s.work.iterations,
            diff / pbar
        );
        assert!(diff < 1e-9 * pbar);
    }
    assert!(largest_phi > 1.2, "{largest_phi}");
}

/// The circular mean position of the contact set relative to the crest at x = 0, in wavelengths
/// (negative: the contact sits behind the crest, towards -x).
fn contact_shift(s: &State, setup: &Setup) -> f64 {
    let (mut c, mut sn) = (0.0, 0.0);
    for (i, on) in s.contact().iter().enumerate() {
        if *on {
            let a = 2.0 * PI * setup.grid.x(i) / setup.grid.lx;
            (c, sn) = (c + a.cos(), sn + a.sin());
        }
    }
    sn.atan2(c) / (2.0 * PI)
}

#[test]
fn friction_moves_the_contact_backwards_and_b_below_zero_reverses_it() {
    // route 6: B > 0 (half-space): contact towards -x, psi < 0, mu* < mu; a thin nearly
    // incompressible layer with kh = 1.26 < X*(0.49) = 4.02 (B < 0): all three reverse.
    let cases = [
        (layer(3e9, 0.3, f64::INFINITY), 1e-3, -1.0),
        (layer(5e6, 0.49, 1e-3), 5e-3, 1.0),
    ];
    let mu = 1.0;
    for (material, l, sign) in cases {
        let mut input = inputs(material, mu, 0.0, 1.0, vec![cosine(1e-6, l)]);
        input.mean_pressure = 0.3 * oscillation(&input, 512);
        let (setup, s) = state(&input, 512);
        let o = s.outputs;
        let shift = contact_shift(&s, &setup);
        println!(
            "B sign {sign}: shift {shift:+.4} l, psi {:+.3e}, mu* - mu {:+.3e}",
            o.psi,
            o.mu_star - mu
        );
        assert!(!o.complete);
        assert!(sign * shift > 0.0 && sign * o.psi > 0.0 && sign * (o.mu_star - mu) > 0.0);
    }
}

#[test]
fn adhesion_in_contact_converges_with_the_cycle_guard() {
    // tau0 acts only in contact (section 8): it shifts the contact like friction with B > 0;
    // on fine grids the active set may cycle among edge nodes (section 3), and the global outputs
    // still converge with N (measured: psi changes by 7e-5 relative from N = 4096 to 16384).
    let (e, nu, delta, l) = (2e11, 0.3, 1e-6, 1e-3);
    let p_star = PI * e / (1.0 - nu * nu) * delta / l;
    let material = layer(e, nu, f64::INFINITY);
    let mut outputs = vec![];
    for (tau0, n) in [(0.0, 4096), (0.1 * p_star, 4096), (0.1 * p_star, 16384)] {
        let input = inputs(material, 0.3, tau0, 0.3 * p_star, vec![cosine(delta, l)]);
        let (setup, s) = state(&input, n);
        println!("tau0 = {tau0:.3e}, N = {n}: {:?}, {:?}", s.outputs, s.work);
        // p >= 0 always; the gap of a cycled state may dip by O(tau0 w) at the edge nodes
        // (measured 7.8e-12 m against a 1e-6 m wave at N = 16384)
        assert!(s.pressure.iter().all(|p| *p >= 0.0));
        assert!(s.gap.iter().all(|g| *g > -1e-4 * delta));
        outputs.push((s.outputs, contact_shift(&s, &setup)));
    }
    let (free, stuck, fine) = (outputs[0], outputs[1], outputs[2]);
    assert!(stuck.1 < free.1 && stuck.0.psi < free.0.psi);
    assert!((fine.0.psi / stuck.0.psi - 1.0).abs() < 1e-3);
    assert!((fine.0.mean_gap / stuck.0.mean_gap - 1.0).abs() < 1e-4);
    assert!((fine.0.mu_star - stuck.0.mu_star).abs() < 1e-7);
}

#[test]
fn mu_star_over_the_whole_range_of_mean_pressure() {
    // one curve, partial contact below the complete-contact load, the closed
    // form (docs/physics/spatial.md section 5) above it; the "wave-thick-layer" preset's wave
    use std::ops::ControlFlow;
    use wearlab::physics::Spacing;
    use wearlab::physics::spatial::partial::sweep::load_curve;
    let material = layer(3e9, 0.3, 1e-2);
    let input = inputs(material, 0.3, 0.0, 2e7, vec![cosine(1e-6, 1e-3)]);
    let setup = Setup::new(&input, 256).unwrap();
    let pressures = Spacing::Log.points(1e5, 5e7, 40);
    let curve = load_curve(
        &setup,
        &setup.initial_shape,
        &pressures,
        Stop::Never,
        &mut |_| ControlFlow::Continue(()),
    )
    .unwrap();
    // the complete-contact load is the pressure amplitude A/M (sampled at the nodes)
    let closed = solve(&input, 0.0).unwrap();
    let amplitude = 1e-6 / closed.harmonics[0].evolution.m;
    let pc = curve.complete_mean_pressure;
    assert!(pc <= amplitude && pc > amplitude * (1.0 - (PI / 256.0).powi(2)));
    for (i, &pbar) in pressures.iter().enumerate() {
        let fraction = curve.contact_fraction[i];
        assert_eq!(fraction == 1.0, pbar >= pc, "pbar = {pbar:e}");
        if pbar >= pc {
            let mut at = input.clone();
            at.mean_pressure = pbar;
            assert!((curve.mu_star[i].unwrap() - solve(&at, 0.0).unwrap().mu_star).abs() < 1e-14);
        }
        assert!(curve.mu_star[i].unwrap() < 0.3);
    }
    // the contact grows with the load, and mu* is continuous through the complete-contact load
    assert!(curve.contact_fraction.windows(2).all(|f| f[1] >= f[0]));
    let below = pressures.iter().rposition(|p| *p < pc).unwrap();
    let mu_star = |i: usize| curve.mu_star[i].unwrap();
    let jump = (mu_star(below + 1) - mu_star(below)).abs();
    let step = (mu_star(below) - mu_star(below - 1)).abs();
    assert!(jump < 3.0 * step, "{jump:e} vs {step:e}");
}
