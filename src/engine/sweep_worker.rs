//! The explorer's sweeps and regime maps on a background thread of their own: the
//! library's `sweeps::curve` and `sweeps::map`, the newest request first, a map delivered after
//! each of its passes (coarse first, then refined), and the work in progress cancelled as soon as
//! a newer request arrives (an input edited, another axis chosen). Finished results are kept in a
//! small cache keyed by the request, so going back to an earlier sweep costs nothing.

use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use crate::engine::cache::Cache;
use crate::engine::footprint::Footprint;
use crate::engine::latest::{Delivery, LatestJob};
use crate::preset::Preset;
use crate::sweeps::Opening;
use crate::sweeps::curve::{self, Curve};
use crate::sweeps::map::{Map, regime_map};

/// A sweep or a map of a preset.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepRequest {
    /// The inputs (the varied parameters take their values from the job's axes).
    pub preset: Preset,
    /// The curve or the map.
    pub job: Opening,
}

/// What is known of a request.
#[derive(Clone, Debug)]
pub enum SweepResult {
    /// The curve (`Curve::judged` false before its verdicts).
    Curve(Arc<Curve>),
    /// The map after a pass (`Map::stride` is 1 once complete).
    Map(Arc<Map>),
}

/// One delivery of the sweep worker.
#[derive(Clone, Debug)]
pub struct SweepAnswer {
    /// The generation number the request was submitted with.
    pub generation: u64,
    /// The request answered.
    pub request: Arc<SweepRequest>,
    /// The result so far.
    pub explored: SweepResult,
    /// True when nothing more comes for this request.
    pub complete: bool,
}

/// Computes a request: `on_pass` gets what is known before the end (a curve before its
/// verdicts, each coarse pass of a map); None when `cancel` was set before the end.
pub fn explore(
    request: &SweepRequest,
    cancel: &AtomicBool,
    on_pass: &mut dyn FnMut(SweepResult),
) -> Option<SweepResult> {
    match &request.job {
        Opening::Curve(spec) => {
            let solved = curve::solve(&request.preset, spec, cancel.into())?;
            on_pass(SweepResult::Curve(Arc::new(solved.unjudged())));
            solved
                .judged(cancel.into())
                .map(|c| SweepResult::Curve(c.into()))
        }
        Opening::Map(spec) => regime_map(&request.preset, spec, cancel, &mut |m: &Map| {
            if m.stride > 1 {
                on_pass(SweepResult::Map(Arc::new(m.clone())))
            }
        })
        .map(|m| SweepResult::Map(m.into())),
    }
}

impl Footprint for SweepResult {
    fn bytes(&self) -> usize {
        match self {
            SweepResult::Curve(curve) => curve.bytes(),
            SweepResult::Map(map) => map.bytes(),
        }
    }
}

/// Finished results kept.
const KEPT: usize = 4;
/// The bytes they hold at most: a map holds some 64 bytes a point, so four maps of 250 x 250
/// points (4 MB each) fit; a larger result is computed again when asked again rather than kept.
const KEPT_BYTES: usize = 16 << 20;

/// The sweep worker: the newest request on a thread of its own (`LatestJob`); a newer request
/// replaces any pending one and cancels the running one (its solves stop at the next point).
pub struct SweepWorker {
    job: LatestJob<SweepRequest>,
}

impl SweepWorker {
    /// Starts the thread; `deliver` gets every answer and returns false when nobody listens any
    /// more (the thread then ends).
    pub fn spawn(mut deliver: impl FnMut(SweepAnswer) -> bool + Send + 'static) -> SweepWorker {
        let mut kept: Cache<SweepRequest, SweepResult> = Cache::new(KEPT, KEPT_BYTES);
        let job = LatestJob::spawn(move |generation, request: Arc<SweepRequest>, cancel| {
            let answer = |explored, complete| SweepAnswer {
                generation,
                request: Arc::clone(&request),
                explored,
                complete,
            };
            if let Some(done) = kept.get(&request) {
                return deliver(answer(done, true));
            }
            let mut listening = true;
            let result = explore(&request, cancel, &mut |pass| {
                listening &= deliver(answer(pass, false));
            });
            if let Some(done) = result {
                kept.insert((*request).clone(), done.clone());
                listening &= deliver(answer(done, true));
            }
            listening
        });
        SweepWorker { job }
    }

    /// Asks for a sweep or a map; replaces any request not yet started and stops the running one.
    pub fn submit(&self, generation: u64, request: SweepRequest) {
        self.job.submit(generation, request);
    }
}

impl Delivery for SweepAnswer {
    fn generation(&self) -> u64 {
        self.generation
    }

    fn complete(&self) -> bool {
        self.complete
    }
}
