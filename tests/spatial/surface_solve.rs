//! A height map as the punch (docs/physics/spatial-surface.md) through the spatial pipeline:
//! against the closed form of the harmonics it was sampled from, Westergaard's wave, and the mean
//! wear of the running-in.

use crate::common;

use std::f64::consts::PI;
use std::sync::Arc;

use common::{cosine, harmonic as wave, layer};

use wearlab::physics::spatial::harmonic::Harmonic;
use wearlab::physics::spatial::partial::Setup;
use wearlab::physics::spatial::pipeline;
use wearlab::physics::spatial::result::SpatialResult;
use wearlab::physics::spatial::surface::{
    Amplitude, SelfAffine, Surface, SurfaceShape, SurfaceSource, generate, read_csv,
};
use wearlab::physics::spatial::{PunchShape, SpatialInputs, StateAt};
use wearlab::physics::{Spacing, SweepRange};

fn at(time: f64, grid: usize) -> StateAt {
    StateAt {
        time,
        grid,
        time_tolerance: 1e-4,
        sweep: SweepRange {
            min: 1e3,
            max: 1e7,
            points: 5,
            spacing: Spacing::Log,
        },
    }
}

fn with_surface(inputs: &SpatialInputs, surface: Surface) -> SpatialInputs {
    let source = SurfaceSource::File {
        file: "sampled.csv".into(),
        length_x: surface.lx,
        length_y: surface.ly,
    };
    SpatialInputs {
        shape: PunchShape::Surface(Arc::new(SurfaceShape { source, surface })),
        ..inputs.clone()
    }
}

/// The harmonics' shape sampled on the grid the harmonics' own solve uses.
fn sampled(inputs: &SpatialInputs, n: usize) -> SpatialInputs {
    let setup = Setup::new(inputs, n).unwrap();
    let g = setup.grid;
    let surface = Surface::new(g.nx, g.ny, g.lx, g.ly, setup.initial_shape.clone()).unwrap();
    with_surface(inputs, surface)
}

/// Three harmonics over a 1 mm cell on a compressible thin layer (B < 0 at small kh) with
/// friction and wear.
fn three_waves(pbar: f64) -> SpatialInputs {
    let w = 2.0 * PI / 1e-3;
    let h: Vec<Harmonic> = vec![
        wave(2e-8, w, 0.0, 0.3, PI / 2.0),
        wave(1e-8, 2.0 * w, w, 1.1, 0.4),
        wave(5e-9, w, 2.0 * w, -0.7, 2.0),
    ];
    common::spatial(layer(1e9, 0.4, 3e-4), 0.5, 0.0, 1e-11, pbar, h)
}

fn solve(inputs: &SpatialInputs, time: f64, n: usize, probes: &[[f64; 2]]) -> SpatialResult {
    pipeline::solve(inputs, &at(time, n), probes, false).unwrap()
}

#[test]
fn a_map_sampled_from_harmonics_gives_their_closed_form() {
    // Independent routes: the harmonics' closed form (per-harmonic decay and drift, psi from
    // section 5 of docs/physics/spatial.md) against the map's modes decayed by FFT and psi
    // from the nodes, in complete contact from t = 0, at t = 0 and over the decay times of the
    // three waves (beta = 55 to 85 1/s).
    let n = 32;
    let pbar = 2e5;
    let harmonics = three_waves(pbar);
    let map = sampled(&harmonics, n);
    let setup = Setup::new(&harmonics, n).unwrap();
    println!("beta {:?} 1/s", setup.decay_rates());
    let grid = setup.grid;
    let probes: Vec<[f64; 2]> = [(0, 0), (5, 3), (17, 29), (31, 12)]
        .iter()
        .map(|&(i, j)| [grid.x(i), grid.y(j)])
        .collect();
    for time in [0.0, 0.01, 0.05] {
        let exact = solve(&harmonics, time, n, &probes);
        let nodes = solve(&map, time, n, &probes);
        assert!(exact.contact.complete && nodes.contact.complete);
        assert_eq!(exact.harmonics_hold, "now");
        let close = |a: f64, b: f64, what: &str| {
            println!("t = {time}: {what} {a:.12e} vs {b:.12e}");
            assert!((a - b).abs() <= 1e-10 * pbar, "{what} at t = {time}");
        };
        close(exact.load, nodes.load, "P");
        close(exact.tangential_force, nodes.tangential_force, "T");
        close(exact.psi, nodes.psi, "psi");
        close(exact.mu_star * pbar, nodes.mu_star * pbar, "mu* pbar");
        close(exact.max_pressure, nodes.max_pressure, "p_max");
        for (a, b) in exact.probes.iter().zip(&nodes.probes) {
            close(a.pressure, b.pressure, "p at a node");
            close(
                a.shape / 1e-8 * pbar,
                b.shape / 1e-8 * pbar,
                "U at a node (per 10 nm)",
            );
        }
    }
}

#[test]
fn a_map_sampled_from_harmonics_gives_their_partial_contact_and_running_in() {
    // The harmonics' partial contact and running-in on their cell against the same on the map:
    // the same operators, reached through the map's grid, mean and decay rates.
    let n = 32;
    let pbar = 1.5e5;
    let harmonics = three_waves(pbar);
    let map = sampled(&harmonics, n);
    for time in [0.0, 0.001, 0.005] {
        let a = solve(&harmonics, time, n, &[]);
        let b = solve(&map, time, n, &[]);
        println!(
            "t = {time}: fraction {} vs {}, mu* {} vs {}",
            a.contact.fraction, b.contact.fraction, a.mu_star, b.mu_star
        );
        assert_eq!(a.contact.complete, b.contact.complete);
        assert!((a.contact.fraction - b.contact.fraction).abs() < 1e-12);
        for (x, y) in [
            (a.load, b.load),
            (a.psi, b.psi),
            (a.max_pressure, b.max_pressure),
            (a.mu_star * pbar, b.mu_star * pbar),
        ] {
            assert!((x - y).abs() <= 1e-10 * pbar, "{x} vs {y} at t = {time}");
        }
        for (p, q) in a.field.pressure.iter().zip(&b.field.pressure) {
            assert!((p - q).abs() <= 1e-10 * pbar);
        }
    }
}

