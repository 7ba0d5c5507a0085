//! The spatial problem (docs/physics/spatial.md) against independent routes and classical results.

use crate::common;

use std::f64::consts::PI;

use common::rel;
use wearlab::physics::elastic::{plane_modulus, strip_transfer};
use wearlab::physics::roots::brent;
use wearlab::physics::spatial::contact::check;
use wearlab::physics::spatial::harmonic::{Harmonic, evolution, layer_response};
use wearlab::physics::spatial::{Cell, PunchShape, SpatialInputs, solve};
use wearlab::physics::{Friction, Material};
use wearlab::preset::bundled;

fn wave(a: f64, wx: f64, wy: f64, px: f64, py: f64) -> Harmonic {
    Harmonic {
        amplitude: a,
        wavenumber_x: wx,
        wavenumber_y: wy,
        phase_x: px,
        phase_y: py,
    }
}

fn inputs(
    e: f64,
    nu: f64,
    h: f64,
    mu: f64,
    k: f64,
    pbar: f64,
    harmonics: Vec<Harmonic>,
) -> SpatialInputs {
    SpatialInputs {
        material: Material {
            youngs_modulus: e,
            poisson_ratio: nu,
            thickness: h,
        },
        friction: Friction {
            coefficient: mu,
            adhesion: 0.0,
        },
        wear: k,
        wear_exponent: 1.0,
        reference_pressure: 1.0,
        sliding_speed: 1.0,
        mean_pressure: pbar,
        shape: PunchShape::Harmonics(harmonics),
    }
}

fn preset(file: &str) -> SpatialInputs {
    bundled(file).unwrap().unwrap().spatial_inputs()
}

#[test]
fn a_wave_along_x_sees_the_plane_strain_kernels() {
    // docs/physics/spatial.md section 2: with wy = 0, A = (pi/m) K2/k and B = (pi chi/m) K12/k (docs/physics/plane.md section 2).
    for (nu, h) in [(0.3, f64::INFINITY), (0.3, 1e-3), (0.45, 2e-4), (0.0, 5e-3)] {
        let mat = Material {
            youngs_modulus: 7e9,
            poisson_ratio: nu,
            thickness: h,
        };
        let m = plane_modulus(7e9, nu);
        for k in [100.0, 3000.0, 1e5] {
            let t = strip_transfer(nu, k * h);
            let r = layer_response(&mat, k);
            assert!(rel(r.a, PI / m * t.k2 / k) < 1e-14);
            assert!((r.b - PI / m * t.chi_k12 / k).abs() < 1e-14 * r.a);
        }
    }
}

#[test]
fn westergaard_and_johnson_greenwood_higginson_amplitudes() {
    // mu = 0, half-space. Westergaard (1939), a 1-D wave Delta cos(2 pi x/l): pressure amplitude
    // pi E* Delta/l. Johnson, Greenwood & Higginson (1985), Delta cos(2 pi x/l) cos(2 pi y/l):
    // sqrt(2) pi E* Delta/l. E* = E/(1 - nu^2).
    let (e, nu, delta, l) = (2e11, 0.3, 1e-7, 1e-3);
    let e_star = e / (1.0 - nu * nu);
    let w = 2.0 * PI / l;
    for (harmonic, expected) in [
        (
            wave(delta, w, 0.0, PI / 2.0, PI / 2.0),
            PI * e_star * delta / l,
        ),
        (
            wave(delta, w, w, PI / 2.0, PI / 2.0),
            2f64.sqrt() * PI * e_star * delta / l,
        ),
    ] {
        let sol = solve(
            &inputs(e, nu, f64::INFINITY, 0.0, 0.0, 1e9, vec![harmonic]),
            0.0,
        )
        .unwrap();
        let amp = sol.pressure(0.0, 0.0) - 1e9;
        assert!(rel(amp, expected) < 1e-13, "{amp} vs {expected}");
        assert_eq!(sol.mu_star, 0.0);
    }
}

#[test]
fn half_space_closed_forms_of_decay_and_drift() {
    // docs/physics/spatial.md section 3: Dh = (1-nu)^2 + mu^2 sx^2 (1-2nu)^2/4, beta = k_w G k (1-nu)/Dh,
    // c = k_w mu G (1-2nu)/(2 Dh), tan phi = mu sx (1-2nu)/(2(1-nu)).
    let (e, nu, mu, kw) = (3e9, 0.3, 0.6, 2e-15);
    let mat = Material {
        youngs_modulus: e,
        poisson_ratio: nu,
        thickness: f64::INFINITY,
    };
    let g = mat.shear_modulus();
    let f = Friction {
        coefficient: mu,
        adhesion: 0.0,
    };
    for (wx, wy) in [(5000.0, 0.0), (3000.0, 4000.0), (100.0, 9000.0)] {
        let h = wave(1e-6, wx, wy, 0.0, 0.0);
        let k = h.wavenumber();
        let sx = wx / k;
        let dh = (1.0 - nu).powi(2) + (mu * sx * (1.0 - 2.0 * nu)).powi(2) / 4.0;
        let ev = evolution(&mat, &f, kw, &h);
        assert!(rel(ev.decay_rate, kw * g * k * (1.0 - nu) / dh) < 1e-13);
        assert!(
            rel(
                ev.drift_velocity,
                kw * mu * g * (1.0 - 2.0 * nu) / (2.0 * dh)
            ) < 1e-13
        );
        assert!(
            rel(
                ev.phase_lead.tan(),
                mu * sx * (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))
            ) < 1e-13
        );
    }
}

