//! mu*(P), a(P), b(P), Q2(P) over a range of loads.

use serde::Serialize;

use crate::physics::plane::wide::{self, WideConstants};
use crate::physics::plane::{Model, PlaneInputs, PlaneSolution, solve_narrow, strip};
use crate::physics::plane::{checks, general, scope, sharp, strip_check};
use crate::physics::{SweepRange, limits};

/// The sweep; entries are None where the model has no solution at that load.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Sweep {
    /// P [N/m].
    pub load: Vec<f64>,
    /// mu*, dimensionless.
    pub mu_star: Vec<Option<f64>>,
    /// a [m].
    pub a: Vec<Option<f64>>,
    /// b [m].
    pub b: Vec<Option<f64>>,
    /// Q2 [N/m].
    pub normal_force: Vec<Option<f64>>,
    /// Whether the model holds at the point (`strip_check::verdict`, as at the operating point).
    pub valid: Vec<Option<bool>>,
}

/// Solves the model at every load of the sweep (loads P [N/m]) (the inputs' own load is ignored).
/// A range outside `limits::LINE_LOAD` gives an empty sweep.
pub fn sweep(inputs: &PlaneInputs, model: Model, loads: &SweepRange) -> Sweep {
    if loads
        .check(["load_min", "load_max"], &limits::LINE_LOAD)
        .is_err()
    {
        return gather(Vec::new(), &[]);
    }
    let valid = inputs.validate().is_ok() && scope::check(inputs, model).is_ok();
    let closed = inputs.is_classical();
    if model == Model::Strip && closed {
        return by_contact_width(inputs, loads, valid);
    }
    let load = loads.values();
    let wide = (valid && closed && model == Model::Wide).then(|| WideConstants::new(inputs));
    let solutions: Vec<_> = load
        .iter()
        .map(|&p| {
            let at = inputs.with_load(p);
            match (model, at.shape.sharp_half_width()) {
                _ if !valid => None,
                (_, Some(c)) => sharp::solve(&at, model, c).ok(),
                (Model::Wide, _) if closed => wide::solve_with(wide.as_ref()?, &at).ok(),
                (Model::Wide, _) => general::answer::solve(&at, model).ok(),
                (Model::Narrow, _) => solve_narrow(&at).ok(),
                (Model::Strip, _) => general::answer::solve(&at, model).ok(),
            }
            .filter(|sol| checks::check(sol).is_ok())
        })
        .collect();
    gather(load, &solutions)
}

fn gather(load: Vec<f64>, solutions: &[Option<PlaneSolution>]) -> Sweep {
    let pick = |f: fn(&PlaneSolution) -> f64| -> Vec<Option<f64>> {
        solutions.iter().map(|s| s.as_ref().map(f)).collect()
    };
    Sweep {
        mu_star: pick(|s| s.mu_star),
        a: pick(|s| s.a),
        b: pick(|s| s.b),
        normal_force: pick(|s| s.normal_force),
        valid: solutions
            .iter()
            .map(|s| s.as_ref().map(|s| strip_check::verdict(s).ok))
            .collect(),
        load,
    }
}

/// The strip sweep, parametrized by the contact width: Brent finds only the widths of the end
/// loads, then one collocation per point gives its load (so the loads are the solutions', spaced
/// like the requested ones in contact width; a width that fails the checks is left out).
fn by_contact_width(inputs: &PlaneInputs, loads: &SweepRange, valid: bool) -> Sweep {
    let none = || {
        let load = loads.values();
        let none = vec![None; load.len()];
        gather(load, &none)
    };
    if !valid || inputs.material.is_half_space() {
        return none();
    }
    let Ok(solutions) = strip::sweep_by_width(inputs, loads) else {
        return none();
    };
    // a width whose collocation fails the checks has no load: it is left out of the curve
    let solutions: Vec<Option<PlaneSolution>> = solutions
        .into_iter()
        .flatten()
        .filter(|sol| checks::check(sol).is_ok())
        .map(Some)
        .collect();
    let load = solutions
        .iter()
        .flatten()
        .map(|s| s.inputs.load)
        .collect::<Vec<_>>();
    gather(load, &solutions)
}
