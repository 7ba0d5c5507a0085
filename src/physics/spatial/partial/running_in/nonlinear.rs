//! The implicit wear step of a nonlinear wear law. The punch recedes at k_w F(p) with
//! F(p) = p |p/p0|^(n-1) (the wear law of docs/physics/plane-general.md section 1 on the running-in
//! of docs/physics/spatial-partial.md section 5), so that a BE or BDF2 step of the zero-mean shape
//!   U_{k+1} = base - c (F(p) - <F(p)>)      (c = h k_w for BE, h (1 + w)/(1 + 2w) k_w for BDF2)
//! is a contact problem whose operator K + c F'(p) depends on p. Newton's method linearises F at
//! the iterate p*: c F(p) ~ c F(p*) + c F'(p*) (p - p*), so that each iterate is one contact solve
//! with the nodal diagonal D = c F'(p*) and the shape base - c (F(p*) - F'(p*) p*). It starts from
//! the uniform pressure pbar and stops when the pressure moves by less than `TOLERANCE` pbar at
//! every node with the contact set unchanged. The rows' constant c <F(p)> only moves the offset:
//! the mean gap of the true problem for U_{k+1} is the solve's offset plus c <F(p)>.

use crate::physics::spatial::SpatialInputs;
use crate::physics::spatial::partial::Setup;
use crate::physics::spatial::partial::active_set::{ContactProblem, ContactSolution, solve};
use crate::physics::spatial::partial::operator::Diagonal;
use crate::physics::spatial::partial::running_in::{
    RunningIn, Sample, Stepper, Stepping, Stopped, cancelled_or, run_in_until,
};
use crate::physics::stop::Stop;
use std::ops::ControlFlow;

use crate::physics::{SolveError, limits};

/// Most Newton iterates of one step; a step that has not converged then, or whose linearised
/// contact problem is not solved, is refused (and tried again shorter by the step control).
pub const MAX_ITERATES: usize = 25;
/// The change of the nodal pressure, relative to pbar, below which the iterates have converged.
pub const TOLERANCE: f64 = 1e-10;

/// The solution of one nonlinear step.
pub(super) struct Step {
    /// The last iterate's contact solution (its pressure is the step's p_{k+1}).
    pub(super) solution: ContactSolution,
    /// U_{k+1} [m].
    pub(super) shape: Vec<f64>,
    /// The mean gap [m] of the true problem for U_{k+1}.
    pub(super) mean_gap: f64,
    /// False when the iterates did not converge within `MAX_ITERATES`.
    pub(super) converged: bool,
}

/// The step of `stepper` from its `base` with the factor `c` [m/Pa] (see the module).
pub(super) fn step(stepper: &mut Stepper, base: &[f64], c: f64) -> Result<Step, SolveError> {
    let inputs = &stepper.setup.inputs;
    let pbar = inputs.mean_pressure;
    let n = base.len();
    let mut pressure = vec![pbar; n];
    let mut contact = stepper.contact.clone();
    let (mut diagonal, mut shape) = (vec![0.0; n], vec![0.0; n]);
    let mut iterates = 0;
    loop {
        iterates += 1;
        for i in 0..n {
            let (f, slope) = (
                inputs.worn_pressure(pressure[i]),
                inputs.worn_pressure_slope(pressure[i]),
            );
            diagonal[i] = c * slope;
            shape[i] = base[i] - c * (f - slope * pressure[i]);
        }
        let problem = ContactProblem {
            shape: &shape,
            mean_pressure: pbar,
            adhesion: inputs.friction.adhesion,
            diagonal: Diagonal::Nodal(&diagonal),
            stop: stepper.stop,
        };
        let solution = match solve(&mut stepper.op, &problem, Some(&contact)) {
            Ok(solution) => solution,
            Err(why) if stepper.stop.now() => return Err(why),
            // a linearised problem the contact solver cannot answer (an iterate far off): the
            // step is refused, and a shorter one tried
            Err(_) => return Ok(refused(pressure, base)),
        };
        let moved = solution
            .pressure
            .iter()
            .zip(&pressure)
            .map(|(new, old)| (new - old).abs())
            .fold(0.0, f64::max);
        let next = solution.contact();
        let converged = moved <= TOLERANCE * pbar && next == contact;
        if converged || iterates == MAX_ITERATES || !moved.is_finite() {
            return Ok(finish(inputs, base, c, solution, converged));
        }
        pressure.clone_from(&solution.pressure);
        contact = next;
    }
}

/// A step not solved, to be refused: the last iterate `pressure` [Pa] and the shape `base` [m].
fn refused(pressure: Vec<f64>, base: &[f64]) -> Step {
    Step {
        solution: ContactSolution {
            pressure,
            offset: 0.0,
            complete: false,
            iterations: 0,
            linear_iterations: 0,
            cycled: false,
            damped: false,
            residual: f64::INFINITY,
        },
        shape: base.to_vec(),
        mean_gap: 0.0,
        converged: false,
    }
}

