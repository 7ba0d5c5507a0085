//! A full plane refresh: the operating point, a 201-point profile and a 200-point load sweep.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use wearlab::physics::plane::profile::profile;
use wearlab::physics::plane::sweep::sweep;
use wearlab::physics::plane::{Model, solve};
use wearlab::physics::{Spacing, SweepRange};
use wearlab::preset::bundled;

fn refresh(c: &mut Criterion) {
    for (file, model) in [
        ("polymer-coating.toml", Model::Wide),
        ("thin-strip-winkler.toml", Model::Narrow),
    ] {
        let preset = bundled(file).unwrap().unwrap();
        let inputs = preset.plane_inputs();
        let loads = SweepRange {
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

criterion_group!(benches, refresh);
criterion_main!(benches);
