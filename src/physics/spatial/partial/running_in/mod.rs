//! Running-in by wear (docs/physics/spatial-partial.md section 5): the zero-mean shape U stepped
//! implicitly while contact is partial, the mean gbar(t) = gbar(0) - k_w pbar t kept apart.
//!
//! The steps (BE, then variable-step BDF2: [`stepper`]) are sized by the estimate of their local
//! error: each step's error, relative to the rms of U(0), stays below `tolerance` beta_min h
//! (error per unit step, so that the sum over the running-in, the reported estimate, grows like
//! the tolerance times the decay times 1/beta_min elapsed). The time at which contact becomes
//! complete is the zero of m(t) = min over the nodes of p_cc(U(t)), interpolated by the quadratic
//! through the last three steps; from the first complete step on, every Fourier mode of the worn
//! shape follows the closed form U^(t) = U^(t1) exp(-k_w (t - t1)/(A - i mu sx B)).
//!
//! That closed form holds for the linear wear law only. A nonlinear law (n != 1, the punch
//! receding at k_w F(p)) is stepped on the grid through complete contact too ([`nonlinear`]), to
//! the end of its stepping, its mean wear <W> stepped alongside; its time to complete contact is
//! still the first zero of m(t).

mod extend;
pub mod nonlinear;
mod scaled;
pub mod stepper;

use std::ops::ControlFlow;

use serde::Serialize;
use thiserror::Error;

use crate::physics::SolveError;
use crate::physics::spatial::partial::Setup;
use crate::physics::spatial::partial::state::{Outputs, State};
use crate::physics::stop::{STOPPED, Stop};

pub use nonlinear::run_in_to;
pub use stepper::{Stepper, Trial};

/// The running-in is stepped over at most this many decay times 1/beta_min of the slowest
/// harmonic; a contact still partial then has no time to complete contact.
pub const HORIZON_DECAY_TIMES: f64 = 100.0;
/// And over at most this many steps.
pub const MAX_STEPS: usize = 100_000;
/// Most tries of one step (each rejected try shrinks it).
pub const MAX_TRIES: usize = 30;
/// Shape values kept for replaying the steps (32 MiB; snapshots are thinned beyond it).
pub const SNAPSHOT_VALUES: usize = 1 << 22;

/// Why a long computation stopped without an answer.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum Stopped {
    /// The physics has no answer (see the message).
    #[error(transparent)]
    Failed(#[from] SolveError),
    /// The caller's progress callback asked to stop.
    #[error("cancelled")]
    Cancelled,
}

impl From<Stopped> for SolveError {
    /// For callers that never cancel: a cancel still reads as "no answer".
    fn from(stopped: Stopped) -> SolveError {
        match stopped {
            Stopped::Failed(why) => why,
            Stopped::Cancelled => SolveError::NoSolution(STOPPED.into()),
        }
    }
}

/// How the running-in is stepped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stepping {
    /// The local error allowed per step, relative to the rms of U(0), per decay time 1/beta_min
    /// (the preset's `spatial.time_tolerance`).
    pub tolerance: f64,
    /// beta_min [1/s]: the closed-form decay rate of the slowest harmonic, times F'(pbar) for a
    /// nonlinear wear law (its rate linearised about the mean pressure).
    pub rate: f64,
    /// The first step [s].
    pub first: f64,
    /// The stepping stops at this time [s] while the contact is still partial.
    pub horizon: f64,
    /// Most steps.
    pub max_steps: usize,
    /// Most shape values kept for replaying the steps in `state_at` (every k-th step is kept,
    /// k doubling whenever the snapshots would exceed it).
    pub memory: usize,
}

