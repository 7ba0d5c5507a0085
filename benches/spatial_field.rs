//! The spatial field (pressure, shape and wear): 8 harmonics on 128 x 128 and 32 on 512 x 512,
//! the cases of `benches/reference/spatial_field.py` (numpy, one matrix product per field), into
//! fresh buffers (`field`, as numpy allocates its results: page faults included) and into reused
//! ones (`field_into`); and the complete-contact check on the 8-harmonic pattern. In CPU time.

use criterion::{Criterion, criterion_group, criterion_main};
use std::f64::consts::PI;
use std::hint::black_box;
use wearlab::physics::spatial::contact::check;
use wearlab::physics::spatial::field::{field, field_into};
use wearlab::physics::spatial::harmonic::Harmonic;
use wearlab::physics::spatial::{Cell, PunchShape, SpatialInputs, solve};
use wearlab::physics::{Friction, Material};

mod common;
use common::cpu_time::CpuTime;

/// `count` harmonics in distinct directions: wx = w (1 + n mod d), wy = w (n div e): on
/// d x count/e wave vectors, sharing wavenumbers (merged by the field) unless d = count, e = 1.
fn harmonics(count: usize, (d, e): (usize, usize)) -> SpatialInputs {
    let w = 2.0 * PI / 4e-3;
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
        wear_exponent: 1.0,
        reference_pressure: 1.0,
        sliding_speed: 0.1,
        mean_pressure: 2e6,
        shape: PunchShape::Harmonics(harmonics),
    }
}

fn bench(c: &mut Criterion<CpuTime>) {
    // the reference script's cases, then 32 harmonics that share no wavenumber (no merging)
    for (count, n, spread, name) in [
        (8, 128, (4, 2), ""),
        (32, 512, (8, 8), ""),
        (32, 512, (32, 1), "_distinct"),
    ] {
        let inputs = harmonics(count, spread);
        let sol = solve(&inputs, 10.0).unwrap();
        let cell = Cell::of(inputs.harmonics());
        if name.is_empty() {
            c.bench_function(&format!("spatial_field/{n}x{n}x{count}"), |b| {
                b.iter(|| black_box(field(black_box(&sol), &cell, n)))
            });
        }
        let mut reused = field(&sol, &cell, n);
        c.bench_function(
            &format!("spatial_field_reused/{n}x{n}x{count}{name}"),
            |b| b.iter(|| field_into(black_box(&sol), &cell, n, black_box(&mut reused))),
        );
    }
    let inputs = harmonics(8, (4, 2));
    let sol = solve(&inputs, 10.0).unwrap();
    let cell = Cell::of(inputs.harmonics());
    c.bench_function("spatial_contact/8", |b| {
        b.iter(|| black_box(check(black_box(&sol), &cell)))
    });
    c.bench_function("spatial_solve/8", |b| {
        b.iter(|| black_box(solve(black_box(&inputs), 10.0).unwrap()))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().with_measurement(CpuTime);
    targets = bench
}
criterion_main!(benches);
