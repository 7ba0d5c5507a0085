//! Partial contact on the period cell (docs/physics/spatial-partial.md) against classical
//! closed forms and the second algorithm.

use std::f64::consts::PI;
use std::sync::Arc;

use wearlab::physics::Material;
use wearlab::physics::spatial::harmonic::Harmonic;
use wearlab::physics::spatial::partial::active_set::{ContactProblem, solve};
use wearlab::physics::spatial::partial::grid::Grid;
use wearlab::physics::spatial::partial::operator::{Multipliers, Operator};

fn cosine(delta: f64, wavelength: f64) -> Harmonic {
    Harmonic {
        amplitude: delta,
        wavenumber_x: 2.0 * PI / wavelength,
        wavenumber_y: 0.0,
        phase_x: PI / 2.0,
        phase_y: PI / 2.0,
    }
}

#[test]
fn westergaard() {
    let (e, nu, delta, lambda) = (2e11, 0.3, 1e-6, 1e-3);
    let e_star = e / (1.0 - nu * nu);
    let p_star = PI * e_star * delta / lambda;
    let mat = Material {
        youngs_modulus: e,
        poisson_ratio: nu,
        thickness: f64::INFINITY,
    };
    for n in [128, 256, 512, 1024, 2048, 4096] {
        let h = [cosine(delta, lambda)];
        let grid = Grid::new(&h, n).unwrap();
        let mut op = Operator::new(Arc::new(Multipliers::new(&mat, 0.0, grid)));
        let u = grid.sample(&h);
        let pbar = 0.3 * p_star;
        let t0 = std::time::Instant::now();
        let sol = solve(
            &mut op,
            &ContactProblem {
                shape: &u,
                mean_pressure: pbar,
                adhesion: 0.0,
                diagonal: 0.0,
            },
            None,
        )
        .unwrap();
        let el = t0.elapsed();
        let s2 = 0.3f64;
        let a = lambda / PI * s2.sqrt().asin();
        let exact = |x: f64| {
            let x = (x + lambda / 2.0).rem_euclid(lambda) - lambda / 2.0;
            let s = (PI * x / lambda).sin().powi(2);
            if s < s2 {
                2.0 * pbar * (PI * x / lambda).cos() / s2 * (s2 - s).sqrt()
            } else {
                0.0
            }
        };
        let rms = (sol
            .pressure
            .iter()
            .enumerate()
            .map(|(i, p)| (p - exact(grid.x(i))).powi(2))
            .sum::<f64>()
            / n as f64)
            .sqrt()
            / p_star;
        let frac = sol.pressure.iter().filter(|p| **p > 0.0).count() as f64 / n as f64;
        let pmax = sol.pressure.iter().copied().fold(0.0, f64::max);
        println!(
            "n {n} it {} lin {} frac err {:.2e} (2/N {:.2e}) pmax err {:.2e} rms {:.2e} resid {:.1e} {:?}",
            sol.iterations,
            sol.linear_iterations,
            frac - 2.0 * a / lambda,
            2.0 / n as f64,
            (pmax - exact(0.0)) / p_star,
            rms,
            sol.residual,
            el
        );
    }
}

#[test]
fn two_algorithms() {
    use wearlab::physics::spatial::partial::fixed_point;
    for (nu, h, mu, n) in [
        (0.3, f64::INFINITY, 0.5, 256usize),
        (0.49, 1e-3, 1.0, 256),
        (0.49, 2e-4, 2.0, 128),
    ] {
        let mat = Material {
            youngs_modulus: 1e7,
            poisson_ratio: nu,
            thickness: h,
        };
        let hs = [
            cosine(1e-6, 1e-3),
            Harmonic {
                amplitude: 4e-7,
                wavenumber_x: 3.0 * 2.0 * PI / 1e-3,
                wavenumber_y: 0.0,
                phase_x: 0.4,
                phase_y: PI / 2.0,
            },
        ];
        let grid = Grid::new(&hs, n).unwrap();
        let mult = Arc::new(Multipliers::new(&mat, mu, grid));
        println!(
            "tan phi max {} phi {}",
            mult.tan_phi_max(),
            mult.tan_phi_max().atan()
        );
        let mut op = Operator::new(mult);
        let u = grid.sample(&hs);
        let mut pcc = vec![0.0; n];
        op.inverse(&u, &mut pcc, 0.0);
        let amp = pcc.iter().copied().fold(0.0, f64::max);
        let pbar = 0.3 * amp;
        let t0 = std::time::Instant::now();
        let a = solve(
            &mut op,
            &ContactProblem {
                shape: &u,
                mean_pressure: pbar,
                adhesion: 0.0,
                diagonal: 0.0,
            },
            None,
        )
        .unwrap();
        let t1 = t0.elapsed();
        let (b, it) = fixed_point::solve(&mut op, &u, pbar, 1e-11, 5000).unwrap();
        let t2 = t0.elapsed();
        let diff = a
            .pressure
            .iter()
            .zip(&b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
            / pbar;
        let frac = a.pressure.iter().filter(|p| **p > 0.0).count() as f64 / n as f64;
        println!(
            "nu {nu} h {h} mu {mu}: pdas it {} lin {} {:?}; fp it {it} {:?}; diff {diff:.2e} frac {frac}",
            a.iterations,
            a.linear_iterations,
            t1,
            t2 - t1
        );
    }
}

#[test]
fn running_in_scratch() {
    use wearlab::physics::Friction;
    use wearlab::physics::spatial::SpatialInputs;
    use wearlab::physics::spatial::harmonic::evolution;
    use wearlab::physics::spatial::partial::Setup;
    use wearlab::physics::spatial::partial::running_in::run_in;
    for mu in [0.0, 0.3] {
        for n in [128, 256, 512] {
            let (e, nu, delta, lambda) = (2e11, 0.3, 1e-6, 1e-3);
            let p_star = PI * e / (1.0 - nu * nu) * delta / lambda;
            let inputs = SpatialInputs {
                material: Material {
                    youngs_modulus: e,
                    poisson_ratio: nu,
                    thickness: f64::INFINITY,
                },
                friction: Friction {
                    coefficient: mu,
                    adhesion: 0.0,
                },
                wear: 1e-16,
                sliding_speed: 1.0,
                mean_pressure: 0.3 * p_star,
                harmonics: vec![cosine(delta, lambda)],
            };
            let setup = Setup::new(&inputs, n).unwrap();
            let beta = evolution(
                &inputs.material,
                &inputs.friction,
                inputs.wear_rate(),
                &inputs.harmonics[0],
            )
            .decay_rate;
            let t0 = std::time::Instant::now();
            let run = run_in(&setup, &mut |_| std::ops::ControlFlow::Continue(())).unwrap();
            println!(
                "mu {mu} n {n}: steps {} t_cc beta = {:.5} ({:?})",
                run.samples.len() - 1,
                run.time_to_complete.unwrap() * beta,
                t0.elapsed()
            );
        }
    }
}
