//! Each Fourier mode of a height map in complete contact decays and drifts by its own closed form
//! (docs/physics/spatial.md section 3): a map of a few cosine modes on a half-space with friction
//! and wear, solved by the pipeline at t, against the half-space's decay rate
//! beta = k_w G k (1 - nu)/Dh and drift velocity c = k_w mu G (1 - 2 nu)/(2 Dh),
//! Dh = (1 - nu)^2 + mu^2 sx^2 (1 - 2 nu)^2/4, evaluated here from those formulas alone.

use crate::common;

use std::f64::consts::PI;
use std::sync::Arc;

use common::layer;

use wearlab::physics::spatial::pipeline;
use wearlab::physics::spatial::surface::{Surface, SurfaceShape, SurfaceSource};
use wearlab::physics::spatial::{PunchShape, SpatialInputs, StateAt};
use wearlab::physics::{Spacing, SweepRange};

/// One mode a cos(qx x + qy y + phase) with mode numbers (mx, my) over the cell.
struct Mode {
    mx: i64,
    my: i64,
    amplitude: f64,
    phase: f64,
}

const MODES: [Mode; 4] = [
    Mode {
        mx: 1,
        my: 0,
        amplitude: 2e-8,
        phase: 0.3,
    },
    Mode {
        mx: 2,
        my: 1,
        amplitude: 1e-8,
        phase: -1.2,
    },
    Mode {
        mx: 3,
        my: -2,
        amplitude: 6e-9,
        phase: 2.0,
    },
    Mode {
        mx: 0,
        my: 1,
        amplitude: 8e-9,
        phase: 0.9,
    },
];

const N: usize = 32;
const L: f64 = 1e-3;

fn wave_vector(m: &Mode) -> (f64, f64) {
    (2.0 * PI * m.mx as f64 / L, 2.0 * PI * m.my as f64 / L)
}

fn node(i: usize) -> f64 {
    i as f64 * L / N as f64
}

/// The complex amplitude a e^{i phase} of mode m in the heights (the projection on the grid:
/// each mode is resolved exactly, none aliases another).
fn projection(heights: &[f64], m: &Mode) -> (f64, f64) {
    let (qx, qy) = wave_vector(m);
    let (mut re, mut im) = (0.0, 0.0);
    for j in 0..N {
        for i in 0..N {
            let arg = qx * node(i) + qy * node(j);
            re += heights[j * N + i] * arg.cos();
            im -= heights[j * N + i] * arg.sin();
        }
    }
    let scale = 2.0 / (N * N) as f64;
    (re * scale, im * scale)
}

#[test]
fn every_mode_decays_and_drifts_at_its_own_closed_form_rate() {
    let (e, nu, mu, k, pbar) = (3e9, 0.35, 0.4, 1e-13, 5e6);
    let g = e / (2.0 * (1.0 + nu));
    let heights: Vec<f64> = (0..N * N)
        .map(|n| {
            let (x, y) = (node(n % N), node(n / N));
            MODES
                .iter()
                .map(|m| {
                    let (qx, qy) = wave_vector(m);
                    m.amplitude * (qx * x + qy * y + m.phase).cos()
                })
                .sum()
        })
        .collect();
    let surface = Surface::new(N, N, L, L, heights).unwrap();
    let source = SurfaceSource::File {
        file: "modes.csv".into(),
        length_x: L,
        length_y: L,
    };
    let inputs = SpatialInputs {
        shape: PunchShape::Surface(Arc::new(SurfaceShape { source, surface })),
        ..common::spatial(layer(e, nu, f64::INFINITY), mu, 0.0, k, pbar, vec![])
    };
    let k_w = k * inputs.sliding_speed;
    for time in [0.0, 0.5, 2.0] {
        let at = StateAt {
            time,
            grid: 8,
            time_tolerance: 1e-4,
            sweep: SweepRange {
                min: 1e3,
                max: 1e7,
                points: 5,
                spacing: Spacing::Log,
            },
        };
        let r = pipeline::solve(&inputs, &at, &[], false).unwrap();
        assert!(r.contact.complete, "complete at t = {time}");
        for m in &MODES {
            let (qx, qy) = wave_vector(m);
            let q = qx.hypot(qy);
            let sx = qx / q;
            let dh = (1.0 - nu).powi(2) + (mu * sx * (1.0 - 2.0 * nu)).powi(2) / 4.0;
            let beta = k_w * g * q * (1.0 - nu) / dh;
            let c = k_w * mu * g * (1.0 - 2.0 * nu) / (2.0 * dh);
            // the pattern a e^{-beta t} cos(qx (x - c t) + qy y + phase)
            let amplitude = m.amplitude * (-beta * time).exp();
            let phase = m.phase - qx * c * time;
            let expected = (amplitude * phase.cos(), amplitude * phase.sin());
            let found = projection(&r.field.shape, m);
            let error = (found.0 - expected.0).hypot(found.1 - expected.1);
            println!(
                "t = {time} s, mode ({}, {}): beta {beta:.6} 1/s, c {c:.6e} m/s, amplitude \
                 {:.6e} m, error {:.2e} of the initial amplitude",
                m.mx,
                m.my,
                found.0.hypot(found.1),
                error / m.amplitude
            );
            assert!(error <= 1e-10 * m.amplitude);
        }
    }
}
