//! A running-in stepped in parts: started at t = 0, then extended as far as it is asked for, so
//! that a caller can stop it between two wear steps (a newer request) and go on later with the
//! same steps as in one call.

use std::ops::ControlFlow;

use crate::physics::SolveError;
use crate::physics::spatial::partial::Setup;
use crate::physics::spatial::partial::running_in::{
    RunningIn, Sample, Snapshot, Stepper, Stepping,
};
use crate::physics::spatial::partial::state::{State, evaluate};

impl RunningIn {
    /// The running-in of `setup` at t = 0: the first contact state solved, nothing stepped yet
    /// (`stepping` None: no stepping, the state of t = 0 holds). [`RunningIn::extend`] steps it.
    pub fn start(setup: &Setup, stepping: Option<Stepping>) -> Result<RunningIn, SolveError> {
        let first = setup.state(
            &mut setup.operator(),
            setup.initial_shape.clone(),
            0.0,
            None,
        )?;
        Ok(RunningIn {
            setup: setup.clone(),
            stepping,
            samples: vec![Sample {
                time: 0.0,
                outputs: first.outputs,
            }],
            time_to_complete: None,
            complete_from: first.outputs.complete.then_some(0.0),
            end_shape: setup.initial_shape.clone(),
            end_previous: None,
            end_contact: first.contact(),
            snapshots: vec![Snapshot {
                step: 0,
                previous: None,
                shape: setup.initial_shape.clone(),
                contact: first.contact(),
            }],
            stride: 1,
        })
    }

    /// True when nothing more is stepped: contact is complete, there is no wear, or the step
    /// bound of [`Stepping`] is reached.
    pub fn finished(&self) -> bool {
        self.complete_from.is_some()
            || self
                .stepping
                .is_none_or(|s| self.samples.len() > s.max_steps)
    }

    /// Steps the wear on until the last stepped state is at time `until` [s] or later, or the
    /// running-in is [finished](RunningIn::finished). `progress` gets the running-in after every
    /// step that leaves the contact partial; `ControlFlow::Break` stops after that step, and a
    /// later call goes on from there (the steps are the same as in one call).
    pub fn extend(
        &mut self,
        until: f64,
        progress: &mut dyn FnMut(&RunningIn) -> ControlFlow<()>,
    ) -> Result<(), SolveError> {
        let Some(stepping) = self.stepping.filter(|_| !self.finished()) else {
            return Ok(());
        };
        let setup = self.setup.clone();
        let (pbar, friction) = (setup.inputs.mean_pressure, setup.inputs.friction);
        let mut stepper = Stepper::new(
            &setup,
            stepping.dt,
            self.samples.len() - 1,
            self.end_previous.take(),
            std::mem::take(&mut self.end_shape),
            std::mem::take(&mut self.end_contact),
        );
        let mut result = Ok(());
        while stepper.step < stepping.max_steps && self.end_time() < until {
            let (sol, mean_gap) = match stepper.advance() {
                Ok(step) => step,
                Err(why) => {
                    result = Err(why);
                    break;
                }
            };
            let (outputs, _) = evaluate(
                &mut stepper.op,
                &stepper.current,
                pbar,
                &friction,
                &sol,
                mean_gap,
            );
            let time = stepper.step as f64 * stepping.dt;
            let before = self.samples.last().expect("t = 0 is sampled").outputs;
            self.samples.push(Sample { time, outputs });
            if outputs.complete {
                let (m1, m2) = (before.min_pressure_complete, outputs.min_pressure_complete);
                self.time_to_complete = Some(time - stepping.dt * m2 / (m2 - m1));
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
        result
    }

    /// The last stepped state (one contact solve, started from its contact set): what
    /// [`RunningIn::state_at`] gives at [`RunningIn::end_time`], without the replay.
    pub fn end_state(&self) -> Result<State, SolveError> {
        let setup = &self.setup;
        let shape = self.end_shape.clone();
        setup.state(
            &mut setup.operator(),
            shape,
            self.end_time(),
            Some(&self.end_contact),
        )
    }
}