impl Stepping {
    /// The stepping of `setup` with `tolerance`, from the closed-form decay rates beta of the
    /// shape's modes ([`Setup::decay_rates`]) times F'(pbar) = n (pbar/p0)^(n-1) (1 for the
    /// linear law): a first step of `tolerance`/beta_max, over at most 100/beta_min (of the
    /// smaller of the two rates) and `MAX_STEPS` steps; None without wear.
    pub fn of(setup: &Setup, tolerance: f64) -> Option<Stepping> {
        let rates = setup.decay_rates();
        let factor = setup.inputs.worn_pressure_slope(setup.inputs.mean_pressure);
        let fastest = rates.iter().copied().fold(0.0, f64::max) * factor;
        let slowest = rates.iter().copied().fold(f64::INFINITY, f64::min);
        if rates.is_empty() || slowest <= 0.0 || !fastest.is_finite() || factor <= 0.0 {
            return None;
        }
        Some(Stepping {
            tolerance,
            rate: slowest * factor,
            first: tolerance / fastest,
            horizon: HORIZON_DECAY_TIMES / (slowest * factor.min(1.0)),
            max_steps: MAX_STEPS,
            memory: SNAPSHOT_VALUES,
        })
    }
}

/// What a replay starts from: the step index, t_{k-1} and U_{k-1} (None at k = 0), U_k and its
/// contact set.
#[derive(Clone, Debug, PartialEq)]
struct Snapshot {
    step: usize,
    previous: Option<(f64, Vec<f64>)>,
    shape: Vec<f64>,
    contact: Vec<bool>,
}

/// One point of the history.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Sample {
    /// t [s].
    pub time: f64,
    /// The outputs at t.
    pub outputs: Outputs,
    /// The sum of the steps' local error estimates up to t, relative to the rms of U(0): the
    /// estimated time-stepping error of the state at t (0 at t = 0).
    pub time_error: f64,
    /// The mean wear depth <W> [m] at t (k_w pbar t for the linear law).
    pub mean_wear: f64,
}

/// The running-in of one setup: the stepped history, the time to complete contact, and what is
/// needed to give the state at any time.
#[derive(Clone, Debug, PartialEq)]
pub struct RunningIn {
    /// The problem.
    pub setup: Setup,
    /// The stepping (None without wear: nothing changes).
    pub stepping: Option<Stepping>,
    /// The stepped states' outputs, from t = 0 (only t = 0 when complete from the start).
    pub samples: Vec<Sample>,
    /// The simulated time [s] at which contact becomes complete; None when it is complete at
    /// t = 0, or still partial at the end of the stepping (see [`Stepping::of`]).
    pub time_to_complete: Option<f64>,
    /// The time [s] from which the closed form holds (the first complete state); None while
    /// partial at the end.
    pub complete_from: Option<f64>,
    /// Steps tried and rejected by the error estimate.
    pub rejected: usize,
    /// U_k [m] of the last stepped state.
    end_shape: Vec<f64>,
    /// t_{k-1}, U_{k-1}, the contact set and the slope U'_k of the last stepped state, and the
    /// next step [s] (where [`RunningIn::extend`] goes on from).
    end_previous: Option<(f64, Vec<f64>)>,
    end_contact: Vec<bool>,
    end_slope: Vec<f64>,
    next_step: f64,
    snapshots: Vec<Snapshot>,
    stride: usize,
}

/// Steps the wear of `setup` from t = 0 until contact is complete (or the bound of
/// [`Stepping::of`]) with the time tolerance `tolerance`. `progress` gets the fraction done (how
/// far min p_cc has risen from its start towards 0) after every step; `ControlFlow::Break`
/// abandons the work.
pub fn run_in(
    setup: &Setup,
    tolerance: f64,
    progress: &mut dyn FnMut(f64) -> ControlFlow<()>,
) -> Result<RunningIn, Stopped> {
    run_in_with(setup, Stepping::of(setup, tolerance), progress)
}