#[test]
fn westergaard_for_a_cosine_file() {
    // Frictionless half-space under g = Delta cos(2 pi x/l) (Westergaard; Johnson (1985) 13.3):
    // p* = pi E* Delta/l, the contact half-width a from sin^2(pi a/l) = pbar/p*, and the peak
    // p(0) = 2 pbar/sin(pi a/l) = 2 p* sqrt(pbar/p*). The heights come from a CSV file.
    let (e, nu, delta, l, n) = (2e11, 0.3, 1e-6, 1e-3, 1024);
    let p_star = PI * e / (1.0 - nu * nu) * delta / l;
    let ratio = 0.3;
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cosine.csv");
    let row: Vec<String> = (0..n)
        .map(|i| format!("{:.17e}", delta * (2.0 * PI * i as f64 / n as f64).cos()))
        .collect();
    std::fs::write(
        &path,
        format!("# a cosine, 1 um over 1 mm\n{}\n", row.join(",")),
    )
    .unwrap();
    let surface = read_csv(&path, l, 0.0).unwrap();
    let inputs = common::spatial(
        layer(e, nu, f64::INFINITY),
        0.0,
        0.0,
        0.0,
        ratio * p_star,
        vec![],
    );
    let r = solve(&with_surface(&inputs, surface), 0.0, 8, &[]);
    let half_width = l / PI * ratio.sqrt().asin();
    let fraction = r.contact.fraction - 2.0 * half_width / l;
    let peak = 2.0 * p_star * ratio.sqrt();
    println!(
        "fraction {fraction:+.2e}, p_max {:.3e} p*",
        (r.max_pressure - peak) / p_star
    );
    assert!(!r.contact.complete);
    assert!(fraction.abs() <= 2.0 / n as f64);
    // the bound of the harmonic's own test at 1024 nodes per wavelength (spatial_partial.rs)
    assert!((r.max_pressure - peak).abs() < 3e-6 * p_star);
}

#[test]
fn the_running_in_of_a_rough_profile_wears_k_v_pbar_t_per_unit_area() {
    // Mass balance: the mean of W(x, t) is k V pbar t (the zero-mean shape carries no volume),
    // in partial contact during the running-in and after it.
    let p = SelfAffine {
        hurst: 0.8,
        amplitude: Amplitude::RmsHeight(2e-8),
        rolloff_wavelength: 2.5e-4,
        cutoff_wavelength: 4e-5,
        length_x: 1e-3,
        length_y: 0.0,
        grid: 256,
        seed: 3,
    };
    let inputs = common::spatial(layer(3e9, 0.35, 1e-4), 0.3, 0.0, 1e-12, 1e6, vec![]);
    let source = SurfaceSource::SelfAffine(p);
    let surface = generate(&p).unwrap();
    let inputs = SpatialInputs {
        shape: PunchShape::Surface(Arc::new(SurfaceShape { source, surface })),
        sliding_speed: 2.0,
        ..inputs
    };
    let rates = Setup::new(&inputs, 8).unwrap().decay_rates();
    let slowest = rates.iter().copied().fold(f64::INFINITY, f64::min);
    println!(
        "beta from {slowest:.3} to {:.3} 1/s",
        rates.iter().copied().fold(0.0, f64::max)
    );
    let partial_at_start = solve(&inputs, 0.0, 8, &[]);
    assert!(!partial_at_start.contact.complete);
    let mut seen_partial = false;
    // the band's modes decay at beta = 88 to 513 1/s: complete contact within 0.1 s
    for time in [1e-3, 1e-2, 0.1] {
        let r = solve(&inputs, time, 8, &[]);
        let mean = r.field.wear.iter().sum::<f64>() / r.field.wear.len() as f64;
        let expected = 1e-12 * 2.0 * 1e6 * time;
        println!(
            "t = {time}: complete {}, fraction {:.4}, mean W {mean:.6e} (k V pbar t {expected:.6e})",
            r.contact.complete, r.contact.fraction
        );
        seen_partial |= !r.contact.complete;
        assert!((mean - expected).abs() <= 1e-12 * expected);
    }
    assert!(seen_partial);
}

#[test]
fn a_surface_has_no_harmonics_in_the_result() {
    let map = sampled(&three_waves(2e5), 32);
    let r = solve(&map, 0.0, 8, &[]);
    assert!(r.harmonics.is_empty());
    assert_eq!(r.field.x.len(), 32);
    assert_eq!(r.field.y.len(), 32);
}

/// A one-node-wide grid is a profile: its cell has no width (Surface::new keeps ly = 0).
#[test]
fn a_sampled_cosine_profile_is_one_row() {
    let inputs = common::spatial(
        layer(2e11, 0.3, f64::INFINITY),
        0.0,
        0.0,
        0.0,
        1e9,
        vec![cosine(1e-7, 1e-3)],
    );
    let map = sampled(&inputs, 64);
    assert_eq!(map.surface().unwrap().ny, 1);
    let r = solve(&map, 0.0, 8, &[]);
    assert_eq!(r.field.y, vec![0.0]);
}
