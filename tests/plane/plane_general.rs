//! The general plane solver (physics::plane::general) on the half-plane and the wide strip against
//! independent routes (docs/physics/plane-general.md section 5): the closed forms of the parabola
//! with the linear laws, the power punch's continuity through n = 2, the rounded flat's limit
//! c -> 0, the physical sense of the half-plane's shifts, and two node counts.

use wearlab::physics::plane::energy::energy;
use wearlab::physics::plane::general::{Problem, Solution, solve};
use wearlab::physics::plane::laws::FrictionLaw;
use wearlab::physics::plane::{Model, PlaneInputs, Shape, WearLaw, wide};
use wearlab::physics::{Friction, Material};

pub(super) fn parabola(radius: f64) -> Shape {
    Shape::Parabola { radius }
}

pub(super) fn power(radius: f64, exponent: f64) -> Shape {
    Shape::Power { radius, exponent }
}

pub(super) fn rounded_flat(half_width: f64, edge_radius: f64) -> Shape {
    Shape::Flat {
        half_width,
        edge_radius,
    }
}

pub(super) fn material(thickness: f64) -> Material {
    Material {
        youngs_modulus: 1e10,
        poisson_ratio: 0.3,
        thickness,
    }
}

pub(super) fn laws(mu: f64, tau0: f64, tau_max: f64, k: f64, n: f64) -> (FrictionLaw, WearLaw) {
    (
        FrictionLaw {
            coulomb: Friction {
                coefficient: mu,
                adhesion: tau0,
            },
            shear_strength: tau_max,
        },
        WearLaw {
            coefficient: k,
            exponent: n,
            reference_pressure: 1e8,
        },
    )
}

pub(super) fn general(
    shape: &Shape,
    thickness: f64,
    (friction, wear): (FrictionLaw, WearLaw),
    load: f64,
    nodes: usize,
) -> Solution {
    let problem = Problem {
        material: material(thickness),
        friction,
        wear,
        shape,
        load,
        strip: None,
    };
    solve(&problem, nodes).unwrap_or_else(|e| panic!("{shape:?}: {e}"))
}

pub(super) fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(f64::MIN_POSITIVE)
}

#[test]
fn parabola_with_the_linear_laws_is_the_closed_form() {
    // the cases of tests/plane/plane_wide.rs's table (plane.md section 6), tau0 and a thin strip
    let m = material(1.0).plane_modulus();
    for thickness in [f64::INFINITY, 1e-3] {
        for (mu, tau0, km) in [
            (0.3, 0.0, 0.5),
            (0.0, 0.0, 0.0),
            (0.5, 1e5, 0.0),
            (0.1, 2e5, 2.0),
        ] {
            for load in [1e2, 1e4, 1e5] {
                let radius = 0.05;
                let k = km / m;
                let closed = wide::solve(&PlaneInputs::parabolic(
                    material(thickness),
                    Friction {
                        coefficient: mu,
                        adhesion: tau0,
                    },
                    k,
                    radius,
                    load,
                ))
                .unwrap();
                for tau_max in [f64::INFINITY, 1e3 * (tau0 + mu * 1e10)] {
                    let g = general(
                        &parabola(radius),
                        thickness,
                        laws(mu, tau0, tau_max, k, 1.0),
                        load,
                        16,
                    );
                    let what =
                        format!("h {thickness} mu {mu} tau0 {tau0} km {km} P {load} cap {tau_max}");
                    assert!(
                        rel(g.a, closed.a) < 1e-9,
                        "{what}: a {} vs {}",
                        g.a,
                        closed.a
                    );
                    assert!(
                        rel(g.b, closed.b) < 1e-9,
                        "{what}: b {} vs {}",
                        g.b,
                        closed.b
                    );
                    assert!(
                        (g.mu_star - closed.mu_star).abs() < 1e-9 * closed.mu_star + 1e-13,
                        "{what}: mu* {} vs {}",
                        g.mu_star,
                        closed.mu_star
                    );
                    assert!(
                        (g.psi - closed.psi).abs() < 1e-9 * closed.psi.abs() + 1e-13 * load,
                        "{what}: psi {} vs {}",
                        g.psi,
                        closed.psi
                    );
                }
            }
        }
    }
}

/// The half-plane with mu = 0.3, k m = 0.5 (linear wear) at P = 1e4 N/m, R = 5 cm.
fn sliding(shape: &Shape, wear_exponent: f64, nodes: usize) -> Solution {
    let k = 0.5 / material(1.0).plane_modulus();
    general(
        shape,
        f64::INFINITY,
        laws(0.3, 0.0, f64::INFINITY, k, wear_exponent),
        1e4,
        nodes,
    )
}

