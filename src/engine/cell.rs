//! The spatial problem on the period cell (docs/physics/spatial-partial.md): the contact state at
//! the preset's time, the running-in by wear that leads to it, and mu* against the mean pressure.
//!
//! A running-in is kept per (inputs, grid) and only ever extended: a change of the time replays
//! it from its snapshots, a change of anything else starts another. It is stepped with progress,
//! first to the preset's time, then on to complete contact, and stops between two wear steps when
//! a newer request waits, to go on from there when it is asked for again.

use std::ops::ControlFlow;
use std::sync::Arc;
use std::time::Instant;

use crate::engine::footprint::Footprint;
use crate::engine::{Engine, HISTORY_POINTS, Proceed};
use crate::physics::spatial::SpatialInputs;
use crate::physics::spatial::partial::Setup;
use crate::physics::spatial::partial::history::History;
use crate::physics::spatial::partial::running_in::{RunningIn, Stepping, Stopped};
use crate::physics::spatial::partial::state::State;
use crate::physics::spatial::partial::sweep::{LoadCurve, load_curve};
use crate::physics::spatial::pipeline;
use crate::physics::stop::{STOPPED, Stop};
use crate::physics::{SolveError, SweepRange};

/// Where the running-in stands.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Progress {
    /// The wear is being stepped: the simulated time reached [s], and the preset's time t [s]
    /// while it is not reached yet (None: past t, on to complete contact).
    Running {
        /// The time of the last stepped state [s].
        reached: f64,
        /// The time being stepped to [s], when it is the preset's t.
        towards: Option<f64>,
    },
    /// Nothing more is stepped: contact is complete, there is no wear, or the step bound of the
    /// running-in is reached (`History::time_to_complete` says which).
    Done {
        /// The time of the last stepped state [s].
        reached: f64,
    },
}

/// The contact solved on the nodes of the period cell.
#[derive(Clone, Debug)]
pub struct CellOutput {
    /// The contact state at the preset's time t; while the running-in has not reached t, the
    /// last stepped state (its `time` says when).
    pub state: Result<Arc<State>, SolveError>,
    /// The running-in over [0, duration] so far: the stepped states, then (once the contact is
    /// complete) the closed form.
    pub history: Result<Arc<History>, SolveError>,
    /// Where the running-in stands.
    pub progress: Progress,
    /// True when the contact is complete at t = 0: nothing is stepped, and the closed form of the
    /// harmonics (`SpatialOutput::state`) holds exactly.
    pub complete_from_start: bool,
    /// mu* against the mean pressure for the shape at t; None until computed or when not asked.
    pub load_curve: Option<Result<Arc<LoadCurve>, SolveError>>,
    /// Why the running-in is simulated whatever the contact, in words (`SpatialInputs::simulated`: a
    /// nonlinear wear law; None for the linear one).
    pub simulated: Option<String>,
}

impl CellOutput {
    /// True when nothing more comes: the running-in is over and the load curve is there if asked.
    pub fn done(&self, curve: bool) -> bool {
        matches!(self.progress, Progress::Done { .. }) && (!curve || self.load_curve.is_some())
    }
}

/// What a running-in depends on: everything but the time, the duration and the sweep.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct CellKey {
    pub(super) inputs: SpatialInputs,
    pub(super) grid: usize,
    pub(super) time_tolerance: f64,
}

/// A running-in and the error that stopped its stepping, if one did.
pub(super) struct Run {
    running_in: RunningIn,
    stuck: Option<SolveError>,
}

impl Footprint for Run {
    fn bytes(&self) -> usize {
        self.running_in.held_bytes()
    }
}

impl Run {
    fn over(&self) -> bool {
        self.stuck.is_some() || self.running_in.finished()
    }

    fn reached(&self, time: f64) -> bool {
        self.over() || self.running_in.end_time() >= time
    }

