//! The strip model over a load sweep, by contact width: one collocation per width, the widths
//! spaced like the requested loads, neighbouring widths sharing node counts and factorizations.

use std::rc::Rc;

use super::collocation::{Rules, System};
use super::{
    ColumnKernel, Kernels, MAX_NODES, Missed, SWEEP_TOLERANCE, columns, kernels_for, node_count,
    search, solution, widest,
};
use crate::physics::plane::{Model, PlaneInputs, PlaneSolution, exponent};
use crate::physics::{SolveError, SweepRange};

/// The strip sweep by contact width: the widths of the end loads to 1e-6 (the widest width the
/// model resolves when the heavier load needs more), then one collocation per width, spaced
/// between them like the requested loads, each at the load it carries (None where the system is
/// singular or the load is not positive). Neighbouring widths share node counts and
/// factorizations, and the ends' searches lend theirs.
pub fn sweep_by_width(
    inputs: &PlaneInputs,
    loads: &SweepRange,
) -> Result<Vec<Option<PlaneSolution>>, SolveError> {
    let kernels = kernels_for(inputs.material.poisson_ratio);
    let regular = columns(inputs, kernels.as_ref());
    let search_at = |p: f64| {
        search(
            &inputs.with_load(p),
            kernels.as_ref(),
            &regular,
            p,
            (1e-6, SWEEP_TOLERANCE),
            false,
        )
    };
    let (l_min, low) = search_at(loads.min)?;
    // a heavier end than the model resolves: the sweep stops at the widest width it resolves
    let (l_max, high) = match search_at(loads.max) {
        Err(Missed::Beyond(_)) => {
            let l = widest(inputs) * (1.0 - 1e-3);
            let rules = Rules::cached(exponent(inputs).2, MAX_NODES);
            let system = System::new(inputs, kernels.as_ref(), &regular, rules, SWEEP_TOLERANCE);
            (l.max(l_min), system)
        }
        other => other?,
    };
    let widths = loads.spacing.points(l_min, l_max, loads.points);
    Ok(solve_at_widths(
        inputs,
        (kernels.as_ref(), &regular),
        &widths,
        [low, high],
    ))
}

/// The strip solutions at the contact widths `widths` (increasing), each at the load it carries;
/// None where the width is beyond the model's range, the system is singular or the load is not
/// positive. `ends` are systems to use where they fit. Taken from the widest down, a system with
/// up to SLACK more nodes than a width needs serves it (more nodes are only more accurate), so a
/// sweep factors once per SLACK/4 thicknesses of contact width.
fn solve_at_widths<'a>(
    inputs: &PlaneInputs,
    (kernels, regular): (&'a dyn Kernels, &Rc<ColumnKernel<'a>>),
    widths: &[f64],
    ends: [System<'a>; 2],
) -> Vec<Option<PlaneSolution>> {
    const SLACK: usize = 16;
    let (_, _, theta) = exponent(inputs);
    let h = inputs.material.thickness;
    // the two ends' systems, then the current one
    let mut systems: Vec<System> = ends.into();
    let mut solutions: Vec<Option<PlaneSolution>> = widths
        .iter()
        .rev()
        .map(|&l| {
            let needed = node_count(l / h)?;
            let fits = |s: &System| (needed..=needed + SLACK).contains(&s.nodes());
            let i = match systems.iter().rposition(fits) {
                Some(i) => i,
                None => {
                    systems.truncate(2);
                    let rules = Rules::cached(theta, needed);
                    systems.push(System::new(
                        inputs,
                        kernels,
                        regular,
                        rules,
                        SWEEP_TOLERANCE,
                    ));
                    2
                }
            };
            let col = systems[i].at(l)?;
            (col.load > 0.0).then(|| solution(&inputs.with_load(col.load), col, Model::Strip))
        })
        .collect();
    solutions.reverse();
    solutions
}
