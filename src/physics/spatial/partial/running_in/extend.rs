//! A running-in stepped in parts: started at t = 0, then extended as far as it is asked for, so
//! that a caller can stop it between two wear steps (a newer request) and go on later with the
//! same steps as in one call.

use std::ops::ControlFlow;

use crate::physics::SolveError;
use crate::physics::spatial::partial::Setup;
use crate::physics::spatial::partial::running_in::{
    MAX_TRIES, RunningIn, Sample, Snapshot, Stepper, Stepping, Trial, nonlinear, stepper,
};
use crate::physics::spatial::partial::state::{State, evaluate};
use crate::physics::stop::Stop;

/// The step factor of the controller: the next step is `SAFETY` (allowed/estimated)^(1/2) times
/// the last (BDF2's local error grows like h^3, the allowed error like h), within
/// [`SHRINK`, `GROW`], and not above 1 right after a refused try; `GROW` keeps the step ratio of
/// variable-step BDF2 below its zero-stability bound 1 + sqrt 2 (Hairer, Norsett, Wanner,
/// Solving ODEs I, section III.5).
const SAFETY: f64 = 0.9;
const SHRINK: f64 = 0.2;
const GROW: f64 = 2.0;

impl RunningIn {
    /// The running-in of `setup` at t = 0: the first contact state solved, nothing stepped yet
    /// (`stepping` None: no stepping, the state of t = 0 holds). [`RunningIn::extend`] steps it.
    /// The first solve's active set asks `stop` (its error is then `stop::STOPPED`).
    pub fn start(
        setup: &Setup,
        stepping: Option<Stepping>,
        stop: Stop,
    ) -> Result<RunningIn, SolveError> {
        let first = setup.state(
            &mut setup.operator(),
            setup.initial_shape.clone(),
            0.0,
            None,
            stop,
        )?;
        Ok(RunningIn {
            setup: setup.clone(),
            stepping,
            samples: vec![Sample {
                time: 0.0,
                outputs: first.outputs,
                time_error: 0.0,
                mean_wear: 0.0,
            }],
            time_to_complete: None,
            // the closed form holds from a complete start under the linear law only
            complete_from: (first.outputs.complete && setup.inputs.linear_wear()).then_some(0.0),
            rejected: 0,
            end_shape: setup.initial_shape.clone(),
            end_previous: None,
            end_contact: first.contact(),
            end_slope: stepper::slope(setup, &first.pressure),
            next_step: stepping.map_or(0.0, |s| s.first),
            snapshots: vec![Snapshot {
                step: 0,
                previous: None,
                shape: setup.initial_shape.clone(),
                contact: first.contact(),
            }],
            stride: 1,
        })
    }

    /// True when nothing more is stepped: contact is complete, there is no wear, or the horizon
    /// or the step bound of [`Stepping`] is reached.
    pub fn finished(&self) -> bool {
        self.complete_from.is_some()
            || self
                .stepping
                .is_none_or(|s| self.samples.len() > s.max_steps || self.end_time() >= s.horizon)
    }

    /// Steps the wear on until the last stepped state is at time `until` [s] or later, or the
    /// running-in is [finished](RunningIn::finished). `progress` gets the running-in after every
    /// step that leaves the contact partial (every step of a nonlinear wear law);
    /// `ControlFlow::Break` stops after that step, and a later call goes on from there (the steps
    /// are the same as in one call).
    pub fn extend(
        &mut self,
        until: f64,
        progress: &mut dyn FnMut(&RunningIn) -> ControlFlow<()>,
    ) -> Result<(), SolveError> {
        self.extend_until(until, Stop::Never, progress)
    }

    /// As [`RunningIn::extend`], and `stop` is asked before every step and every active-set
    /// iteration of a step: once it says so, the stepping ends (a step it cut short is not taken,
    /// and its error, `stop::STOPPED`, is returned).
    pub fn extend_until(
        &mut self,
        until: f64,
        stop: Stop,
        progress: &mut dyn FnMut(&RunningIn) -> ControlFlow<()>,
    ) -> Result<(), SolveError> {
        let Some(stepping) = self.stepping.filter(|_| !self.finished()) else {
            return Ok(());
        };
        let setup = self.setup.clone();
        let (pbar, friction) = (setup.inputs.mean_pressure, setup.inputs.friction);
        let mut stepper = Stepper::new(
            &setup,
            self.samples.len() - 1,
            self.end_time(),
            self.end_previous.take(),
            std::mem::take(&mut self.end_shape),
            std::mem::take(&mut self.end_contact),
        );
        stepper.slope = Some(std::mem::take(&mut self.end_slope));
        stepper.stop = stop;
        let scale = rms(&setup.initial_shape);
        let linear = setup.inputs.linear_wear();
        let mut result = Ok(());
        while !self.finished() && self.end_time() < until && !stop.now() {
            let (trial, error) = match self.try_step(&mut stepper, &stepping, scale) {
                Ok(step) => step,
                Err(why) => {
                    result = Err(why);
                    break;
                }
            };
            let (outputs, _) = evaluate(
                &mut stepper.op,
                &trial.shape,
                pbar,
                &friction,
                &trial.solution,
                trial.mean_gap,
            );
            let time = trial.time;
            let mean_wear =
                nonlinear::mean_wear(&setup, &self.samples, time, &trial.solution.pressure);
            stepper.accept(trial);
            let time_error = self.samples.last().expect("t = 0 is sampled").time_error + error;
            let was_partial = self.time_to_complete.is_none() && !self.samples[0].outputs.complete;
            self.samples.push(Sample {
                time,
                outputs,
                time_error,
                mean_wear,
            });
            if outputs.complete && was_partial {
                self.time_to_complete = Some(self.zero_of_min_pressure());
            }
            if outputs.complete && linear {
                // the closed form of every mode holds from here on
                self.complete_from = Some(time);
                break;
            }
            self.keep(&stepper, stepping.memory);
            // the callback sees the running-in as it stands
            self.end_shape.clone_from(&stepper.current);
            self.end_previous.clone_from(&stepper.previous);
            self.end_contact.clone_from(&stepper.contact);
            if progress(self).is_break() {
                break;
            }
        }
        self.end_shape = stepper.current;
        self.end_previous = stepper.previous;
        self.end_contact = stepper.contact;
        self.end_slope = stepper.slope.unwrap_or_default();
        result
    }

