//! Running-in by wear (docs/physics/spatial-partial.md section 5; verification routes 7 to 9):
//! conservation, monotone wear, the closed form of complete contact from the stepping, the time
//! to complete contact, the explicit step's stability bound, replay and cancel.

use crate::common;

use std::f64::consts::PI;

use common::cosine;
use std::ops::ControlFlow;

use wearlab::physics::Material;
use wearlab::physics::spatial::harmonic::{Harmonic, evolution, layer_response};
use wearlab::physics::spatial::partial::Setup;
use wearlab::physics::spatial::partial::running_in::{
    RunningIn, Stepper, Stepping, Stopped, run_in, run_in_with,
};
use wearlab::physics::spatial::{SpatialInputs, solve};
use wearlab::physics::stop::Stop;

fn inputs(material: Material, mu: f64, tau0: f64, pbar: f64, h: Vec<Harmonic>) -> SpatialInputs {
    common::spatial(material, mu, tau0, 1e-15, pbar, h)
}

fn half_space() -> Material {
    common::layer(2e11, 0.3, f64::INFINITY)
}

/// The 1-D wave of `docs/verification.md`'s running-in check: 1 um, 1 mm on a half-space at pbar = 0.3 p*.
fn westergaard_wave(mu: f64, tau0: f64) -> SpatialInputs {
    let (delta, l) = (1e-6, 1e-3);
    let p_star = PI * 2e11 / (1.0 - 0.09) * delta / l;
    inputs(half_space(), mu, tau0, 0.3 * p_star, vec![cosine(delta, l)])
}

/// The time tolerance of these tests (the default's 1e-6 takes 3 times the steps; the step
/// study of tests/spatial_time_steps.rs checks what the tolerance buys).
const TOLERANCE: f64 = 1e-5;

fn go(setup: &Setup) -> RunningIn {
    run_in(setup, TOLERANCE, &mut |_| ControlFlow::Continue(())).unwrap()
}

fn decay_rate(i: &SpatialInputs) -> f64 {
    evolution(&i.material, &i.friction, i.wear_rate(), &i.harmonics()[0]).decay_rate
}

#[test]
fn running_in_completes_the_contact_and_conserves_the_wear() {
    let input = westergaard_wave(0.3, 0.0);
    let setup = Setup::new(&input, 128).unwrap();
    let run = go(&setup);
    let beta = decay_rate(&input);
    let t_cc = run.time_to_complete.unwrap();
    // an independent simulation of this case (mu = 0; `docs/verification.md`) gives 2.71 decay
    // times, where the closed-form bound says 1.20; friction shortens it a little
    println!(
        "t_cc beta = {:.5}, {} steps",
        t_cc * beta,
        run.samples.len() - 1
    );
    assert!((2.6..2.72).contains(&(t_cc * beta)));
    // route 8: the contact grows to complete and the mean gap closes
    let first = run.samples[0].outputs;
    let last = run.samples.last().unwrap().outputs;
    assert!(first.contact_fraction < 0.4 && last.complete && last.mean_gap == 0.0);
    for pair in run.samples.windows(2) {
        let (a, b) = (pair[0].outputs, pair[1].outputs);
        assert!(b.contact_fraction >= a.contact_fraction - 1.0 / 128.0);
        assert!(b.mean_gap <= a.mean_gap && b.min_pressure_complete > a.min_pressure_complete);
    }
    // route 7: worn volume = k_w pbar t Lx Ly to round-off
    let k_w = input.wear_rate();
    for t in [0.1 / beta, 1.0 / beta, 2.0 / beta, t_cc, 4.0 / beta] {
        let s = run.state_at(t).unwrap();
        let mean = s.wear.iter().sum::<f64>() / s.wear.len() as f64;
        assert!((mean / (k_w * input.mean_pressure * t) - 1.0).abs() < 1e-12);
    }
    // route 7: the local wear depth W = k_w pbar t + U0 - U of every step is >= 0 and grows,
    // up to round-off (1e-16 of the 1 um wave per step, accumulated over the steps: W reaches
    // -1e-21 m at nodes never in contact)
    let mut s = Stepper::new(
        &setup,
        0,
        0.0,
        None,
        setup.initial_shape.clone(),
        vec![true; 128],
    );
    let mut before = vec![0.0; 128];
    while s.step < run.samples.len() - 1 {
        s.advance(run.samples[s.step + 1].time).unwrap();
        let mean_wear = k_w * input.mean_pressure * s.time;
        for ((b, u0), u) in before.iter_mut().zip(&setup.initial_shape).zip(&s.current) {
            let w = mean_wear + u0 - u;
            assert!(w >= -1e-13 * 1e-6 && w >= *b - 1e-13 * 1e-6);
            *b = w;
        }
    }
}