#[test]
fn thin_layer_limits() {
    // docs/physics/spatial.md section 3: as kh -> 0, beta -> k_w (lambda_L + 2G)/h and
    // c -> k_w mu (1 - 4nu) G (1 - nu)/(1 - 2nu)^2, with lambda_L = 2 G nu/(1 - 2nu).
    let (e, nu, mu, kw, h) = (1e7, 0.35, 0.5, 1e-12, 1e-3);
    let mat = Material {
        youngs_modulus: e,
        poisson_ratio: nu,
        thickness: h,
    };
    let g = mat.shear_modulus();
    let lame = 2.0 * g * nu / (1.0 - 2.0 * nu);
    let ev = evolution(
        &mat,
        &Friction {
            coefficient: mu,
            adhesion: 0.0,
        },
        kw,
        &wave(1e-6, 1e-3 / h, 0.0, 0.0, 0.0),
    );
    assert!(rel(ev.decay_rate, kw * (lame + 2.0 * g) / h) < 1e-5);
    let c = kw * mu * (1.0 - 4.0 * nu) * g * (1.0 - nu) / (1.0 - 2.0 * nu).powi(2);
    assert!(
        rel(ev.drift_velocity, c) < 1e-5,
        "{} vs {c}",
        ev.drift_velocity
    );
}

#[test]
fn the_sign_change_of_the_coupling_matches_the_reference_x_star() {
    // docs/physics/spatial.md section 2: X*(0.3) = 1.0090, X*(0.35) = 1.5377, X*(0.4) = 2.0759, X*(0.45) = 2.7794, X*(0.49) = 4.0215.
    for (nu, x_star) in [
        (0.3, 1.0090),
        (0.35, 1.5377),
        (0.4, 2.0759),
        (0.45, 2.7794),
        (0.49, 4.0215),
    ] {
        let root = brent(0.01, 20.0, |x| strip_transfer(nu, x).chi_k12).unwrap();
        assert!((root - x_star).abs() < 6e-5, "nu={nu}: {root}");
    }
}

