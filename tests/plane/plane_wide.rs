//! The wide-strip / half-plane solution (Soldatenkov (2007) section 4) against independent routes.

use crate::common;

use std::f64::consts::PI;

use common::{hilbert, integrate_cos, plane, rel};
use nalgebra::{DMatrix, DVector};
use wearlab::physics::elastic::{chi, chi_c12, plane_modulus};
use wearlab::physics::plane::energy::energy;
use wearlab::physics::plane::{Model, PlaneInputs, solve};
use wearlab::physics::quadrature::{gauss_jacobi, jacobi_zeros};
use wearlab::physics::roots::brent;

/// What the independent collocation solver returns.
struct Collocated {
    a: f64,
    b: f64,
    q2: f64,
    psi: f64,
    delta_g: f64,
}

/// Gauss–Jacobi collocation of the singular integral equation (4.3)
///   gamma q2 + (1/m) p.v. int q2/(s - x) ds = -x/R - Phi0,
///   Phi0 = pi chi tau0/m + chi c12 (mu Q2 + tau0 L)/(m h),
/// for a contact width L: q2 = w(t) phi(t) with w = (1-t)^(1/2+theta) (1+t)^(1/2-theta), unknowns
/// phi at the zeros of P_N^(1/2+theta, 1/2-theta), collocation at the zeros of
/// P_{N+1}^(-1/2-theta, -1/2+theta), where (1/pi) sum W_i phi_i/(t_i - x_k) equals
/// tan(pi theta) q2 + (1/pi) p.v. int q2/(t - x) exactly (Erdogan–Gupta–Cook). The shift
/// c = (b - a)/2 is an unknown (sigma = c/R); a, b and Q2 come out of the linear solve and P
/// from (3.11) — none of (4.4)-(4.8) is used.
fn collocate(inp: &PlaneInputs, l: f64, n: usize) -> Collocated {
    let mat = &inp.material;
    let m = plane_modulus(mat.youngs_modulus, mat.poisson_ratio);
    let chi = chi(mat.poisson_ratio);
    let (mu, tau0, r) = (
        inp.friction.coefficient,
        inp.friction.adhesion,
        inp.radius(),
    );
    let gamma = PI * chi * mu / m - inp.wear.coefficient;
    let theta = (m * gamma / PI).atan() / PI;
    let c12h = if mat.thickness.is_finite() {
        chi_c12(mat.poisson_ratio) / mat.thickness
    } else {
        0.0
    };
    let rule = gauss_jacobi(n, 0.5 + theta, 0.5 - theta);
    let xk = jacobi_zeros(n + 1, -0.5 - theta, -0.5 + theta);
    let mut mat_a = DMatrix::<f64>::zeros(n + 1, n + 1);
    let mut rhs = DVector::<f64>::zeros(n + 1);
    for (k, &x) in xk.iter().enumerate() {
        for i in 0..n {
            let w = rule.weights[i];
            mat_a[(k, i)] =
                w / (PI * (rule.nodes[i] - x)) + (m / PI) * (c12h * mu / m) * 0.5 * l * w;
        }
        mat_a[(k, n)] = m / PI;
        rhs[k] = (m / PI) * (-l * x / (2.0 * r) - PI * chi * tau0 / m - c12h * tau0 * l / m);
    }
    let sol = mat_a
        .col_piv_qr()
        .solve(&rhs)
        .expect("collocation system is regular");
    let c = sol[n] * r;
    let q2: f64 = 0.5 * l * (0..n).map(|i| rule.weights[i] * sol[i]).sum::<f64>();
    let psi: f64 = 0.5
        * l
        * (0..n)
            .map(|i| rule.weights[i] * sol[i] * (c + 0.5 * l * rule.nodes[i]) / r)
            .sum::<f64>();
    Collocated {
        a: 0.5 * l - c,
        b: 0.5 * l + c,
        q2,
        psi,
        delta_g: l * c / r,
    }
}

