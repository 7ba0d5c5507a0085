//! The laws the general plane solver takes (docs/physics/plane-general.md section 1): the punch
//! shape g(x), the wear law F(q2) and the friction law Pi(q2).

/// A smooth punch profile g(x) [m], g(0) = 0, x [m] in the moving frame.
pub trait Punch {
    /// g(x) [m], the punch's height above its tip at x.
    fn height(&self, x: f64) -> f64;
    /// g'(x), the slope (dimensionless).
    fn slope(&self, x: f64) -> f64;
    /// g''(x) [1/m], where it exists; by default a central difference of the slope on the scale
    /// `step` [m].
    fn curvature(&self, x: f64, step: f64) -> f64 {
        (self.slope(x + step) - self.slope(x - step)) / (2.0 * step)
    }
    /// The points [m] where g'' jumps or is singular (the tip of a power punch, the ends of a
    /// flat face, the knots of a table): quadratures are split there.
    fn kinks(&self) -> Vec<f64>;
}

/// Wear law W' = -F(q2), F(q) = k q (q/p0)^(n-1) (Soldatenkov (2007) eq. (1.1) with F depending
/// on the pressure only).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WearLaw {
    /// k [1/Pa], >= 0.
    pub coefficient: f64,
    /// n, in [1, 4]; 1 is the paper's linear law.
    pub exponent: f64,
    /// p0 [Pa], > 0 (no part when n = 1).
    pub reference_pressure: f64,
}

impl WearLaw {
    /// Whether F is linear in q (n = 1): then k enters the edge exponents.
    pub fn is_linear(&self) -> bool {
        self.exponent == 1.0
    }

    /// The linear part k [1/Pa] of F that the edge exponents carry: k for n = 1, else 0.
    pub fn linear_part(&self) -> f64 {
        if self.is_linear() {
            self.coefficient
        } else {
            0.0
        }
    }

    /// F(q), the wear depth per unit sliding distance (dimensionless), extended as an odd
    /// function to q < 0 so that Newton's iterates stay finite.
    pub fn rate(&self, q: f64) -> f64 {
        if self.is_linear() {
            return self.coefficient * q;
        }
        self.coefficient * q * (q.abs() / self.reference_pressure).powf(self.exponent - 1.0)
    }

    /// dF/dq [1/Pa].
    pub fn rate_derivative(&self, q: f64) -> f64 {
        if self.is_linear() {
            return self.coefficient;
        }
        self.coefficient
            * self.exponent
            * (q.abs() / self.reference_pressure).powf(self.exponent - 1.0)
    }
}

/// Friction law q1 = Pi(q2) = min(mu q2 + tau0, tau_max).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrictionLaw {
    /// mu, >= 0.
    pub coefficient: f64,
    /// tau0 [Pa], >= 0.
    pub adhesion: f64,
    /// tau_max [Pa], > tau0; infinite for plain Coulomb with adhesion.
    pub shear_strength: f64,
}

impl FrictionLaw {
    /// Pi(q) [Pa].
    pub fn shear(&self, q: f64) -> f64 {
        (self.coefficient * q + self.adhesion).min(self.shear_strength)
    }

    /// dPi/dq (dimensionless): mu below the cap, 0 on it.
    pub fn shear_derivative(&self, q: f64) -> f64 {
        if self.coefficient * q + self.adhesion < self.shear_strength {
            self.coefficient
        } else {
            0.0
        }
    }

    /// max(0, mu q + tau0 - tau_max) [Pa]: what the cap takes off the Coulomb shear.
    pub fn excess(&self, q: f64) -> f64 {
        (self.coefficient * q + self.adhesion - self.shear_strength).max(0.0)
    }
}
