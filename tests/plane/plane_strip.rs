//! The strip of any thickness (docs/physics/plane.md section 6) against independent routes.

use crate::common;

use common::{hilbert, integrate_cos, plane, rel};
use wearlab::physics::SolveError;
use wearlab::physics::elastic::plane_modulus;
use wearlab::physics::plane::energy::energy;
use wearlab::physics::plane::narrow::winkler_beta;
use wearlab::physics::plane::strip::{
    MAX_NODES, WideLimit, collocate, kernels_for, nodes_for, solve_with,
};
use wearlab::physics::plane::{Model, PlaneInputs, solve};

fn table_inputs(h: f64, p: f64) -> PlaneInputs {
    let m = plane_modulus(1e10, 0.3);
    plane(1e10, 0.3, h, 0.3, 0.0, 0.5 / m, 0.05, p)
}

#[test]
fn reference_table_of_plane_md() {
    // docs/physics/plane.md section 6: mu*(P) from an independent computation, E = 1e10, nu = 0.3, R = 0.05,
    // mu = 0.3, k m = 0.5 (8 digits).
    let rows = [
        (1e-3, 1e2, 0.30003392),
        (1e-3, 1e3, 0.30011585),
        (1e-3, 1e4, 0.30045234),
        (1e-3, 1e5, 0.30215441),
        (1e-5, 1e2, 0.30010592),
        (1e-5, 1e3, 0.30048261),
        (1e-5, 1e4, 0.30201080),
        (1e-5, 1e5, 0.30731337),
    ];
    for (h, p, expected) in rows {
        let sol = solve(&table_inputs(h, p), Model::Strip).unwrap();
        assert!(
            (sol.mu_star - expected).abs() < 6e-9,
            "h={h} P={p}: {}",
            sol.mu_star
        );
    }
}

/// (a, b, Q2, mu*) of an independent strip solver (commit fc95cc2: dense Householder QR at every
/// width, N = 40 + 4 L/h, Golub–Welsch rules, Brent from the half-plane width), at its own test
/// cases, printed to 17 digits.
const PREVIOUS_SOLVER: [(&str, PlaneInputsFn, [f64; 4]); 6] = [
    (
        "table h=1e-3 P=1e5",
        |_| table_inputs(1e-3, 1e5),
        [
            0.0005892312754753917,
            0.0007573169806599475,
            100059.29566233356,
            0.3021544090647889,
        ],
    ),
    (
        "table h=1e-5 P=1e3",
        |_| table_inputs(1e-5, 1e3),
        [
            2.0649386277371494e-05,
            5.700069290953825e-05,
            1000.1328290563633,
            0.30048261223812406,
        ],
    ),
    (
        "table h=1e-5 P=1e4",
        |_| table_inputs(1e-5, 1e4),
        [
            2.4434334840730247e-05,
            0.0001710726647462341,
            10005.53431362479,
            0.30201080061700125,
        ],
    ),
    (
        "table h=1e-5 P=1e5",
        |_| table_inputs(1e-5, 1e5),
        [
            2.4538424413288586e-05,
            0.0005382573979582524,
            100201.28554510865,
            0.30731337480561327,
        ],
    ),
    (
        "adhesion",
        |m| plane(1e10, 0.3, 1e-3, 0.3, 1e5, 0.5 / m, 0.05, 3e4),
        [
            0.0003609320171302331,
            0.0004326105369152299,
            30007.742946222515,
            0.3009314368252074,
        ],
    ),
    (
        "strong wear",
        |_| plane(1e8, 0.3, 1e-4, 0.3, 0.0, 1e-7, 0.05, 1e3),
        [
            3.970800071407404e-06,
            0.0031790978079257026,
            1012.8488780179534,
            0.34668425679857556,
        ],
    ),
];

type PlaneInputsFn = fn(f64) -> PlaneInputs;

#[test]
fn agrees_with_the_previous_solver_to_1e_10() {
    let m = plane_modulus(1e10, 0.3);
    for (name, inputs, [a, b, q2, mu_star]) in PREVIOUS_SOLVER {
        let sol = solve(&inputs(m), Model::Strip).unwrap();
        let l = a + b;
        assert!(
            (sol.a - a).abs() < 1e-10 * l && (sol.b - b).abs() < 1e-10 * l,
            "{name}: a, b"
        );
        assert!(rel(sol.normal_force, q2) < 1e-10, "{name}: Q2");
        assert!(
            (sol.mu_star - mu_star).abs() < 1e-10 * (mu_star - 0.3),
            "{name}: mu* {} vs {mu_star}",
            sol.mu_star
        );
    }
}