/// U_{k+1} = base - c (F(p) - <F(p)>) and the mean gap from the last iterate.
fn finish(
    inputs: &SpatialInputs,
    base: &[f64],
    c: f64,
    solution: ContactSolution,
    converged: bool,
) -> Step {
    let worn: Vec<f64> = solution
        .pressure
        .iter()
        .map(|p| inputs.worn_pressure(*p))
        .collect();
    let mean = worn.iter().sum::<f64>() / worn.len() as f64;
    let shape = base
        .iter()
        .zip(&worn)
        .map(|(u, f)| u - c * (f - mean))
        .collect();
    let mean_gap = solution.offset + c * mean;
    Step {
        solution,
        shape,
        mean_gap,
        converged: converged && mean_gap.is_finite(),
    }
}

/// The mean wear depth <W> [m] at `time` [s] after the last of the stepped `samples` (state k),
/// for the pressure `pressure` [Pa] of the step to `time`: the step's BE or BDF2 formula applied
/// to the mean, <W>' = k_w <F(p)> (exactly k_w pbar t for the linear law).
pub(super) fn mean_wear(setup: &Setup, samples: &[Sample], time: f64, pressure: &[f64]) -> f64 {
    let inputs = &setup.inputs;
    let k_w = inputs.wear_rate();
    if inputs.linear_wear() {
        return k_w * inputs.mean_pressure * time;
    }
    let worn = pressure
        .iter()
        .map(|p| inputs.worn_pressure(*p))
        .sum::<f64>()
        / pressure.len() as f64;
    let now = samples.last().expect("t = 0 is sampled");
    let h = time - now.time;
    match samples.len() {
        1 => now.mean_wear + h * k_w * worn,
        k => {
            let before = &samples[k - 2];
            let w = h / (now.time - before.time);
            let d = 1.0 + 2.0 * w;
            ((1.0 + w) * (1.0 + w) * now.mean_wear - w * w * before.mean_wear) / d
                + h * (1.0 + w) / d * k_w * worn
        }
    }
}

/// The refusal of a step to `time` [s] whose Newton iterates did not converge.
pub(super) fn unconverged(time: f64) -> SolveError {
    SolveError::NoSolution(format!(
        "the wear step to t = {time:.6e} s did not converge in {MAX_ITERATES} Newton iterates of \
         the nonlinear wear law"
    ))
}

/// The mean wear depth, relative to the rms of U(0), beyond which a nonlinear law's running-in
/// is refused: each step's contact solve leaves a round-off of about 1e-13 of the depth it wears
/// in U, which would then exceed 1e-5 of the shape.
pub const RESOLVED_WEAR: f64 = 1e8;

/// Refuses a step of a nonlinear wear law to `time` [s] when the mean wear depth by then,
/// k_w F(pbar) t at least, exceeds `RESOLVED_WEAR` times `scale` (the rms of U(0) [m]).
pub(super) fn resolved(setup: &Setup, time: f64, scale: f64) -> Result<(), SolveError> {
    let inputs = &setup.inputs;
    let depth = inputs.wear_rate() * inputs.worn_pressure(inputs.mean_pressure) * time;
    if inputs.linear_wear() || depth <= RESOLVED_WEAR * scale {
        return Ok(());
    }
    Err(SolveError::NoSolution(format!(
        "wear exponent n = {} with reference pressure p0 = {} Pa wears the punch by {depth:.3e} m \
         by t = {time:.3e} s, more than {RESOLVED_WEAR:.0e} times its waviness (rms {scale:.3e} \
         m): the shape is lost in the round-off of the simulated running-in (raise \
         wear.reference_pressure, or ask for an earlier time)",
        limits::show(inputs.wear_exponent),
        limits::show(inputs.reference_pressure),
    )))
}

/// The running-in of `setup` that answers the state at `time` [s]: [`run_in_until`] for the
/// linear law (stepped to complete contact, the closed form after); for a nonlinear law, whose
/// running-in has no closed form, stepped on the grid to `time` at least (the stepping's horizon
/// moved out to it), and on while the contact is partial, to its time to complete contact
/// (within the horizon and `MAX_STEPS`).
pub fn run_in_to(
    setup: &Setup,
    tolerance: f64,
    time: f64,
    stop: Stop,
) -> Result<RunningIn, Stopped> {
    if setup.inputs.linear_wear() {
        return run_in_until(setup, tolerance, stop);
    }
    let stepping = Stepping::of(setup, tolerance).map(|s| Stepping {
        horizon: s.horizon.max(time),
        ..s
    });
    let mut run = RunningIn::start(setup, stepping, stop).map_err(|why| cancelled_or(why, stop))?;
    let mut stepped = run.extend_until(time, stop, &mut |_| ControlFlow::Continue(()));
    // partial at t = 0 and not yet complete
    let partial = |ri: &RunningIn| ri.time_to_complete.is_none() && !ri.samples[0].outputs.complete;
    if stepped.is_ok() && partial(&run) {
        stepped = run.extend_until(f64::INFINITY, stop, &mut |ri| {
            if partial(ri) {
                ControlFlow::Continue(())
            } else {
                ControlFlow::Break(())
            }
        });
    }
    if stop.now() {
        return Err(Stopped::Cancelled);
    }
    stepped?;
    Ok(run)
}
