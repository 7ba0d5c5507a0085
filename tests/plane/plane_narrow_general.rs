//! The narrow (Winkler) model for any punch shape, wear law and shear cap (`narrow_ode`) against
//! the closed form (5.7) where it holds and an independent fixed-step integration elsewhere.

use std::sync::Arc;

use crate::common::{plane, rel};
use wearlab::physics::plane::energy::energy;
use wearlab::physics::plane::narrow::{self, winkler_beta};
use wearlab::physics::plane::shape::Table;
use wearlab::physics::plane::spline::Spline;
use wearlab::physics::plane::{
    Model, PlaneInputs, PlaneSolution, Shape, WearLaw, narrow_ode, solve,
};

/// The closed-form cases of plane_narrow.rs: lambda L ~ 1, ~ 0.05, ~ 30 with adhesion, no wear.
fn parabolas() -> Vec<PlaneInputs> {
    vec![
        plane(1e8, 0.3, 1e-4, 0.3, 0.0, 5e-10, 0.05, 1e4),
        plane(1e8, 0.3, 1e-4, 0.3, 0.0, 2e-11, 0.05, 1e4),
        plane(1e8, 0.45, 1e-4, 0.5, 1e4, 2e-9, 0.05, 1e5),
        plane(1e8, 0.3, 1e-4, 0.3, 0.0, 0.0, 0.05, 1e4),
    ]
}

fn with_shape(shape: Shape) -> PlaneInputs {
    PlaneInputs {
        shape,
        ..plane(1e8, 0.3, 1e-4, 0.3, 1e3, 5e-10, 0.05, 1e4)
    }
}

/// A flat pin with rounded edges, a power punch, the law n = 2, and a capped friction.
fn general() -> Vec<PlaneInputs> {
    let flat = with_shape(Shape::Flat {
        half_width: 5e-4,
        edge_radius: 2e-3,
    });
    let power = with_shape(Shape::Power {
        radius: 0.05,
        exponent: 3.5,
    });
    let mut square = with_shape(Shape::Parabola { radius: 0.05 });
    square.wear = WearLaw {
        coefficient: 5e-10,
        exponent: 2.0,
        reference_pressure: 1e6,
    };
    let mut capped = flat.clone();
    capped.shear_strength = 4e6;
    let mut blunt = with_shape(Shape::Power {
        radius: 0.05,
        exponent: 1.5,
    });
    blunt.wear = WearLaw {
        coefficient: 2e-10,
        exponent: 3.0,
        reference_pressure: 1e6,
    };
    vec![flat, power, square, capped, blunt]
}

#[test]
fn the_shooting_reproduces_the_closed_form_of_the_parabola() {
    for inp in parabolas() {
        let closed = narrow::solve(&inp).unwrap();
        let shot = narrow_ode::solve(&inp).unwrap();
        let l = closed.contact_width();
        for (what, x, y, scale) in [
            ("a", shot.a, closed.a, l),
            ("b", shot.b, closed.b, l),
            ("Q2", shot.normal_force, closed.normal_force, inp.load),
            ("psi", shot.psi, closed.psi, inp.load),
            (
                "T",
                shot.tangential_force,
                closed.tangential_force,
                inp.load,
            ),
        ] {
            assert!((x - y).abs() < 1e-9 * scale, "{what}: {x} vs {y} ({inp:?})");
        }
        assert!((shot.mu_star - closed.mu_star).abs() < 1e-9, "{inp:?}");
        let peak = (1..40)
            .map(|i| closed.pressure(-closed.a + l * i as f64 / 40.0))
            .fold(1.0, f64::max);
        // a and b agree to 1e-9 L, which moves the steep q2 by up to about 1.2e-8 of its peak
        for i in 1..40 {
            let x = -closed.a + l * i as f64 / 40.0;
            let (got, want) = (shot.pressure(x), closed.pressure(x));
            assert!(
                (got - want).abs() < 2e-8 * peak,
                "x {x}: {got} vs {want} (peak {peak})"
            );
        }
    }
}

#[test]
fn the_power_punch_of_exponent_two_is_the_parabola() {
    for inp in parabolas() {
        let closed = solve(&inp, Model::Narrow).unwrap();
        let power = solve(
            &PlaneInputs {
                shape: Shape::Power {
                    radius: inp.radius(),
                    exponent: 2.0,
                },
                ..inp.clone()
            },
            Model::Narrow,
        )
        .unwrap();
        assert!(rel(power.contact_width(), closed.contact_width()) < 1e-9);
        assert!((power.mu_star - closed.mu_star).abs() < 1e-9);
    }
}

