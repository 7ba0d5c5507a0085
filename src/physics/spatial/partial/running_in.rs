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

use std::ops::ControlFlow;

use serde::Serialize;
use thiserror::Error;

use crate::physics::SolveError;
use crate::physics::spatial::harmonic::evolution;
use crate::physics::spatial::partial::Setup;
use crate::physics::spatial::partial::active_set::{ContactProblem, ContactSolution, solve};
use crate::physics::spatial::partial::operator::Operator;
use crate::physics::spatial::partial::state::{Outputs, State, evaluate};

/// Steps per decay time 1/beta_max of the fastest harmonic: dt = 0.02/beta_max (section 5: BDF2
/// with beta dt <= 0.02 gives the time to complete contact to about 5e-4).
pub const STEPS_PER_DECAY_TIME: f64 = 50.0;
/// The running-in is stepped over at most this many decay times 1/beta_min of the slowest
/// harmonic; a contact still partial then has no time to complete contact.
pub const HORIZON_DECAY_TIMES: f64 = 100.0;
/// And over at most this many steps.
pub const MAX_STEPS: usize = 20_000;
/// Most shape values kept for replaying the steps (older snapshots are thinned beyond it).
const SNAPSHOT_VALUES: usize = 1 << 22;

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

/// The time step of the running-in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stepping {
    /// dt [s].
    pub dt: f64,
    /// Most steps.
    pub max_steps: usize,
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
        })
    }
}

/// One step from U_k (and U_{k-1} when k >= 1; BE without it) with the contact set `start`:
/// U_{k+1}, the step's contact solution and the mean gap of the true problem.
fn advance(
    op: &mut Operator,
    setup: &Setup,
    dt: f64,
    previous: Option<&[f64]>,
    current: &[f64],
    start: &[bool],
) -> Result<(Vec<f64>, ContactSolution, f64), SolveError> {
    let inputs = &setup.inputs;
    let pbar = inputs.mean_pressure;
    let (base, c) = match previous {
        None => (current.to_vec(), dt * inputs.wear_rate()),
        Some(before) => (
            current
                .iter()
                .zip(before)
                .map(|(u1, u0)| (4.0 * u1 - u0) / 3.0)
                .collect(),
            2.0 / 3.0 * dt * inputs.wear_rate(),
        ),
    };
    let problem = ContactProblem {
        shape: &base,
        mean_pressure: pbar,
        adhesion: inputs.friction.adhesion,
        diagonal: c,
    };
    let sol = solve(op, &problem, Some(start))?;
    let next = base
        .iter()
        .zip(&sol.pressure)
        .map(|(u, p)| u - c * (p - pbar))
        .collect();
    let mean_gap = sol.offset + c * pbar;
    Ok((next, sol, mean_gap))
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
    end_shape: Vec<f64>,
    snapshots: Vec<Snapshot>,
    stride: usize,
}

/// Steps the wear of `setup` from t = 0 until contact is complete (or the stepping's bound).
/// `progress` gets the fraction done (how far min p_cc has risen from its start towards 0) after
/// every step; `ControlFlow::Break` abandons the work.
pub fn run_in(
    setup: &Setup,
    progress: &mut dyn FnMut(f64) -> ControlFlow<()>,
) -> Result<RunningIn, Stopped> {
    let mut op = setup.operator();
    let first = setup.state(&mut op, setup.initial_shape.clone(), 0.0, None)?;
    let stepping = Stepping::of(setup);
    let mut run = RunningIn {
        setup: setup.clone(),
        stepping,
        samples: vec![Sample {
            time: 0.0,
            outputs: first.outputs,
        }],
        time_to_complete: None,
        complete_from: first.outputs.complete.then_some(0.0),
        end_shape: setup.initial_shape.clone(),
        snapshots: vec![Snapshot {
            step: 0,
            previous: None,
            shape: setup.initial_shape.clone(),
            contact: first.contact(),
        }],
        stride: 1,
    };
    let Some(stepping) = stepping.filter(|_| !first.outputs.complete) else {
        return Ok(run);
    };
    let m0 = first.outputs.min_pressure_complete;
    let pbar = setup.inputs.mean_pressure;
    let (mut previous, mut current, mut contact) = (
        None::<Vec<f64>>,
        setup.initial_shape.clone(),
        first.contact(),
    );
    for step in 1..=stepping.max_steps {
        let (next, sol, mean_gap) = advance(
            &mut op,
            setup,
            stepping.dt,
            previous.as_deref(),
            &current,
            &contact,
        )?;
        let friction = setup.inputs.friction;
        let (outputs, _) = evaluate(&mut op, &next, pbar, &friction, &sol, mean_gap);
        let time = step as f64 * stepping.dt;
        let before = run.samples.last().expect("t = 0 is sampled").outputs;
        run.samples.push(Sample { time, outputs });
        contact = sol.contact();
        (previous, current) = (Some(current), next);
        if outputs.complete {
            let (m1, m2) = (before.min_pressure_complete, outputs.min_pressure_complete);
            run.time_to_complete = Some(time - stepping.dt * m2 / (m2 - m1));
            run.complete_from = Some(time);
            break;
        }
        run.keep(step, &previous, &current, &contact);
        let done = (1.0 - outputs.min_pressure_complete / m0).clamp(0.0, 1.0);
        if progress(done).is_break() {
            return Err(Stopped::Cancelled);
        }
    }
    run.end_shape = current;
    Ok(run)
}

impl RunningIn {
    /// Keeps a snapshot of every `stride`-th step, thinning to every other one beyond the budget.
    fn keep(&mut self, step: usize, previous: &Option<Vec<f64>>, shape: &[f64], contact: &[bool]) {
        if step % self.stride != 0 {
            return;
        }
        self.snapshots.push(Snapshot {
            step,
            previous: previous.clone(),
            shape: shape.to_vec(),
            contact: contact.to_vec(),
        });
        if self.snapshots.len() * 2 * shape.len() > SNAPSHOT_VALUES && self.snapshots.len() > 2 {
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
    /// partial.
    pub fn state_at(&self, t: f64) -> Result<State, SolveError> {
        let setup = &self.setup;
        let mut op = setup.operator();
        let k_w = setup.inputs.wear_rate();
        if let Some(from) = self.complete_from.filter(|from| t >= *from) {
            let mut shape = vec![0.0; self.end_shape.len()];
            op.decay(&self.end_shape, &mut shape, k_w * (t - from));
            return setup.state(&mut op, shape, t, None);
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
        let (mut previous, mut current) = (snap.previous.clone(), snap.shape.clone());
        let mut contact = snap.contact.clone();
        for _ in snap.step..k {
            let (next, sol, _) = advance(
                &mut op,
                setup,
                stepping.dt,
                previous.as_deref(),
                &current,
                &contact,
            )?;
            contact = sol.contact();
            (previous, current) = (Some(current), next);
        }
        let fraction = t / stepping.dt - k as f64;
        if fraction > 0.0 {
            let (next, _, _) = advance(
                &mut op,
                setup,
                stepping.dt,
                previous.as_deref(),
                &current,
                &contact,
            )?;
            current
                .iter_mut()
                .zip(&next)
                .for_each(|(u, v)| *u += fraction * (v - *u));
        }
        setup.state(&mut op, current, t, Some(&contact))
    }
}
