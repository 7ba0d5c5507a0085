//! The spatial field: 128 x 128 grid, 8 harmonics (pressure, shape and wear), and the
//! complete-contact check on the same pattern.

use criterion::{Criterion, criterion_group, criterion_main};
use std::f64::consts::PI;
use std::hint::black_box;
use wearlab::physics::spatial::contact::check;
use wearlab::physics::spatial::field::field;
use wearlab::physics::spatial::harmonic::Harmonic;
use wearlab::physics::spatial::{Cell, SpatialInputs, solve};
use wearlab::physics::{Friction, Material};

fn eight_harmonics() -> SpatialInputs {
    let w = 2.0 * PI / 4e-3;
    let harmonics = (0..8)
        .map(|n| Harmonic {
            amplitude: 1e-6 / (n + 1) as f64,
            wavenumber_x: w * (1 + n % 4) as f64,
            wavenumber_y: w * (n / 2) as f64,
            phase_x: 0.3 * n as f64,
            phase_y: 1.0 + 0.2 * n as f64,
        })
        .collect();
    SpatialInputs {
        material: Material {
            youngs_modulus: 1e7,
            poisson_ratio: 0.45,
            thickness: 5e-4,
        },
        friction: Friction {
            coefficient: 0.8,
            adhesion: 0.0,
        },
        wear: 1e-12,
        sliding_speed: 0.1,
        mean_pressure: 2e6,
        harmonics,
    }
}

fn bench(c: &mut Criterion) {
    let inputs = eight_harmonics();
    let sol = solve(&inputs, 10.0).unwrap();
    let cell = Cell::of(&inputs.harmonics);
    c.bench_function("spatial_field/128x128x8", |b| {
        b.iter(|| black_box(field(black_box(&sol), &cell, 128)))
    });
    c.bench_function("spatial_contact/8", |b| {
        b.iter(|| black_box(check(black_box(&sol), &cell)))
    });
    c.bench_function("spatial_solve/8", |b| {
        b.iter(|| black_box(solve(black_box(&inputs), 10.0).unwrap()))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
