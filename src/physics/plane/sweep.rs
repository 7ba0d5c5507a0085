//! mu*(P), a(P), b(P), Q2(P) over a range of loads, and the energy losses' shares of T.

use serde::Serialize;

use crate::physics::plane::energy::wear_loss;
use crate::physics::plane::wide::{self, WideConstants};
use crate::physics::plane::{Model, PlaneInputs, PlaneSolution, solve_narrow, strip};
use crate::physics::plane::{checks, general, scope, sharp, sweep_verdicts};
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
    /// Whether the model holds at the point (`strip_check::verdict`, as at the operating point;
    /// measured along the sweep by `sweep_verdicts::holds_along`); None where the model has no
    /// solution, and everywhere while `judged` is false.
    pub valid: Vec<Option<bool>>,
    /// Whether `valid` holds the verdicts: false for the curve delivered before them
    /// (`Solved::unjudged`).
    #[serde(skip)]
    pub judged: bool,
}

/// A sweep's solutions, before their verdicts: the curve can be drawn from them at once and the
/// verdicts, which measure the model against the strip model where the study's estimate doubts
/// it (strip solves of a few milliseconds each), follow (`Solved::judged`).
#[derive(Clone, Debug)]
pub struct Solved {
    /// P [N/m].
    load: Vec<f64>,
    /// The model's solution at each load (None where it has none or fails the checks).
    solutions: Vec<Option<PlaneSolution>>,
}

impl Solved {
    /// The sweep without verdicts (`judged` false, every `valid` None).
    pub fn unjudged(&self) -> Sweep {
        gather(self.load.clone(), &self.solutions, None)
    }

    /// The sweep with the verdict at every point.
    pub fn judged(self) -> Sweep {
        let valid = sweep_verdicts::holds_along(&self.solutions);
        gather(self.load, &self.solutions, Some(valid))
    }
}

/// The friction loss and the wear loss over a range of loads, as shares of the external work T
/// (Soldatenkov (2007) eqs. (2.5), (2.7)): the wear loss as the integral of q2 F(q2) (`wear_loss`),
/// the friction loss as T less it, which (2.8)-(2.9) make equal to Q1 + I; entries are None where
/// the model has no solution, T = 0, or the loss has no number (sharp corners, `energy`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct EnergySweep {
    /// P [N/m].
    pub load: Vec<f64>,
    /// Friction loss over T, dimensionless.
    pub friction_share: Vec<Option<f64>>,
    /// Wear loss over T, dimensionless.
    pub wear_share: Vec<Option<f64>>,
}

/// Solves the model at every load of the sweep (loads P [N/m]) (the inputs' own load is ignored).
/// A range outside `limits::LINE_LOAD` gives an empty sweep.
pub fn sweep(inputs: &PlaneInputs, model: Model, loads: &SweepRange) -> Sweep {
    solve(inputs, model, loads).judged()
}

/// The model solved at every load of the sweep, its verdicts not yet measured (`Solved`).
pub fn solve(inputs: &PlaneInputs, model: Model, loads: &SweepRange) -> Solved {
    let (load, solutions) = solutions(inputs, model, loads);
    Solved { load, solutions }
}

/// The energy losses' shares of T at every load of the sweep, from the same solutions as `sweep`.
pub fn energy_sweep(inputs: &PlaneInputs, model: Model, loads: &SweepRange) -> EnergySweep {
    let (load, solutions) = solutions(inputs, model, loads);
    let shares: Vec<Option<(Option<f64>, Option<f64>)>> = solutions
        .iter()
        .map(|s| {
            let s = s.as_ref()?;
            let t = s.tangential_force;
            let (friction, wear) = match wear_loss(s) {
                Ok(wear) => (Some(t - wear), Some(wear)),
                Err(undefined) => (None, undefined.wear_loss),
            };
            (t != 0.0).then(|| (friction.map(|f| f / t), wear.map(|w| w / t)))
        })
        .collect();
    EnergySweep {
        friction_share: shares.iter().map(|s| s.and_then(|s| s.0)).collect(),
        wear_share: shares.iter().map(|s| s.and_then(|s| s.1)).collect(),
        load,
    }
}

/// The loads and the model's solution at each (None where it has none or fails the checks).
fn solutions(
    inputs: &PlaneInputs,
    model: Model,
    loads: &SweepRange,
) -> (Vec<f64>, Vec<Option<PlaneSolution>>) {
    if loads
        .check(["load_min", "load_max"], &limits::LINE_LOAD)
        .is_err()
    {
        return (Vec::new(), Vec::new());
    }
    let valid = inputs.validate().is_ok() && scope::check(inputs, model).is_ok();
    let closed = inputs.is_classical();
    if model == Model::Strip && closed {
        return by_contact_width(inputs, loads, valid);
    }
    let load = loads.values();
    let wide = (valid && closed && model == Model::Wide).then(|| WideConstants::new(inputs));
    // the general wide solver starts each load from the last one solved (continuation), its
    // width's first step with the slope d ln P/d ln L between the last two
    let (mut last, mut before): (Option<PlaneSolution>, Option<PlaneSolution>) = (None, None);
    let solutions: Vec<_> = load
        .iter()
        .map(|&p| {
            let at = inputs.with_load(p);
            let sol = match (model, at.shape.sharp_half_width()) {
                _ if !valid => None,
                (_, Some(c)) => sharp::solve(&at, model, c).ok(),
                (Model::Wide, _) if closed => wide::solve_with(wide.as_ref()?, &at).ok(),
                (Model::Wide, _) => {
                    general::answer::solve_from(&at, last.as_ref(), before.as_ref()).ok()
                }
                (Model::Narrow, _) => solve_narrow(&at).ok(),
                (Model::Strip, _) => general::answer::solve(&at, model).ok(),
            }
            .filter(|sol| checks::check(sol).is_ok());
            if sol.is_some() {
                before = std::mem::replace(&mut last, sol.clone());
            }
            sol
        })
        .collect();
    (load, solutions)
}

/// The sweep of the solutions, with the verdicts given (None: not judged yet).
fn gather(
    load: Vec<f64>,
    solutions: &[Option<PlaneSolution>],
    valid: Option<Vec<Option<bool>>>,
) -> Sweep {
    let pick = |f: fn(&PlaneSolution) -> f64| -> Vec<Option<f64>> {
        solutions.iter().map(|s| s.as_ref().map(f)).collect()
    };
    Sweep {
        mu_star: pick(|s| s.mu_star),
        a: pick(|s| s.a),
        b: pick(|s| s.b),
        normal_force: pick(|s| s.normal_force),
        judged: valid.is_some(),
        valid: valid.unwrap_or_else(|| vec![None; solutions.len()]),
        load,
    }
}

/// The strip sweep, parametrized by the contact width: Brent finds only the widths of the end
/// loads, then one collocation per point gives its load (so the loads are the solutions', spaced
/// like the requested ones in contact width; a width that fails the checks is left out).
fn by_contact_width(
    inputs: &PlaneInputs,
    loads: &SweepRange,
    valid: bool,
) -> (Vec<f64>, Vec<Option<PlaneSolution>>) {
    let none = || {
        let load = loads.values();
        let none = vec![None; load.len()];
        (load, none)
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
    (load, solutions)
}