#[test]
fn the_time_to_complete_contact_converges_in_the_tolerance_and_n() {
    // route 8: the time to complete contact converges as the time tolerance and the grid shrink
    let input = westergaard_wave(0.0, 0.0);
    let beta = decay_rate(&input);
    let at = |n: usize, tolerance: f64| {
        let setup = Setup::new(&input, n).unwrap();
        let run = run_in(&setup, tolerance, &mut |_| ControlFlow::Continue(())).unwrap();
        run.time_to_complete.unwrap() * beta
    };
    let (coarse, fine, finer) = (at(256, 1e-3), at(256, 1e-4), at(256, 1e-5));
    let (grid_a, grid_b) = (at(128, 1e-4), at(512, 1e-4));
    println!("tolerance: {coarse:.7} {fine:.7} {finer:.7}; N: {grid_a:.6} {fine:.6} {grid_b:.6}");
    assert!((fine - finer).abs() < 1e-4 * finer && (coarse - fine).abs() > (fine - finer).abs());
    // the grid's error (section 2), well above the time steps'
    assert!((grid_a - grid_b).abs() < 5e-4 * grid_b);
}

/// Amplitude and phase rho of U = A sin(wx x + rho) on a 1-D grid of n nodes over one wave.
fn amplitude_phase(u: &[f64]) -> (f64, f64) {
    let n = u.len() as f64;
    let (mut a, mut b) = (0.0, 0.0);
    for (i, v) in u.iter().enumerate() {
        let x = 2.0 * PI * i as f64 / n;
        (a, b) = (a + 2.0 * v * x.sin() / n, b + 2.0 * v * x.cos() / n);
    }
    (a.hypot(b), b.atan2(a))
}

#[test]
fn stepped_wear_in_complete_contact_follows_the_closed_form() {
    // route 8: in complete contact each harmonic decays at beta and drifts at c
    // (docs/physics/spatial.md section 3), forwards on a thick layer and backwards for
    // nu > 1/4, kh < X* (the rubber preset: nu = 0.49, h = 1 mm, kh = 1.26 < X*(0.49) = 4.02)
    let thick = Material {
        youngs_modulus: 3e9,
        poisson_ratio: 0.3,
        thickness: 1e-2,
    };
    let rubber = Material {
        youngs_modulus: 5e6,
        poisson_ratio: 0.49,
        thickness: 1e-3,
    };
    for (material, mu, pbar, l, forward) in [
        (thick, 0.3, 2e7, 1e-3, true),
        (rubber, 1.0, 2e5, 5e-3, false),
    ] {
        let input = inputs(material, mu, 0.0, pbar, vec![cosine(1e-6, l)]);
        let ev = evolution(
            &input.material,
            &input.friction,
            input.wear_rate(),
            &input.harmonics()[0],
        );
        assert_eq!(ev.drift_velocity > 0.0, forward);
        let setup = Setup::new(&input, 64).unwrap();
        let t_end = 1.0 / ev.decay_rate;
        let mut errors = vec![];
        for steps in [50, 100] {
            let mut s = Stepper::new(
                &setup,
                0,
                0.0,
                None,
                setup.initial_shape.clone(),
                vec![true; 64],
            );
            while s.step < steps {
                let (sol, _) = s
                    .advance(t_end * (s.step + 1) as f64 / steps as f64)
                    .unwrap();
                assert!(sol.complete);
            }
            let (a, rho) = amplitude_phase(&s.current);
            let beta = -(a / 1e-6).ln() / t_end;
            let c = -(rho - PI / 2.0) / (2.0 * PI / l) / t_end;
            errors.push((
                (beta / ev.decay_rate - 1.0).abs(),
                (c / ev.drift_velocity - 1.0).abs(),
            ));
        }
        println!("{errors:?}");
        // second order: halving dt divides the errors by about 4
        assert!(errors[1].0 < 1e-4 && errors[1].1 < 1e-4);
        assert!(errors[0].0 / errors[1].0 > 3.5 && errors[0].1 / errors[1].1 > 3.5);
    }
}