#[test]
fn the_wide_limit_of_the_kernels_reproduces_the_wide_closed_form() {
    // R2 -> 0 and chi B12 -> chi c12 in the same solver (docs/physics/plane.md section 6).
    let m = plane_modulus(3e9, 0.35);
    for inp in [
        plane(3e9, 0.35, 2e-3, 0.3, 2e6, 1.5 / m, 0.02, 2e3),
        plane(3e9, 0.35, 1e-2, 0.4, 0.0, 0.0, 0.01, 1e3),
    ] {
        let wide = solve(&inp, Model::Wide).unwrap();
        let limit = solve_with(&inp, &WideLimit::new(0.35)).unwrap();
        let l = wide.contact_width();
        assert!((wide.a - limit.a).abs() < 1e-10 * l && (wide.b - limit.b).abs() < 1e-10 * l);
        assert!(rel(wide.normal_force, limit.normal_force) < 1e-10);
        assert!((wide.mu_star - limit.mu_star).abs() < 1e-10);
    }
}

#[test]
fn spectral_convergence_in_the_number_of_nodes() {
    let kernels = kernels_for(0.3);
    for (h, p) in [(1e-3, 1e4), (1e-5, 1e2)] {
        let inp = table_inputs(h, p);
        let l = solve(&inp, Model::Strip).unwrap().contact_width();
        let n = nodes_for(l / h);
        let (a, b) = (
            collocate(&inp, kernels.as_ref(), l, n).unwrap(),
            collocate(&inp, kernels.as_ref(), l, n * 3 / 2).unwrap(),
        );
        assert!(
            rel(a.q2, b.q2) < 1e-8 && (a.c - b.c).abs() < 1e-8 * l && rel(a.psi, b.psi) < 1e-8,
            "h={h}"
        );
    }
}

#[test]
fn limits_wide_and_winkler() {
    // as (a+b)/h -> 0 the strip tends to the wide model, its error in mu* - mu about 0.09 (L/h)^2;
    for p in [1e2, 1e3] {
        let inp = table_inputs(1e-3, p);
        let (s, w) = (
            solve(&inp, Model::Strip).unwrap(),
            solve(&inp, Model::Wide).unwrap(),
        );
        let lh = s.contact_width() / 1e-3;
        assert!(
            (s.mu_star - w.mu_star).abs() < 0.2 * lh * lh * (s.mu_star - 0.3),
            "P={p}"
        );
    }
    // as (a+b)/h grows, the contact width tends to Winkler's less about 0.22 h (nu = 0.3).
    let inp = table_inputs(1e-5, 1e4);
    let (s, n) = (
        solve(&inp, Model::Strip).unwrap(),
        solve(&inp, Model::Narrow).unwrap(),
    );
    assert!(s.contact_width() / 1e-5 > 19.0);
    let short = (n.contact_width() - s.contact_width()) / 1e-5;
    assert!((0.1..0.3).contains(&short), "L_Winkler - L = {short} h");
}

#[test]
fn the_contact_condition_holds_between_the_nodes() {
    // d/dx of (1.11) with W' = -k q2: m (v' + k q2) = m x/R, v' from (3.7) with the tabulated
    // kernels, evaluated by brute-force quadrature at points that are not collocation points.
    let inp = plane(
        1e10,
        0.3,
        1e-3,
        0.3,
        1e5,
        0.5 / plane_modulus(1e10, 0.3),
        0.05,
        3e4,
    );
    let sol = solve(&inp, Model::Strip).unwrap();
    let k = kernels_for(0.3);
    let (m, chi, h) = (plane_modulus(1e10, 0.3), inp.material.chi(), 1e-3);
    let (lo, hi) = (-sol.a, sol.b);
    let q2 = |x: f64| sol.pressure(x);
    let q1 = |x: f64| sol.shear(x);
    for frac in [0.111, 0.333, 0.5003, 0.777, 0.911] {
        let x = lo + frac * (hi - lo);
        let regular = integrate_cos(lo, hi, 60, |s| {
            q2(s) * k.r2((s - x) / h) + q1(s) * k.chi_b12((s - x) / h)
        }) / h;
        let mv = -std::f64::consts::PI * chi * q1(x) - hilbert(lo, hi, x, &q2) - regular;
        let lhs = mv + m * inp.wear.coefficient * q2(x);
        assert!(
            (lhs - m * x / inp.radius()).abs() < 1e-6 * m * sol.contact_width() / inp.radius(),
            "at {frac}: {lhs} vs {}",
            m * x / inp.radius()
        );
    }
}

#[test]
fn a_narrow_strip_with_strong_wear_keeps_a_positive_pressure() {
    // lambda L ~ 100: where LU with partial pivoting gave garbage (docs/physics/plane.md section 6).
    let inp = plane(1e8, 0.3, 1e-4, 0.3, 0.0, 1e-7, 0.05, 1e3);
    let sol = solve(&inp, Model::Strip).unwrap();
    let lambda_l = inp.wear.coefficient / winkler_beta(&inp) * sol.contact_width();
    assert!(lambda_l > 50.0, "lambda L = {lambda_l}");
    let prof = wearlab::physics::plane::profile::profile(&sol, 101);
    assert!(
        prof.pressure
            .iter()
            .all(|q| q.is_finite()
                && *q >= -1e-6 * prof.pressure.iter().cloned().fold(0.0, f64::max))
    );
    assert!(sol.mu_star.is_finite() && sol.mu_star > 0.3);
}

