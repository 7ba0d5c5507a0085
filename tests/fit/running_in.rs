//! A running-in trace fitted: the fit's model reads every row's time from one running-in
//! (`spatial::at_times`); each value is the one a solve at that row's time alone gives
//! (`synthetic::measure` without noise: `sweeps::point::solve`, `wearlab solve --time T`).

use std::path::Path;

use nalgebra::DVector;
use wearlab::data;
use wearlab::fit::{Free, Model, synthetic};
use wearlab::physics::stop::Stop;
use wearlab::preset::{self, Preset};
use wearlab::sweeps::QuantityKey;

/// The model's values at `times` (in file order) against one solve per time, for `mu_star` and
/// the contact fraction: the largest difference relative to the value.
fn largest_difference(truth: &Preset, times: &[f64]) -> f64 {
    let time = truth.key("spatial.time").unwrap();
    let mut text = String::from("time [s],mu [-],contact fraction [-]\n");
    let q = |name| QuantityKey::parse(name, truth).unwrap();
    let mu = synthetic::measure(truth, time, times, q("mu_star"), 0.0, 1).unwrap();
    let fraction = synthetic::measure(truth, time, times, q("contact.fraction"), 0.0, 1).unwrap();
    for ((t, m), f) in times.iter().zip(&mu).zip(&fraction) {
        text.push_str(&format!("{t:e},{m:e},{f:e}\n"));
    }
    let set = data::read_text(Path::new("trace.csv"), &text, truth).unwrap();
    let k = truth.key("wear.coefficient").unwrap();
    let free = [Free::new(truth, k, time).unwrap()];
    let model = Model {
        base: truth,
        data: &set,
        free: &free,
        weights: vec![1.0; 2 * times.len()],
        stop: Stop::Never,
    };
    let theta = DVector::from_element(1, free[0].coordinate(truth.get(k).unwrap()));
    let shared = model.predictions(&theta).unwrap();
    let alone = model.observed();
    shared
        .iter()
        .zip(&alone)
        .map(|(s, a)| (s - a).abs() / a.abs())
        .fold(0.0, f64::max)
}

/// The running-in's own accuracy: `spatial.time_tolerance`, 1e-6 in these presets, bounds the
/// time-stepping error of its outputs at about that relative size (`preset::default_spatial_section`,
/// docs/physics/spatial-partial.md section 5); the shared running-in takes the same steps, so
/// the values agree far closer than that.
const TOLERANCE: f64 = 1e-6;

/// The linear law: the rubber's running-in (complete at 4.31 ks), at times before and after
/// complete contact, out of order and one twice.
#[test]
fn one_running_in_read_at_every_time_gives_each_times_own_solve() {
    let truth = preset::load(Path::new("presets/rubber-running-in.toml")).unwrap();
    let times = [3600.0, 450.0, 0.0, 5000.0, 1800.0, 450.0, 4300.0];
    let d = largest_difference(&truth, &times);
    assert!(d <= TOLERANCE, "{d:e}");
}

/// A nonlinear wear law (n = 2), stepped on the grid through complete contact: the running-in
/// to the latest time takes the steps of each earlier time's own.
#[test]
fn a_nonlinear_laws_running_in_read_at_every_time_gives_each_times_own_solve() {
    let truth = preset::load(Path::new("presets/rubber-running-in.toml"))
        .unwrap()
        .with_settings(&["wear.exponent=2", "wear.reference_pressure=40kPa"])
        .unwrap();
    let times = [2000.0, 500.0, 6000.0, 1000.0];
    let d = largest_difference(&truth, &times);
    assert!(d <= TOLERANCE, "{d:e}");
}