#[test]
fn explicit_euler_is_stable_only_below_two_min_a_over_k_w() {
    // route 9: U1 = U0 - dt k_w (p0 - pbar) with p0 - pbar = K^-1 U0 in complete contact is stable
    // for dt < 2 min_k A(k)/k_w, min at the grid's largest |k| (here the Nyquist, pi N/l).
    let input = inputs(half_space(), 0.5, 0.0, 1e9, vec![cosine(1e-7, 1e-3)]);
    let n = 64;
    let setup = Setup::new(&input, n).unwrap();
    let a_min = layer_response(&input.material, PI * n as f64 / 1e-3).a;
    let bound = 2.0 * a_min / input.wear_rate();
    let mut op = setup.operator();
    for (factor, stable) in [(0.9, true), (1.1, false)] {
        // the wave plus grid-scale round-off-sized noise
        let mut u: Vec<f64> = setup
            .initial_shape
            .iter()
            .enumerate()
            .map(|(i, v)| v + 1e-15 * (-1f64).powi(i as i32))
            .collect();
        let mut p = vec![0.0; n];
        for _ in 0..400 {
            op.inverse(&u, &mut p, 0.0);
            u.iter_mut()
                .zip(&p)
                .for_each(|(u, p)| *u -= factor * bound * input.wear_rate() * p);
        }
        let size = u.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert_eq!(size < 1e-7, stable, "factor {factor}: max |U| = {size:e}");
    }
}

#[test]
fn states_between_steps_replay_and_join_the_closed_form() {
    let input = westergaard_wave(0.3, 0.0);
    let setup = Setup::new(&input, 128).unwrap();
    let run = go(&setup);
    // a stepped time gives the stepped state
    for k in [0, 1, 7, 40] {
        let sample = run.samples[k];
        let s = run.state_at(sample.time).unwrap();
        assert!((s.outputs.psi / sample.outputs.psi - 1.0).abs() < 1e-9);
        assert!((s.outputs.mean_gap / sample.outputs.mean_gap - 1.0).abs() < 1e-9);
        assert_eq!(s.outputs.contact_fraction, sample.outputs.contact_fraction);
    }
    // between two steps the outputs lie between theirs
    let (a, b) = (run.samples[20], run.samples[21]);
    let mid = run.state_at(0.5 * (a.time + b.time)).unwrap().outputs;
    assert!(mid.mean_gap < a.outputs.mean_gap && mid.mean_gap > b.outputs.mean_gap);
    // continuous where the closed form takes over
    let from = run.complete_from.unwrap();
    let (just_before, at) = (
        run.state_at(from * (1.0 - 1e-9)).unwrap(),
        run.state_at(from).unwrap(),
    );
    let jump = just_before
        .pressure
        .iter()
        .zip(&at.pressure)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    assert!(jump < 1e-6 * input.mean_pressure, "{jump:e}");
    // later states are complete, and the history follows
    let history = run.history(2.0 * from, 10).unwrap();
    assert_eq!(history.time.len(), run.samples.len() + 10);
    assert!(history.contact_fraction.last() == Some(&1.0) && history.mean_gap.last() == Some(&0.0));
    assert!(history.time.windows(2).all(|t| t[1] > t[0]));
}

#[test]
fn complete_from_the_start_is_the_closed_form_at_every_time() {
    let input = inputs(half_space(), 0.3, 1e6, 2e9, vec![cosine(1e-6, 1e-3)]);
    let setup = Setup::new(&input, 64).unwrap();
    let run = go(&setup);
    assert_eq!((run.time_to_complete, run.complete_from), (None, Some(0.0)));
    let t = 3.0 / decay_rate(&input);
    let s = run.state_at(t).unwrap();
    let closed = solve(&input, t).unwrap();
    for i in 0..64 {
        let expected = closed.pressure(setup.grid.x(i), 0.0);
        assert!((s.pressure[i] - expected).abs() < 1e-12 * input.mean_pressure);
    }
    assert!((s.outputs.mu_star - closed.mu_star).abs() < 1e-14);
}

