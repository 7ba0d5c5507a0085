//! The general plane solver (docs/physics/plane-general.md): one operating point of the wide model
//! for a power punch (n = 3) with the wear law n = 2 and a shear cap, on the half-plane and on a
//! 1 mm strip, and one with the linear laws on a flat punch with rounded edges; both punches on
//! the narrow model (a 0.1 mm layer, the power punch with the cap) and on the exact strip (0.1 mm,
//! no cap: the strip refuses one; (a+b)/h = 15.4 and 4.6, printed). Targets: < 5 ms wide and
//! narrow, < 20 ms the strip at (a+b)/h <= 20. Then the library's 60-point load sweep from
//! P = 1e3 to 1e5 N/m for both punches on the wide (half-plane) and narrow models, in two stages
//! as the explorer's mu*(P) chart and `wearlab solve`'s sweep take them: the curve
//! (`general_sweep/*`: `sweep::solve`, the model at every load; target < 100 ms) and its validity
//! verdicts (`general_sweep_verdicts/*`: `Solved::judged` on the curve solved beforehand, the
//! strip solves where the study doubts the model).
//! Case: E = 1e10 Pa, nu = 0.3, R = 0.05 m, c = 0.1 mm, r = 0.05 m, mu = 0.3, tau0 = 1e5 Pa,
//! k m = 0.5, p0 = 1e8 Pa, P = 1e4 N/m. Measured in CPU time (see benches/strip.rs).

use std::hint::black_box;
use std::time::Duration;

use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use wearlab::physics::plane::sweep::solve as solve_sweep;
use wearlab::physics::plane::{Model, PlaneInputs, Shape, WearLaw, solve};
use wearlab::physics::{Friction, Material, Spacing, SweepRange};

mod common;
use common::cpu_time::CpuTime;

fn inputs(thickness: f64, shape: Shape, wear_exponent: f64, shear_strength: f64) -> PlaneInputs {
    let m = wearlab::physics::elastic::plane_modulus(1e10, 0.3);
    PlaneInputs {
        material: Material {
            youngs_modulus: 1e10,
            poisson_ratio: 0.3,
            thickness,
        },
        friction: Friction {
            coefficient: 0.3,
            adhesion: 1e5,
        },
        shear_strength,
        wear: WearLaw {
            coefficient: 0.5 / m,
            exponent: wear_exponent,
            reference_pressure: 1e8,
        },
        shape,
        load: 1e4,
    }
}

fn power() -> Shape {
    Shape::Power {
        radius: 0.05,
        exponent: 3.0,
    }
}

fn rounded_flat() -> Shape {
    Shape::Flat {
        half_width: 1e-4,
        edge_radius: 0.05,
    }
}

fn operating_points(c: &mut Criterion<CpuTime>) {
    let cases = [
        (
            "power_capped_half_plane",
            inputs(f64::INFINITY, power(), 2.0, 2e6),
            Model::Wide,
        ),
        (
            "power_capped_1mm",
            inputs(1e-3, power(), 2.0, 2e6),
            Model::Wide,
        ),
        (
            "rounded_flat_half_plane",
            inputs(f64::INFINITY, rounded_flat(), 1.0, f64::INFINITY),
            Model::Wide,
        ),
        (
            "power_capped_narrow",
            inputs(1e-4, power(), 2.0, 2e6),
            Model::Narrow,
        ),
        (
            "rounded_flat_narrow",
            inputs(1e-4, rounded_flat(), 1.0, f64::INFINITY),
            Model::Narrow,
        ),
        (
            "power_strip_0.1mm",
            inputs(1e-4, power(), 2.0, f64::INFINITY),
            Model::Strip,
        ),
        (
            "rounded_flat_strip_0.1mm",
            inputs(1e-4, rounded_flat(), 1.0, f64::INFINITY),
            Model::Strip,
        ),
    ];
    for (name, at, model) in cases {
        let once = solve(&at, model).unwrap();
        println!(
            "general_point/{name}: (a+b)/h = {:.2}",
            once.contact_width() / at.material.thickness
        );
        c.bench_function(&format!("general_point/{name}"), |b| {
            b.iter(|| solve(black_box(&at), model).unwrap())
        });
    }
}

fn load_sweeps(c: &mut Criterion<CpuTime>) {
    let loads = SweepRange {
        min: 1e3,
        max: 1e5,
        points: 60,
        spacing: Spacing::Log,
    };
    let cases = [
        (
            "power_capped_wide_60",
            inputs(f64::INFINITY, power(), 2.0, 2e6),
            Model::Wide,
        ),
        (
            "rounded_flat_wide_60",
            inputs(f64::INFINITY, rounded_flat(), 1.0, f64::INFINITY),
            Model::Wide,
        ),
        (
            "power_capped_narrow_60",
            inputs(1e-4, power(), 2.0, 2e6),
            Model::Narrow,
        ),
        (
            "rounded_flat_narrow_60",
            inputs(1e-4, rounded_flat(), 1.0, f64::INFINITY),
            Model::Narrow,
        ),
    ];
    for (name, at, model) in cases {
        let curve = solve_sweep(&at, model, &loads);
        let once = curve.clone().judged();
        println!(
            "general_sweep/{name}: {} of {} points solved, {} held",
            once.mu_star.iter().flatten().count(),
            loads.points,
            once.valid.iter().flatten().filter(|v| **v).count()
        );
        c.bench_function(&format!("general_sweep/{name}"), |b| {
            b.iter(|| solve_sweep(black_box(&at), model, &loads).unjudged())
        });
        c.bench_function(&format!("general_sweep_verdicts/{name}"), |b| {
            b.iter_batched(
                || curve.clone(),
                |solved| solved.judged(),
                BatchSize::SmallInput,
            )
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .with_measurement(CpuTime)
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3));
    targets = operating_points, load_sweeps
}
criterion_main!(benches);
