//! The plane problem's pipeline stage "operating point": one solve at the inputs' load and
//! everything derived from it (profile, energy identity, validity). The explorer's engine caches
//! it and `wearlab solve` reports it, so both go through this one function.

use crate::physics::SolveError;
use crate::physics::plane::energy::{Energy, Undefined, energy};
use crate::physics::plane::profile::{Profile, profile};
use crate::physics::plane::strip_check::verdict;
use crate::physics::plane::validity::Validity;
use crate::physics::plane::{Model, PlaneInputs, PlaneSolution, solve};

/// A solved operating point with everything derived from it.
#[derive(Clone, Debug, PartialEq)]
pub struct OperatingPoint {
    /// The solution at the inputs' load.
    pub solution: PlaneSolution,
    /// q2, q1, wear rate and wear per pass at evenly spaced points of [-a, b].
    pub profile: Profile,
    /// The two sides of the energy identity (2.9), or why they have no number (sharp corners).
    pub energy: Result<Energy, Undefined>,
    /// Whether the model holds at this point.
    pub validity: Validity,
}

/// Solves `model` at the inputs' load and derives the profile at `profile_points` >= 2 points,
/// the energy identity and the validity verdict.
pub fn operating_point(
    inputs: &PlaneInputs,
    model: Model,
    profile_points: usize,
) -> Result<OperatingPoint, SolveError> {
    let solution = solve(inputs, model)?;
    Ok(OperatingPoint {
        profile: profile(&solution, profile_points),
        energy: energy(&solution),
        validity: verdict(&solution),
        solution,
    })
}
