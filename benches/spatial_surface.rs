//! Rough surfaces (docs/physics/spatial-surface.md), the three cases of benches/reference/*.toml:
//! one frictionless partial-contact solve from cold of a self-affine map on 256 x 256 (the case
//! Tamaas also solves, scripts/tamaas-comparison/rough_surface.py), the state at t of a
//! 1024 x 1024 map in complete contact on a thin layer (every Fourier mode's closed form by FFT;
//! the same script computes it with numpy).

use std::path::Path;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use wearlab::physics::spatial::partial::Setup;
use wearlab::physics::spatial::pipeline;
use wearlab::preset::{Preset, parse};

fn preset(text: &str, name: &str) -> Preset {
    parse(text, Path::new(name)).unwrap()
}

fn bench(c: &mut Criterion) {
    let rough = preset(include_str!("reference/rough-256.toml"), "rough-256.toml");
    let setup = Setup::new(&rough.spatial_inputs(), 8).unwrap();
    let s = setup.initial_state().unwrap();
    assert!(!s.outputs.complete);
    println!(
        "rough_partial/256x256: contact {:.6}, p_max {:.9e} Pa, mean gap {:.9e} m, {:?}",
        s.outputs.contact_fraction, s.outputs.max_pressure, s.outputs.mean_gap, s.work
    );
    c.bench_function("rough_partial/256x256", |b| {
        b.iter(|| black_box(setup.initial_state().unwrap()))
    });

    let complete = preset(
        include_str!("reference/rough-1024-complete.toml"),
        "rough-1024-complete.toml",
    );
    let inputs = complete.spatial_inputs();
    let at = complete.spatial_state_at();
    let r = pipeline::solve(&inputs, &at, &[], false).unwrap();
    assert!(r.contact.complete);
    let surface = r.surface.as_ref().unwrap();
    println!(
        "rough_complete_state/1024x1024 at t = {} s: p from {:.9e} to {:.9e} Pa, rms height \
         {:.9e} m",
        r.time, r.contact.min_pressure, r.max_pressure, surface.rms_height
    );
    c.bench_function("rough_complete_state/1024x1024", |b| {
        b.iter(|| black_box(pipeline::solve(&inputs, &at, &[], false).unwrap()))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).measurement_time(Duration::from_secs(3));
    targets = bench
}
criterion_main!(benches);
