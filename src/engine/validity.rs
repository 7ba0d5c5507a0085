//! The plane stage after the operating point: the shown model against the exact strip model
//! (`plane::strip_check::strip_check`, a strip solve of a few milliseconds when the contact is at
//! most `CHEAP_STRIP_WIDTH` thicknesses wide), cached by the inputs and model like the point.

use crate::engine::Engine;
use crate::physics::plane::strip_check::{StripCheck, strip_check};
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
}
