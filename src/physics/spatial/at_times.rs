//! The spatial problem at several times of one history (a measured trace fitted, `fit::model`):
//! at each time the result `pipeline::solve_until` gives there, the running-in on the period cell
//! stepped once, to the latest time, and read at every time, instead of stepped again from t = 0
//! for each.
//!
//! The results are those of one solve per time: the linear law's running-in is stepped to
//! complete contact whatever the time asked (`run_in_to`), the same steps for every time; a
//! nonlinear law's is stepped to the latest time (and on while the contact is partial), and its
//! steps up to an earlier time are those of a running-in to that time, the steps being sized by
//! their error estimate alone, except near the stepping's horizon (100 decay times), which a time
//! beyond it moves out. The state at each time is read from the steps as `RunningIn::state_at`
//! reads it.
//!
//! `Kept` keeps the linear law's running-ins for problems that differ only in the wear
//! coefficient, on which the running-in depends only through k t (`RunningIn::scaled_to`): a fit
//! of k steps one running-in, not one per value of k it tries.

use std::sync::{Arc, Mutex};

use crate::physics::SolveError;
use crate::physics::limits;
use crate::physics::spatial::partial::Setup;
use crate::physics::spatial::partial::running_in::{RunningIn, Stopped};
use crate::physics::spatial::pipeline::{self, from_the_run, run_in_for};
use crate::physics::spatial::result::SpatialResult;
use crate::physics::spatial::state::{StateAt, state_at};
use crate::physics::spatial::{self, SpatialInputs};
use crate::physics::stop::Stop;

/// The results at each of `times` [s] (`at.time` is not read; no probes, no mean-pressure
/// sweep), each Err where `pipeline::solve_until` at that time has no answer; Err of the whole
/// where none of the times has one for a reason they share (the inputs, the running-in).
pub fn solve_at_times_until(
    inputs: &SpatialInputs,
    at: &StateAt,
    times: &[f64],
    stop: Stop,
) -> Result<Vec<Result<SpatialResult, Stopped>>, Stopped> {
    solve_with(inputs, at, times, stop, &|setup, latest| {
        run_in_for(setup, latest, stop)
    })
}

/// Running-ins of the linear wear law kept for problems that differ from theirs only in the
/// wear coefficient (a fit of k tries many): each such problem's running-in is a kept one with
/// its time scaled (`RunningIn::scaled_to`), the same steps, instead of one stepped from t = 0.
/// A nonlinear law's is stepped for each problem.
#[derive(Debug, Default)]
pub struct Kept {
    /// The running-ins, the latest used last (at most `KEPT`).
    runs: Mutex<Vec<Arc<RunningIn>>>,
}

/// Running-ins kept at most (each holds at most `running_in::SNAPSHOT_VALUES` shape values).
pub const KEPT: usize = 4;

impl Kept {
    /// As [`solve_at_times_until`], the running-in of a linear law scaled from a kept one that
    /// differs only in the wear coefficient, else stepped and kept.
    pub fn solve_at_times_until(
        &self,
        inputs: &SpatialInputs,
        at: &StateAt,
        times: &[f64],
        stop: Stop,
    ) -> Result<Vec<Result<SpatialResult, Stopped>>, Stopped> {
        solve_with(inputs, at, times, stop, &|setup, latest| {
            if !setup.inputs.linear_wear() {
                return run_in_for(setup, latest, stop);
            }
            if let Some(run) = self.scaled(setup, latest.time_tolerance) {
                return Ok(run);
            }
            let run = run_in_for(setup, latest, stop)?;
            self.keep(Arc::new(run.clone()));
            Ok(run)
        })
    }

    /// The running-ins kept.
    pub fn len(&self) -> usize {
        self.runs.lock().map_or(0, |runs| runs.len())
    }

