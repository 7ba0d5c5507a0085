//! Running-in by wear (docs/physics/spatial-partial.md section 5): the zero-mean shape U stepped
//! implicitly while contact is partial, the mean gbar(t) = gbar(0) - k_w pbar t kept apart.
//!
//! One contact solve per step, with the operator K + c dt k_w:
//!   BE (first step, c = 1):  U1 = U0 - dt k_w (p1 - pbar),
//!   BDF2 (c = 2/3):          U2 = (4 U1 - U0)/3 - (2/3) dt k_w (p2 - pbar).
//! (U_new, p_new) then solves the true contact problem for U_new. The time at which contact
//! becomes complete is the zero of m(t) = min over the nodes of p_cc(U(t)), linearly interpolated
//! between steps; from the first complete step on, every Fourier mode of the worn shape follows
//! the closed form U^(t) = U^(t1) exp(-k_w (t - t1)/(A - i mu sx B)).

mod extend;

use std::ops::ControlFlow;

use serde::Serialize;
use thiserror::Error;

use crate::physics::SolveError;
use crate::physics::spatial::harmonic::evolution;
use crate::physics::spatial::partial::Setup;
use crate::physics::spatial::partial::active_set::{ContactProblem, ContactSolution, solve};
use crate::physics::spatial::partial::operator::Operator;
use crate::physics::spatial::partial::state::{Outputs, State};

/// Steps per decay time 1/beta_max of the fastest harmonic: dt = 0.02/beta_max (section 5: BDF2
/// with beta dt <= 0.02 gives the time to complete contact to about 5e-4).
pub const STEPS_PER_DECAY_TIME: f64 = 50.0;
/// The running-in is stepped over at most this many decay times 1/beta_min of the slowest
/// harmonic; a contact still partial then has no time to complete contact.
pub const HORIZON_DECAY_TIMES: f64 = 100.0;
/// And over at most this many steps.
pub const MAX_STEPS: usize = 20_000;
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
            Stopped::Cancelled => SolveError::NoSolution("the computation was cancelled".into()),
        }
    }
}

/// The time step of the running-in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stepping {
    /// dt [s].
    pub dt: f64,
    /// Most steps.
    pub max_steps: usize,
    /// Most shape values kept for replaying the steps in `state_at` (every k-th step is kept,
    /// k doubling whenever the snapshots would exceed it).
    pub memory: usize,
}

impl Stepping {
    /// dt = 1/(50 beta_max) over at most 100/beta_min and `MAX_STEPS` steps, with the
    /// closed-form decay rates beta of the harmonics of nonzero amplitude; None without wear.
    pub fn of(setup: &Setup) -> Option<Stepping> {
        let inputs = &setup.inputs;
        let rates: Vec<f64> = inputs
            .harmonics
            .iter()
            .filter(|h| h.amplitude > 0.0)
            .map(|h| evolution(&inputs.material, &inputs.friction, inputs.wear_rate(), h))
            .map(|ev| ev.decay_rate)
            .collect();
        let fastest = rates.iter().copied().fold(0.0, f64::max);
        let slowest = rates.iter().copied().fold(f64::INFINITY, f64::min);
        if rates.is_empty() || slowest <= 0.0 || !fastest.is_finite() {
            return None;
        }
        let dt = 1.0 / (STEPS_PER_DECAY_TIME * fastest);
        let steps = (HORIZON_DECAY_TIMES / slowest / dt).ceil();
        Some(Stepping {
            dt,
            max_steps: if steps < MAX_STEPS as f64 {
                steps as usize
            } else {
                MAX_STEPS
            },
            memory: SNAPSHOT_VALUES,
        })
    }
}

/// The implicit stepper: U_{k-1}, U_k and the contact set of step k.
pub struct Stepper<'a> {
    /// The problem.
    pub setup: &'a Setup,
    /// The operator (its buffers are reused by every step).
    pub op: Operator,
    /// dt [s].
    pub dt: f64,
    /// k: the steps done.
    pub step: usize,
    /// U_{k-1} [m] (None at k = 0: the next step is BE).
    pub previous: Option<Vec<f64>>,
    /// U_k [m].
    pub current: Vec<f64>,
    /// The contact set of step k (the next step starts from it).
    pub contact: Vec<bool>,
}

impl<'a> Stepper<'a> {
    /// A stepper at step k = `step` with U_{k-1} = `previous`, U_k = `current` and its contact
    /// set.
    pub fn new(
        setup: &'a Setup,
        dt: f64,
        step: usize,
        previous: Option<Vec<f64>>,
        current: Vec<f64>,
        contact: Vec<bool>,
    ) -> Stepper<'a> {
        Stepper {
            op: setup.operator(),
            setup,
            dt,
            step,
            previous,
            current,
            contact,
        }
    }

    /// One step (BE when k = 0, BDF2 after): U_{k+1}, and the step's contact solution with the
    /// mean gap [m] of the true problem for U_{k+1}.
    pub fn advance(&mut self) -> Result<(ContactSolution, f64), SolveError> {
        let inputs = &self.setup.inputs;
        let pbar = inputs.mean_pressure;
        let (base, c) = match &self.previous {
            None => (self.current.clone(), self.dt * inputs.wear_rate()),
            Some(before) => (
                self.current
                    .iter()
                    .zip(before)
                    .map(|(u1, u0)| (4.0 * u1 - u0) / 3.0)
                    .collect(),
                2.0 / 3.0 * self.dt * inputs.wear_rate(),
            ),
        };
        let problem = ContactProblem {
            shape: &base,
            mean_pressure: pbar,
            adhesion: inputs.friction.adhesion,
            diagonal: c,
        };
        let sol = solve(&mut self.op, &problem, Some(&self.contact))?;
        let next = base
            .iter()
            .zip(&sol.pressure)
            .map(|(u, p)| u - c * (p - pbar))
            .collect();
        self.previous = Some(std::mem::replace(&mut self.current, next));
        self.contact = sol.contact();
        self.step += 1;
        let mean_gap = sol.offset + c * pbar;
        Ok((sol, mean_gap))
    }
}

