//! The spatial problem's pipeline stage "state at time t": from the harmonics' evolutions (the
//! costly, time-independent stage, `evolutions`) to everything shown or reported at one instant:
//! the solution, the period cell, the complete-contact check, the fields on a grid and the
//! mu*(pbar) sweep. The explorer's engine and `wearlab solve` both go through `state_at`.
//!
//! This is the seam where a partial-contact state will plug in: a state whose contact check fails
//! is still a state (the check says why), and everything downstream reads it from here.

use crate::physics::spatial::checks;
use crate::physics::spatial::contact::{self, Contact};
use crate::physics::spatial::field::{Field, field};
use crate::physics::spatial::harmonic::Evolution;
use crate::physics::spatial::history::{MeanPressureSweep, pressure_sweep};
use crate::physics::spatial::{Cell, SpatialInputs, SpatialSolution, solve_with};
use crate::physics::{SolveError, SweepRange, limits};

/// Everything about the spatial problem at one instant.
#[derive(Clone, Debug, PartialEq)]
pub struct SpatialState {
    /// The solution at time t.
    pub solution: SpatialSolution,
    /// The period cell (the extent of the field and of the contact search).
    pub cell: Cell,
    /// The complete-contact check p > 0.
    pub contact: Contact,
    /// p, U and W on the grid over the cell.
    pub field: Field,
    /// mu* against the mean pressure at time t.
    pub sweep: MeanPressureSweep,
}

/// What a state is evaluated on besides the inputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StateAt {
    /// t [s], in `limits::TIME`.
    pub time: f64,
    /// Points per side of the field grid.
    pub grid: usize,
    /// The time tolerance of the running-in in partial contact (`limits::TIME_TOLERANCE`).
    pub time_tolerance: f64,
    /// The mean pressures of the mu*(pbar) sweep [Pa].
    pub sweep: SweepRange,
}

/// The state at `at.time` from validated inputs of harmonics and their evolutions
/// (`spatial::evolutions`); the solution has passed the physical checks (`spatial::checks`).
pub fn state_at(
    inputs: &SpatialInputs,
    evolutions: &[Evolution],
    at: &StateAt,
) -> Result<SpatialState, SolveError> {
    limits::TIME
        .check("time", at.time)
        .map_err(SolveError::InvalidInput)?;
    if inputs.surface().is_some() {
        return Err(SolveError::NoSolution(
            "a height map has no closed form of harmonics: it is solved on its own grid \
             (pipeline::solve)"
                .into(),
        ));
    }
    let solution = solve_with(inputs, evolutions, at.time);
    checks::check(&solution)?;
    let cell = Cell::of(inputs.harmonics());
    let contact = contact::check(&solution, &cell);
    let sweep = pressure_sweep(
        inputs,
        evolutions,
        at.time,
        contact.min_pressure - inputs.mean_pressure,
        &at.sweep,
    );
    Ok(SpatialState {
        field: field(&solution, &cell, at.grid),
        solution,
        cell,
        contact,
        sweep,
    })
}
