//! The explorer's fits on a background thread of their own: the library's `fit::fit_until`, the
//! same fit as `wearlab fit`, on the newest request (`latest`), stopped as soon as a newer request
//! or a cancel arrives (an edit, Esc), so that the screen never waits for it.

use std::sync::atomic::AtomicBool;

use crate::data::DataSet;
use crate::engine::latest::LatestJob;
use crate::fit::{self, Fit, FitError};
use crate::physics::stop::Stop;
use crate::preset::{Key, Preset};

/// A fit of `keys` of `preset` to `data`.
#[derive(Clone, Debug, PartialEq)]
pub struct FitRequest {
    /// The inputs the fit starts from.
    pub preset: Preset,
    /// The measurements.
    pub data: DataSet,
    /// The free parameters, in the order shown.
    pub keys: Vec<Key>,
}

/// What the fit thread is asked: a fit, or to stop the running one.
#[derive(Clone, Debug, PartialEq)]
pub enum FitJob {
    /// Fit.
    Fit(Box<FitRequest>),
    /// Stop the running fit (nothing is delivered for it).
    Cancel,
}

/// A finished fit.
#[derive(Clone, Debug)]
pub struct FitAnswer {
    /// The generation number the request was submitted with.
    pub generation: u64,
    /// The fit, or why there is none.
    pub result: Result<Box<Fit>, FitError>,
}

/// Carries out a request; None when `cancel` was raised before the fit was done.
pub fn run(generation: u64, request: &FitRequest, cancel: &AtomicBool) -> Option<FitAnswer> {
    let stop = Stop::Flag(cancel);
    let result = fit::fit_until(&request.preset, &request.data, &request.keys, stop);
    (!stop.now()).then(|| FitAnswer {
        generation,
        result: result.map(Box::new),
    })
}

/// The fit worker: the newest request on a thread of its own; a newer request or a cancel stops
/// the running fit within one solve of the model.
pub struct FitWorker {
    job: LatestJob<FitJob>,
}

impl FitWorker {
    /// Starts the thread; `deliver` gets every finished fit and returns false when nobody
    /// listens any more (the thread then ends).
    pub fn spawn(mut deliver: impl FnMut(FitAnswer) -> bool + Send + 'static) -> FitWorker {
        let job =
            LatestJob::spawn(
                move |generation, job: std::sync::Arc<FitJob>, cancel| match &*job {
                    FitJob::Fit(request) => {
                        run(generation, request, cancel).is_none_or(&mut deliver)
                    }
                    FitJob::Cancel => true,
                },
            );
        FitWorker { job }
    }

    /// Asks for a fit (stopping the running one) or, with `FitJob::Cancel`, only stops it.
    pub fn submit(&self, generation: u64, job: FitJob) {
        self.job.submit(generation, job);
    }
}