/// What a replay starts from: the step index, U_{k-1} (None at k = 0), U_k and its contact set.
#[derive(Clone, Debug, PartialEq)]
struct Snapshot {
    step: usize,
    previous: Option<Vec<f64>>,
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
}

/// The running-in of one setup: the stepped history, the time to complete contact, and what is
/// needed to give the state at any time.
#[derive(Clone, Debug, PartialEq)]
pub struct RunningIn {
    /// The problem.
    pub setup: Setup,
    /// The time step (None without wear: nothing changes).
    pub stepping: Option<Stepping>,
    /// The stepped states' outputs, from t = 0 (only t = 0 when complete from the start).
    pub samples: Vec<Sample>,
    /// The simulated time [s] at which contact becomes complete; None when it is complete at
    /// t = 0, or still partial at the end of the stepping (see [`Stepping::of`]).
    pub time_to_complete: Option<f64>,
    /// The time [s] from which the closed form holds (the first complete state); None while
    /// partial at the end.
    pub complete_from: Option<f64>,
    /// U_k [m] of the last stepped state.
    end_shape: Vec<f64>,
    /// U_{k-1} [m] and the contact set of the last stepped state (where [`RunningIn::extend`]
    /// goes on from).
    end_previous: Option<Vec<f64>>,
    end_contact: Vec<bool>,
    snapshots: Vec<Snapshot>,
    stride: usize,
}

/// Steps the wear of `setup` from t = 0 until contact is complete (or the bound of
/// [`Stepping::of`]). `progress` gets the fraction done (how far min p_cc has risen from its
/// start towards 0) after every step; `ControlFlow::Break` abandons the work.
pub fn run_in(
    setup: &Setup,
    progress: &mut dyn FnMut(f64) -> ControlFlow<()>,
) -> Result<RunningIn, Stopped> {
    run_in_with(setup, Stepping::of(setup), progress)
}

/// As [`run_in`] with a given time step (None: no stepping, the state of t = 0 holds).
pub fn run_in_with(
    setup: &Setup,
    stepping: Option<Stepping>,
    progress: &mut dyn FnMut(f64) -> ControlFlow<()>,
) -> Result<RunningIn, Stopped> {
    let mut run = RunningIn::start(setup, stepping)?;
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

    /// U [m] at the last stepped state (where the closed form starts when it is complete).
    pub(crate) fn end_shape(&self) -> &[f64] {
        &self.end_shape
    }

    /// The time [s] of the last stepped state.
    pub fn end_time(&self) -> f64 {
        self.samples.last().map_or(0.0, |s| s.time)
    }

    /// The state at time t [s] >= 0: the closed form from the first complete state on; before it,
    /// the contact solution for the shape interpolated linearly between the two steps around t
    /// (replayed from the nearest snapshot). Refused beyond the end of a running-in that stayed
    /// partial, and where the closed form separates the contact again.
    pub fn state_at(&self, t: f64) -> Result<State, SolveError> {
        let setup = &self.setup;
        let mut op = setup.operator();
        let k_w = setup.inputs.wear_rate();
        if let Some(from) = self.complete_from.filter(|from| t >= *from) {
            let mut shape = vec![0.0; self.end_shape.len()];
            op.decay(&self.end_shape, &mut shape, k_w * (t - from));
            let state = setup.state(&mut op, shape, t, None)?;
            if !state.outputs.complete {
                // harmonics drifting at different speeds can bring the valleys into phase again
                return Err(SolveError::NoSolution(format!(
                    "contact, complete from t = {from:.6e} s, separates again by t = {t:.6e} s \
                     (the harmonics drift into phase); the running-in after that is not simulated"
                )));
            }
            return Ok(state);
        }
        let Some(stepping) = self.stepping else {
            return setup.state(&mut op, setup.initial_shape.clone(), t, None);
        };
        let end = self.end_time();
        if t > end {
            return Err(SolveError::NoSolution(format!(
                "contact is still partial at t = {end:.6e} s, where the running-in stops ({} steps \
                 of {:.3e} s); ask for t <= {end:.6e} s",
                self.samples.len() - 1,
                stepping.dt
            )));
        }
        let k = ((t / stepping.dt).floor() as usize).min(self.samples.len() - 1);
        let snap = self
            .snapshots
            .iter()
            .rev()
            .find(|s| s.step <= k)
            .expect("step 0 is kept");
        let mut stepper = Stepper::new(
            setup,
            stepping.dt,
            snap.step,
            snap.previous.clone(),
            snap.shape.clone(),
            snap.contact.clone(),
        );
        while stepper.step < k {
            stepper.advance()?;
        }
        let (mut shape, contact) = (stepper.current.clone(), stepper.contact.clone());
        let fraction = t / stepping.dt - k as f64;
        if fraction > 0.0 {
            stepper.advance()?;
            shape
                .iter_mut()
                .zip(&stepper.current)
                .for_each(|(u, v)| *u += fraction * (v - *u));
        }
        setup.state(&mut op, shape, t, Some(&contact))
    }
}