/// What the independent integration finds on [-a, b]: q2(-a) over the peak, and by the
/// trapezoidal rule Q2, phi = int Pi(q2) g', Q1 = int Pi(q2) and psi = int q2 g' [N/m].
struct Integrated {
    end: f64,
    peak: f64,
    q2: f64,
    phi: f64,
    q1: f64,
    psi: f64,
}

/// q2 on [-a, b] by 80 000 fixed RK4 steps of q2' = (F(q2) - g'(x))/beta from q2(b) = 0, with
/// the integrals by the trapezoidal rule on the same points.
fn integrate(sol: &PlaneSolution) -> Integrated {
    let inp = &sol.inputs;
    let beta = winkler_beta(inp);
    let f = |x: f64, q: f64| (inp.wear.rate(q) - inp.shape.slope(x)) / beta;
    let steps = 80_000;
    let h = -(sol.a + sol.b) / steps as f64;
    let (mut x, mut q, mut peak) = (sol.b, 0.0f64, 0.0f64);
    let integrands = |x: f64, q: f64| {
        let (shear, slope) = (inp.shear_at(q), inp.shape.slope(x));
        [q, shear * slope, shear, q * slope]
    };
    let mut sums = [0.0; 4];
    let mut last = integrands(x, q);
    for _ in 0..steps {
        let k1 = f(x, q);
        let k2 = f(x + h / 2.0, q + h / 2.0 * k1);
        let k3 = f(x + h / 2.0, q + h / 2.0 * k2);
        let k4 = f(x + h, q + h * k3);
        q += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        x += h;
        peak = peak.max(q);
        let now = integrands(x, q);
        for (s, (l, n)) in sums.iter_mut().zip(last.iter().zip(&now)) {
            *s -= h * 0.5 * (l + n);
        }
        last = now;
    }
    let [q2, phi, q1, psi] = sums;
    Integrated {
        end: q / peak,
        peak,
        q2,
        phi,
        q1,
        psi,
    }
}

#[test]
fn the_shot_satisfies_the_end_conditions_and_the_load_by_an_independent_integration() {
    for inp in general() {
        let sol = solve(&inp, Model::Narrow).unwrap_or_else(|e| panic!("{e}: {inp:?}"));
        let Integrated { end, q2, phi, .. } = integrate(&sol);
        // q2(-a) = 0 to the fine integration's accuracy (its uniform steps lose order at the
        // blunt power punch's tip: 5e-9 of the peak there); the trapezoidal load to (h/L)^2
        assert!(end.abs() < 1e-7, "q2(-a)/peak = {end}: {inp:?}");
        assert!(
            rel(q2 - phi, inp.load) < 1e-6,
            "{} vs {}",
            q2 - phi,
            inp.load
        );
        assert!(rel(q2, sol.normal_force) < 1e-6);
        let en = energy(&sol).unwrap();
        // Winkler: I = J = 0 (q1 = tau0 at both ends); the wear loss psi - J = int q2 F(q2)
        assert!(en.contact_residual < 1e-6, "{en:?}");
        assert!((en.friction_loss + en.wear_loss - en.external).abs() < 1e-6 * en.external);
    }
}

/// The power punch n = 3 with the wear law n = 2 and a shear cap on a 0.1 mm layer, the case of
/// benches/plane_general.rs: E = 10 GPa, nu = 0.3, mu = 0.3, tau0 = 0.1 MPa, tau_max = 2 MPa,
/// k m = 0.5, p0 = 100 MPa, R = 50 mm.
fn capped_power(load: f64) -> PlaneInputs {
    let m = wearlab::physics::elastic::plane_modulus(1e10, 0.3);
    PlaneInputs {
        shape: Shape::Power {
            radius: 0.05,
            exponent: 3.0,
        },
        shear_strength: 2e6,
        wear: WearLaw {
            coefficient: 0.5 / m,
            exponent: 2.0,
            reference_pressure: 1e8,
        },
        ..plane(1e10, 0.3, 1e-4, 0.3, 1e5, 0.0, 0.05, load)
    }
}