    /// One step within the tolerance: tried with the proposed step, shrunk while its estimate is
    /// above `tolerance` beta_min h (at most `MAX_TRIES` tries); the step after it proposed.
    /// Returns the step and its error estimate relative to `scale` [m]. A try whose contact
    /// solve fails (or is stopped) leaves the proposed step and the count of refused tries as
    /// they were before the step, so that a later call tries the same steps again.
    fn try_step(
        &mut self,
        stepper: &mut Stepper,
        stepping: &Stepping,
        scale: f64,
    ) -> Result<(Trial, f64), SolveError> {
        let now = stepper.time;
        let before = (self.next_step, self.rejected);
        let mut refused = false;
        for _ in 0..MAX_TRIES {
            let time = (now + self.next_step).min(stepping.horizon);
            if time <= now {
                break;
            }
            let trial = match nonlinear::resolved(&self.setup, time, scale)
                .and_then(|()| stepper.trial(time))
            {
                Ok(trial) => trial,
                Err(why) => {
                    (self.next_step, self.rejected) = before;
                    return Err(why);
                }
            };
            let h = time - now;
            let error = stepper.local_error(&trial).map_or(0.0, |e| rms(&e) / scale);
            let error = if error.is_finite() {
                error
            } else {
                f64::INFINITY
            };
            let allowed = stepping.tolerance * stepping.rate * h;
            let factor = if error > 0.0 {
                (SAFETY * (allowed / error).sqrt()).clamp(SHRINK, GROW)
            } else {
                GROW
            };
            self.next_step = h * if refused { factor.min(1.0) } else { factor };
            if error <= allowed {
                return Ok((trial, error));
            }
            self.rejected += 1;
            refused = true;
        }
        Err(SolveError::NoSolution(format!(
            "the running-in's time step at t = {now:.6e} s was refused by its error estimate down \
             to {:.3e} s: the time tolerance {:.1e} cannot be met there",
            self.next_step, stepping.tolerance
        )))
    }

    /// The zero of m(t) = min over the nodes of p_cc in the last step, on the quadratic through
    /// the last three samples (the line through the last two after the first step).
    fn zero_of_min_pressure(&self) -> f64 {
        let n = self.samples.len();
        let point = |s: &Sample| (s.time, s.outputs.min_pressure_complete);
        let (t1, m1) = point(&self.samples[n - 2]);
        let (t2, m2) = point(&self.samples[n - 1]);
        let curve = |t: f64| match n {
            0..=2 => m1 + (m2 - m1) * (t - t1) / (t2 - t1),
            _ => {
                let (t0, m0) = point(&self.samples[n - 3]);
                m0 * (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2))
                    + m1 * (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2))
                    + m2 * (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1))
            }
        };
        // m(t1) < 0 <= m(t2): bisection down to adjacent floating-point numbers
        let (mut low, mut high) = (t1, t2);
        for _ in 0..200 {
            let mid = 0.5 * (low + high);
            if mid <= low || mid >= high {
                break;
            }
            if curve(mid) < 0.0 {
                low = mid;
            } else {
                high = mid;
            }
        }
        0.5 * (low + high)
    }

    /// The last stepped state (one contact solve, started from its contact set): what
    /// [`RunningIn::state_at`] gives at [`RunningIn::end_time`], without the replay.
    pub fn end_state(&self) -> Result<State, SolveError> {
        let setup = &self.setup;
        let shape = self.end_shape.clone();
        let mean_wear = self.samples.last().expect("t = 0 is sampled").mean_wear;
        setup.worn_state(
            &mut setup.operator(),
            shape,
            self.end_time(),
            mean_wear,
            Some(&self.end_contact),
            Stop::Never,
        )
    }
}

/// The root mean square of `values`.
fn rms(values: &[f64]) -> f64 {
    (values.iter().map(|v| v * v).sum::<f64>() / values.len() as f64).sqrt()
}
