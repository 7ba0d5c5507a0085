//! What a cached value holds in memory, approximately: the bytes of its vectors (length times
//! element size) and of whatever it owns behind a pointer, so that the engine's caches can be
//! bounded in bytes. Small fixed parts (a few numbers, a short message) are counted by their
//! inline size only; shared parts (an `Arc` held by several values) are counted in each.

use std::mem::size_of;
use std::sync::Arc;

use crate::physics::SolveError;
use crate::physics::plane::OperatingPoint;
use crate::physics::plane::strip_check::StripCheck;
use crate::physics::plane::sweep::{EnergySweep, Sweep};
use crate::physics::plane::yield_onset::YieldCheck;
use crate::physics::spatial::SpatialState;
use crate::physics::spatial::harmonic::Evolution;
use crate::physics::spatial::history::{Dispersion, History};
use crate::physics::spatial::partial::history::History as RunHistory;
use crate::physics::spatial::partial::state::State;
use crate::physics::spatial::partial::sweep::LoadCurve;
use crate::sweeps::curve::Curve;
use crate::sweeps::map::Map;

/// The bytes a value holds outside its own inline size.
pub trait Footprint {
    /// Heap bytes [B], approximately.
    fn bytes(&self) -> usize;
}

/// The bytes of a slice's elements [B].
fn of<T>(values: &[T]) -> usize {
    std::mem::size_of_val(values)
}

impl<T: Footprint> Footprint for Arc<T> {
    fn bytes(&self) -> usize {
        size_of::<T>() + (**self).bytes()
    }
}

impl<A: Footprint, B: Footprint> Footprint for (A, B) {
    fn bytes(&self) -> usize {
        self.0.bytes() + self.1.bytes()
    }
}

impl<T: Footprint> Footprint for Result<T, SolveError> {
    fn bytes(&self) -> usize {
        match self {
            Ok(value) => value.bytes(),
            Err(SolveError::InvalidInput(why) | SolveError::NoSolution(why)) => why.len(),
        }
    }
}

impl Footprint for Vec<Evolution> {
    fn bytes(&self) -> usize {
        of(self)
    }
}

impl Footprint for OperatingPoint {
    fn bytes(&self) -> usize {
        let p = &self.profile;
        let v = &self.validity;
        let texts = v.warnings.iter().chain(&v.failed_criteria);
        of(&p.x)
            + of(&p.pressure)
            + of(&p.shear)
            + of(&p.wear_rate)
            + of(&p.wear)
            + of(&p.shape)
            + of(&p.surface)
            + texts.map(|t| size_of::<String>() + t.len()).sum::<usize>()
            + of(&v.reasons)
    }
}

impl Footprint for StripCheck {
    fn bytes(&self) -> usize {
        match self {
            StripCheck::Estimated { why, .. } => why.len(),
            _ => 0,
        }
    }
}

/// A yield check holds a few numbers and a static note.
impl Footprint for Option<YieldCheck> {
    fn bytes(&self) -> usize {
        0
    }
}

impl Footprint for Sweep {
    fn bytes(&self) -> usize {
        of(&self.load)
            + of(&self.mu_star)
            + of(&self.a)
            + of(&self.b)
            + of(&self.normal_force)
            + of(&self.valid)
    }
}

impl Footprint for EnergySweep {
    fn bytes(&self) -> usize {
        of(&self.load) + of(&self.friction_share) + of(&self.wear_share)
    }
}

impl Footprint for Dispersion {
    fn bytes(&self) -> usize {
        of(&self.k)
            + of(&self.angles)
            + self
                .drift_velocity
                .iter()
                .map(|v| size_of::<Vec<f64>>() + of(v))
                .sum::<usize>()
    }
}

impl Footprint for History {
    fn bytes(&self) -> usize {
        of(&self.time)
            + of(&self.mu_star)
            + self
                .amplitudes
                .iter()
                .map(|v| size_of::<Vec<f64>>() + of(v))
                .sum::<usize>()
    }
}

impl Footprint for SpatialState {
    fn bytes(&self) -> usize {
        let (f, s) = (&self.field, &self.sweep);
        of(&self.solution.harmonics)
            + of(&f.x)
            + of(&f.y)
            + of(&f.pressure)
            + of(&f.shape)
            + of(&f.wear)
            + of(&s.mean_pressure)
            + of(&s.load)
            + of(&s.mu_star)
    }
}

impl Footprint for State {
    fn bytes(&self) -> usize {
        of(&self.shape) + of(&self.pressure) + of(&self.gap) + of(&self.wear)
    }
}

impl Footprint for RunHistory {
    fn bytes(&self) -> usize {
        of(&self.time)
            + of(&self.contact_fraction)
            + of(&self.max_pressure)
            + of(&self.mu_star)
            + of(&self.psi)
            + of(&self.mean_gap)
            + of(&self.min_pressure_complete)
    }
}

impl Footprint for LoadCurve {
    fn bytes(&self) -> usize {
        of(&self.mean_pressure) + of(&self.load) + of(&self.mu_star) + of(&self.contact_fraction)
    }
}

impl Footprint for Curve {
    fn bytes(&self) -> usize {
        let series = self.series.iter().map(|s| {
            let reasons = s.y.iter().filter_map(|y| y.as_ref().err()).map(String::len);
            of(&s.y) + reasons.sum::<usize>() + of(&s.holds) + of(&s.changes) + of(&s.group)
        });
        of(&self.x) + of(&self.series) + series.sum::<usize>()
    }
}

impl Footprint for Map {
    fn bytes(&self) -> usize {
        let reasons = self
            .samples
            .iter()
            .flatten()
            .filter_map(|s| s.value.as_ref().err());
        of(&self.x)
            + of(&self.y)
            + of(&self.samples)
            + reasons.map(String::len).sum::<usize>()
            + of(&self.lines)
            + self.lines.iter().map(|l| of(&l.segments)).sum::<usize>()
    }
}
