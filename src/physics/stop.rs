//! When a caller no longer wants the answer of long work: asked by the work between two of its
//! steps (a time step of the running-in, an iteration of the active set, a point of a sweep), so
//! that it ends within one step of being told.

use std::fmt;
use std::sync::atomic::{AtomicBool, Ordering};

/// The error of work that stopped because it was told to.
pub const STOPPED: &str = "the computation was cancelled";

/// Whether long work should stop now.
#[derive(Clone, Copy)]
pub enum Stop<'a> {
    /// Never: the work runs to its end (or its own bounds).
    Never,
    /// When the flag is raised (by a newer request, or a time bound).
    Flag(&'a AtomicBool),
    /// When the function says so (it may count the steps: a bound on work).
    Asked(&'a (dyn Fn() -> bool + Sync)),
}

impl Stop<'_> {
    /// True when the work should stop before its next step.
    pub fn now(&self) -> bool {
        match self {
            Stop::Never => false,
            Stop::Flag(flag) => flag.load(Ordering::Relaxed),
            Stop::Asked(asked) => asked(),
        }
    }
}

impl<'a> From<&'a AtomicBool> for Stop<'a> {
    fn from(flag: &'a AtomicBool) -> Stop<'a> {
        Stop::Flag(flag)
    }
}

impl fmt::Debug for Stop<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Stop::Never => "Stop::Never",
            Stop::Flag(_) => "Stop::Flag",
            Stop::Asked(_) => "Stop::Asked",
        })
    }
}