/// Time-steps the wear law dg/dt = -k_w p on a periodic grid with RK4, the pressure obtained from
/// the shape through the layer's transfer function mode by mode (a 2-D DFT; p^ = U^/(A - i mu sx B)
/// for every wave vector, sx = kx/k signed), and compares with the closed-form evolution.
fn time_step_against_closed_form(inp: &SpatialInputs, t_end: f64, steps: usize) {
    let cell = Cell::of(inp.harmonics());
    let n = 16;
    let (lx, ly) = (cell.lx, cell.ly);
    let xs: Vec<f64> = (0..n).map(|i| i as f64 * lx / n as f64).collect();
    let ys: Vec<f64> = (0..n).map(|j| j as f64 * ly / n as f64).collect();
    let initial = solve(inp, 0.0).unwrap();
    let mut u: Vec<f64> = ys
        .iter()
        .flat_map(|&y| xs.iter().map(move |&x| (x, y)))
        .map(|(x, y)| initial.shape(x, y))
        .collect();
    let kw = inp.wear_rate();
    let mu = inp.friction.coefficient;
    // transfer factor 1/(A - i mu sx B) for every mode (p, q): kx = 2 pi p/lx, ky = 2 pi q/ly
    let freq = |i: usize| {
        if i <= n / 2 {
            i as f64
        } else {
            i as f64 - n as f64
        }
    };
    let factor: Vec<(f64, f64)> = (0..n * n)
        .map(|idx| {
            let (kx, ky) = (2.0 * PI * freq(idx % n) / lx, 2.0 * PI * freq(idx / n) / ly);
            let k = kx.hypot(ky);
            if k == 0.0 {
                return (0.0, 0.0);
            }
            let r = layer_response(&inp.material, k);
            let (re, im) = (r.a, -mu * kx / k * r.b);
            let d = re * re + im * im;
            (re / d, -im / d)
        })
        .collect();
    let osc_pressure = |u: &[f64]| -> Vec<f64> {
        // naive separable DFT forward, multiply, inverse: a 1-D transform along the rows, then
        // along the columns
        let dft_1d = |line: &[(f64, f64)], sign: f64| -> Vec<(f64, f64)> {
            (0..n)
                .map(|p| {
                    line.iter().enumerate().fold((0.0, 0.0), |acc, (i, v)| {
                        let angle = 2.0 * PI * (p * i) as f64 / n as f64;
                        let (s, c) = (sign * angle.sin(), angle.cos());
                        (acc.0 + v.0 * c - v.1 * s, acc.1 + v.0 * s + v.1 * c)
                    })
                })
                .collect()
        };
        let dft = |data: &[(f64, f64)], sign: f64| -> Vec<(f64, f64)> {
            let rows: Vec<(f64, f64)> = data.chunks(n).flat_map(|row| dft_1d(row, sign)).collect();
            let mut out = vec![(0.0, 0.0); n * n];
            for p in 0..n {
                let column: Vec<(f64, f64)> = (0..n).map(|j| rows[j * n + p]).collect();
                for (q, v) in dft_1d(&column, sign).into_iter().enumerate() {
                    out[q * n + p] = v;
                }
            }
            out
        };
        let spectrum = dft(&u.iter().map(|&v| (v, 0.0)).collect::<Vec<_>>(), -1.0);
        let filtered: Vec<(f64, f64)> = spectrum
            .iter()
            .zip(&factor)
            .map(|(s, f)| (s.0 * f.0 - s.1 * f.1, s.0 * f.1 + s.1 * f.0))
            .collect();
        dft(&filtered, 1.0)
            .iter()
            .map(|v| v.0 / (n * n) as f64)
            .collect()
    };
    let dt = t_end / steps as f64;
    let rate = |u: &[f64]| -> Vec<f64> { osc_pressure(u).iter().map(|p| -kw * p).collect() };
    let axpy = |u: &[f64], k: &[f64], h: f64| -> Vec<f64> {
        u.iter().zip(k).map(|(a, b)| a + h * b).collect()
    };
    for _ in 0..steps {
        let k1 = rate(&u);
        let k2 = rate(&axpy(&u, &k1, dt / 2.0));
        let k3 = rate(&axpy(&u, &k2, dt / 2.0));
        let k4 = rate(&axpy(&u, &k3, dt));
        for i in 0..u.len() {
            u[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
    }
    let closed = solve(inp, t_end).unwrap();
    let amp0: f64 = inp.harmonics().iter().map(|h| h.amplitude).sum();
    let p_scale: f64 = initial
        .harmonics
        .iter()
        .map(|h| h.state.amplitude / h.evolution.m)
        .sum();
    let p = osc_pressure(&u);
    for (idx, (&ui, &pi)) in u.iter().zip(&p).enumerate() {
        let (x, y) = (xs[idx % n], ys[idx / n]);
        assert!(
            (ui - closed.shape(x, y)).abs() < 1e-6 * amp0,
            "shape at ({x},{y}): {ui} vs {}",
            closed.shape(x, y)
        );
        let pc = closed.pressure(x, y) - inp.mean_pressure;
        assert!(
            (pi - pc).abs() < 1e-6 * p_scale,
            "pressure at ({x},{y}): {pi} vs {pc}"
        );
    }
}

#[test]
fn closed_form_evolution_agrees_with_time_stepping() {
    // several decay times of the slowest harmonic
    let thick = preset("wave-thick-layer.toml");
    time_step_against_closed_form(&thick, 150.0, 600);
    let disp = preset("dispersion.toml");
    time_step_against_closed_form(&disp, 600.0, 600);
}

#[test]
fn certified_minimum_agrees_with_a_brute_force_grid() {
    for inp in [
        preset("dispersion.toml"),
        preset("jgh-egg-box.toml"),
        four_directions(),
    ] {
        let sol = solve(&inp, 0.0).unwrap();
        let cell = Cell::of(inp.harmonics());
        let c = check(&sol, &cell);
        assert!(c.exact);
        let n = 700;
        let brute = (0..n * n)
            .map(|i| {
                sol.pressure(
                    (i % n) as f64 * cell.lx / n as f64,
                    (i / n) as f64 * cell.ly / n as f64,
                )
            })
            .fold(f64::INFINITY, f64::min);
        let h: f64 = sol
            .harmonics
            .iter()
            .map(|h| h.initial.wavenumber().powi(2) * h.state.amplitude / h.evolution.m)
            .sum();
        let delta = 0.5 * (cell.lx / n as f64).hypot(cell.ly / n as f64);
        assert!(
            c.min_pressure <= brute + 1e-9 * inp.mean_pressure,
            "{} vs brute {brute}",
            c.min_pressure
        );
        assert!(
            c.min_pressure >= brute - 0.5 * h * delta * delta,
            "{} vs brute {brute}",
            c.min_pressure
        );
        let [x, y] = c.at.unwrap();
        assert!(rel(sol.pressure(x, y), c.min_pressure) < 1e-12);
    }
}

/// Four harmonics of equal |k| = 5 w in four directions, phased so that their troughs never meet.
fn four_directions() -> SpatialInputs {
    let w = 2.0 * PI / 5e-3;
    inputs(
        3e9,
        0.3,
        f64::INFINITY,
        0.3,
        1e-15,
        3.0e7,
        vec![
            wave(1e-6, 5.0 * w, 0.0, 0.0, PI / 2.0),
            wave(1e-6, 0.0, 5.0 * w, 0.0, 1.0),
            wave(0.7e-6, 3.0 * w, 4.0 * w, 2.0, 0.5),
            wave(0.7e-6, 4.0 * w, 3.0 * w, 4.0, 2.5),
        ],
    )
}

#[test]
fn the_bound_can_be_negative_while_contact_is_complete() {
    let inp = four_directions();
    let sol = solve(&inp, 0.0).unwrap();
    let c = check(&sol, &Cell::of(inp.harmonics()));
    assert!(c.lower_bound < 0.0, "bound {}", c.lower_bound);
    assert!(c.min_pressure > 0.0 && c.complete && c.exact, "{c:?}");
}

#[test]
fn deformation_friction_is_the_cell_average_of_p_g_x() {
    // docs/physics/spatial.md section 5: D = <p g_x>, psi = -D; the average over whole periods by the trapezoid
    // rule (exact for trigonometric polynomials of low degree).
    for inp in [
        preset("dispersion.toml"),
        preset("wave-thick-layer.toml"),
        preset("rubber-backward-drift.toml"),
    ] {
        let sol = solve(&inp, 37.0).unwrap();
        let cell = Cell::of(inp.harmonics());
        let n = 64;
        let mut d = 0.0;
        for j in 0..n {
            for i in 0..n {
                let (x, y) = (i as f64 * cell.lx / n as f64, j as f64 * cell.ly / n as f64);
                let gx: f64 = sol
                    .harmonics
                    .iter()
                    .map(|h| {
                        h.state.amplitude
                            * h.initial.wavenumber_x
                            * (h.initial.wavenumber_x * x + h.state.phase_x).cos()
                            * (h.initial.wavenumber_y * y + h.state.phase_y).sin()
                    })
                    .sum();
                d += sol.pressure(x, y) * gx;
            }
        }
        d /= (n * n) as f64;
        assert!(rel(-d, sol.psi) < 1e-10, "{} vs {}", -d, sol.psi);
        // the force balance: T - tau0 = mu* P
        assert!(
            rel(
                sol.tangential - inp.friction.adhesion,
                sol.mu_star * sol.load
            ) < 1e-14
        );
    }
}

#[test]
fn run_in_brings_mu_star_back_to_mu() {
    let inp = preset("wave-thick-layer.toml");
    let early = solve(&inp, 0.0).unwrap();
    let late = solve(&inp, 2000.0).unwrap();
    assert!(early.mu_star < 0.3 && (late.mu_star - 0.3).abs() < 1e-12);
}

#[test]
fn bad_input_says_what_is_wrong() {
    let base = preset("wave-thick-layer.toml");
    let err = |f: &dyn Fn(&mut SpatialInputs)| {
        let mut i = base.clone();
        f(&mut i);
        solve(&i, 0.0).unwrap_err().to_string()
    };
    assert_eq!(
        err(&|i| waves(i)[0].wavenumber_x = 0.0),
        "invalid input: harmonic 1: the wave vector is zero (wavenumber_x = wavenumber_y = 0); a constant belongs in the mean pressure, not in a harmonic"
    );
    assert_eq!(
        err(&|i| waves(i)[0].amplitude = -1e-6),
        "invalid input: harmonic 1: amplitude = -0.000001 is out of range: allowed 0 <= A <= 1 (m)"
    );
    assert_eq!(
        err(&|i| i.material.thickness = 0.0),
        "invalid input: thickness = 0 is out of range: allowed 1e-9 <= h <= 1e3 (m) or inf"
    );
    assert_eq!(
        err(&|i| waves(i).clear()),
        "invalid input: the punch has no harmonics: add at least one (amplitude, wavenumbers, phases)"
    );
    assert_eq!(
        err(&|i| {
            let first = i.harmonics()[0];
            waves(i).push(first)
        }),
        "invalid input: harmonics 1 and 2 have the same wave vector: give each wave vector once"
    );
}

/// The harmonics of inputs made of harmonics, to edit.
fn waves(i: &mut SpatialInputs) -> &mut Vec<Harmonic> {
    match &mut i.shape {
        PunchShape::Harmonics(h) => h,
        PunchShape::Surface(_) => panic!("these inputs are harmonics"),
    }
}
