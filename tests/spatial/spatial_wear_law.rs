//! The spatial running-in under the nonlinear wear law W' = -k V p (p/p0)^(n-1)
//! (docs/physics/plane-general.md section 1), simulated on the grid (its closed form holds for
//! n = 1 only), against independent routes written here: the mean wear rate k V <p^n>/p0^(n-1)
//! of the Westergaard pressure, the decay of a small wave at the linearised rate
//! n (pbar/p0)^(n-1) beta_1, and n -> 1 against the closed form of the linear law.

use crate::common;

use std::f64::consts::PI;

use common::cosine;
use wearlab::physics::SolveError;
use wearlab::physics::spatial::SpatialInputs;
use wearlab::physics::spatial::partial::Setup;
use wearlab::physics::spatial::partial::running_in::{RunningIn, run_in_to};
use wearlab::physics::spatial::partial::state::State;
use wearlab::physics::spatial::pipeline;
use wearlab::physics::spatial::state::StateAt;
use wearlab::physics::stop::Stop;
use wearlab::preset::default_spatial_section;

const E: f64 = 2e11;
const NU: f64 = 0.3;
const WAVELENGTH: f64 = 1e-3;
const PBAR: f64 = 1e8;
/// k [1/Pa] with V = 1 m/s (`common::spatial`): k_w = 1e-17 m/(Pa s).
const K: f64 = 1e-17;

/// A wave of amplitude `delta` on a steel-like half-space without friction, pbar = 100 MPa,
/// under the wear law (n, p0).
fn wave(delta: f64, n: f64, p0: f64) -> SpatialInputs {
    let material = common::layer(E, NU, f64::INFINITY);
    let mut inputs = common::spatial(material, 0.0, 0.0, K, PBAR, vec![cosine(delta, WAVELENGTH)]);
    inputs.wear_exponent = n;
    inputs.reference_pressure = p0;
    inputs
}

/// The Westergaard pressure amplitude pi E* Delta/lambda of a wave in complete contact
/// (docs/physics/spatial.md section 6, E* = E/(1 - nu^2)).
fn pressure_amplitude(delta: f64) -> f64 {
    PI * E / (1.0 - NU * NU) * delta / WAVELENGTH
}

/// The closed-form decay rate of the linear law on the half-space without friction,
/// beta_1 = k_w E k/(2 (1 - nu^2)) (docs/physics/spatial.md section 3, Dh = (1 - nu)^2).
fn beta_linear() -> f64 {
    K * E * (2.0 * PI / WAVELENGTH) / (2.0 * (1.0 - NU * NU))
}

fn simulated(inputs: &SpatialInputs, time: f64) -> (RunningIn, State) {
    let setup = Setup::new(inputs, 64).unwrap();
    let tolerance = default_spatial_section().time_tolerance;
    let run = run_in_to(&setup, tolerance, time, Stop::Never).unwrap();
    let state = run.state_at(time).unwrap();
    (run, state)
}

/// The amplitude of the first harmonic of the nodal shape: 2 |<U e^{-ikx}>|.
fn amplitude(state: &State) -> f64 {
    let k = 2.0 * PI / WAVELENGTH;
    let xs = state.grid.xs();
    let (mut c, mut s) = (0.0, 0.0);
    for (x, u) in xs.iter().zip(&state.shape) {
        c += u * (k * x).cos();
        s += u * (k * x).sin();
    }
    let n = xs.len() as f64;
    2.0 * (c * c + s * s).sqrt() / n
}

fn mean(values: &[f64]) -> f64 {
    values.iter().sum::<f64>() / values.len() as f64
}

#[test]
fn the_mean_wear_rate_is_k_v_times_the_mean_of_p_to_the_n_over_p0_to_the_n_minus_1() {
    // a 10 nm wave: p1/pbar = 0.069, so <p^n> differs from pbar^n by 0.7 % (n = 2) and 1.4 %
    // (n = 3), far above the tolerance below
    let delta = 1e-8;
    let p1 = pressure_amplitude(delta);
    for (n, p0, mean_power) in [
        // <(pbar + p1 sin)^2> = pbar^2 + p1^2/2; <(pbar + p1 sin)^3> = pbar^3 + 3 pbar p1^2/2
        (2.0, 5e7, PBAR * PBAR + p1 * p1 / 2.0),
        (3.0, 2e8, PBAR.powi(3) + 1.5 * PBAR * p1 * p1),
    ] {
        let inputs = wave(delta, n, p0);
        let rate = K * mean_power / p0.powf(n - 1.0);
        // a short time: 1e-3 of the linearised decay time, so that p1 changes by 1e-3 of itself
        let factor = n * (PBAR / p0).powf(n - 1.0);
        let t = 1e-3 / (factor * beta_linear());
        let (run, state) = simulated(&inputs, t);
        assert!(state.outputs.complete && run.complete_from.is_none());
        let worn = mean(&state.wear);
        let expected = rate * t;
        println!(
            "n = {n}: <W> = {worn:.12e} m, k V <p^n>/p0^(n-1) t = {expected:.12e} m, linear \
             law's {:.12e} m",
            K * PBAR * t
        );
        // p1^2 changes by 2e-3 of itself over t: <p^n> by 2e-3 of its 0.7-1.4 % part
        assert!((worn - expected).abs() < 1e-5 * expected);
        // the wave's part is resolved: a uniform pressure would wear k V pbar^n/p0^(n-1) t
        let uniform = K * PBAR.powf(n) / p0.powf(n - 1.0) * t;
        assert!((worn - uniform).abs() > 1e-3 * expected);
    }
}