fn collocated_at_load(inp: &PlaneInputs) -> Collocated {
    let load = |c: &Collocated| {
        c.q2 - inp.friction.coefficient * c.psi - inp.friction.adhesion * c.delta_g
    };
    let f = |l: f64| load(&collocate(inp, l, 12)) - inp.load;
    let mut hi = 1e-6;
    while f(hi) < 0.0 {
        hi *= 1.5;
    }
    let l = brent(hi / 1.5, hi, f).unwrap();
    collocate(inp, l, 12)
}

fn cases() -> Vec<PlaneInputs> {
    let e = 3e9;
    let m = plane_modulus(e, 0.35);
    vec![
        // friction dominates (gamma > 0), half-plane
        plane(e, 0.35, f64::INFINITY, 0.4, 0.0, 0.0, 0.01, 1e3),
        // wear dominates (gamma < 0), half-plane
        plane(e, 0.35, f64::INFINITY, 0.2, 0.0, 2.0 / m, 0.01, 1e3),
        // adhesion and a finite thickness (c12 term), gamma < 0
        plane(e, 0.35, 2e-3, 0.3, 2e6, 1.5 / m, 0.02, 2e3),
        // adhesion, strong friction, nu = 0.1
        plane(5e10, 0.1, 1e-2, 0.8, 5e6, 0.0, 0.05, 5e4),
    ]
}

#[test]
fn closed_form_agrees_with_gauss_jacobi_collocation() {
    for inp in cases() {
        let closed = solve(&inp, Model::Wide).unwrap();
        let col = collocated_at_load(&inp);
        let scale = closed.contact_width();
        assert!(
            (closed.a - col.a).abs() < 1e-9 * scale,
            "a: {} vs {}",
            closed.a,
            col.a
        );
        assert!(
            (closed.b - col.b).abs() < 1e-9 * scale,
            "b: {} vs {}",
            closed.b,
            col.b
        );
        assert!(rel(closed.normal_force, col.q2) < 1e-9, "Q2");
        assert!(
            (closed.psi - col.psi).abs() < 1e-9 * closed.normal_force * scale / inp.radius(),
            "psi"
        );
    }
}

#[test]
fn hertz_line_contact() {
    // Johnson, Contact Mechanics (1985) eq. 4.45: a = sqrt(4 R P/(pi E*)), p0 = 2P/(pi a), E* = E/(1 - nu^2).
    let (e, nu, r, p) = (2.1e11, 0.3, 0.05, 1e4);
    let sol = solve(
        &plane(e, nu, f64::INFINITY, 0.0, 0.0, 0.0, r, p),
        Model::Wide,
    )
    .unwrap();
    let e_star = e / (1.0 - nu * nu);
    let a = (4.0 * r * p / (PI * e_star)).sqrt();
    assert!(rel(sol.a, a) < 1e-13 && rel(sol.b, a) < 1e-13);
    assert!(rel(sol.pressure(0.0), 2.0 * p / (PI * a)) < 1e-13);
    assert_eq!((sol.psi, sol.mu_star), (0.0, 0.0));
    // Hertz pressure at x = a/2: p0 sqrt(1 - 1/4)
    assert!(rel(sol.pressure(0.5 * a), 2.0 * p / (PI * a) * 0.75f64.sqrt()) < 1e-13);
}

#[test]
fn galin_sliding_punch_exponent_and_pointwise_equation() {
    // Without wear, the end exponents satisfy tan(pi theta) = mu (1 - 2 nu)/(2 (1 - nu))
    // (Galin 1953; Johnson, Contact Mechanics §7.2). Check it, and that the closed-form q2
    // satisfies (4.3) pointwise with the Hilbert transform done by brute-force quadrature.
    let (e, nu, mu, r, p) = (3e9, 0.35, 0.6, 0.01, 1e3);
    let inp = plane(e, nu, f64::INFINITY, mu, 0.0, 0.0, r, p);
    let sol = solve(&inp, Model::Wide).unwrap();
    let theta = sol.theta.unwrap();
    assert!(
        rel(
            (PI * theta).tan(),
            mu * (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))
        ) < 1e-14
    );
    let m = plane_modulus(e, nu);
    let gamma = sol.gamma.unwrap();
    let q2 = |x: f64| sol.pressure(x);
    let (lo, hi) = (-sol.a, sol.b);
    for frac in [0.05, 0.3, 0.5, 0.77, 0.95] {
        let x = lo + frac * (hi - lo);
        let lhs = gamma * q2(x) + hilbert(lo, hi, x, &q2) / m;
        assert!(
            (lhs + x / r).abs() < 1e-7 * sol.contact_width() / r,
            "at {frac}: {lhs} vs {}",
            -x / r
        );
    }
}

