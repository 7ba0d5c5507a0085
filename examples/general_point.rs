//! Times one operating point of the general plane solver for
//! `scripts/scipy-comparison/general_ratio.py`:
//! `general_point MODEL E nu h mu tau0 tau_max km n p0 SHAPE P reps [cold]`, with MODEL wide,
//! narrow or strip, h = inf for the half-plane, km the wear coefficient times m (dimensionless), n
//! the wear exponent, p0 its reference pressure [Pa], SHAPE `power:R:n` or `flat:c:r` (lengths
//! in m). Prints the median seconds per solve after one solve that builds the kernel table and the
//! Gauss–Jacobi rules, then (a+b)/h, psi [N/m] and mu*. `cold` changes mu by a relative 1e-12 per
//! repetition, so that every solve builds its Gauss–Jacobi rules anew.

use std::time::Instant;

use wearlab::physics::plane::{Model, PlaneInputs, Shape, WearLaw, solve};
use wearlab::physics::{Friction, Material};

fn shape(spec: &str) -> Shape {
    let parts: Vec<&str> = spec.split(':').collect();
    let number = |i: usize| -> f64 { parts[i].parse().expect("a number in the shape") };
    match parts[0] {
        "power" => Shape::Power {
            radius: number(1),
            exponent: number(2),
        },
        "flat" => Shape::Flat {
            half_width: number(1),
            edge_radius: number(2),
        },
        other => panic!("unknown shape {other}: power:R:n or flat:c:r"),
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let number = |i: usize| -> f64 { args[i].parse().expect("a number") };
    let model = match args[0].as_str() {
        "wide" => Model::Wide,
        "narrow" => Model::Narrow,
        "strip" => Model::Strip,
        other => panic!("unknown model {other}: wide, narrow or strip"),
    };
    let (e, nu, h, mu, tau0, tau_max, km, n, p0) = (
        number(1),
        number(2),
        number(3),
        number(4),
        number(5),
        number(6),
        number(7),
        number(8),
        number(9),
    );
    let punch = shape(&args[10]);
    let load = number(11);
    let reps: usize = args[12].parse().expect("a count");
    let cold = args.get(13).is_some_and(|a| a == "cold");
    let m = wearlab::physics::elastic::plane_modulus(e, nu);
    let inputs = |coefficient: f64| PlaneInputs {
        material: Material {
            youngs_modulus: e,
            poisson_ratio: nu,
            thickness: h,
        },
        friction: Friction {
            coefficient,
            adhesion: tau0,
        },
        shear_strength: tau_max,
        wear: WearLaw {
            coefficient: km / m,
            exponent: n,
            reference_pressure: p0,
        },
        shape: punch.clone(),
        load,
    };
    let sol = solve(&inputs(mu), model).expect("the operating point solves");
    let mut times: Vec<f64> = (0..reps)
        .map(|rep| {
            // cold: a new theta, so new Gauss–Jacobi rules
            let coefficient = if cold {
                mu * (1.0 + 1e-12 * (rep + 1) as f64)
            } else {
                mu
            };
            let at = inputs(coefficient);
            let start = Instant::now();
            let once = solve(&at, model).expect("the operating point solves");
            let seconds = start.elapsed().as_secs_f64();
            std::hint::black_box(once);
            seconds
        })
        .collect();
    times.sort_by(f64::total_cmp);
    println!(
        "{} {} {} {}",
        times[reps / 2],
        sol.contact_width() / h,
        sol.psi,
        sol.mu_star
    );
}
