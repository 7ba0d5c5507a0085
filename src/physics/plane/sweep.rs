//! mu*(P), a(P), b(P), Q2(P) over a range of loads.

use serde::Serialize;

use crate::physics::Spacing;
use crate::physics::plane::wide::{self, WideConstants};
use crate::physics::plane::{Model, PlaneInputs, narrow};

/// The loads of a sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LoadSweep {
    /// Smallest load [N/m], > 0.
    pub min: f64,
    /// Largest load [N/m], > min.
    pub max: f64,
    /// Number of loads, >= 2.
    pub points: usize,
    /// Log or linear spacing.
    pub spacing: Spacing,
}

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
}

/// Solves the model at every load of the sweep (the inputs' own load is ignored).
pub fn sweep(inputs: &PlaneInputs, model: Model, loads: &LoadSweep) -> Sweep {
    let load = loads.spacing.points(loads.min, loads.max, loads.points);
    let valid = inputs.validate().is_ok();
    let wide = (valid && model == Model::Wide).then(|| WideConstants::new(inputs));
    let solutions: Vec<_> = load
        .iter()
        .map(|&p| {
            let at = inputs.with_load(p);
            match model {
                _ if !valid => None,
                Model::Wide => wide::solve_with(wide.as_ref()?, &at).ok(),
                Model::Narrow => narrow::solve(&at).ok(),
            }
        })
        .collect();
    let pick = |f: fn(&super::PlaneSolution) -> f64| -> Vec<Option<f64>> {
        solutions.iter().map(|s| s.as_ref().map(f)).collect()
    };
    Sweep {
        mu_star: pick(|s| s.mu_star),
        a: pick(|s| s.a),
        b: pick(|s| s.b),
        normal_force: pick(|s| s.normal_force),
        load,
    }
}
