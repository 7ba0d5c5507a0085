//! The spatial problem in partial contact and its running-in by wear
//! (docs/physics/spatial-partial.md): the contact solved on the nodes of the period cell with the
//! layer's transfer functions and the friction coupling, under load control (pbar given).
//!
//! The entry points: [`Setup`] (inputs, grid, operators; the state of any shape),
//! [`running_in::run_in`] (the wear of the punch from t = 0 until contact is complete, then the
//! closed form; `state_at(t)` and the history) and [`sweep::load_curve`] (mu* against pbar).

pub mod active_set;
pub mod fixed_point;
mod gmres;
pub mod grid;
pub mod history;
pub mod operator;
pub mod running_in;
pub mod state;
pub mod sweep;
pub mod zone_ends;

use std::sync::Arc;

use crate::physics::SolveError;
use crate::physics::spatial::SpatialInputs;
use crate::physics::spatial::harmonic::{Harmonic, evolution};
use crate::physics::spatial::partial::active_set::{ContactProblem, solve};
use crate::physics::spatial::partial::grid::Grid;
use crate::physics::spatial::partial::operator::{Diagonal, Multipliers, Operator};
use crate::physics::spatial::partial::state::{State, Work, evaluate};
use crate::physics::spatial::surface;
use crate::physics::stop::Stop;

/// A height map's Fourier mode counts in the running-in's step sizes when its amplitude exceeds
/// this fraction of the largest (the rest is the round-off of the transform).
pub const MODE_THRESHOLD: f64 = 1e-9;

/// The time-independent part of a partial-contact problem: the validated inputs, the grid, the
/// operators' multipliers and the shape at t = 0.
#[derive(Clone, Debug, PartialEq)]
pub struct Setup {
    /// The inputs (validated).
    pub inputs: SpatialInputs,
    /// The grid.
    pub grid: Grid,
    /// The Fourier multipliers of the layer on the grid.
    pub multipliers: Arc<Multipliers>,
    /// U(0) [m] at the nodes.
    pub initial_shape: Vec<f64>,
}

impl Setup {
    /// Validates the inputs and builds the grid with `side` nodes along each axis on which the
    /// shape varies (see [`Grid::new`]). The side is not held to the preset's limits here (the
    /// tests go beyond them); callers with user input check `spatial::validate_grid` first.
    pub fn new(inputs: &SpatialInputs, side: usize) -> Result<Setup, SolveError> {
        inputs.validate()?;
        let (grid, initial_shape) = match inputs.surface() {
            Some(surface) => (Grid::of_surface(surface), surface.heights.clone()),
            None => {
                let grid = Grid::new(inputs.harmonics(), side)?;
                (grid, grid.sample(inputs.harmonics()))
            }
        };
        let multipliers = Multipliers::new(&inputs.material, inputs.friction.coefficient, grid);
        Ok(Setup {
            inputs: inputs.clone(),
            grid,
            multipliers: Arc::new(multipliers),
            initial_shape,
        })
    }

    /// The closed-form decay rates beta [1/s] (docs/physics/spatial.md section 3) of the modes
    /// the shape holds at t = 0: its harmonics of nonzero amplitude, or the Fourier modes of a
    /// height map above `MODE_THRESHOLD` of its largest.
    pub fn decay_rates(&self) -> Vec<f64> {
        let inputs = &self.inputs;
        let rate = |h: &Harmonic| {
            evolution(&inputs.material, &inputs.friction, inputs.wear_rate(), h).decay_rate
        };
        match inputs.surface() {
            None => inputs
                .harmonics()
                .iter()
                .filter(|h| h.amplitude > 0.0)
                .map(rate)
                .collect(),
            Some(surface) => surface::mode_wave_vectors(surface, MODE_THRESHOLD)
                .into_iter()
                .map(|(qx, qy)| {
                    rate(&Harmonic {
                        amplitude: 1.0,
                        wavenumber_x: qx.abs(),
                        wavenumber_y: qy.abs(),
                        phase_x: 0.0,
                        phase_y: 0.0,
                    })
                })
                .collect(),
        }
    }