    /// True when none is kept.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The running-in of `setup` with `tolerance` scaled from a kept one of the same problem but
    /// for its wear coefficient (None: none kept).
    fn scaled(&self, setup: &Setup, tolerance: f64) -> Option<RunningIn> {
        let found = {
            let mut runs = self.runs.lock().ok()?;
            let same = |run: &Arc<RunningIn>| {
                let kept = &run.setup;
                let inputs = SpatialInputs {
                    wear: kept.inputs.wear,
                    ..setup.inputs.clone()
                };
                kept.grid == setup.grid
                    && run.stepping.is_some_and(|s| s.tolerance == tolerance)
                    && kept.inputs == inputs
            };
            let i = runs.iter().position(same)?;
            let run = runs.remove(i);
            runs.push(run.clone());
            run
        };
        found.scaled_to(setup)
    }

    /// Keeps `run`, forgetting the least recently used beyond `KEPT`.
    fn keep(&self, run: Arc<RunningIn>) {
        if let Ok(mut runs) = self.runs.lock() {
            if runs.len() == KEPT {
                runs.remove(0);
            }
            runs.push(run);
        }
    }
}

/// As [`solve_at_times_until`], the running-in for the latest time from `run_in`.
fn solve_with(
    inputs: &SpatialInputs,
    at: &StateAt,
    times: &[f64],
    stop: Stop,
    run_in: &dyn Fn(&Setup, &StateAt) -> Result<RunningIn, Stopped>,
) -> Result<Vec<Result<SpatialResult, Stopped>>, Stopped> {
    inputs.validate()?;
    let at_time = |time: f64| StateAt { time, ..*at };
    let refused = |why: String| Stopped::Failed(SolveError::InvalidInput(why));
    if inputs.surface().is_some() {
        // a height map: every value from the nodes of its own grid
        let checked: Vec<Result<f64, Stopped>> = (times.iter())
            .map(|t| limits::TIME.check("time", *t).map(|()| *t).map_err(refused))
            .collect();
        let Some(latest) = latest(&checked) else {
            return Ok(every_one_refused(checked));
        };
        let setup = Setup::new(inputs, at.grid)?;
        let run = run_in(&setup, &at_time(latest))?;
        return Ok((checked.into_iter())
            .map(|t| from_the_run(&run, None, &at_time(t?), &[], None, stop))
            .collect());
    }
    spatial::validate_grid(inputs.harmonics(), at.grid)?;
    let Ok(setup) = Setup::new(inputs, at.grid) else {
        // no period cell: the closed form alone, no running-in to share
        return Ok((times.iter())
            .map(|t| pipeline::solve_until(inputs, &at_time(*t), &[], false, stop))
            .collect());
    };
    let evolutions = spatial::evolutions(inputs);
    // with a period cell the fields come from its nodes: the closed-form field is not reported
    let closed: Vec<Result<(f64, _), Stopped>> = (times.iter())
        .map(|t| {
            let on_the_nodes = StateAt {
                grid: 8,
                ..at_time(*t)
            };
            state_at(inputs, &evolutions, &on_the_nodes)
                .map(|c| (*t, c))
                .map_err(Stopped::Failed)
        })
        .collect();
    let checked: Vec<Result<f64, Stopped>> = closed
        .iter()
        .map(|c| c.as_ref().map(|(t, _)| *t).map_err(Clone::clone))
        .collect();
    let Some(latest) = latest(&checked) else {
        return Ok(every_one_refused(checked));
    };
    let run = run_in(&setup, &at_time(latest))?;
    Ok((closed.into_iter())
        .map(|c| {
            let (t, closed) = c?;
            from_the_run(&run, Some(&closed), &at_time(t), &[], None, stop)
        })
        .collect())
}

/// The refusals of times none of which passed its checks.
fn every_one_refused(checked: Vec<Result<f64, Stopped>>) -> Vec<Result<SpatialResult, Stopped>> {
    checked
        .into_iter()
        .filter_map(Result::err)
        .map(Err)
        .collect()
}

/// The latest of the times that have passed their checks.
fn latest(checked: &[Result<f64, Stopped>]) -> Option<f64> {
    checked.iter().flatten().copied().reduce(f64::max)
}
