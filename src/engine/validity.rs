//! The plane stages after the operating point: the shown model against the exact strip model
//! (`plane::strip_check::strip_check`, a strip solve of a few milliseconds when the contact is at
//! most `CHEAP_STRIP_WIDTH` thicknesses wide), cached by the inputs and model like the point; and
//! the yield check (`plane::yield_onset::judge`, 4-20 ms in a release build), cached by the
//! inputs, the model and the strength.

use crate::engine::Engine;
use crate::physics::plane::strip_check::{StripCheck, strip_check};
use crate::physics::plane::yield_onset::{Strength, YieldCheck, judge};
use crate::physics::plane::{Model, OperatingPoint, PlaneInputs};

impl Engine {
    /// The check of `point` (solved from `inputs` with `model`) against the strip model.
    pub(super) fn strip_check(
        &mut self,
        inputs: PlaneInputs,
        model: Model,
        point: &OperatingPoint,
    ) -> StripCheck {
        self.strip_checks
            .get_or((inputs, model), &mut self.counts.strip_check, || {
                strip_check(&point.solution)
            })
    }

    /// The yield check of `point` (solved from the key's inputs and model) against the key's
    /// strength; None where neither Y nor H is given (nothing is computed then).
    pub(super) fn yield_check(
        &mut self,
        key: (PlaneInputs, Model, Strength),
        point: &OperatingPoint,
    ) -> Option<YieldCheck> {
        let strength = key.2;
        strength.yield_stress()?;
        self.yield_checks
            .get_or(key, &mut self.counts.yield_check, || {
                judge(&point.solution, strength)
            })
    }
}
