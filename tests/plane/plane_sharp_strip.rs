//! The flat punch with sharp corners on the strip of any thickness (physics::plane::sharp_strip)
//! against independent routes (docs/physics/plane-general.md section 6): the wide-strip limit of
//! the kernels against the closed form q2 = Z (A + B (c + x)), a thick strip (h/c >= 1e3) against
//! the half-plane's and the wide strip's closed forms, N against 2N nodes, a thin strip against the
//! Winkler strip's pressure on the face, and what the energy report says.

use wearlab::physics::plane::energy::energy;
use wearlab::physics::plane::sharp::solve_refined;
use wearlab::physics::plane::strip::WideLimit;
use wearlab::physics::plane::{Model, PlaneInputs, Shape, WearLaw, sharp_strip, solve};
use wearlab::physics::{Friction, Material};

const C: f64 = 1e-3;

fn inputs(thickness: f64, mu: f64, tau0: f64, k: f64) -> PlaneInputs {
    PlaneInputs {
        material: Material {
            youngs_modulus: 1e10,
            poisson_ratio: 0.3,
            thickness,
        },
        friction: Friction {
            coefficient: mu,
            adhesion: tau0,
        },
        shear_strength: f64::INFINITY,
        wear: WearLaw::linear(k),
        shape: Shape::Flat {
            half_width: C,
            edge_radius: 0.0,
        },
        load: 1e5,
    }
}

/// Friction alone, friction with adhesion, wear stronger than friction (theta < 0), all three.
const LAWS: [(f64, f64, f64); 4] = [
    (0.3, 0.0, 0.0),
    (0.5, 2e6, 0.0),
    (0.1, 0.0, 4e-11),
    (0.4, 1e6, 2e-11),
];

/// Interior points of the face, x/c, and points near both corners.
const XS: [f64; 7] = [-0.999, -0.9, -0.4, 0.0, 0.5, 0.95, 0.999];

#[test]
fn with_the_wide_limit_of_the_kernels_it_is_the_closed_form() {
    // the wide limit of the kernels (R2 = 0, chi B12 = chi c12, chi l12(z) = chi c12 z) turns
    // the strip's (E) into the wide strip's, whose solution is the closed form of section 3
    for thickness in [0.05, 2e-3, 5e-4] {
        for (mu, tau0, k) in LAWS {
            let inp = inputs(thickness, mu, tau0, k);
            let wide = solve(&inp, Model::Wide).unwrap();
            let limit = WideLimit::new(inp.material.poisson_ratio);
            let p = sharp_strip::solve(&inp, &limit, C, 32).unwrap();
            assert!((p.normal_force() / inp.load - 1.0).abs() < 1e-13);
            for x in XS {
                let u = (1.0 + x) * C;
                let (got, want) = (
                    p.pressure_from_trailing_edge(u),
                    wide.pressure_from_trailing_edge(u),
                );
                assert!(
                    (got / want - 1.0).abs() < 1e-11,
                    "h {thickness} laws {mu} {tau0} {k} x/c {x}: {got:e} {want:e}"
                );
            }
        }
    }
}

#[test]
fn a_thick_strip_is_the_half_plane() {
    // h/c = 1e3: the strip's correction to the half-plane is the wide strip's chi c12 Q1/(m h)
    // to leading order (O(L/h)), so the strip meets the wide closed form to O((L/h)^2) = 4e-6
    // and the half-plane to O(L/h) = 2e-3 (seen: 0.9e-6 .. 1.0e-6 and 2e-4 .. 4e-4)
    for (mu, tau0, k) in LAWS {
        let inp = inputs(1e3 * C, mu, tau0, k);
        let strip = solve(&inp, Model::Strip).unwrap();
        let wide = solve(&inp, Model::Wide).unwrap();
        let half_plane = solve(&inputs(f64::INFINITY, mu, tau0, k), Model::Wide).unwrap();
        assert_eq!(
            (strip.a, strip.b, strip.psi, strip.delta_g),
            (C, C, 0.0, 0.0)
        );
        assert!((strip.normal_force / inp.load - 1.0).abs() < 1e-12);
        assert_eq!(strip.theta, wide.theta);
        assert!((strip.mu_star - mu).abs() < 1e-12);
        let (mut to_wide, mut to_half_plane) = (0.0f64, 0.0f64);
        for x in XS {
            let u = (1.0 + x) * C;
            let q = strip.pressure_from_trailing_edge(u);
            to_wide = to_wide.max((q / wide.pressure_from_trailing_edge(u) - 1.0).abs());
            to_half_plane =
                to_half_plane.max((q / half_plane.pressure_from_trailing_edge(u) - 1.0).abs());
        }
        eprintln!(
            "h/c = 1e3 laws {mu} {tau0} {k}: to the wide {to_wide:.2e}, to the half-plane {to_half_plane:.2e}"
        );
        assert!(
            to_wide < 4e-6 && to_half_plane < 2e-3,
            "{to_wide:e} {to_half_plane:e}"
        );
    }
}