#[test]
fn integrals_of_the_pressure_match_q2_and_psi() {
    for inp in cases() {
        let sol = solve(&inp, Model::Wide).unwrap();
        let q2 = integrate_cos(-sol.a, sol.b, 100, |x| sol.pressure(x));
        let psi = integrate_cos(-sol.a, sol.b, 100, |x| sol.pressure(x) * x / inp.radius());
        assert!(
            rel(q2, sol.normal_force) < 1e-8,
            "Q2 {q2} vs {}",
            sol.normal_force
        );
        assert!(rel(psi, sol.psi) < 1e-7, "psi {psi} vs {}", sol.psi);
    }
}

#[test]
fn corrected_eq_4_9_at_small_friction() {
    // docs/physics/plane.md section 3: for h = inf, tau0 = 0, mu << 1, mu* = mu - (8/3) theta sqrt(2P/((1-4theta^2) m R)),
    // with an error of about mu^2/(1 + mu^2) relative to mu* - mu.
    let (e, nu, r) = (1e10, 0.3, 0.05);
    let m = plane_modulus(e, nu);
    for (mu, km) in [(0.02, 0.0), (0.05, 0.5), (0.1, 0.02), (0.05, 2.0)] {
        for p in [1e2, 1e4] {
            let sol = solve(
                &plane(e, nu, f64::INFINITY, mu, 0.0, km / m, r, p),
                Model::Wide,
            )
            .unwrap();
            let th = sol.theta.unwrap();
            let approx = -(8.0 / 3.0) * th * (2.0 * p / ((1.0 - 4.0 * th * th) * m * r)).sqrt();
            let exact = sol.mu_star - mu;
            assert!(
                (exact - approx).abs() <= 1.5 * mu * mu * approx.abs(),
                "mu={mu} km={km}: {exact} vs {approx}"
            );
        }
    }
}

#[test]
fn half_plane_row_of_the_reference_table() {
    // docs/physics/plane.md section 6 (independent computation): E = 1e10, nu = 0.3, R = 0.05, mu = 0.3, k m = 0.5.
    let m = plane_modulus(1e10, 0.3);
    let table = [
        (1e2, 0.30003269),
        (1e3, 0.30010337),
        (1e4, 0.30032691),
        (1e5, 0.30103408),
    ];
    for (p, expected) in table {
        let sol = solve(
            &plane(1e10, 0.3, f64::INFINITY, 0.3, 0.0, 0.5 / m, 0.05, p),
            Model::Wide,
        )
        .unwrap();
        assert!(
            (sol.mu_star - expected).abs() < 6e-9,
            "P={p}: {}",
            sol.mu_star
        );
    }
    // The h = 1e-3 row at P = 1e2 ((a+b)/h = 0.05): the wide model is within 0.09 (L/h)^2 (mu* - mu).
    let sol = solve(
        &plane(1e10, 0.3, 1e-3, 0.3, 0.0, 0.5 / m, 0.05, 1e2),
        Model::Wide,
    )
    .unwrap();
    let lh = sol.contact_width() / 1e-3;
    assert!((sol.mu_star - 0.30003392).abs() < 0.09 * lh * lh * (0.30003392 - 0.3) + 1e-8);
}

