//! The rules between the values of the laws beyond the paper's worked example, shared by the
//! preset file's checks and `--set` (`Preset::check_rules`).

use crate::physics::limits;
use crate::preset::{Preset, Problem};

/// The rules between the laws' values, for the file and for `--set`: a nonlinear wear law needs
/// its reference pressure; the shear strength exceeds the adhesion; the spatial problem takes
/// friction without a cap.
pub(super) fn check(p: &Preset) -> Result<(), String> {
    if p.wear_exponent != 1.0 && p.reference_pressure.is_none() {
        return Err(format!(
            "wear.exponent = {} needs wear.reference_pressure p0 [Pa], the pressure at which the \
             wear rate is k p0 (e.g. reference_pressure = \"1 MPa\")",
            p.wear_exponent
        ));
    }
    if p.shear_strength <= p.friction.adhesion {
        return Err(format!(
            "friction.shear_strength = {} Pa must exceed friction.adhesion = {} Pa (with tau_max \
             <= tau0 the cap holds everywhere)",
            limits::show(p.shear_strength),
            limits::show(p.friction.adhesion)
        ));
    }
    if p.problem == Problem::Spatial && p.shear_strength.is_finite() {
        return Err(
            "the spatial problem takes friction without a shear cap: remove \
                    friction.shear_strength, or solve problem = \"plane\""
                .into(),
        );
    }
    Ok(())
}
