//! A running-in trace fitted: the fit's model reads every row's time from one running-in
//! (`spatial::at_times`); each value is the one a solve at that row's time alone gives
//! (`synthetic::measure` without noise: `sweeps::point::solve`, `wearlab solve --time T`), and
//! under the linear law at every k from one running-in with its time scaled.

use std::path::Path;

use nalgebra::DVector;
use wearlab::data;
use wearlab::fit::{Free, Model, synthetic};
use wearlab::physics::stop::Stop;
use wearlab::preset::{self, Preset};
use wearlab::sweeps::QuantityKey;

/// `mu_star` and the contact fraction at `times` by one solve per time, as a data file's rows.
fn each_time_alone(truth: &Preset, times: &[f64]) -> Vec<f64> {
    let time = truth.key("spatial.time").unwrap();
    let q = |name| QuantityKey::parse(name, truth).unwrap();
    let mu = synthetic::measure(truth, time, times, q("mu_star"), 0.0, 1).unwrap();
    let fraction = synthetic::measure(truth, time, times, q("contact.fraction"), 0.0, 1).unwrap();
    mu.iter()
        .zip(&fraction)
        .flat_map(|(m, f)| [*m, *f])
        .collect()
}

/// The largest difference of `values` from `reference`, relative to the reference.
fn relative_difference(values: &[f64], reference: &[f64]) -> f64 {
    values
        .iter()
        .zip(reference)
        .map(|(s, a)| (s - a).abs() / a.abs())
        .fold(0.0, f64::max)
}

/// The data file of `mu_star` and the contact fraction of `truth` at `times`.
fn trace(truth: &Preset, times: &[f64]) -> data::DataSet {
    let mut text = String::from("time [s],mu [-],contact fraction [-]\n");
    let alone = each_time_alone(truth, times);
    for (t, row) in times.iter().zip(alone.chunks(2)) {
        text.push_str(&format!("{t:e},{:e},{:e}\n", row[0], row[1]));
    }
    data::read_text(Path::new("trace.csv"), &text, truth).unwrap()
}

/// The model's values at `times` (in file order) against one solve per time, for `mu_star` and
/// the contact fraction: the largest difference relative to the value.
fn largest_difference(truth: &Preset, times: &[f64]) -> f64 {
    let set = trace(truth, times);
    let time = truth.key("spatial.time").unwrap();
    let k = truth.key("wear.coefficient").unwrap();
    let free = [Free::new(truth, k, time).unwrap()];
    let model = Model::new(truth, &set, &free, vec![1.0; 2 * times.len()], Stop::Never);
    let theta = DVector::from_element(1, free[0].coordinate(truth.get(k).unwrap()));
    relative_difference(&model.predictions(&theta).unwrap(), &model.observed())
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

/// The linear law's running-in depends on k only through k t (`RunningIn::scaled_to`): the
/// model steps one running-in, at the first k it is asked for (3e-12 1/Pa), and reads every
/// other k from it with its time scaled. Each value against a running-in stepped at that k from
/// t = 0 for each time alone, over two decades of k: at 1e-11 1/Pa the contact is complete from
/// 431 s (the preset's 4.31 ks over 10), so the later times are read from the closed form after
/// it; at 3e-13 1/Pa every time is before complete contact.
#[test]
fn one_running_in_scaled_in_time_gives_the_running_in_at_every_k() {
    let truth = preset::load(Path::new("presets/rubber-running-in.toml")).unwrap();
    let times = [450.0, 1800.0, 3600.0, 5000.0];
    let set = trace(&truth, &times);
    let time = truth.key("spatial.time").unwrap();
    let k = truth.key("wear.coefficient").unwrap();
    let free = [Free::new(&truth, k, time).unwrap()];
    let model = Model::new(&truth, &set, &free, vec![1.0; 2 * times.len()], Stop::Never);
    for value in [3e-12, 1e-12, 3e-13, 1e-11, 1.234_567e-12] {
        let at = truth
            .with_settings(&[&format!("wear.coefficient={value:e}")])
            .unwrap();
        let theta = DVector::from_element(1, free[0].coordinate(value));
        let scaled = model.predictions(&theta).unwrap();
        let d = relative_difference(&scaled, &each_time_alone(&at, &times));
        assert!(d <= TOLERANCE, "k = {value:e}: {d:e}");
    }
    assert_eq!(model.running_ins_stepped(), 1);
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
