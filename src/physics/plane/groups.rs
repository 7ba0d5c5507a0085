//! The plane problem's dimensionless groups, functions of the inputs or of a solution; the
//! formulas are those of `docs/physics/plane.md`. The sweeps' quantity table and the explorer's
//! dimensionless view both evaluate these.

use crate::physics::plane::{PlaneInputs, PlaneSolution};

/// (a+b)/R: the contact width a + b over the punch radius R. The small-slope theory needs it
/// small; for a half-plane without friction or wear (Hertz) it is sqrt(8 P/(m R)).
pub fn width_over_radius(s: &PlaneSolution) -> f64 {
    s.contact_width() / s.inputs.radius()
}

/// k m: the wear coefficient k [1/Pa] times the plane modulus m = pi E/(2(1 - nu^2)) [Pa], how
/// strongly wear shifts the pressure forwards (gamma m = pi mu chi - k m, eq. 4.3).
pub fn wear_number(i: &PlaneInputs) -> f64 {
    i.wear.coefficient * i.material.plane_modulus()
}

/// mu chi: the friction coefficient times chi = (1 - 2 nu)/(2(1 - nu)), how strongly friction
/// shifts the pressure backwards; theta = 0 where mu chi = k m/pi (eq. 4.3, 4.5).
pub fn friction_number(i: &PlaneInputs) -> f64 {
    i.friction.coefficient * i.material.chi()
}

/// P/(m R): the load per unit length P [N/m] over the plane modulus m [Pa] times the radius R
/// [m]; (a+b)/R grows like its square root.
pub fn load_number(i: &PlaneInputs) -> f64 {
    i.load / (i.material.plane_modulus() * i.radius())
}
