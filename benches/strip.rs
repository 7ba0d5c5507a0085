//! The strip of any thickness (docs/physics/plane.md section 6): kernel table, Gauss–Jacobi rules,
//! one operating point at (a+b)/h of about 1, 5, 20, 56, 86, 135 and 238, 100-point sweeps, the
//! growth of the cost per point with the node count (`strip_growth`: 100-point sweeps over loads
//! P to 1.3 P at the first five (a+b)/h), and `wearlab solve` of a preset at (a+b)/h = 56 as a
//! whole process, and of the wide default preset (start-up: reading, checking, solving and writing
//! the JSON of a wide preset).
//! Case: E = 1e10 Pa, nu = 0.3, R = 0.05 m, mu = 0.3, k m = 0.5 on h = 1e-5 m (the strip preset's
//! material; P = 1e5 N/m is the SciPy reference's README case).
//! Measured in CPU time (this process's, plus its children's for `wearlab_solve`): on the shared
//! 2-core machine the wall time of a busy hour is several times the work done; the CPU time is
//! what a quiet machine's wall time would be.

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use wearlab::physics::plane::sweep::sweep;
use wearlab::physics::plane::{Model, PlaneInputs, solve, strip};
use wearlab::physics::quadrature::{gauss_jacobi, jacobi_zeros};
use wearlab::physics::{Friction, Material};
use wearlab::physics::{Spacing, SweepRange};

mod common;
use common::cpu_time::CpuTime;

fn inputs(mu: f64, load: f64) -> PlaneInputs {
    let m = wearlab::physics::elastic::plane_modulus(1e10, 0.3);
    PlaneInputs {
        material: Material {
            youngs_modulus: 1e10,
            poisson_ratio: 0.3,
            thickness: 1e-5,
        },
        friction: Friction {
            coefficient: mu,
            adhesion: 0.0,
        },
        shear_strength: f64::INFINITY,
        wear: wearlab::physics::plane::WearLaw::linear(0.5 / m),
        shape: wearlab::physics::plane::Shape::Parabola { radius: 0.05 },
        load,
    }
}

fn table_and_rules(c: &mut Criterion<CpuTime>) {
    c.bench_function("strip_table", |b| {
        b.iter(|| wearlab::physics::plane::strip::kernel_table::StripKernels::new(black_box(0.3)))
    });
    // the rule pair of the 56 h operating point: 272 nodes, 273 collocation points, theta = 0.1
    c.bench_function("strip_rules/272", |b| {
        b.iter(|| {
            let theta = black_box(0.1);
            (
                gauss_jacobi(272, 0.5 + theta, 0.5 - theta),
                jacobi_zeros(273, -0.5 - theta, -0.5 + theta),
            )
        })
    });
}

/// Loads [N/m] for (a+b)/h = 1.04, 4.97, 19.97, 56.28 and 85.89 (N = 48, 64, 128, 272, 400).
const POINTS: [(&str, f64); 5] = [
    ("1h", 5.5),
    ("5h", 300.0),
    ("20h", 1.05e4),
    ("56h", 1e5),
    ("86h", 2.4e5),
];

/// Operating points only (a sweep there takes seconds): (a+b)/h = 134.5 and 238.1 (N = 592 and
/// 1008, the most the model uses).
const WIDE_POINTS: [(&str, f64); 2] = [("135h", 6e5), ("238h", 1.9e6)];

fn operating_points(c: &mut Criterion<CpuTime>) {
    strip::kernels_for(0.3);
    for (name, load) in POINTS.into_iter().chain(WIDE_POINTS) {
        let at = inputs(0.3, load);
        c.bench_function(&format!("strip_point/{name}"), |b| {
            b.iter(|| solve(black_box(&at), Model::Strip).unwrap())
        });
    }
    // every solve with new Gauss–Jacobi rules (mu changed by 1e-12 relative each time)
    let mut count = 0.0;
    c.bench_function("strip_point_cold/56h", |b| {
        b.iter(|| {
            count += 1.0;
            solve(&inputs(0.3 * (1.0 + 1e-12 * count), 1e5), Model::Strip).unwrap()
        })
    });
}

fn sweeps(c: &mut Criterion<CpuTime>) {
    strip::kernels_for(0.3);
    let at = inputs(0.3, 1e3);
    // (a+b)/h from 1.35 to 4.6; 19.6 to 26; 60 to 86
    for (name, min, max) in [
        ("strip_sweep/upto_5h", 10.0, 250.0),
        ("strip_sweep/20h", 1e4, 2e4),
        ("strip_sweep/60_86h", 1.19e5, 3.13e5),
    ] {
        let loads = SweepRange {
            min,
            max,
            points: 100,
            spacing: Spacing::Log,
        };
        c.bench_function(name, |b| {
            b.iter(|| sweep(black_box(&at), Model::Strip, &loads))
        });
    }
}

fn growth(c: &mut Criterion<CpuTime>) {
    strip::kernels_for(0.3);
    let at = inputs(0.3, 1e3);
    // (a+b)/h grows by some 10 % over each sweep: one or two node counts
    for (name, load) in POINTS {
        let loads = SweepRange {
            min: load,
            max: 1.3 * load,
            points: 100,
            spacing: Spacing::Log,
        };
        c.bench_function(&format!("strip_growth/{name}"), |b| {
            b.iter(|| sweep(black_box(&at), Model::Strip, &loads))
        });
    }
}

fn whole_process(c: &mut Criterion<CpuTime>) {
    // the strip preset at P = 1e5 N/m ((a+b)/h = 56) with a 2-point sweep, as a user runs it
    let preset = std::fs::read_to_string("presets/hard-coating-strip.toml")
        .unwrap()
        .replace("load = 1.0e3", "load = 1.0e5")
        .replace("points = 40", "points = 2");
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("strip-56h.toml");
    std::fs::write(&path, preset).unwrap();
    let solve = |file: &str| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_wearlab"))
            .args(["solve", file])
            .output()
            .unwrap();
        assert!(out.status.success());
    };
    c.bench_function("wearlab_solve/strip_56h", |b| {
        b.iter(|| solve(path.to_str().unwrap()))
    });
    c.bench_function("wearlab_solve/wide_polymer_coating", |b| {
        b.iter(|| solve("presets/polymer-coating.toml"))
    });
}

criterion_group! {
    name = strip_benches;
    config = Criterion::default()
        .with_measurement(CpuTime)
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3));
    targets = table_and_rules, operating_points, sweeps, growth, whole_process
}
criterion_main!(strip_benches);
