//! A full plane refresh: the operating point, a 201-point profile and a 200-point load sweep.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use wearlab::physics::Spacing;
use wearlab::physics::plane::profile::profile;
use wearlab::physics::plane::sweep::{LoadSweep, sweep};
use wearlab::physics::plane::{Model, solve};
use wearlab::preset::bundled;

fn refresh(c: &mut Criterion) {
    for (file, model) in [
        ("polymer-coating.toml", Model::Wide),
        ("thin-strip-winkler.toml", Model::Narrow),
    ] {
        let preset = bundled(file).unwrap().unwrap();
        let inputs = preset.plane_inputs();
        let loads = LoadSweep {
            points: 200,
            spacing: Spacing::Log,
            ..preset.plane.sweep
        };
        c.bench_function(&format!("plane_refresh/{}", model.name()), |b| {
            b.iter(|| {
                let sol = solve(black_box(&inputs), model).unwrap();
                let prof = profile(&sol, 201);
                let sw = sweep(&inputs, model, &loads);
                black_box((prof, sw))
            })
        });
        c.bench_function(&format!("plane_energy/{}", model.name()), |b| {
            let sol = solve(&inputs, model).unwrap();
            b.iter(|| black_box(wearlab::physics::plane::energy::energy(black_box(&sol))))
        });
    }
}

fn strip_table(c: &mut Criterion) {
    c.bench_function("strip_table", |b| {
        b.iter(|| wearlab::physics::plane::kernels::StripKernels::new(black_box(0.3)))
    });
}

criterion_group!(benches, refresh, strip_table);
criterion_main!(benches);
