//! What the general plane solver takes besides the strip: the punch as a profile g(x) with the
//! points where it is not smooth (`Punch`, implemented by `plane::Shape`), and the capped friction
//! law Pi(q2) = min(mu q2 + tau0, tau_max) with its derivative (docs/physics/plane-general.md
//! section 1). The wear law is `plane::WearLaw`.

use crate::physics::Friction;
use crate::physics::plane::Shape;
use crate::physics::plane::laws::{capped_shear, capped_shear_slope};

/// A smooth punch profile g(x) [m], g(0) = 0, x [m] in the moving frame.
pub trait Punch {
    /// g(x) [m], the punch's height above its tip at x.
    fn height(&self, x: f64) -> f64;
    /// g'(x), the slope (dimensionless).
    fn slope(&self, x: f64) -> f64;
    /// g''(x) [1/m], as Newton's steps need it: a central difference of the slope on the scale
    /// `step` [m], which stays finite at a power punch's tip (n < 2) and steps over the jumps of
    /// g'' (the exact g'' there made Newton's steps overshoot).
    fn curvature(&self, x: f64, step: f64) -> f64 {
        (self.slope(x + step) - self.slope(x - step)) / (2.0 * step)
    }
    /// The points [m] where g'' jumps or is singular (the tip of a power punch, the ends of a
    /// flat face, the knots of a table): quadratures are split there.
    fn kinks(&self) -> Vec<f64>;
}

impl Punch for Shape {
    fn height(&self, x: f64) -> f64 {
        self.g(x)
    }

    fn slope(&self, x: f64) -> f64 {
        Shape::slope(self, x)
    }

    fn kinks(&self) -> Vec<f64> {
        Shape::kinks(self)
    }
}

/// Friction law q1 = Pi(q2) = min(mu q2 + tau0, tau_max).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrictionLaw {
    /// mu and tau0 [Pa].
    pub coulomb: Friction,
    /// tau_max [Pa], > tau0; infinite for plain Coulomb with adhesion.
    pub shear_strength: f64,
}

impl FrictionLaw {
    /// Pi(q) [Pa].
    pub fn shear(&self, q: f64) -> f64 {
        capped_shear(&self.coulomb, self.shear_strength, q)
    }

    /// dPi/dq (dimensionless): mu below the cap, 0 on it.
    pub fn shear_slope(&self, q: f64) -> f64 {
        capped_shear_slope(&self.coulomb, self.shear_strength, q)
    }

    /// max(0, mu q + tau0 - tau_max) [Pa]: what the cap takes off the Coulomb shear.
    pub fn excess(&self, q: f64) -> f64 {
        (self.coulomb.coefficient * q + self.coulomb.adhesion - self.shear_strength).max(0.0)
    }

    /// mu (dimensionless).
    pub fn coefficient(&self) -> f64 {
        self.coulomb.coefficient
    }

    /// tau0 [Pa].
    pub fn adhesion(&self) -> f64 {
        self.coulomb.adhesion
    }
}
