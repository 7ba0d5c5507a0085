//! The running-in's time steps (docs/physics/spatial-partial.md section 5): sized by the estimate
//! of their local error, with the sum of the estimates reported. A step study (halving the time
//! tolerance moves the reported values by less than the estimate says) and an independent
//! reference (fixed-step BDF2 written here, without the library's stepper, extrapolated to
//! dt -> 0 by Richardson) on a small 1-D half-plane case.

use crate::common;

use std::f64::consts::PI;
use std::ops::ControlFlow;

use common::cosine;
use wearlab::physics::spatial::SpatialInputs;
use wearlab::physics::spatial::partial::Setup;
use wearlab::physics::spatial::partial::active_set::{ContactProblem, solve};
use wearlab::physics::spatial::partial::operator::Diagonal;
use wearlab::physics::spatial::partial::running_in::{RunningIn, run_in};
use wearlab::physics::spatial::partial::state::Outputs;
use wearlab::physics::stop::Stop;
use wearlab::preset::default_spatial_section;

/// A 0.1 um, 1 mm wave on a steel-like half-plane at pbar = 0.3 p* with mu = 0.3 (p_max about
/// 55 MPa, as in the case the running-in was first checked on) and a wear coefficient that
/// makes the running-in last about 200 s, so that t = 50 s and 100 s are partial.
fn half_plane_wave() -> SpatialInputs {
    let (delta, l) = (1e-7, 1e-3);
    let p_star = PI * 2e11 / (1.0 - 0.09) * delta / l;
    let material = common::layer(2e11, 0.3, f64::INFINITY);
    common::spatial(
        material,
        0.3,
        0.0,
        2e-17,
        0.3 * p_star,
        vec![cosine(delta, l)],
    )
}

const TIMES: [f64; 2] = [50.0, 100.0];

fn run(setup: &Setup, tolerance: f64) -> RunningIn {
    run_in(setup, tolerance, &mut |_| ControlFlow::Continue(())).unwrap()
}

fn rms(u: &[f64]) -> f64 {
    (u.iter().map(|v| v * v).sum::<f64>() / u.len() as f64).sqrt()
}

#[test]
fn halving_the_tolerance_moves_the_values_by_less_than_the_estimate() {
    let setup = Setup::new(&half_plane_wave(), 64).unwrap();
    let tolerance = default_spatial_section().time_tolerance;
    let (a, b) = (run(&setup, tolerance), run(&setup, 0.5 * tolerance));
    let scale = rms(&setup.initial_shape);
    let (t_a, t_b) = (a.time_to_complete.unwrap(), b.time_to_complete.unwrap());
    let error = a.time_error(f64::INFINITY).unwrap();
    println!(
        "steps {} / {}, t_cc {t_a:.10e} / {t_b:.10e} s, estimate {error:.2e}",
        a.samples.len() - 1,
        b.samples.len() - 1
    );
    assert!((t_a - t_b).abs() < error * t_b);
    // the default tolerance: the sum of the steps' estimates stays below tolerance beta t_cc
    // (2.7e-6 here); the error itself is below 1e-6 (the reference test below)
    assert!(error < 2.7e-6 && b.time_error(f64::INFINITY).unwrap() < error);
    for t in TIMES {
        let (x, y): (Outputs, Outputs) = (
            a.state_at(t).unwrap().outputs,
            b.state_at(t).unwrap().outputs,
        );
        let error = a.time_error(t).unwrap();
        println!(
            "t = {t}: p_max {:.10e} / {:.10e}, mean gap {:.10e} / {:.10e}, mu* {:.12e} / \
             {:.12e}, estimate {error:.2e}",
            x.max_pressure, y.max_pressure, x.mean_gap, y.mean_gap, x.mu_star, y.mu_star
        );
        assert!(!x.complete && x.contact_fraction == y.contact_fraction);
        assert!((x.max_pressure - y.max_pressure).abs() < error * y.max_pressure);
        assert!((x.mu_star - y.mu_star).abs() < error * y.mu_star);
        assert!((x.mean_gap - y.mean_gap).abs() < error * scale);
        assert!((x.mean_gap - y.mean_gap).abs() < error * y.mean_gap);
    }
}

