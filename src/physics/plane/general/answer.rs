//! The general solver as `plane::solve` calls it for the wide model (half-plane and wide strip)
//! and the strip of any thickness (without a shear cap) when the inputs are not the closed
//! form's or the strip solver's (a parabola, the linear wear law, no shear cap):
//! the inputs turned into a `Problem`, the solution into a `PlaneSolution` whose pressure law
//! (`PressureLaw::General`) the profiles, the energy identity and the charts evaluate.

use std::sync::Arc;

use crate::physics::SolveError;
use crate::physics::plane::general::{
    NODES, Problem, Solution, solve_from as solve_general_from, solve_refined as solve_general,
};
use crate::physics::plane::strip::{Kernels, kernels_for};
use crate::physics::plane::{Model, PlaneInputs, PlaneSolution, PressureLaw};

/// The wide or strip model's solution of smooth, non-classical inputs; an error when the
/// general solver does not converge or the contact runs off a measured profile.
pub fn solve(inputs: &PlaneInputs, model: Model) -> Result<PlaneSolution, SolveError> {
    solve_refined(inputs, model, 1)
}

/// `solve` with `factor` >= 1 times the node count it would choose (`general::solve_refined`):
/// the discretisation error is the difference from `solve`'s answer.
pub fn solve_refined(
    inputs: &PlaneInputs,
    model: Model,
    factor: usize,
) -> Result<PlaneSolution, SolveError> {
    let kernels = (model == Model::Strip).then(|| kernels_for(inputs.material.poisson_ratio));
    let problem = problem(inputs, kernels.as_deref().map(|k| k as &dyn Kernels));
    let sol = solve_general(&problem, NODES, factor)?;
    answer(inputs, model, &problem, sol)
}

/// The wide model's solution as `solve` gives it, started from `from`, the solution of the same
/// inputs at another load (a load sweep's previous point; `general::solve_from`), with the slope
/// d ln P/d ln L between `before` (the point before it) and `from` where both are given; `solve`
/// where `from` is not the general solver's on the same nodes or the start does not converge.
pub fn solve_from(
    inputs: &PlaneInputs,
    from: Option<&PlaneSolution>,
    before: Option<&PlaneSolution>,
) -> Result<PlaneSolution, SolveError> {
    let problem = problem(inputs, None);
    let log_slope = from.zip(before).and_then(|(f, b)| {
        let k = (f.inputs.load / b.inputs.load).ln() / (f.contact_width() / b.contact_width()).ln();
        (k.is_finite() && (0.2..=20.0).contains(&k)).then_some(k)
    });
    let started = from.and_then(|f| match &f.law {
        PressureLaw::General { pressure, .. } if f.model == Model::Wide => {
            solve_general_from(&problem, (pressure, f.inputs.load), log_slope).ok()
        }
        _ => None,
    });
    match started {
        Some(sol) => answer(inputs, Model::Wide, &problem, sol),
        None => solve(inputs, Model::Wide),
    }
}

/// The inputs as the general solver's problem, with the exact strip's kernels (the strip of any
/// thickness) or None (the wide strip and the half-plane).
fn problem<'a>(inputs: &'a PlaneInputs, strip: Option<&'a dyn Kernels>) -> Problem<'a> {
    Problem {
        material: inputs.material,
        friction: inputs.friction_law(),
        wear: inputs.wear,
        shape: &inputs.shape,
        load: inputs.load,
        strip,
    }
}

/// The general solution `sol` of `problem` (the inputs') as the model's `PlaneSolution`.
fn answer(
    inputs: &PlaneInputs,
    model: Model,
    problem: &Problem,
    sol: Solution,
) -> Result<PlaneSolution, SolveError> {
    inputs.shape.covers(sol.a, sol.b)?;
    let p = &sol.pressure;
    let kinks: Arc<[f64]> = problem
        .splits(p)
        .iter()
        .map(|t| 0.5 * p.l * (1.0 + t))
        .collect();
    Ok(PlaneSolution {
        model,
        inputs: inputs.clone(),
        normal_force: sol.normal_force,
        friction_force: sol.friction_force,
        tangential_force: sol.tangential_force,
        a: sol.a,
        b: sol.b,
        theta: Some(sol.theta),
        gamma: Some(problem.gamma()),
        psi: sol.psi,
        phi: sol.phi,
        delta_g: sol.delta_g,
        mu_star: sol.mu_star,
        law: PressureLaw::General {
            pressure: Arc::new(sol.pressure),
            kinks,
        },
    })
}
