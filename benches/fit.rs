//! The fit's speed target: a two-parameter fit (mu, k) of the 20-point mu*(P) dataset of
//! `examples/lab/` with the wide model, profiles included (< 50 ms).

use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use wearlab::data;
use wearlab::fit;
use wearlab::preset;

fn two_parameters(c: &mut Criterion) {
    let p = preset::load(Path::new("examples/lab/friction-against-load.toml")).unwrap();
    let set = data::read(Path::new("examples/lab/friction-against-load.csv"), &p).unwrap();
    let keys = [
        p.key("friction.coefficient").unwrap(),
        p.key("wear.coefficient").unwrap(),
    ];
    c.bench_function("fit/wide_mu_k_20_points", |b| {
        b.iter(|| black_box(fit::fit(&p, black_box(&set), &keys).unwrap()))
    });
}

criterion_group!(benches, two_parameters);
criterion_main!(benches);
