//! The general plane solver (physics::plane::general) on the half-plane and the wide strip against
//! independent routes (docs/physics/plane-general.md section 5): the closed forms of the parabola
//! with the linear laws, the power punch's continuity through n = 2, the rounded flat's limit
//! c -> 0, the physical sense of the half-plane's shifts, and two node counts.

use wearlab::physics::Material;
use wearlab::physics::plane::general::laws::{FrictionLaw, Punch, WearLaw};
use wearlab::physics::plane::general::{Problem, Solution, solve};
use wearlab::physics::plane::{PlaneInputs, wide};

/// g = x^2/(2R).
struct Parabola(f64);

impl Punch for Parabola {
    fn height(&self, x: f64) -> f64 {
        x * x / (2.0 * self.0)
    }
    fn slope(&self, x: f64) -> f64 {
        x / self.0
    }
    fn kinks(&self) -> Vec<f64> {
        Vec::new()
    }
}

/// g = (R/n)(|x|/R)^n.
struct Power(f64, f64);

impl Punch for Power {
    fn height(&self, x: f64) -> f64 {
        self.0 / self.1 * (x.abs() / self.0).powf(self.1)
    }
    fn slope(&self, x: f64) -> f64 {
        x.signum() * (x.abs() / self.0).powf(self.1 - 1.0)
    }
    fn kinks(&self) -> Vec<f64> {
        vec![0.0]
    }
}

/// A flat face |x| <= c with edges g = (|x| - c)^2/(2r).
struct RoundedFlat(f64, f64);

impl Punch for RoundedFlat {
    fn height(&self, x: f64) -> f64 {
        let d = (x.abs() - self.0).max(0.0);
        d * d / (2.0 * self.1)
    }
    fn slope(&self, x: f64) -> f64 {
        x.signum() * (x.abs() - self.0).max(0.0) / self.1
    }
    fn kinks(&self) -> Vec<f64> {
        vec![-self.0, self.0]
    }
}

fn material(thickness: f64) -> Material {
    Material {
        youngs_modulus: 1e10,
        poisson_ratio: 0.3,
        thickness,
    }
}

fn laws(mu: f64, tau0: f64, tau_max: f64, k: f64, n: f64) -> (FrictionLaw, WearLaw) {
    (
        FrictionLaw {
            coefficient: mu,
            adhesion: tau0,
            shear_strength: tau_max,
        },
        WearLaw {
            coefficient: k,
            exponent: n,
            reference_pressure: 1e8,
        },
    )
}

fn general(
    shape: &dyn Punch,
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
    };
    solve(&problem, nodes).unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
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
                    wearlab::physics::Friction {
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
                        &Parabola(radius),
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
fn sliding(shape: &dyn Punch, wear_exponent: f64, nodes: usize) -> Solution {
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
    let at = |n: f64| sliding(&Power(0.05, n), 1.0, 64);
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
    let parabola = sliding(&Parabola(r), 1.0, 64);
    let l = parabola.a + parabola.b;
    let mut last = f64::INFINITY;
    for c in [1e-2 * l, 1e-3 * l, 1e-4 * l] {
        let flat = sliding(&RoundedFlat(c, r), 1.0, 64);
        let gap = rel(flat.a, parabola.a)
            .max(rel(flat.b, parabola.b))
            .max(rel(flat.psi, parabola.psi));
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
    let shapes: [(&str, &dyn Punch); 4] = [
        ("parabola", &Parabola(0.05)),
        ("power 1.5", &Power(0.05, 1.5)),
        ("power 4", &Power(0.05, 4.0)),
        ("rounded flat", &RoundedFlat(1e-4, 0.05)),
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
            .map(|&nodes| sliding(&Parabola(0.05), n, nodes).a)
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