#[test]
fn energy_identity_holds_and_matches_the_kernel_identity() {
    // I = J to 1e-6 (relative); and m I = -pi chi int q1 q2 - chi c12 Q1 Q2/h (docs/physics/plane.md section 5),
    // with int q1 q2 by an independent quadrature.
    for inp in cases() {
        let sol = solve(&inp, Model::Wide).unwrap();
        let en = energy(&sol).unwrap();
        assert!(rel(en.i, en.j) < 1e-6, "I {} J {}", en.i, en.j);
        let mat = &inp.material;
        let m = plane_modulus(mat.youngs_modulus, mat.poisson_ratio);
        let c12h = if mat.thickness.is_finite() {
            chi_c12(mat.poisson_ratio) / mat.thickness
        } else {
            0.0
        };
        let q1q2 = integrate_cos(-sol.a, sol.b, 100, |x| sol.shear(x) * sol.pressure(x));
        let expected = (-PI * chi(mat.poisson_ratio) * q1q2
            - c12h * sol.friction_force * sol.normal_force)
            / m;
        assert!(rel(en.i, expected) < 1e-6, "I {} vs {expected}", en.i);
    }
}

#[test]
fn wear_per_pass_totals_k_q2_at_the_trailing_edge() {
    let inp = cases()[1].clone();
    let sol = solve(&inp, Model::Wide).unwrap();
    let prof = wearlab::physics::plane::profile::profile(&sol, 201);
    assert_eq!(prof.x.len(), 201);
    assert_eq!((prof.x[0], prof.x[200]), (-sol.a, sol.b));
    assert!(
        rel(prof.wear[0], inp.wear.coefficient * sol.normal_force) < 1e-6,
        "{} vs {}",
        prof.wear[0],
        inp.wear.coefficient * sol.normal_force
    );
    assert_eq!(prof.wear[200], 0.0);
    assert!(prof.wear.windows(2).all(|w| w[0] >= w[1]));
}

#[test]
fn the_width_is_the_first_that_carries_the_load_up_to_the_most_the_model_carries() {
    use wearlab::physics::plane::wide::{WideConstants, solve_with, state};
    // a wide strip whose load P(L) has a maximum ((4.6) with the thickness correction): loads
    // from far below it to just under it, against a scan of P(L) on 20,000 widths
    let inp = plane(3e9, 0.35, 2e-4, 0.3, 0.0, 0.0, 0.01, 1.0);
    let c = WideConstants::new(&inp);
    let carried = |l: f64| state(&c, &inp, l).load;
    let scan: Vec<f64> = (0..20_000)
        .map(|i| 1e-7 * 10f64.powf(6.0 * i as f64 / 19_999.0))
        .collect();
    let (most, at_most) = scan
        .iter()
        .map(|&l| (carried(l), l))
        .fold((f64::MIN, 0.0), |m, x| if x.0 > m.0 { x } else { m });
    assert!(
        at_most > scan[0] && at_most < scan[19_999],
        "the scan holds the maximum"
    );
    // (within about 0.2 % of the maximum the march by factors of 1.1 steps over the widths that
    // carry the load, and the model says it has no contact there)
    for fraction in [1e-6, 1e-3, 0.1, 0.5, 0.9, 0.99, 0.995] {
        let p = fraction * most;
        // the model's own answer, before the checks that refuse a contact off the punch tip
        let sol = solve_with(&c, &inp.with_load(p)).unwrap();
        let l = sol.contact_width();
        assert!(
            rel(carried(l), p) < 1e-12,
            "{fraction}: P(L) = {}",
            carried(l)
        );
        // no narrower width of the scan carries the load: L is the first crossing
        let first = scan.iter().position(|&w| carried(w) >= p).unwrap();
        assert!(
            scan[first - 1] < l && l <= scan[first] && l < at_most,
            "{fraction}: L = {l}, scan {} .. {}",
            scan[first - 1],
            scan[first]
        );
    }
    let err = solve_with(&c, &inp.with_load(1.01 * most))
        .unwrap_err()
        .to_string();
    let said: f64 = err
        .split("carries at most P = ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .and_then(|s| s.parse().ok())
        .unwrap();
    // the message's maximum is the largest load of its own march (factors of 1.1 in L), which
    // lies within 1 % of the scan's at a smooth maximum
    assert!(rel(said, most) < 1e-2, "{said} against {most}");
}