/// As [`run_in`] with a given stepping (None: no stepping, the state of t = 0 holds).
pub fn run_in_with(
    setup: &Setup,
    stepping: Option<Stepping>,
    progress: &mut dyn FnMut(f64) -> ControlFlow<()>,
) -> Result<RunningIn, Stopped> {
    let mut run = RunningIn::start(setup, stepping, Stop::Never)?;
    let m0 = run.samples[0].outputs.min_pressure_complete;
    let mut cancelled = false;
    run.extend(f64::INFINITY, &mut |run: &RunningIn| {
        let m = run.samples.last().expect("t = 0 is sampled").outputs;
        let done = (1.0 - m.min_pressure_complete / m0).clamp(0.0, 1.0);
        cancelled = progress(done).is_break();
        if cancelled {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    })?;
    if cancelled {
        return Err(Stopped::Cancelled);
    }
    Ok(run)
}

/// As [`run_in`] without progress, told to stop by `stop`: it is asked before every time step,
/// every active-set iteration and every product of a linear solve, the first contact solve's
/// included, so the work ends within one step of being told (`Stopped::Cancelled`).
pub fn run_in_until(setup: &Setup, tolerance: f64, stop: Stop) -> Result<RunningIn, Stopped> {
    let mut run = RunningIn::start(setup, Stepping::of(setup, tolerance), stop)
        .map_err(|why| cancelled_or(why, stop))?;
    let stepped = run.extend_until(f64::INFINITY, stop, &mut |_| ControlFlow::Continue(()));
    if stop.now() {
        return Err(Stopped::Cancelled);
    }
    stepped?;
    Ok(run)
}

/// `Stopped::Cancelled` when `stop` says so (the error of a solve it cut short), else the
/// solver's own error.
pub fn cancelled_or(why: SolveError, stop: Stop) -> Stopped {
    if stop.now() {
        Stopped::Cancelled
    } else {
        Stopped::Failed(why)
    }
}

impl RunningIn {
    /// Keeps a snapshot of every `stride`-th step, thinning to every other one beyond the budget.
    fn keep(&mut self, s: &Stepper, memory: usize) {
        if s.step % self.stride != 0 {
            return;
        }
        self.snapshots.push(Snapshot {
            step: s.step,
            previous: s.previous.clone(),
            shape: s.current.clone(),
            contact: s.contact.clone(),
        });
        if self.snapshots.len() * 2 * s.current.len() > memory && self.snapshots.len() > 2 {
            self.stride *= 2;
            let stride = self.stride;
            self.snapshots.retain(|s| s.step % stride == 0);
        }
    }

    /// The bytes its vectors hold, approximately: the samples, the snapshots, the last stepped
    /// state, and the setup's shape with the operator's four multipliers per node (for callers
    /// that bound their memory).
    pub fn held_bytes(&self) -> usize {
        let (f, b) = (size_of::<f64>(), size_of::<bool>());
        let snapshots: usize = self
            .snapshots
            .iter()
            .map(|s| {
                size_of::<Snapshot>()
                    + s.shape.len() * f
                    + s.contact.len() * b
                    + s.previous.as_ref().map_or(0, |(_, u)| u.len() * f)
            })
            .sum();
        let end = self.end_shape.len() * f
            + self.end_slope.len() * f
            + self.end_contact.len() * b
            + self.end_previous.as_ref().map_or(0, |(_, u)| u.len() * f);
        let setup = (self.setup.initial_shape.len() + 4 * self.setup.grid.len()) * f;
        self.samples.len() * size_of::<Sample>() + snapshots + end + setup
    }

    /// U [m] at the last stepped state (where the closed form starts when it is complete).
    pub(crate) fn end_shape(&self) -> &[f64] {
        &self.end_shape
    }

    /// The time [s] of the last stepped state.
    pub fn end_time(&self) -> f64 {
        self.samples.last().map_or(0.0, |s| s.time)
    }

    /// True when the stepping stopped at its bound of steps, before complete contact and before
    /// its horizon: the running-in has no answer past [`RunningIn::end_time`].
    pub fn step_bound_reached(&self) -> bool {
        self.complete_from.is_none()
            && self
                .stepping
                .is_some_and(|s| self.samples.len() > s.max_steps && self.end_time() < s.horizon)
    }

    /// The estimated time-stepping error of the state at t [s] >= 0, relative to the rms of
    /// U(0) (that of the first stepped state at or after t; after complete contact, that of the
    /// first complete state, which the closed form carries on). None when nothing is stepped.
    pub fn time_error(&self, t: f64) -> Option<f64> {
        self.stepping?;
        if self.complete_from == Some(0.0) {
            return None;
        }
        let k = self.samples.partition_point(|s| s.time < t);
        Some(self.samples[k.min(self.samples.len() - 1)].time_error)
    }

    /// The state at time t [s] >= 0: the closed form from the first complete state on; before it,
    /// the contact solution for the shape of the step from the stepped state before t to t (the
    /// steps replayed from the nearest snapshot). Refused beyond the end of a running-in that
    /// stayed partial, and where the closed form separates the contact again.
    pub fn state_at(&self, t: f64) -> Result<State, SolveError> {
        self.state_at_until(t, Stop::Never)
    }

    /// As [`RunningIn::state_at`], every contact solve of the replay asking `stop` before each
    /// active-set iteration (its error is then `stop::STOPPED`).
    pub fn state_at_until(&self, t: f64, stop: Stop) -> Result<State, SolveError> {
        let setup = &self.setup;
        let mut op = setup.operator();
        let k_w = setup.inputs.wear_rate();
        if let Some(from) = self.complete_from.filter(|from| t >= *from) {
            let mut shape = vec![0.0; self.end_shape.len()];
            op.decay(&self.end_shape, &mut shape, k_w * (t - from));
            let state = setup.state(&mut op, shape, t, None, stop)?;
            if !state.outputs.complete {
                // harmonics drifting at different speeds can bring the valleys into phase again
                return Err(SolveError::NoSolution(format!(
                    "contact, complete from t = {from:.6e} s, separates again by t = {t:.6e} s \
                     (the harmonics drift into phase); the running-in after that is not simulated"
                )));
            }
            return Ok(state);
        }
        if self.stepping.is_none() {
            return setup.state(&mut op, setup.initial_shape.clone(), t, None, stop);
        }
        let end = self.end_time();
        if t > end && !setup.inputs.linear_wear() {
            return Err(SolveError::NoSolution(format!(
                "the running-in of the wear law n = {} is simulated up to t = {end:.6e} s (after \
                 {} steps); ask for t <= {end:.6e} s",
                setup.inputs.wear_exponent,
                self.samples.len() - 1,
            )));
        }
        if t > end {
            return Err(SolveError::NoSolution(format!(
                "contact is still partial at t = {end:.6e} s, where the running-in stops (after \
                 {} steps); ask for t <= {end:.6e} s",
                self.samples.len() - 1,
            )));
        }
        // the last stepped state at or before t
        let k = self.samples.partition_point(|s| s.time <= t).max(1) - 1;
        let snap = self
            .snapshots
            .iter()
            .rev()
            .find(|s| s.step <= k)
            .expect("step 0 is kept");
        let mut stepper = Stepper::new(
            setup,
            snap.step,
            self.samples[snap.step].time,
            snap.previous.clone(),
            snap.shape.clone(),
            snap.contact.clone(),
        );
        stepper.stop = stop;
        while stepper.step < k {
            stepper.advance(self.samples[stepper.step + 1].time)?;
        }
        let (shape, mean_wear) = if t > self.samples[k].time {
            let trial = stepper.trial(t)?;
            if !trial.converged {
                return Err(nonlinear::unconverged(t));
            }
            let samples = &self.samples[..=k];
            let mean_wear = nonlinear::mean_wear(setup, samples, t, &trial.solution.pressure);
            (trial.shape, mean_wear)
        } else {
            (stepper.current.clone(), self.samples[k].mean_wear)
        };
        setup.worn_state(&mut op, shape, t, mean_wear, Some(&stepper.contact), stop)
    }
}
