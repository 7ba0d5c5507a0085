//! Partial contact (docs/physics/spatial-partial.md): one active-set solve on 128 x 128,
//! 256 x 256 and 4096 x 1, and a running-in to complete contact for a 1-D and a 2-D preset.

use std::ops::ControlFlow;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use wearlab::physics::spatial::SpatialInputs;
use wearlab::physics::spatial::partial::Setup;
use wearlab::physics::spatial::partial::running_in::{Stepping, run_in_with};
use wearlab::preset::{bundled, default_spatial_section};

fn preset(file: &str) -> SpatialInputs {
    bundled(file).unwrap().unwrap().spatial_inputs()
}

/// One contact solve from a cold start (the complete-contact set).
fn solve_once(c: &mut Criterion, name: &str, inputs: &SpatialInputs, side: usize) {
    let setup = Setup::new(inputs, side).unwrap();
    let s = setup.initial_state().unwrap();
    assert!(!s.outputs.complete);
    println!(
        "{name}: contact {:.3}, {:?}",
        s.outputs.contact_fraction, s.work
    );
    c.bench_function(name, |b| {
        b.iter(|| black_box(setup.initial_state().unwrap()))
    });
}

fn bench(c: &mut Criterion) {
    // the egg-box of "jgh-egg-box" at a quarter of its mean pressure, with friction on a layer
    let mut egg = preset("jgh-egg-box.toml");
    egg.mean_pressure = 2.5e7;
    egg.friction.coefficient = 0.3;
    egg.material.thickness = 5e-4;
    solve_once(c, "partial_solve/128x128", &egg, 128);
    solve_once(c, "partial_solve/256x256", &egg, 256);
    // the 1-D wave of "contact-lost" (partial at t = 0)
    let wave = preset("contact-lost.toml");
    solve_once(c, "partial_solve/4096x1", &wave, 4096);
    // running-in to complete contact: the 1-D wave on 1024 nodes and the egg-box on 64 x 64,
    // with the default time tolerance
    let tolerance = default_spatial_section().time_tolerance;
    let wave_setup = Setup::new(&wave, 1024).unwrap();
    let egg_setup = Setup::new(&egg, 64).unwrap();
    for (name, setup) in [
        ("running_in/1d_1024", &wave_setup),
        ("running_in/2d_64x64", &egg_setup),
    ] {
        let stepping = Stepping::of(setup, tolerance);
        let go = || run_in_with(setup, stepping, &mut |_| ControlFlow::Continue(())).unwrap();
        let run = go();
        println!(
            "{name}: {} steps ({} refused) to complete contact at t = {:.6e} s, time-step error \
             {:.1e}",
            run.samples.len() - 1,
            run.rejected,
            run.time_to_complete.unwrap(),
            run.time_error(f64::INFINITY).unwrap()
        );
        c.bench_function(name, |b| b.iter(|| black_box(go())));
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).measurement_time(Duration::from_secs(3));
    targets = bench
}
criterion_main!(benches);
