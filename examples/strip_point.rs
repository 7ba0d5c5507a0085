//! Times one strip operating point for `scripts/scipy-comparison/strip_ratio.py`:
//! `strip_point E nu h R mu km P reps [cold]` prints the median seconds per solve after the kernel
//! table is built (as the SciPy reference's timing excludes its table). `cold` changes mu by a
//! relative 1e-12 per repetition, so that every solve builds its Gauss–Jacobi rules anew.

use std::time::Instant;

use wearlab::physics::plane::{Model, PlaneInputs, solve, strip};
use wearlab::physics::{Friction, Material};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let number = |i: usize| -> f64 { args[i].parse().expect("a number") };
    let (e, nu, h, r, mu, km, p) = (
        number(0),
        number(1),
        number(2),
        number(3),
        number(4),
        number(5),
        number(6),
    );
    let reps: usize = args[7].parse().expect("a count");
    let cold = args.get(8).is_some_and(|a| a == "cold");
    let m = wearlab::physics::elastic::plane_modulus(e, nu);
    let inputs = |coefficient: f64| PlaneInputs {
        material: Material {
            youngs_modulus: e,
            poisson_ratio: nu,
            thickness: h,
        },
        friction: Friction {
            coefficient,
            adhesion: 0.0,
        },
        shear_strength: f64::INFINITY,
        wear: wearlab::physics::plane::WearLaw::linear(km / m),
        shape: wearlab::physics::plane::Shape::Parabola { radius: r },
        load: p,
    };
    strip::kernels_for(nu);
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
            let sol = solve(&at, Model::Strip).expect("the strip solves");
            let seconds = start.elapsed().as_secs_f64();
            std::hint::black_box(sol);
            seconds
        })
        .collect();
    times.sort_by(f64::total_cmp);
    let sol = solve(&inputs(mu), Model::Strip).expect("the strip solves");
    println!(
        "{} {} {}",
        times[reps / 2],
        sol.contact_width() / h,
        sol.mu_star
    );
}