#[test]
fn the_power_punch_is_continuous_through_the_parabola() {
    // a, b and psi change linearly in n - 2 near 2 (n = 2 is the parabola, whose closed form the
    // general solver reproduces): the one-sided difference quotients agree to O(delta)
    let at = |n: f64| sliding(&power(0.05, n), 1.0, 64);
    let mid = at(2.0);
    for delta in [1e-3, 1e-2] {
        let (up, down) = (at(2.0 + delta), at(2.0 - delta));
        for (name, f) in [
            ("a", (|s: &Solution| s.a) as fn(&Solution) -> f64),
            ("b", |s| s.b),
            ("psi", |s| s.psi),
        ] {
            let (d_up, d_down) = ((f(&up) - f(&mid)) / delta, (f(&mid) - f(&down)) / delta);
            println!("power n = 2 +- {delta}: d{name}/dn {d_up:.6e} and {d_down:.6e}");
            assert!(
                (d_up - d_down).abs() < 20.0 * delta * d_up.abs(),
                "{name}: {d_up} vs {d_down} at delta {delta}"
            );
        }
    }
}

#[test]
fn the_rounded_flat_tends_to_the_parabola_of_its_edge_radius() {
    let r = 0.05;
    let reference = sliding(&parabola(r), 1.0, 64);
    let l = reference.a + reference.b;
    let mut last = f64::INFINITY;
    for c in [1e-2 * l, 1e-3 * l, 1e-4 * l] {
        let flat = sliding(&rounded_flat(c, r), 1.0, 64);
        let gap = rel(flat.a, reference.a)
            .max(rel(flat.b, reference.b))
            .max(rel(flat.psi, reference.psi));
        println!("rounded flat c = {c:.3e} m: largest relative gap in a, b, psi {gap:.3e}");
        // the flat face changes g' by at most c/r, a step at the tip, whose pressure answer has a
        // logarithm: the gap is O((c/L) ln(L/c))
        assert!(gap < c / l * (1.0 + (l / c).ln()), "c {c}: {gap}");
        assert!(gap < last);
        last = gap;
    }
}

#[test]
fn on_the_half_plane_friction_shifts_back_and_wear_forward() {
    // docs/physics/plane-general.md section 5 route 7, for smooth shapes and wear exponents
    let m = material(1.0).plane_modulus();
    let shapes: [(&str, &Shape); 4] = [
        ("parabola", &parabola(0.05)),
        ("power 1.5", &power(0.05, 1.5)),
        ("power 4", &power(0.05, 4.0)),
        ("rounded flat", &rounded_flat(1e-4, 0.05)),
    ];
    for (name, shape) in shapes {
        for n in [1.0, 2.0, 3.0] {
            let friction = general(
                shape,
                f64::INFINITY,
                laws(0.3, 0.0, f64::INFINITY, 0.0, n),
                1e4,
                32,
            );
            assert!(
                friction.a > friction.b && friction.psi < 0.0,
                "{name} n {n}: friction alone"
            );
            let wear = general(
                shape,
                f64::INFINITY,
                laws(0.0, 0.0, f64::INFINITY, 1.0 / m, n),
                1e4,
                32,
            );
            assert!(
                wear.a < wear.b && wear.psi > 0.0,
                "{name} n {n}: wear alone"
            );
        }
    }
}

#[test]
fn with_a_nonlinear_wear_law_the_error_falls_like_a_power_of_the_nodes() {
    // docs/physics/plane-general.md section 3: the edge terms r^((n-1)(1/2 -+ theta)) give about
    // N^-2.5, N^-3, N^-4 for n = 1.5, 2, 3; the order from three successive differences
    for (n, order) in [(1.5, 2.5), (2.0, 3.0), (3.0, 4.0)] {
        let a: Vec<f64> = [16, 32, 64, 128]
            .iter()
            .map(|&nodes| sliding(&parabola(0.05), n, nodes).a)
            .collect();
        let d: Vec<f64> = a.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
        let seen = [(d[0] / d[1]).log2(), (d[1] / d[2]).log2()];
        let shown: Vec<String> = d.iter().map(|v| format!("{v:.2e}")).collect();
        println!("wear n = {n}: a at N = 16..128 {a:?}, differences {shown:?}, order {seen:.2?}");
        assert!(
            d[2] < 1e-6 * a[3],
            "n {n}: N = 64 and 128 differ by {}",
            d[2]
        );
        for s in seen {
            assert!(
                (s - order).abs() < 0.75,
                "n {n}: order {s}, expected about {order}"
            );
        }
    }
}