#[test]
fn cancel_no_wear_and_the_end_of_the_stepping() {
    let input = westergaard_wave(0.3, 0.0);
    let setup = Setup::new(&input, 64).unwrap();
    let mut calls = 0;
    let stopped = run_in(&setup, TOLERANCE, &mut |_| {
        calls += 1;
        ControlFlow::Break(())
    });
    assert_eq!((stopped.err(), calls), (Some(Stopped::Cancelled), 1));
    // no wear: nothing changes, and contact never completes
    let mut still = input.clone();
    still.wear = 0.0;
    let run = go(&Setup::new(&still, 64).unwrap());
    assert_eq!((run.stepping, run.time_to_complete), (None, None));
    let later = run.state_at(1e6).unwrap();
    assert_eq!(later.pressure, run.state_at(0.0).unwrap().pressure);
    // a stepping stopped by its bound of steps while partial refuses later times, and says why
    let mut short = Stepping::of(&setup, TOLERANCE).unwrap();
    short.max_steps = 3;
    let run = run_in_with(&setup, Some(short), &mut |_| ControlFlow::Continue(())).unwrap();
    let end = run.end_time();
    assert_eq!((run.time_to_complete, run.samples.len()), (None, 4));
    assert!(run.step_bound_reached() && run.finished());
    assert!(run.state_at(0.7 * end).is_ok());
    let err = run.state_at(1.5 * end).unwrap_err().to_string();
    assert!(err.contains("still partial"), "{err}");
    // stopped by its horizon instead: an answer (not complete within the horizon), not the bound
    let mut near = Stepping::of(&setup, TOLERANCE).unwrap();
    near.horizon = 0.1 / decay_rate(&input);
    let run = run_in_with(&setup, Some(near), &mut |_| ControlFlow::Continue(())).unwrap();
    assert_eq!((run.time_to_complete, run.end_time()), (None, near.horizon));
    assert!(!run.step_bound_reached() && run.finished());
}

#[test]
fn thinned_snapshots_replay_the_same_states() {
    // with room for only a few snapshots, the replay from an older one gives the same state
    let input = westergaard_wave(0.3, 0.0);
    let setup = Setup::new(&input, 128).unwrap();
    let full = go(&setup);
    let mut tight = full.stepping.unwrap();
    tight.memory = 8 * 128;
    let thin = run_in_with(&setup, Some(tight), &mut |_| ControlFlow::Continue(())).unwrap();
    assert_eq!(thin.samples, full.samples);
    for k in [3, 50, 101] {
        let t = full.samples[k].time + 0.3 * (full.samples[k + 1].time - full.samples[k].time);
        let (a, b) = (full.state_at(t).unwrap(), thin.state_at(t).unwrap());
        assert_eq!(a.pressure, b.pressure);
    }
}

#[test]
fn a_running_in_extended_in_parts_takes_the_same_steps() {
    // the explorer steps the running-in in parts (stopped by newer requests, resumed later): the
    // same samples, time to complete contact and states as one call, to the bit
    let input = westergaard_wave(0.3, 0.0);
    let setup = Setup::new(&input, 128).unwrap();
    let whole = go(&setup);
    let stepping = whole.stepping.unwrap();
    let mut parts = RunningIn::start(&setup, Some(stepping), Stop::Never).unwrap();
    assert!(!parts.finished());
    // stopped after every third step, then asked up to a time, then to the end
    let mut calls = 0;
    let mut stop_every_third = |_: &RunningIn| {
        calls += 1;
        if calls % 3 == 0 {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    };
    for _ in 0..4 {
        parts.extend(f64::INFINITY, &mut stop_every_third).unwrap();
    }
    assert_eq!(parts.samples.len(), 13);
    let t = 0.5 * (whole.samples[20].time + whole.samples[21].time);
    parts.extend(t, &mut |_| ControlFlow::Continue(())).unwrap();
    assert_eq!(
        parts.samples.len(),
        22,
        "stepped to the first step at or after t"
    );
    // the last stepped state without the replay: state_at replays to it and steps no further,
    // so the two agree to round-off
    let (end, replayed) = (
        parts.end_state().unwrap(),
        whole.state_at(parts.end_time()).unwrap(),
    );
    let p_max = end.outputs.max_pressure;
    let apart = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
    };
    assert!(apart(&end.pressure, &replayed.pressure) < 1e-12 * p_max);
    assert_eq!(end.contact(), replayed.contact());
    parts
        .extend(f64::INFINITY, &mut |_| ControlFlow::Continue(()))
        .unwrap();
    assert!(parts.finished());
    assert_eq!(parts.samples, whole.samples);
    assert_eq!(parts.time_to_complete, whole.time_to_complete);
    for t in [0.0, t, 0.5 * whole.time_to_complete.unwrap(), 1e3] {
        assert_eq!(parts.state_at(t).unwrap(), whole.state_at(t).unwrap());
    }
}