#[test]
fn n_and_2n_nodes_agree() {
    for thickness in [4e-3, 1e-3, 2e-4, 1e-4] {
        for (mu, tau0, k) in LAWS {
            let inp = inputs(thickness, mu, tau0, k);
            let one = solve_refined(&inp, Model::Strip, C, 1).unwrap();
            let two = solve_refined(&inp, Model::Strip, C, 2).unwrap();
            let mut gap = 0.0f64;
            for x in XS {
                let u = (1.0 + x) * C;
                let (q1, q2) = (
                    one.pressure_from_trailing_edge(u),
                    two.pressure_from_trailing_edge(u),
                );
                gap = gap.max((q1 / q2 - 1.0).abs());
            }
            eprintln!("L/h = {}: N against 2N {gap:.2e}", 2.0 * C / thickness);
            assert!(gap < 1e-6, "h {thickness} laws {mu} {tau0} {k}: {gap:e}");
        }
    }
}

#[test]
fn a_thin_strip_is_the_winkler_face_away_from_the_corners() {
    // L/h = 100: the narrow model is the leading order in h/L; the corner layers are some h wide
    for (mu, tau0, k) in [(0.3, 0.0, 0.0), (0.3, 0.0, 2e-12)] {
        let inp = inputs(2.0 * C / 100.0, mu, tau0, k);
        let strip = solve(&inp, Model::Strip).unwrap();
        let narrow = solve(&inp, Model::Narrow).unwrap();
        let mut gap = 0.0f64;
        for x in [-0.5, -0.25, 0.0, 0.25, 0.5] {
            let u = (1.0 + x) * C;
            let (q, w) = (
                strip.pressure_from_trailing_edge(u),
                narrow.pressure_from_trailing_edge(u),
            );
            gap = gap.max((q / w - 1.0).abs());
        }
        eprintln!("L/h = 100, k = {k}: strip against Winkler on |x| <= c/2: {gap:.2e}");
        assert!(gap < 0.05, "{gap:e}");
    }
}

#[test]
fn the_scipy_reference_gives_the_same_pressure() {
    // the project's SciPy reference (scipy-reference/plane-general/gj.py, `GJ.solve_sharp`, its
    // own kernel tables and Jacobi rules, N = 128 and 256 agreeing to 1e-10), c = 1 mm on a
    // 0.1 mm strip, mu = 0.3, tau0 = 0.1 MPa, k m = 0.5, P = 1e4 N/m: q2 [Pa] at x/c = -0.5, 0,
    // 0.5, 0.999 (the wear makes the pressure grow toward the leading corner)
    let m = Material {
        youngs_modulus: 1e10,
        poisson_ratio: 0.3,
        thickness: 1e-4,
    }
    .plane_modulus();
    let inp = PlaneInputs {
        load: 1e4,
        ..inputs(1e-4, 0.3, 1e5, 0.5 / m)
    };
    let sol = solve(&inp, Model::Strip).unwrap();
    for (x, scipy) in [
        (-0.5, 117418.60757757945),
        (0.0, 785398.6281150754),
        (0.5, 5270033.911580112),
        (0.999, 140467474.62790275),
    ] {
        let q = sol.pressure(x * C);
        assert!(
            (q / scipy - 1.0).abs() < 1e-8,
            "x/c {x}: {q:e} against {scipy:e}"
        );
    }
}

#[test]
fn its_energies_diverge_and_its_refusals_hold() {
    let inp = inputs(1e-3, 0.3, 1e6, 1e-11);
    let sol = solve(&inp, Model::Strip).unwrap();
    let undefined = energy(&sol).unwrap_err();
    assert!(undefined.note.contains("diverge"), "{}", undefined.note);
    assert_eq!(undefined.wear_loss, None);
    assert_eq!(undefined.external, sol.tangential_force);
    let mut capped = inp.clone();
    capped.shear_strength = 1e7;
    let err = solve(&capped, Model::Strip).unwrap_err().to_string();
    assert!(err.contains("cannot take a finite shear_strength"), "{err}");
    let mut nonlinear = inp.clone();
    nonlinear.wear = WearLaw {
        exponent: 2.0,
        reference_pressure: 1e6,
        ..inp.wear
    };
    let err = solve(&nonlinear, Model::Strip).unwrap_err().to_string();
    assert!(err.contains("no steady solution"), "{err}");
}
