//! The wear law and the capped friction law of the plane problem (Soldatenkov (2007) eq. (1.1)
//! with F depending on the pressure only, and section 5's friction law q1 = Pi(q2);
//! `docs/physics/plane.md`, "General shapes and laws").

use crate::physics::{Friction, SolveError, limits};

/// base^exponent for base >= 0: by multiplication (`powi`) when the exponent is a whole number,
/// several times faster than `powf`, which the wear law and the power punch take in every step of
/// the narrow model's shot.
pub fn power(base: f64, exponent: f64) -> f64 {
    if exponent.fract() == 0.0 && exponent.abs() <= 64.0 {
        base.powi(exponent as i32)
    } else {
        base.powf(exponent)
    }
}

/// Wear law W'(x) = -F(q2), F(q) = k q (q/p0)^(n-1): wear depth per unit sliding distance
/// (dimensionless) at the pressure q [Pa].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WearLaw {
    /// Wear coefficient k [1/Pa], >= 0.
    pub coefficient: f64,
    /// Exponent n in [1, 4] (dimensionless); 1 is Archard's linear law of the paper.
    pub exponent: f64,
    /// Reference pressure p0 [Pa], > 0; plays no part when n = 1.
    pub reference_pressure: f64,
}

impl WearLaw {
    /// The paper's linear law F = k q (n = 1; p0 is set to 1 Pa and plays no part).
    pub fn linear(coefficient: f64) -> WearLaw {
        WearLaw {
            coefficient,
            exponent: 1.0,
            reference_pressure: 1.0,
        }
    }

    /// True for the linear law (n = 1).
    pub fn is_linear(&self) -> bool {
        self.exponent == 1.0
    }

    /// F(q) = k q |q/p0|^(n-1), the wear rate (dimensionless) at the pressure q [Pa]; odd in q
    /// so that an iterate with q < 0 stays defined. Exactly k q for n = 1.
    pub fn rate(&self, q: f64) -> f64 {
        if self.is_linear() {
            self.coefficient * q
        } else {
            self.coefficient * q * power((q / self.reference_pressure).abs(), self.exponent - 1.0)
        }
    }

    /// dF/dq = n k |q/p0|^(n-1) [1/Pa].
    pub fn rate_slope(&self, q: f64) -> f64 {
        if self.is_linear() {
            self.coefficient
        } else {
            self.exponent
                * self.coefficient
                * power((q / self.reference_pressure).abs(), self.exponent - 1.0)
        }
    }

    /// Checks k, n and (for n != 1) p0 against their ranges.
    pub fn validate(&self) -> Result<(), SolveError> {
        let mut checks = vec![
            (&limits::WEAR, "wear coefficient", self.coefficient),
            (&limits::WEAR_EXPONENT, "wear exponent", self.exponent),
        ];
        if !self.is_linear() {
            checks.push((
                &limits::REFERENCE_PRESSURE,
                "reference_pressure",
                self.reference_pressure,
            ));
        }
        limits::check_all(&checks).map_err(SolveError::InvalidInput)
    }
}

/// Friction law q1 = Pi(q2) = min(mu q2 + tau0, tau_max): Coulomb friction with adhesion capped
/// by a shear strength (the friction law q1 = Pi(q2) of section 5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrictionLaw {
    /// mu and tau0 [Pa].
    pub coulomb: Friction,
    /// tau_max [Pa], > tau0; infinite for plain Coulomb with adhesion.
    pub shear_strength: f64,
}

impl FrictionLaw {
    /// Pi(q) [Pa]: the shear stress at the pressure q [Pa].
    pub fn shear(&self, q: f64) -> f64 {
        (self.coulomb.coefficient * q + self.coulomb.adhesion).min(self.shear_strength)
    }

    /// dPi/dq (dimensionless): mu below the cap, 0 where the cap holds.
    pub fn shear_slope(&self, q: f64) -> f64 {
        if self.coulomb.coefficient * q + self.coulomb.adhesion < self.shear_strength {
            self.coulomb.coefficient
        } else {
            0.0
        }
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

    /// Checks tau_max against its range and against tau0: with tau_max <= tau0 the cap holds at
    /// the contact edges and the shear is tau_max everywhere, which is Coulomb friction with
    /// mu = 0.
    pub fn validate(&self) -> Result<(), SolveError> {
        let (friction, shear_strength) = (&self.coulomb, self.shear_strength);
        limits::check_all(&[(&limits::SHEAR_STRENGTH, "shear_strength", shear_strength)])
            .map_err(SolveError::InvalidInput)?;
        if shear_strength <= friction.adhesion {
            return Err(SolveError::InvalidInput(format!(
                "shear_strength = {} Pa does not exceed the adhesion tau0 = {} Pa: the cap would \
                 hold everywhere (that is mu = 0 with tau0 = shear_strength); give shear_strength \
                 > tau0",
                limits::show(shear_strength),
                limits::show(friction.adhesion)
            )));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_wear_rate_and_its_slope() {
        let law = WearLaw {
            coefficient: 1e-12,
            exponent: 2.0,
            reference_pressure: 1e6,
        };
        // F(2 MPa) = 1e-12 * 2e6 * 2 = 4e-6; dF/dq = 2 * 1e-12 * 2 = 4e-12.
        assert!((law.rate(2e6) - 4e-6).abs() < 1e-20);
        assert!((law.rate_slope(2e6) - 4e-12).abs() < 1e-26);
        assert_eq!(law.rate(-2e6), -law.rate(2e6));
        assert_eq!(WearLaw::linear(3e-12).rate(5e6), 3e-12 * 5e6);
    }

    #[test]
    fn the_cap_limits_the_shear_and_must_exceed_the_adhesion() {
        let f = Friction {
            coefficient: 0.5,
            adhesion: 1e5,
        };
        let law = |shear_strength| FrictionLaw {
            coulomb: f,
            shear_strength,
        };
        assert_eq!(law(f64::INFINITY).shear(2e6), 0.5 * 2e6 + 1e5);
        assert_eq!(law(5e5).shear(2e6), 5e5);
        assert_eq!(law(5e5).shear_slope(2e6), 0.0);
        assert_eq!(law(5e5).shear_slope(1e5), 0.5);
        assert_eq!(law(5e5).excess(2e6), 0.5 * 2e6 + 1e5 - 5e5);
        let err = law(1e5).validate().unwrap_err().to_string();
        assert!(err.contains("does not exceed the adhesion"), "{err}");
        assert!(
            law(0.0)
                .validate()
                .unwrap_err()
                .to_string()
                .contains("out of range")
        );
    }
}
