//! The general solver's load sweep (`plane::sweep::sweep` on the wide model), which starts each
//! load from the previous load's solution, against `plane::solve` at each load on its own (the
//! coarse width search from the first guess): the same discrete problem, so the same answer
//! within the width's tolerance (1e-13 relative), here to 1e-10 in a, b, mu* and Q2.

use wearlab::physics::plane::sweep::sweep;
use wearlab::physics::plane::{Model, PlaneInputs, Shape, solve};
use wearlab::physics::{Spacing, SweepRange};

use crate::plane_general::{laws, material, power, rounded_flat};

fn inputs(thickness: f64, shape: Shape, exponent: f64, shear_strength: f64) -> PlaneInputs {
    let k = 0.5 / wearlab::physics::elastic::plane_modulus(1e10, 0.3);
    let (friction, wear) = laws(0.3, 1e5, shear_strength, k, exponent);
    PlaneInputs {
        material: material(thickness),
        friction: friction.coulomb,
        shear_strength,
        wear,
        shape,
        load: 1e4,
    }
}

#[test]
fn a_wide_sweep_started_from_each_previous_load_is_each_loads_own_solution() {
    let loads = SweepRange {
        min: 1e3,
        max: 1e5,
        points: 12,
        spacing: Spacing::Log,
    };
    let cases = [
        (
            "power n = 3, capped, wear n = 2, half-plane",
            inputs(f64::INFINITY, power(0.05, 3.0), 2.0, 2e6),
        ),
        (
            "power n = 3, capped, wear n = 2, 1 mm",
            inputs(1e-3, power(0.05, 3.0), 2.0, 2e6),
        ),
        (
            "rounded flat, linear laws, half-plane",
            inputs(f64::INFINITY, rounded_flat(1e-4, 0.05), 1.0, f64::INFINITY),
        ),
        (
            "power n = 1.5, wear n = 3, half-plane",
            inputs(f64::INFINITY, power(0.05, 1.5), 3.0, f64::INFINITY),
        ),
    ];
    for (name, at) in cases {
        let swept = sweep(&at, Model::Wide, &loads);
        for (i, &p) in swept.load.iter().enumerate() {
            let own = solve(&at.with_load(p), Model::Wide).unwrap();
            let pairs = [
                ("a", swept.a[i], own.a),
                ("b", swept.b[i], own.b),
                ("mu*", swept.mu_star[i], own.mu_star),
                ("Q2", swept.normal_force[i], own.normal_force),
            ];
            for (what, got, want) in pairs {
                let got = got.unwrap_or_else(|| panic!("{name}: no {what} at P = {p:e}"));
                let gap = (got - want).abs() / want.abs();
                assert!(
                    gap < 1e-10,
                    "{name}, P = {p:e}: {what} {got} vs {want} ({gap:e})"
                );
            }
        }
    }
}