/// The outputs of fixed-step BDF2 (BE first) with `steps` steps to each of `TIMES`, and the time
/// at which min p_cc reaches 0 (quadratic through the last three steps) with steps of
/// `dt_complete`: written apart from the library's stepper, on the same contact solver.
fn fixed_steps(setup: &Setup, steps: usize, dt_complete: f64) -> (Vec<(f64, f64)>, f64) {
    let values = TIMES
        .iter()
        .map(|&t| {
            let (mut p_max, mut gap) = (0.0, 0.0);
            let last = |_: &[f64], pressure: &[f64], mean_gap: f64| {
                (p_max, gap) = (pressure.iter().copied().fold(0.0, f64::max), mean_gap);
                true
            };
            bdf2(setup, t / steps as f64, steps, &mut { last });
            (p_max, gap)
        })
        .collect();
    let mut history: Vec<(f64, f64)> = vec![];
    let mut op = setup.operator();
    let pbar = setup.inputs.mean_pressure;
    let mut complete = None;
    let mut until_complete = |u: &[f64], _: &[f64], _: f64| {
        let mut p = vec![0.0; u.len()];
        op.inverse(u, &mut p, 0.0);
        let m = pbar + p.iter().copied().fold(f64::INFINITY, f64::min);
        history.push((history.len() as f64 * dt_complete, m));
        if m >= 0.0 {
            let n = history.len();
            let [(t0, m0), (t1, m1), (t2, m2)] = [history[n - 3], history[n - 2], history[n - 1]];
            let q = |t: f64| {
                m0 * (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2))
                    + m1 * (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2))
                    + m2 * (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1))
            };
            let (mut lo, mut hi) = (t1, t2);
            for _ in 0..100 {
                let mid = 0.5 * (lo + hi);
                if q(mid) < 0.0 { lo = mid } else { hi = mid }
            }
            complete = Some(0.5 * (lo + hi));
        }
        complete.is_none()
    };
    bdf2(
        setup,
        dt_complete,
        (400.0 / dt_complete) as usize,
        &mut until_complete,
    );
    (values, complete.unwrap())
}

/// What `bdf2` calls after each step: U [m], p [Pa], the mean gap [m]; false stops.
type Each<'a> = dyn FnMut(&[f64], &[f64], f64) -> bool + 'a;

/// At most `steps` steps of dt [s]: `each(U, p, mean gap)` after every step (and U(0) first)
/// says whether to go on.
fn bdf2(setup: &Setup, dt: f64, steps: usize, each: &mut Each) {
    let inputs = &setup.inputs;
    let (pbar, k_w) = (inputs.mean_pressure, inputs.wear_rate());
    let mut op = setup.operator();
    let mut before: Option<Vec<f64>> = None;
    let mut u = setup.initial_shape.clone();
    if !each(&u, &[], 0.0) {
        return;
    }
    for _ in 0..steps {
        let (base, c): (Vec<f64>, f64) = match &before {
            None => (u.clone(), dt * k_w),
            Some(v) => (
                u.iter().zip(v).map(|(a, b)| (4.0 * a - b) / 3.0).collect(),
                2.0 / 3.0 * dt * k_w,
            ),
        };
        let problem = ContactProblem {
            shape: &base,
            mean_pressure: pbar,
            adhesion: inputs.friction.adhesion,
            diagonal: Diagonal::Uniform(c),
            stop: Stop::Never,
        };
        let sol = solve(&mut op, &problem, None).unwrap();
        let next: Vec<f64> = base
            .iter()
            .zip(&sol.pressure)
            .map(|(b, p)| b - c * (p - pbar))
            .collect();
        before = Some(std::mem::replace(&mut u, next));
        if !each(&u, &sol.pressure, sol.offset + c * pbar) {
            return;
        }
    }
}

#[test]
fn the_running_in_agrees_with_fixed_step_bdf2_extrapolated_to_zero_step() {
    let setup = Setup::new(&half_plane_wave(), 64).unwrap();
    let run = run(&setup, default_spatial_section().time_tolerance);
    // BDF2 is second order where the contact front is still: Richardson's x_2M + (x_2M - x_M)/3
    let (m, dt) = (1000, 0.05);
    let (coarse, coarse_complete) = fixed_steps(&setup, m, 2.0 * dt);
    let (fine, fine_complete) = fixed_steps(&setup, 2 * m, dt);
    let extrapolate = |a: f64, b: f64| b + (b - a) / 3.0;
    let t_cc = extrapolate(coarse_complete, fine_complete);
    let got = run.time_to_complete.unwrap();
    println!("t_cc {got:.10e} against {t_cc:.10e} ({coarse_complete:.10e}, {fine_complete:.10e})");
    assert!((got - t_cc).abs() < 1e-6 * t_cc);
    for (k, t) in TIMES.into_iter().enumerate() {
        let o = run.state_at(t).unwrap().outputs;
        let p_max = extrapolate(coarse[k].0, fine[k].0);
        let gap = extrapolate(coarse[k].1, fine[k].1);
        println!(
            "t = {t}: p_max {:.10e} against {p_max:.10e} ({:.10e}, {:.10e}); mean gap {:.10e} \
             against {gap:.10e} ({:.10e}, {:.10e})",
            o.max_pressure, coarse[k].0, fine[k].0, o.mean_gap, coarse[k].1, fine[k].1
        );
        assert!((o.max_pressure - p_max).abs() < 1e-6 * p_max);
        assert!((o.mean_gap - gap).abs() < 1e-6 * gap);
    }
}