    fn progress(&self, time: f64) -> Progress {
        let reached = self.running_in.end_time();
        if self.over() {
            return Progress::Done { reached };
        }
        Progress::Running {
            reached,
            towards: (reached < time).then_some(time),
        }
    }

    /// The state at `time`, once the running-in has reached it.
    fn state_at(&self, time: f64) -> Result<State, SolveError> {
        match &self.stuck {
            Some(why) if time > self.running_in.end_time() => Err(why.clone()),
            _ => self.running_in.state_at(time),
        }
    }
}

/// What one spatial request asks of the cell.
pub(super) struct Ask<'a> {
    pub(super) key: &'a CellKey,
    /// t [s].
    pub(super) time: f64,
    /// The duration of the history [s].
    pub(super) duration: f64,
    /// The mean pressures of mu*(pbar) [Pa], when the chart that draws it is visible.
    pub(super) curve: Option<(&'a SweepRange, &'a [f64])>,
    /// Asked inside every contact solve of the running-in and of the load curve (before each
    /// active-set iteration and linear-solve product): a newer request ends the work inside a step.
    pub(super) stop: Stop<'a>,
}

impl Engine {
    /// The cell output from what is cached or quick: the running-in (started on first use: one
    /// contact solve), the state at t once the running-in has reached it (a replay from its
    /// snapshots), else its last stepped state; the history so far; the load curve if cached.
    /// Err: the contact is not solved on the cell (no period cell, a grid too coarse), or
    /// `ask.stop` ended the first contact solve (`stop::STOPPED`; nothing is kept).
    pub(super) fn cell_now(&mut self, ask: &Ask) -> Result<CellOutput, SolveError> {
        let key = ask.key;
        if self.runs.get_mut(key).is_none() {
            let run = Setup::new(&key.inputs, key.grid).and_then(|setup| {
                let stepping = Stepping::of(&setup, key.time_tolerance);
                let running_in = RunningIn::start(&setup, stepping, ask.stop)?;
                Ok(Run {
                    running_in,
                    stuck: None,
                })
            });
            if run.is_err() && ask.stop.now() {
                return Err(SolveError::NoSolution(STOPPED.into()));
            }
            self.counts.running_in += 1;
            self.runs.insert(key.clone(), run);
        }
        let run = match self.runs.get_mut(key) {
            Some(Ok(run)) => run,
            Some(Err(why)) => return Err(why.clone()),
            None => {
                return Err(SolveError::NoSolution(format!(
                    "the running-in on this grid needs more than the {} MiB the explorer keeps \
                     for it: `wearlab solve` answers it",
                    super::RUN_BYTES >> 20
                )));
            }
        };
        let (counts, states) = (&mut self.counts, &mut self.contact_states);
        let state = if run.reached(ask.time) {
            states.get_or((key.clone(), ask.time), &mut counts.contact_state, || {
                run.state_at(ask.time).map(Arc::new)
            })
        } else {
            run.running_in.end_state().map(Arc::new)
        };
        let history = if run.over() {
            let key = (key.clone(), ask.duration);
            self.run_histories
                .get_or(key, &mut counts.cell_history, || {
                    run.running_in
                        .history(ask.duration, HISTORY_POINTS)
                        .map(Arc::new)
                })
        } else {
            run.running_in.history(ask.duration, 0).map(Arc::new)
        };
        let load_curve = ask
            .curve
            .and_then(|(range, _)| self.load_curves.get(&(key.clone(), ask.time, *range)));
        Ok(CellOutput {
            state,
            history,
            progress: run.progress(ask.time),
            complete_from_start: pipeline::complete_from_start(run.running_in.complete_from),
            load_curve,
            simulated: key.inputs.simulated(),
        })
    }

