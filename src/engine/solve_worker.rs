//! The solve worker: the engine on a background thread of its own, always on the newest request
//! (`LatestJob`), answering in stages.

use std::sync::Arc;
use std::sync::atomic::Ordering;

use crate::engine::latest::{Delivery, LatestJob};
use crate::engine::{Answer, Engine, Request};
use crate::physics::stop::Stop;

/// A background thread running the engine on the newest request (`LatestJob`). A job stops
/// after a delivery, or between two steps of long work, when a newer request is waiting.
pub struct Worker {
    job: LatestJob<Request>,
}

impl Worker {
    /// Starts the worker thread; `deliver` gets every answer and returns false when nobody
    /// listens any more (the thread then ends).
    pub fn spawn(mut deliver: impl FnMut(Answer) -> bool + Send + 'static) -> Worker {
        let mut engine = Engine::new();
        let job = LatestJob::spawn(move |generation, request: Arc<Request>, newer| {
            let newer_waits = || newer.load(Ordering::SeqCst);
            let mut listening = true;
            engine.run_stoppable(&request, Stop::Flag(newer), |output, complete| {
                listening = deliver(Answer {
                    generation,
                    request: Arc::clone(&request),
                    output,
                    complete,
                });
                listening && !newer_waits()
            });
            listening
        });
        Worker { job }
    }

    /// Asks for a solve; replaces any request not yet started.
    pub fn submit(&self, generation: u64, request: Request) {
        self.job.submit(generation, request);
    }
}

impl Delivery for Answer {
    fn generation(&self) -> u64 {
        self.generation
    }

    fn complete(&self) -> bool {
        self.complete
    }
}
