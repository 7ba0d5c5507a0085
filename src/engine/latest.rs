//! A background thread that always works on the newest request (latest wins), the machinery of
//! both of the explorer's workers (the solve worker `Worker`, the sweep worker `SweepWorker`):
//! one job at a time, one pending slot that a newer request overwrites (older pending work is
//! dropped unseen), and a flag, raised by a newer request, that tells the running job to stop at
//! its next step. `Delivery::replaces` is the one rule for which answer the screen keeps.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Condvar, Mutex};
use std::thread;

/// The newest request not yet started (with its generation), and whether a request newer than
/// the running one waits.
struct Shared<R> {
    pending: Mutex<Option<(u64, Arc<R>)>>,
    wake: Condvar,
    newer: AtomicBool,
}

/// The handle of a latest-wins thread that runs requests of type `R`.
pub struct LatestJob<R> {
    shared: Arc<Shared<R>>,
}

impl<R: Send + Sync + 'static> LatestJob<R> {
    /// Starts the thread. `run` carries out one request (its generation, the request, and the
    /// flag a newer request raises: the job stops at its next step once it is set) and returns
    /// false when nobody listens any more (the thread then ends).
    pub fn spawn(
        mut run: impl FnMut(u64, Arc<R>, &AtomicBool) -> bool + Send + 'static,
    ) -> LatestJob<R> {
        let shared = Arc::new(Shared {
            pending: Mutex::new(None),
            wake: Condvar::new(),
            newer: AtomicBool::new(false),
        });
        let ours = Arc::clone(&shared);
        thread::spawn(move || {
            loop {
                let (generation, request) = {
                    let mut pending = ours.pending.lock().expect("never poisoned");
                    while pending.is_none() {
                        pending = ours.wake.wait(pending).expect("never poisoned");
                    }
                    ours.newer.store(false, Ordering::SeqCst);
                    pending.take().expect("checked above")
                };
                if !run(generation, request, &ours.newer) {
                    return;
                }
            }
        });
        LatestJob { shared }
    }

    /// Asks for `request`: it replaces any request not yet started, and the running one is told
    /// to stop.
    pub fn submit(&self, generation: u64, request: R) {
        let mut pending = self.shared.pending.lock().expect("never poisoned");
        *pending = Some((generation, Arc::new(request)));
        self.shared.newer.store(true, Ordering::SeqCst);
        self.shared.wake.notify_one();
    }
}

/// An answer of a latest-wins job: the generation of the request it answers, and whether more
/// comes for that request.
pub trait Delivery {
    /// The generation number its request was submitted with.
    fn generation(&self) -> u64;
    /// True when nothing more comes for its request.
    fn complete(&self) -> bool;

    /// Whether this answer takes the place of `shown` (the one on screen): it answers a newer
    /// request, or the same request further while the one shown is not complete. An answer older
    /// than the one on screen is dropped; a newer one is taken even when a still newer request is
    /// pending (playing time supersedes every request before its answer comes, and must still
    /// move the screen).
    fn replaces(&self, shown: Option<&Self>) -> bool {
        shown.is_none_or(|s| {
            self.generation() > s.generation()
                || (self.generation() == s.generation() && !s.complete())
        })
    }
}
