//! The active set with 64 harmonics (docs/physics/spatial-partial.md section 3): one
//! partial-contact solve from a cold start of the egg-box of `spatial_partial` (one harmonic) and
//! of a punch of 64 harmonics with the same rms height, on 64 x 64, 128 x 128 and 256 x 256. Each
//! case prints its contact fraction and its work (active-set iterations, GMRES products), which
//! the time follows: how the work grows with the grid, and with the harmonics at a given grid.
//! The same punches frictionless on a steel half-space (`frictionless/...`) are the cases Tamaas
//! also solves (`scripts/tamaas-comparison/partial_harmonics.py`): each prints p_max and the mean
//! gap beside the contact fraction, to compare answers as well as times.

use std::f64::consts::PI;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use wearlab::physics::spatial::harmonic::Harmonic;
use wearlab::physics::spatial::partial::Setup;
use wearlab::physics::spatial::{PunchShape, SpatialInputs};
use wearlab::preset::bundled;

/// The egg-box of "jgh-egg-box" at a quarter of its mean pressure, with friction on a layer (the
/// partial-contact case of `spatial_partial`).
fn egg_box() -> SpatialInputs {
    let mut egg = bundled("jgh-egg-box.toml")
        .unwrap()
        .unwrap()
        .spatial_inputs();
    egg.mean_pressure = 2.5e7;
    egg.friction.coefficient = 0.3;
    egg.material.thickness = 5e-4;
    egg
}

/// The egg-box's punch replaced by 64 harmonics: wavenumbers (i, j) k0 for i, j = 1..8 (k0 the
/// egg-box's), amplitudes falling as 1/(i^2 + j^2) and scaled so that the rms height is the
/// egg-box's (the products of sines are orthogonal: rms^2 = sum A^2/4), phases spread by the
/// golden ratio.
fn sixty_four(egg: &SpatialInputs) -> SpatialInputs {
    let one = egg.harmonics()[0];
    let k0 = one.wavenumber_x;
    let golden = 0.5 * (5f64.sqrt() - 1.0);
    let mut harmonics: Vec<Harmonic> = (1..=8)
        .flat_map(|i| (1..=8).map(move |j| (i, j)))
        .enumerate()
        .map(|(n, (i, j))| Harmonic {
            amplitude: 1.0 / f64::from(i * i + j * j),
            wavenumber_x: f64::from(i) * k0,
            wavenumber_y: f64::from(j) * k0,
            phase_x: 2.0 * PI * ((2 * n + 1) as f64 * golden).fract(),
            phase_y: 2.0 * PI * ((2 * n + 2) as f64 * golden).fract(),
        })
        .collect();
    let sum: f64 = harmonics.iter().map(|h| h.amplitude * h.amplitude).sum();
    let scale = one.amplitude / sum.sqrt();
    harmonics.iter_mut().for_each(|h| h.amplitude *= scale);
    SpatialInputs {
        shape: PunchShape::Harmonics(harmonics),
        ..egg.clone()
    }
}

/// The punch of `inputs` without friction on a half-space of the same steel.
fn frictionless(inputs: &SpatialInputs) -> SpatialInputs {
    let mut f = inputs.clone();
    f.friction.coefficient = 0.0;
    f.material.thickness = f64::INFINITY;
    f
}

fn bench(c: &mut Criterion) {
    let egg = egg_box();
    let many = sixty_four(&egg);
    let (egg_hs, many_hs) = (frictionless(&egg), frictionless(&many));
    let cases = [
        ("", 1, &egg),
        ("", 64, &many),
        ("frictionless/", 1, &egg_hs),
        ("frictionless/", 64, &many_hs),
    ];
    for (family, count, inputs) in cases {
        for side in [64, 128, 256] {
            let Ok(setup) = Setup::new(inputs, side) else {
                // 64 harmonics need 16 nodes per wavelength of the 8th: 128 and up
                continue;
            };
            let s = setup.initial_state().unwrap();
            assert!(!s.outputs.complete);
            let name = format!("partial_harmonics/{family}{count}/{side}x{side}");
            let o = s.outputs;
            println!(
                "{name}: contact {:.4}, p_max {:.6e} Pa, mean gap {:.6e} m, {:?}",
                o.contact_fraction, o.max_pressure, o.mean_gap, s.work
            );
            c.bench_function(&name, |b| {
                b.iter(|| black_box(setup.initial_state().unwrap()))
            });
        }
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).measurement_time(Duration::from_secs(2));
    targets = bench
}
criterion_main!(benches);
