//! The explore sweeps' speed targets: a 200-point curve of the wide model (< 2 ms), a 64 x 64 map of the
//! wide model with its lines (< 50 ms), a 32 x 32 map of the strip model (a few seconds on two
//! cores) and its first, coarse pass (< 100 ms).

use std::hint::black_box;
use std::sync::atomic::{AtomicBool, Ordering};

use criterion::{Criterion, criterion_group, criterion_main};
use wearlab::physics::Spacing;
use wearlab::physics::plane::Model;
use wearlab::preset::{Preset, bundled};
use wearlab::sweeps::axis::Axis;
use wearlab::sweeps::curve::{CurveSpec, curve};
use wearlab::sweeps::map::{MapSpec, regime_map};
use wearlab::sweeps::quantity::QuantityKey;

fn axis(p: &Preset, key: &str, ends: [f64; 2], n: usize) -> Axis {
    Axis::new(p, p.key(key).unwrap(), ends, n, Spacing::Log).unwrap()
}

fn wide(c: &mut Criterion) {
    let p = bundled("polymer-coating.toml").unwrap().unwrap();
    let mu_star = QuantityKey::parse("mu_star", &p).unwrap();
    let spec = CurveSpec {
        axis: axis(&p, "material.thickness", [1e-4, 1e-1], 200),
        quantity: mu_star,
        models: vec![Model::Wide],
    };
    let never = AtomicBool::new(false);
    c.bench_function("sweep_curve/wide_200", |b| {
        b.iter(|| black_box(curve(&p, black_box(&spec), &never)))
    });
    let overlays = CurveSpec {
        models: vec![Model::Wide, Model::Narrow],
        ..spec.clone()
    };
    c.bench_function("sweep_curve/wide_200_with_narrow", |b| {
        b.iter(|| black_box(curve(&p, black_box(&overlays), &never)))
    });
    // (P, h) crosses both validity boundaries: every point solves the wide and narrow models
    let map = MapSpec {
        x: axis(&p, "plane.load", [1e2, 1e7], 64),
        y: axis(&p, "material.thickness", [1e-5, 1e-1], 64),
        quantity: mu_star,
    };
    c.bench_function("regime_map/wide_64x64", |b| {
        b.iter(|| black_box(regime_map(&p, black_box(&map), &never, &mut |_| {})))
    });
}

fn strip(c: &mut Criterion) {
    let p = bundled("coating-thickness-sweep.toml").unwrap().unwrap();
    // (a+b)/h from about 0.2 to 30
    let map = MapSpec {
        x: axis(&p, "plane.load", [1e2, 1e4], 32),
        y: axis(&p, "material.thickness", [1e-5, 1e-3], 32),
        quantity: QuantityKey::parse("mu_star_minus_mu", &p).unwrap(),
    };
    let mut group = c.benchmark_group("regime_map");
    group.sample_size(10);
    group.bench_function("strip_32x32_first_pass", |b| {
        b.iter(|| {
            let cancel = AtomicBool::new(false);
            regime_map(&p, &map, &cancel, &mut |_| {
                cancel.store(true, Ordering::Relaxed)
            })
        })
    });
    group.bench_function("strip_32x32", |b| {
        let never = AtomicBool::new(false);
        b.iter(|| black_box(regime_map(&p, &map, &never, &mut |_| {})))
    });
    group.finish();
}

criterion_group!(benches, wide, strip);
criterion_main!(benches);
