//! The explore sweeps' speed targets: a 200-point curve of the wide model (< 2 ms; what the chart
//! draws first, then the whole curve with its verdicts), a 64 x 64 map of the
//! wide model with its lines (< 50 ms), a 32 x 32 map of the strip model (a few seconds on two
//! cores) and its first, coarse pass (< 100 ms).

use std::hint::black_box;
use std::sync::atomic::{AtomicBool, Ordering};

use criterion::{Criterion, criterion_group, criterion_main};
use wearlab::preset::bundled;
use wearlab::sweeps::curve::{curve, solve};
use wearlab::sweeps::map::{MapSpec, regime_map};
use wearlab::sweeps::quantity::QuantityKey;

#[path = "common/explore_sweeps.rs"]
mod explore_sweeps;
use explore_sweeps::{axis, explore_sweeps};

fn wide(c: &mut Criterion) {
    let s = explore_sweeps();
    let never = AtomicBool::new(false);
    // what the sweep chart draws first, then the whole curve with its verdicts
    for (name, spec) in [
        ("wide_200", &s.wide),
        ("wide_200_with_narrow", &s.with_narrow),
    ] {
        c.bench_function(&format!("sweep_curve/{name}"), |b| {
            b.iter(|| {
                black_box(solve(&s.preset, black_box(spec), (&never).into()).map(|c| c.unjudged()))
            })
        });
        c.bench_function(&format!("sweep_curve/{name}_judged"), |b| {
            b.iter(|| black_box(curve(&s.preset, black_box(spec), &never)))
        });
    }
    c.bench_function("regime_map/wide_64x64", |b| {
        b.iter(|| {
            black_box(regime_map(
                &s.preset,
                black_box(&s.map),
                &never,
                &mut |_| {},
            ))
        })
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
