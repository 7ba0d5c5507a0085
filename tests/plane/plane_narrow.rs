//! The narrow-strip (Winkler) solution (Soldatenkov (2007) section 5) against independent routes.

use crate::common;

use common::{integrate_cos, plane, rel};
use wearlab::physics::plane::energy::energy;
use wearlab::physics::plane::narrow::winkler_beta;
use wearlab::physics::plane::{Model, PlaneInputs, PlaneSolution, solve};

fn cases() -> Vec<PlaneInputs> {
    vec![
        // lambda L ~ 1
        plane(1e8, 0.3, 1e-4, 0.3, 0.0, 5e-10, 0.05, 1e4),
        // weak wear, lambda L ~ 0.05 (series branch)
        plane(1e8, 0.3, 1e-4, 0.3, 0.0, 2e-11, 0.05, 1e4),
        // strong wear lambda L ~ 30, adhesion
        plane(1e8, 0.45, 1e-4, 0.5, 1e4, 2e-9, 0.05, 1e5),
        // no wear
        plane(1e8, 0.3, 1e-4, 0.3, 0.0, 0.0, 0.05, 1e4),
    ]
}

/// RK4 integration of (5.3), q2' = lambda q2 - x/(R beta), from the leading edge x = b (q2 = 0)
/// back to x = -a; returns (x, q2) samples.
fn integrate_ode(sol: &PlaneSolution, steps: usize) -> Vec<(f64, f64)> {
    let inp = &sol.inputs;
    let beta = winkler_beta(inp);
    let lambda = inp.wear.coefficient / beta;
    let f = |x: f64, q: f64| lambda * q - x / (inp.radius() * beta);
    let h = -(sol.a + sol.b) / steps as f64;
    let (mut x, mut q) = (sol.b, 0.0);
    let mut out = vec![(x, q)];
    for _ in 0..steps {
        let k1 = f(x, q);
        let k2 = f(x + h / 2.0, q + h / 2.0 * k1);
        let k3 = f(x + h / 2.0, q + h / 2.0 * k2);
        let k4 = f(x + h, q + h * k3);
        q += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        x += h;
        out.push((x, q));
    }
    out
}

#[test]
fn closed_form_agrees_with_ode_integration_from_the_leading_edge() {
    for inp in cases() {
        let sol = solve(&inp, Model::Narrow).unwrap();
        let path = integrate_ode(&sol, 4000);
        let peak = path.iter().map(|p| p.1).fold(0.0, f64::max);
        // the trailing edge condition q2(-a) = 0 that fixed a and b
        assert!(
            path.last().unwrap().1.abs() < 1e-9 * peak,
            "q2(-a) = {}",
            path.last().unwrap().1
        );
        for &(x, q) in path.iter().step_by(97) {
            assert!(
                (sol.pressure(x) - q).abs() < 1e-9 * peak,
                "x={x}: {} vs {q}",
                sol.pressure(x)
            );
        }
        // Q2, psi and P from the ODE path (Simpson), not from (5.8)-(5.10)
        let n = path.len() - 1;
        let dx = (sol.a + sol.b) / n as f64;
        let simpson = |g: &dyn Fn(f64, f64) -> f64| {
            (0..=n)
                .map(|i| {
                    let w = if i == 0 || i == n {
                        1.0
                    } else if i % 2 == 1 {
                        4.0
                    } else {
                        2.0
                    };
                    w * g(path[i].0, path[i].1)
                })
                .sum::<f64>()
                * dx
                / 3.0
        };
        let q2 = simpson(&|_, q| q);
        let psi = simpson(&|x, q| q * x / inp.radius());
        assert!(rel(q2, sol.normal_force) < 1e-9);
        assert!((psi - sol.psi).abs() < 1e-9 * q2 * sol.contact_width() / inp.radius());
        let (mu, tau0) = (inp.friction.coefficient, inp.friction.adhesion);
        let load = q2 - mu * psi - tau0 * inp.wear.coefficient * q2;
        assert!(rel(load, inp.load) < 1e-9);
    }
}

#[test]
fn small_wear_formula_of_the_paper() {
    // End of Soldatenkov (2007) section 5 (confirmed in docs/physics/plane.md): mu* = mu + (3/5)(1 + mu^2) k (2P^2/(3 beta R))^(1/3),
    // relative error about 0.004 (lambda L)^2. The formula also takes Q2 = P, neglecting mu psi, and
    // psi ~ L^5 ~ Q2^(5/3): that adds (5/3) mu (mu* - mu)/(1 + mu^2) relative, which dominates at
    // very small wear (3.6e-6 at k = 1e-12 here).
    for k in [1e-12, 1e-11, 5e-11, 2e-10] {
        let inp = plane(1e8, 0.3, 1e-4, 0.3, 0.0, k, 0.05, 1e4);
        let sol = solve(&inp, Model::Narrow).unwrap();
        let beta = winkler_beta(&inp);
        let approx = 0.6 * (1.0 + 0.09) * k * (2.0 * 1e8 / (3.0 * beta * 0.05)).cbrt();
        let y = k / beta * sol.contact_width();
        let exact = sol.mu_star - 0.3;
        let neglected = 5.0 / 3.0 * 0.3 * exact / 1.09;
        let rel_err = (exact - approx).abs() / approx;
        assert!(
            rel_err <= 0.01 * y * y + 1.01 * neglected,
            "k={k}: {exact} vs {approx} (lambda L = {y})"
        );
    }
}

#[test]
fn without_wear_the_winkler_strip_has_no_deformation_friction() {
    // docs/physics/plane.md section 4: with k = 0 the Winkler model gives a symmetric parabola and mu* = mu.
    let inp = cases()[3].clone();
    let sol = solve(&inp, Model::Narrow).unwrap();
    assert_eq!(sol.mu_star, 0.3);
    assert!(rel(sol.a, sol.b) < 1e-15);
    let beta = winkler_beta(&inp);
    // Q2 = L^3/(12 R beta) for the parabola (a^2 - x^2)/(2 beta R)
    assert!(
        rel(
            sol.normal_force,
            sol.contact_width().powi(3) / (12.0 * inp.radius() * beta)
        ) < 1e-14
    );
}

#[test]
fn energy_identity_is_zero_for_winkler() {
    // I = J = 0 for the Winkler relations (Soldatenkov (2007) section 5): both vanish to quadrature accuracy.
    for inp in cases() {
        let sol = solve(&inp, Model::Narrow).unwrap();
        let en = energy(&sol).unwrap();
        assert!(en.residual < 1e-9, "{en:?}");
        let gross =
            integrate_cos(-sol.a, sol.b, 50, |x| sol.pressure(x).powi(2)) * winkler_beta(&inp);
        assert!(en.j.abs() < 1e-9 * gross, "J = {} vs scale {gross}", en.j);
    }
}

#[test]
fn strong_wear_stays_finite_and_positive() {
    let inp = plane(1e8, 0.3, 1e-4, 0.3, 0.0, 1e-7, 0.05, 1e4);
    let sol = solve(&inp, Model::Narrow).unwrap();
    let y = inp.wear.coefficient / winkler_beta(&inp) * sol.contact_width();
    assert!(y > 100.0, "lambda L = {y}");
    let prof = wearlab::physics::plane::profile::profile(&sol, 201);
    assert!(prof.pressure.iter().all(|q| q.is_finite() && *q >= 0.0));
    assert!(sol.mu_star.is_finite() && sol.mu_star > 0.3);
}
