//! The fit's speed targets (profiles included): a two-parameter fit (mu, k) of the 20-point
//! mu*(P) dataset of `examples/lab/` with the wide model (< 50 ms) and with the strip model
//! (< 1 s), and a fit of k to a running-in trace, mu*(t) of `presets/rubber-running-in.toml`
//! (< 10 s).

use std::hint::black_box;
use std::io::Write;
use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use wearlab::data::{self, DataSet};
use wearlab::fit::{self, synthetic};
use wearlab::preset::{self, Preset};
use wearlab::sweeps::QuantityKey;

fn lab(settings: &[&str]) -> (Preset, DataSet) {
    let p = preset::load(Path::new("examples/lab/friction-against-load.toml"))
        .unwrap()
        .with_settings(settings)
        .unwrap();
    let set = data::read(Path::new("examples/lab/friction-against-load.csv"), &p).unwrap();
    (p, set)
}

fn two_parameters(c: &mut Criterion) {
    let (p, set) = lab(&[]);
    let keys = [
        p.key("friction.coefficient").unwrap(),
        p.key("wear.coefficient").unwrap(),
    ];
    c.bench_function("fit/wide_mu_k_20_points", |b| {
        b.iter(|| black_box(fit::fit(&p, black_box(&set), &keys).unwrap()))
    });
}

fn two_parameters_strip(c: &mut Criterion) {
    let (p, set) = lab(&["plane.model=strip"]);
    let keys = [
        p.key("friction.coefficient").unwrap(),
        p.key("wear.coefficient").unwrap(),
    ];
    let mut group = c.benchmark_group("fit");
    group.sample_size(10);
    group.bench_function("strip_mu_k_20_points", |b| {
        b.iter(|| black_box(fit::fit(&p, black_box(&set), &keys).unwrap()))
    });
    group.finish();
}

/// mu*(t) of the rubber's running-in at 8 times before its contact is complete (4.31 ks), made
/// by the model at the preset's k = 1e-12 1/Pa with noise of sd 0.001 (seed 25); the fit starts
/// from k = 3e-12 1/Pa.
fn running_in(c: &mut Criterion) {
    let truth = preset::load(Path::new("presets/rubber-running-in.toml")).unwrap();
    let time = truth.key("spatial.time").unwrap();
    let quantity = QuantityKey::parse("mu_star", &truth).unwrap();
    let times: Vec<f64> = (1..=8).map(|i| 450.0 * i as f64).collect();
    let mu = synthetic::measure(&truth, time, &times, quantity, 1e-3, 25).unwrap();
    let mut file = tempfile::NamedTempFile::new().unwrap();
    writeln!(
        file,
        "# synthetic: rubber-running-in at k = 1e-12 1/Pa, sd 0.001, seed 25"
    )
    .unwrap();
    writeln!(file, "time [s],mu [-]").unwrap();
    for (t, m) in times.iter().zip(&mu) {
        writeln!(file, "{t:e},{m:e}").unwrap();
    }
    file.flush().unwrap();
    let start = truth.with_settings(&["wear.coefficient=3e-12"]).unwrap();
    let set = data::read(file.path(), &start).unwrap();
    let keys = [start.key("wear.coefficient").unwrap()];
    let mut group = c.benchmark_group("fit");
    group.sample_size(10);
    group.bench_function("running_in_k_8_times", |b| {
        b.iter(|| black_box(fit::fit(&start, black_box(&set), &keys).unwrap()))
    });
    group.finish();
}

criterion_group!(benches, two_parameters, two_parameters_strip, running_in);
criterion_main!(benches);
