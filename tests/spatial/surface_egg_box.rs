//! The egg-box surface g = Delta cos(2 pi x/l) cos(2 pi y/l) pressed on a frictionless half-space
//! (Johnson, Greenwood & Higginson (1985)), given as a height map and solved by the partial
//! contact on its grid, against the paper's closed forms: complete contact from the bearing
//! pressure p* = sqrt(2) pi E* Delta/l on (the complete-contact pressure is
//! pbar + p* cos cos, JGH (1985) section 2; the same amplitude as docs/physics/spatial.md section 6
//! lists), the gaps near complete contact, and Hertz at light load.

use crate::common;

use std::f64::consts::PI;
use std::sync::Arc;

use common::layer;

use wearlab::physics::spatial::pipeline;
use wearlab::physics::spatial::result::SpatialResult;
use wearlab::physics::spatial::surface::{Surface, SurfaceShape, SurfaceSource};
use wearlab::physics::spatial::{PunchShape, SpatialInputs, StateAt};
use wearlab::physics::{Spacing, SweepRange};

const E: f64 = 2e11;
const NU: f64 = 0.3;
const DELTA: f64 = 1e-7;
const L: f64 = 1e-3;

fn e_star() -> f64 {
    E / (1.0 - NU * NU)
}

/// JGH (1985): the mean pressure at which the egg-box comes into complete contact [Pa].
fn p_star() -> f64 {
    2f64.sqrt() * PI * e_star() * DELTA / L
}

fn egg_box(n: usize, pbar: f64) -> SpatialInputs {
    let node = |i: usize| 2.0 * PI * i as f64 / n as f64;
    let heights = (0..n * n)
        .map(|k| DELTA * node(k % n).cos() * node(k / n).cos())
        .collect();
    let surface = Surface::new(n, n, L, L, heights).unwrap();
    let source = SurfaceSource::File {
        file: "egg-box.csv".into(),
        length_x: L,
        length_y: L,
    };
    SpatialInputs {
        shape: PunchShape::Surface(Arc::new(SurfaceShape { source, surface })),
        ..common::spatial(layer(E, NU, f64::INFINITY), 0.0, 0.0, 0.0, pbar, vec![])
    }
}

fn solve(n: usize, ratio: f64) -> SpatialResult {
    let at = StateAt {
        time: 0.0,
        grid: 8,
        time_tolerance: 1e-4,
        sweep: SweepRange {
            min: 1e3,
            max: 1e7,
            points: 5,
            spacing: Spacing::Log,
        },
    };
    pipeline::solve(&egg_box(n, ratio * p_star()), &at, &[], false).unwrap()
}

#[test]
fn the_egg_box_comes_into_complete_contact_at_the_jgh_pressure() {
    let n = 64;
    let below = solve(n, 0.95);
    let above = solve(n, 1.001);
    println!(
        "p* = {:.6e} Pa: fraction {:.6} at 0.95 p*, {:.6} at 1.001 p*; p_max at 1.001 p* {:.6e} \
         (pbar + p* = {:.6e})",
        p_star(),
        below.contact.fraction,
        above.contact.fraction,
        above.max_pressure,
        2.001 * p_star()
    );
    assert!(!below.contact.complete);
    assert!(above.contact.complete);
    assert!((above.max_pressure - 2.001 * p_star()).abs() <= 1e-9 * p_star());
}

#[test]
fn the_gaps_near_complete_contact_are_jgh_penny_cracks() {
    // Near complete contact each trough (two per cell) leaves a gap of radius c where the
    // complete-contact tension p* (1 - 2 pi^2 r^2/l^2) - pbar closes with no stress intensity
    // (an axisymmetric crack, Sneddon (1946): no stress intensity when int_0^c r sigma(r)/sqrt(c^2 - r^2) dr = 0):
    // c^2 = 3 (1 - pbar/p*) l^2/(4 pi^2), so the cell's free fraction is
    // 2 pi c^2/l^2 = 3 (1 - pbar/p*)/(2 pi), the near-complete asymptote of JGH (1985).
    let n = 128;
    for ratio in [0.9, 0.95] {
        let r = solve(n, ratio);
        let free = 1.0 - r.contact.fraction;
        let asymptote = 3.0 * (1.0 - ratio) / (2.0 * PI);
        println!(
            "pbar = {ratio} p*: free fraction {free:.5}, JGH {asymptote:.5} ({:+.1} %)",
            100.0 * (free / asymptote - 1.0)
        );
        assert!((free / asymptote - 1.0).abs() < 0.15);
    }
}

#[test]
fn light_load_gives_a_hertz_contact_on_each_peak() {
    // Two peaks per cell, each carrying pbar l^2/2 with the radius R = l^2/(4 pi^2 Delta) of the
    // cosines' top (Hertz, Johnson (1985) eq. 4.22: a^3 = 3 P R/(4 E*)); the cell's contact fraction is
    // 2 pi a^2/l^2, the light-load limit of JGH (1985). Both departures make the nodes' area the
    // larger (+5 % at 0.01 p*, +9 % at 0.03 p*): the cosine's top is fuller than Hertz's paraboloid
    // (1 - theta^2/2 + theta^4/24), and a node counts in contact when its pressure is positive.
    let n = 128;
    for ratio in [0.01, 0.03] {
        let r = solve(n, ratio);
        let (pbar, radius) = (ratio * p_star(), L * L / (4.0 * PI * PI * DELTA));
        let a = (3.0 * pbar * L * L / 2.0 * radius / (4.0 * e_star())).cbrt();
        let hertz = 2.0 * PI * a * a / (L * L);
        println!(
            "pbar = {ratio} p*: fraction {:.5}, Hertz {hertz:.5} ({:+.1} %), a = {:.1} nodes",
            r.contact.fraction,
            100.0 * (r.contact.fraction / hertz - 1.0),
            a / L * n as f64
        );
        assert!((0.0..0.15).contains(&(r.contact.fraction / hertz - 1.0)));
    }
}