#[test]
fn a_small_wave_decays_at_n_pbar_over_p0_to_the_n_minus_1_times_the_linear_rate() {
    // a 1 nm wave: p1/pbar = 7e-3; q^n = pbar^n + n pbar^(n-1) p1 sin + O(p1^2), so the wave
    // decays at n (pbar/p0)^(n-1) beta_1 to first order in p1/pbar
    let delta = 1e-9;
    for (n, p0) in [(2.0, 5e7), (3.0, 1e8), (1.5, 2e8)] {
        let inputs = wave(delta, n, p0);
        let rate = n * (PBAR / p0).powf(n - 1.0) * beta_linear();
        let t = 1.0 / rate;
        let (run, state) = simulated(&inputs, t);
        let ratio = amplitude(&state) / delta;
        let expected = (-rate * t).exp();
        let error = run.time_error(t).unwrap();
        println!(
            "n = {n}: A(t)/A(0) = {ratio:.10}, exp(-n (pbar/p0)^(n-1) beta_1 t) = \
             {expected:.10}, {} steps, time-step error {error:.1e}",
            run.samples.len() - 1
        );
        // second order in p1/pbar (5e-5) plus the time stepping
        assert!((ratio - expected).abs() < 1e-4 * expected + error);
    }
}

#[test]
fn n_near_1_through_the_simulated_path_is_the_closed_form_of_the_linear_law() {
    // F(p) = p (p/pbar)^1e-9 differs from p by 1e-9 p ln(p/pbar) (< 1e-10 p here): the stepped
    // running-in must follow the linear law's closed form U^(t) = U^(0) exp(-beta_1 t)
    let delta = 3e-8;
    let inputs = wave(delta, 1.0 + 1e-9, PBAR);
    let mut linear = inputs.clone();
    linear.wear_exponent = 1.0;
    let t = 2.0 / beta_linear();
    let (run, state) = simulated(&inputs, t);
    let setup = Setup::new(&linear, 64).unwrap();
    let closed = wearlab::physics::spatial::partial::running_in::run_in_until(
        &setup,
        default_spatial_section().time_tolerance,
        Stop::Never,
    )
    .unwrap();
    assert_eq!(closed.complete_from, Some(0.0));
    let exact = closed.state_at(t).unwrap();
    let scale = delta / 2f64.sqrt();
    let error = run.time_error(t).unwrap();
    let apart = state
        .shape
        .iter()
        .zip(&exact.shape)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    println!(
        "max |U_stepped - U_closed| = {:.2e} of rms U(0), estimate {error:.1e}; A(t)/A(0) = \
         {:.10}, exp(-2) = {:.10}",
        apart / scale,
        amplitude(&state) / delta,
        (-2.0f64).exp()
    );
    assert!(apart < (error + 1e-8) * scale);
    assert!((mean(&state.wear) - K * PBAR * t).abs() < 1e-8 * K * PBAR * t);
    let max = |s: &State| s.pressure.iter().copied().fold(0.0, f64::max);
    assert!((max(&state) - max(&exact)).abs() < (error + 1e-8) * pressure_amplitude(delta));
}

#[test]
fn solve_says_in_words_that_a_nonlinear_law_is_simulated() {
    let inputs = wave(1e-8, 2.0, 5e7);
    let at = StateAt {
        time: 1e-3,
        grid: 64,
        ..default_at()
    };
    let result = pipeline::solve(&inputs, &at, &[], false).unwrap();
    assert_eq!(
        result.running_in.as_deref(),
        Some(
            "wear exponent n = 2: the running-in is simulated on the grid; the closed form holds \
             for n = 1 only"
        )
    );
    assert_eq!(result.harmonics_hold, "for n = 1 only");
    assert!(result.contact.complete);
    // the linear law keeps its closed form and says nothing more
    let linear = pipeline::solve(&wave(1e-8, 1.0, 5e7), &at, &[], false).unwrap();
    assert_eq!((linear.running_in, linear.harmonics_hold), (None, "now"));
}

fn default_at() -> StateAt {
    let preset = wearlab::preset::bundled("jgh-egg-box.toml")
        .unwrap()
        .unwrap();
    preset.spatial_state_at()
}

#[test]
fn a_tiny_reference_pressure_is_refused_in_words_within_bounded_work() {
    // n = 4, p0 = 1e-3 Pa under pbar = 100 MPa: F(pbar)/pbar = 1e33, the wave decays in 1e-31 s
    // and the punch wears 1e8 times its waviness within 1e-24 s
    let inputs = wave(1e-8, 4.0, 1e-3);
    let at = StateAt {
        time: 10.0,
        grid: 32,
        ..default_at()
    };
    let started = std::time::Instant::now();
    let why = pipeline::solve(&inputs, &at, &[], false).unwrap_err();
    println!("{why} ({:.2} s)", started.elapsed().as_secs_f64());
    assert!(
        matches!(&why, SolveError::NoSolution(w) if w.contains("raise wear.reference_pressure"))
    );
    assert!(started.elapsed().as_secs() < 60);
    // a reference pressure of the order of pbar: the answer at t, finite
    let fine = pipeline::solve(&wave(1e-8, 4.0, 1e8), &at, &[], false).unwrap();
    assert!(fine.max_pressure.is_finite() && fine.contact.complete);
}