    /// A fresh operator (its own FFT buffers) on the shared multipliers.
    pub fn operator(&self) -> Operator {
        Operator::new(Arc::clone(&self.multipliers))
    }

    /// The contact state at t = 0 (a fresh operator; the first thing to show after an edit).
    pub fn initial_state(&self) -> Result<State, SolveError> {
        self.state(
            &mut self.operator(),
            self.initial_shape.clone(),
            0.0,
            None,
            Stop::Never,
        )
    }

    /// The contact state of the zero-mean shape `shape` [m] at time `time` [s] (which sets the
    /// mean wear k_w pbar t of the linear law), starting the active set from `start` when given;
    /// the active set asks `stop` before every iteration (its error is then `stop::STOPPED`).
    /// Refused when the vertical force P is not positive (slopes far beyond the small-slope
    /// theory).
    pub fn state(
        &self,
        op: &mut Operator,
        shape: Vec<f64>,
        time: f64,
        start: Option<&[bool]>,
        stop: Stop,
    ) -> Result<State, SolveError> {
        let mean_wear = self.inputs.wear_rate() * self.inputs.mean_pressure * time;
        self.worn_state(op, shape, time, mean_wear, start, stop)
    }

    /// As [`Setup::state`] with the mean wear depth <W> [m] given (a nonlinear wear law's, from
    /// its running-in).
    pub fn worn_state(
        &self,
        op: &mut Operator,
        shape: Vec<f64>,
        time: f64,
        mean_wear: f64,
        start: Option<&[bool]>,
        stop: Stop,
    ) -> Result<State, SolveError> {
        let state = self.unchecked_worn(op, shape, time, mean_wear, start, stop)?;
        let p = state.outputs.normal_force;
        if p.is_nan() || p <= 0.0 {
            return Err(SolveError::NoSolution(format!(
                "the vertical force P = pbar - mu psi - tau0 Delta = {p:.6e} Pa is not positive: \
                 the slopes are far beyond the small-slope theory"
            )));
        }
        Ok(state)
    }

    /// As [`Setup::state`], without the check that P > 0.
    pub(crate) fn unchecked_state(
        &self,
        op: &mut Operator,
        shape: Vec<f64>,
        time: f64,
        start: Option<&[bool]>,
        stop: Stop,
    ) -> Result<State, SolveError> {
        let mean_wear = self.inputs.wear_rate() * self.inputs.mean_pressure * time;
        self.unchecked_worn(op, shape, time, mean_wear, start, stop)
    }

    fn unchecked_worn(
        &self,
        op: &mut Operator,
        shape: Vec<f64>,
        time: f64,
        mean_wear: f64,
        start: Option<&[bool]>,
        stop: Stop,
    ) -> Result<State, SolveError> {
        let pbar = self.inputs.mean_pressure;
        let friction = self.inputs.friction;
        let problem = ContactProblem {
            shape: &shape,
            mean_pressure: pbar,
            adhesion: friction.adhesion,
            diagonal: Diagonal::Uniform(0.0),
            stop,
        };
        let sol = solve(op, &problem, start)?;
        let (outputs, gap) = evaluate(op, &shape, pbar, &friction, &sol, sol.offset);
        // W >= 0 exactly (each BE/BDF2 increment of W is >= 0, section 5): the max only removes
        // the round-off of the subtraction (~1e-16 of U)
        let wear = self
            .initial_shape
            .iter()
            .zip(&shape)
            .map(|(u0, u)| (mean_wear + u0 - u).max(0.0))
            .collect();
        Ok(State {
            grid: self.grid,
            time,
            shape,
            wear,
            gap,
            outputs,
            work: Work::of(&sol),
            pressure: sol.pressure,
        })
    }
}