#[test]
fn the_capped_power_punch_answers_across_its_load_sweep_where_the_cap_holds() {
    // P = 1e3 to 1e5 N/m as the bench's sweep: the cap starts to hold where mu q2 + tau0 reaches
    // tau_max (q2 = 6.33 MPa, near P = 7e3 N/m) and covers most of the contact at 1e5 N/m
    let cap_from = (2e6 - 1e5) / 0.3;
    let mut capped = 0;
    for i in 0..12 {
        let inp = capped_power(1e3 * 100f64.powf(i as f64 / 11.0));
        let sol = solve(&inp, Model::Narrow).unwrap_or_else(|e| panic!("{e}: {inp:?}"));
        let fine = integrate(&sol);
        capped += usize::from(fine.peak > cap_from);
        assert!(fine.end.abs() < 1e-7, "q2(-a)/peak = {}: {inp:?}", fine.end);
        // the load balance P = Q2 - phi (2.1), Q2, phi and mu* = (Q1 + psi - tau0 L)/P (3.13)
        // with the cap's Pi(q2) integrated by the trapezoidal rule: (h/L)^2 ~ 2e-10 away from
        // the kink where the cap starts, (h/L) (h/L-jump of Pi') at it
        let p = inp.load;
        assert!(
            rel(fine.q2 - fine.phi, p) < 1e-6,
            "{} vs {p}",
            fine.q2 - fine.phi
        );
        assert!(rel(fine.q2, sol.normal_force) < 1e-6);
        assert!(
            (fine.phi - sol.phi).abs() < 1e-6 * p,
            "phi {} vs {}",
            fine.phi,
            sol.phi
        );
        let mu_star = (fine.q1 + fine.psi - 1e5 * sol.contact_width()) / p;
        assert!(
            (mu_star - sol.mu_star).abs() < 1e-6,
            "{mu_star} vs {}",
            sol.mu_star
        );
        // N against 2N Runge-Kutta steps
        let twice = narrow_ode::solve_refined(&inp, 2).unwrap();
        assert!(rel(twice.contact_width(), sol.contact_width()) < 1e-6);
        assert!((twice.mu_star - sol.mu_star).abs() < 1e-6);
    }
    // the seven loads from 8.1e3 N/m
    assert!(capped >= 7, "the cap holds at {capped} of the 12 loads");
}

#[test]
fn a_rounded_flat_tends_to_the_parabola_of_its_edge_radius_as_its_face_shrinks() {
    let parabola = solve(&with_shape(Shape::Parabola { radius: 2e-3 }), Model::Narrow).unwrap();
    let flat = solve(
        &with_shape(Shape::Flat {
            half_width: 1e-9,
            edge_radius: 2e-3,
        }),
        Model::Narrow,
    )
    .unwrap();
    // a face of 2 nm against a contact of some 0.2 mm: the difference is of order c/L ~ 1e-5
    assert!(rel(flat.contact_width(), parabola.contact_width()) < 1e-4);
    assert!((flat.mu_star - parabola.mu_star).abs() < 1e-4 * parabola.mu_star);
}

#[test]
fn a_table_through_a_parabola_answers_as_the_parabola_and_refuses_a_contact_off_its_range() {
    let r = 0.05;
    let table = |half: f64| {
        let x: Vec<f64> = (0..=400)
            .map(|i| -half + 2.0 * half * i as f64 / 400.0)
            .collect();
        let g = x.iter().map(|v| v * v / (2.0 * r)).collect();
        Shape::Table(Arc::new(Table {
            file: "p.csv".into(),
            spline: Spline::new(x, g).unwrap(),
        }))
    };
    let parabola = with_shape(Shape::Parabola { radius: r });
    let closed = solve(&parabola, Model::Narrow).unwrap();
    let l = closed.contact_width();
    let from_table = solve(
        &PlaneInputs {
            shape: table(l),
            ..parabola.clone()
        },
        Model::Narrow,
    )
    .unwrap();
    // the natural spline's end curvature 0 reaches the contact only as e^-(distance/knot
    // spacing): the interior error is the spline's h^4, below 1e-8 here
    assert!(rel(from_table.contact_width(), l) < 1e-7);
    let err = solve(
        &PlaneInputs {
            shape: table(0.3 * l),
            ..parabola
        },
        Model::Narrow,
    )
    .unwrap_err()
    .to_string();
    assert!(err.contains("runs off the measured profile"), "{err}");
}

#[test]
fn the_wide_and_strip_models_answer_other_shapes_and_laws_or_say_why_not() {
    // these cases are contacts some 10 to 100 thicknesses wide, outside the wide model's range:
    // the general solver answers some (answers that passed plane::checks) and says why not for
    // the rest; the strip model refuses a shear cap by name
    for inp in general() {
        for model in [Model::Wide, Model::Strip] {
            if let Err(e) = solve(&inp, model) {
                let why = e.to_string();
                assert!(why.len() > 40 && !why.contains("NaN"), "{why}");
                if model == Model::Strip && inp.shear_strength.is_finite() {
                    assert!(why.contains("no shear_strength"), "{why}");
                }
            }
        }
    }
}