/// Plane inputs on a 1 mm strip (the wide model) or the half-plane.
pub(super) fn plane_inputs(
    shape: Shape,
    thickness: f64,
    (friction, wear): (FrictionLaw, WearLaw),
    load: f64,
) -> PlaneInputs {
    PlaneInputs {
        material: material(thickness),
        friction: friction.coulomb,
        shear_strength: friction.shear_strength,
        wear,
        shape,
        load,
    }
}

#[test]
fn the_wide_model_answers_every_smooth_shape_and_law_with_the_energy_identity() {
    // docs/physics/plane-general.md section 4: I = J checks the kernels and the quadrature, J =
    // psi - integral q2 F(q2) checks that the solution satisfies the contact condition. The
    // latter is the collocation's own error: near round-off where q2 is smooth, algebraic where it
    // is not (section 3: a power punch with n < 2 has q2 - q2(0) ~ |x|^(3/2) at the tip, the
    // rounded flat a jump of g'' at its face's ends, the cap a kink of Pi), so those get the
    // bounds of 64 nodes (observed with the projection of the slope: 7.4e-8, 4.6e-10, 1.4e-13)
    let k = 0.5 / material(1.0).plane_modulus();
    let cases = [
        (
            "parabola, n = 2",
            parabola(0.05),
            laws(0.3, 1e5, f64::INFINITY, k, 2.0),
            1e-8,
            1e-8,
        ),
        (
            "parabola, n = 3",
            parabola(0.05),
            laws(0.3, 0.0, f64::INFINITY, k, 3.0),
            1e-8,
            1e-8,
        ),
        (
            "power 3, n = 1",
            power(0.05, 3.0),
            laws(0.3, 0.0, f64::INFINITY, k, 1.0),
            1e-8,
            1e-8,
        ),
        (
            "power 1.5, n = 2",
            power(0.05, 1.5),
            laws(0.3, 0.0, f64::INFINITY, k, 2.0),
            1e-8,
            3e-4,
        ),
        (
            "rounded flat, n = 1",
            rounded_flat(1e-4, 0.05),
            laws(0.3, 0.0, f64::INFINITY, k, 1.0),
            1e-8,
            1e-5,
        ),
        (
            "parabola, capped",
            parabola(0.05),
            laws(0.3, 1e5, 5e6, k, 1.0),
            1e-8,
            1e-7,
        ),
        (
            "power 4, n = 2, capped",
            power(0.05, 4.0),
            laws(0.3, 1e5, 2e6, k, 2.0),
            1e-8,
            1e-8,
        ),
    ];
    for thickness in [f64::INFINITY, 1e-3] {
        for (name, shape, law, identity, contact) in cases.clone() {
            let inputs = plane_inputs(shape, thickness, law, 1e4);
            let sol = wearlab::physics::plane::solve(&inputs, Model::Wide).unwrap();
            let e = energy(&sol).unwrap();
            println!(
                "{name}, h = {thickness}: a {:.6e} b {:.6e} mu* {:.6e} T {:.6e} friction loss {:.6e} wear loss {:.6e} residual {:.2e} contact residual {:.2e}",
                sol.a,
                sol.b,
                sol.mu_star,
                e.external,
                e.friction_loss,
                e.wear_loss,
                e.residual,
                e.contact_residual
            );
            assert!(e.residual < identity, "{name}: I = J to {}", e.residual);
            assert!(
                e.contact_residual < contact,
                "{name}: contact {}",
                e.contact_residual
            );
            assert!(
                (e.external - e.friction_loss - e.wear_loss).abs() <= identity * e.external.abs(),
                "{name}: T = friction loss + wear loss"
            );
            assert!(e.friction_loss > 0.0 && e.wear_loss > 0.0, "{name}");
        }
    }
}

#[test]
fn the_closed_form_stays_the_answer_where_it_exists() {
    let inputs = plane_inputs(
        parabola(0.05),
        1e-3,
        laws(0.3, 1e5, f64::INFINITY, 1e-11, 1.0),
        1e4,
    );
    let sol = wearlab::physics::plane::solve(&inputs, Model::Wide).unwrap();
    assert_eq!(sol, wide::solve(&inputs).unwrap());
}