    /// The slow part: steps the running-in to t, then on to complete contact, then computes the
    /// load curve when asked. `deliver(output, complete)` gets progress at most every
    /// `progress_every` and the output after each part; the work stops between two wear steps
    /// (or two points of the load curve) when `cancelled()` or `deliver` says so, and inside a
    /// step when `ask.stop` says so (the step is not taken: a later request tries it again).
    pub(super) fn cell_rest(
        &mut self,
        ask: &Ask,
        cancelled: &dyn Fn() -> bool,
        deliver: &mut dyn FnMut(CellOutput, bool) -> Proceed,
    ) {
        for until in [ask.time, f64::INFINITY] {
            let Some(Ok(run)) = self.runs.get_mut(ask.key) else {
                return;
            };
            if run.reached(until) {
                continue;
            }
            // past t, the state at t (cell_now computed it) stays on screen
            let shown = run
                .reached(ask.time)
                .then(|| self.contact_states.get(&(ask.key.clone(), ask.time)))
                .flatten();
            let (every, before) = (self.progress_every, run.running_in.samples.len());
            let mut last = Instant::now();
            let mut stopped = false;
            let stepped = run.running_in.extend_until(until, ask.stop, &mut |ri| {
                if cancelled() {
                    stopped = true;
                    return ControlFlow::Break(());
                }
                // the step that ends a part is not reported: the part's own delivery follows
                if last.elapsed() < every || ri.end_time() >= until {
                    return ControlFlow::Continue(());
                }
                last = Instant::now();
                let reached = ri.end_time();
                let output = CellOutput {
                    state: shown
                        .clone()
                        .unwrap_or_else(|| ri.end_state().map(Arc::new)),
                    history: ri.history(ask.duration, 0).map(Arc::new),
                    progress: Progress::Running {
                        reached,
                        towards: (reached < ask.time).then_some(ask.time),
                    },
                    complete_from_start: false,
                    load_curve: None,
                    simulated: ask.key.inputs.simulated(),
                };
                stopped = !deliver(output, false);
                if stopped {
                    ControlFlow::Break(())
                } else {
                    ControlFlow::Continue(())
                }
            });
            self.counts.wear_steps += run.running_in.samples.len() - before;
            if let Err(why) = stepped {
                if ask.stop.now() {
                    stopped = true;
                } else {
                    run.stuck = Some(why);
                }
            }
            // the running-in grew in place: the older one goes when both no longer fit
            self.runs.remeasure_front();
            if stopped {
                return;
            }
            let Ok(output) = self.cell_now(ask) else {
                return;
            };
            let done = output.done(ask.curve.is_some());
            if !deliver(output, done) || done {
                return;
            }
        }
        self.load_curve(ask, cancelled, deliver);
    }

    /// mu* against pbar for the shape at t, cached by (inputs, grid, t, range).
    fn load_curve(
        &mut self,
        ask: &Ask,
        cancelled: &dyn Fn() -> bool,
        deliver: &mut dyn FnMut(CellOutput, bool) -> Proceed,
    ) {
        let Some((range, pressures)) = ask.curve else {
            return;
        };
        let Ok(mut output) = self.cell_now(ask) else {
            return;
        };
        if output.load_curve.is_none() {
            let Some(Ok(run)) = self.runs.get_mut(ask.key) else {
                return;
            };
            let curve = match &output.state {
                Ok(state) => {
                    let setup = &run.running_in.setup;
                    load_curve(setup, &state.shape, pressures, ask.stop, &mut |_| {
                        if cancelled() {
                            ControlFlow::Break(())
                        } else {
                            ControlFlow::Continue(())
                        }
                    })
                }
                Err(why) => Err(Stopped::Failed(why.clone())),
            };
            let curve = match curve {
                Ok(curve) => Ok(Arc::new(curve)),
                Err(Stopped::Failed(why)) => Err(why),
                Err(Stopped::Cancelled) => return,
            };
            self.counts.load_curve += 1;
            let key = (ask.key.clone(), ask.time, *range);
            self.load_curves.insert(key, curve.clone());
            output.load_curve = Some(curve);
        }
        deliver(output, true);
    }
}
