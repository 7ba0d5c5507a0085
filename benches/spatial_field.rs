//! The spatial field (pressure, shape and wear): 8 harmonics on 128 x 128 and 32 on 512 x 512,
//! the cases of `benches/reference/spatial_field.py` (numpy, one matrix product per field); and
//! the complete-contact check on the 8-harmonic pattern.

use criterion::{Criterion, criterion_group, criterion_main};
use std::f64::consts::PI;
use std::hint::black_box;
use wearlab::physics::spatial::contact::check;
use wearlab::physics::spatial::field::field;
use wearlab::physics::spatial::harmonic::Harmonic;
use wearlab::physics::spatial::{Cell, SpatialInputs, solve};
use wearlab::physics::{Friction, Material};

/// `count` harmonics in distinct directions: wx = w (1 + n mod d), wy = w (n div e) with
/// (d, e) = (4, 2) for 8 harmonics and (8, 8) for more.
fn harmonics(count: usize) -> SpatialInputs {
    let w = 2.0 * PI / 4e-3;
    let (d, e) = if count > 8 { (8, 8) } else { (4, 2) };
    let harmonics = (0..count)
        .map(|n| Harmonic {
            amplitude: 1e-6 / (n + 1) as f64,
            wavenumber_x: w * (1 + n % d) as f64,
            wavenumber_y: w * (n / e) as f64,
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
    for (count, n) in [(8, 128), (32, 512)] {
        let inputs = harmonics(count);
        let sol = solve(&inputs, 10.0).unwrap();
        let cell = Cell::of(&inputs.harmonics);
        c.bench_function(&format!("spatial_field/{n}x{n}x{count}"), |b| {
            b.iter(|| black_box(field(black_box(&sol), &cell, n)))
        });
    }
    let inputs = harmonics(8);
    let sol = solve(&inputs, 10.0).unwrap();
    let cell = Cell::of(&inputs.harmonics);
    c.bench_function("spatial_contact/8", |b| {
        b.iter(|| black_box(check(black_box(&sol), &cell)))
    });
    c.bench_function("spatial_solve/8", |b| {
        b.iter(|| black_box(solve(black_box(&inputs), 10.0).unwrap()))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
