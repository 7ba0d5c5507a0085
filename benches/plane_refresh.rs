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

fn strip_sweep(c: &mut Criterion) {
    use wearlab::physics::{Friction, Material};
    // docs/physics/plane.md's table case (E = 1e10, nu = 0.3, R = 0.05, mu = 0.3, k m = 0.5) on h = 1e-5 m:
    // loads 10..500 N/m give (a+b)/h from about 1.5 to 5; 1e4..2e4 N/m give about 20.
    let m = wearlab::physics::elastic::plane_modulus(1e10, 0.3);
    let inputs = wearlab::physics::plane::PlaneInputs {
        material: Material {
            youngs_modulus: 1e10,
            poisson_ratio: 0.3,
            thickness: 1e-5,
        },
        friction: Friction {
            coefficient: 0.3,
            adhesion: 0.0,
        },
        wear: 0.5 / m,
        radius: 0.05,
        load: 100.0,
    };
    wearlab::physics::plane::strip::kernels_for(0.3);
    for (name, min, max) in [
        ("strip_sweep/upto_5h", 10.0, 500.0),
        ("strip_sweep/20h", 1e4, 2e4),
    ] {
        let loads = SweepRange {
            min,
            max,
            points: 100,
            spacing: Spacing::Log,
        };
        c.bench_function(name, |b| {
            b.iter(|| sweep(black_box(&inputs), Model::Strip, &loads))
        });
    }
}

fn strip_table(c: &mut Criterion) {
    c.bench_function("strip_table", |b| {
        b.iter(|| wearlab::physics::plane::kernels::StripKernels::new(black_box(0.3)))
    });
}

criterion_group! {
    name = strip;
    config = Criterion::default().sample_size(10);
    targets = strip_sweep
}
criterion_group!(benches, refresh, strip_table);
criterion_main!(benches, strip);