#[test]
fn energy_identity_with_the_exact_kernels() {
    let sol = solve(
        &plane(
            1e10,
            0.3,
            1e-3,
            0.3,
            1e5,
            0.5 / plane_modulus(1e10, 0.3),
            0.05,
            3e4,
        ),
        Model::Strip,
    )
    .unwrap();
    let en = energy(&sol).unwrap();
    assert!(rel(en.i, en.j) < 1e-6, "{en:?}");
}

#[test]
fn nearly_incompressible_layer_against_an_independent_boundary_element_width() {
    // E = 2 MPa, nu = 0.49, h = 0.1 mm, R = 0.1 m, P = 1.86e4 N/m, no friction or wear;
    // an independent FFT boundary-element code (converged to 1e-7) gives a = b = 2.276 mm.
    let inp = plane(2e6, 0.49, 1e-4, 0.0, 0.0, 0.0, 0.1, 1.86e4);
    let sol = solve(&inp, Model::Strip).unwrap();
    assert!(
        (sol.a - 2.276e-3).abs() < 0.5e-6 && (sol.b - 2.276e-3).abs() < 0.5e-6,
        "a = {}, b = {}",
        sol.a,
        sol.b
    );
    // and N against 1.5 N at that width ((a+b)/h = 45.5)
    let l = sol.contact_width();
    let n = nodes_for(l / 1e-4);
    let k = kernels_for(0.49);
    let (a, b) = (
        collocate(&inp, k.as_ref(), l, n).unwrap(),
        collocate(&inp, k.as_ref(), l, n * 3 / 2).unwrap(),
    );
    assert!(rel(a.q2, b.q2) < 1e-8, "{} vs {}", a.q2, b.q2);
}

#[test]
fn tends_to_winkler_less_a_fixed_edge_offset() {
    // As (a+b)/h grows, L_Winkler - L tends to a constant (an edge effect of order h), so the
    // strip's width joins the Winkler closed form like h/L, for every nu up to 0.49 (the offset
    // grows as nu -> 1/2: 0.24 h at 0.3, -1.1 h at 0.45, -5.4 h at 0.49, where the layer is
    // softer than Winkler's). E = 2 MPa, h = 0.1 mm, R = 0.1 m, no friction or wear.
    for (nu, loads) in [(0.3, [1e2, 3e4]), (0.45, [1e3, 1e5]), (0.49, [1e4, 3e5])] {
        let offsets = loads.map(|p| {
            let inp = plane(2e6, nu, 1e-4, 0.0, 0.0, 0.0, 0.1, p);
            let strip = solve(&inp, Model::Strip).unwrap().contact_width();
            let winkler = solve(&inp, Model::Narrow).unwrap().contact_width();
            ((winkler - strip) / 1e-4, strip / 1e-4)
        });
        let [(near, l_near), (far, l_far)] = offsets;
        assert!(
            l_far > 2.5 * l_near,
            "nu = {nu}: (a+b)/h {l_near} to {l_far}"
        );
        assert!(
            (far - near).abs() < 0.05 * far.abs(),
            "nu = {nu}: offsets {near} h at {l_near} h, {far} h at {l_far} h"
        );
    }
}

#[test]
fn a_contact_wider_than_the_model_resolves_is_an_error_not_a_number() {
    // the strip preset's material at P = 1e8 N/m: (a+b)/h about 350 (Winkler), beyond the
    // (MAX_NODES - 40)/4 = 242 thicknesses that MAX_NODES resolve
    let err = solve(&table_inputs(1e-5, 1e8), Model::Strip).unwrap_err();
    match err {
        SolveError::NoSolution(why) => assert!(why.contains("wider than the strip model resolves")),
        other => panic!("{other:?}"),
    }
    assert_eq!(MAX_NODES, nodes_for(242.0));
}

#[test]
fn a_solution_to_check_against_agrees_with_the_full_solution_to_1e_8() {
    // the accuracy `strip_check` measures with (width to 1e-9, linear solves to 1e-10) against
    // the full solve (width to 1e-15), from a contact narrower than the layer to one wide enough
    // for the two-grid solve (N >= 224 nodes from (a+b)/h about 46; the widest here about 155)
    let mut widest = 0.0_f64;
    for (h, p) in [
        (1e-3, 1e3),
        (1e-4, 1e3),
        (2e-5, 1e4),
        (1e-5, 1e5),
        (5e-6, 2e5),
    ] {
        let inputs = table_inputs(h, p);
        let full = solve(&inputs, Model::Strip).unwrap();
        let check = wearlab::physics::plane::strip::solve_to_check(&inputs).unwrap();
        let l = full.contact_width();
        widest = widest.max(l / h);
        assert!(
            rel(check.contact_width(), l) < 1e-8,
            "h = {h}, P = {p}: width"
        );
        assert!(
            (check.mu_star - full.mu_star).abs() < 1e-8 * (full.mu_star - 0.3).abs(),
            "h = {h}, P = {p}: mu* {} vs {}",
            check.mu_star,
            full.mu_star
        );
    }
    assert!(widest > 50.0, "(a+b)/h reached only {widest}");
}
