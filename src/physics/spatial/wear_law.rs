//! The wear law of the spatial problem: the punch recedes at V F(p), F(p) = k p |p/p0|^(n-1)
//! (the law of docs/physics/plane-general.md section 1; n = 1 is the wavy-punch paper's (1.2)),
//! and where its running-in has a closed form (n = 1 only).

use crate::physics::limits;
use crate::physics::plane::laws::WearLaw;
use crate::physics::spatial::SpatialInputs;

impl SpatialInputs {
    /// The wear law F(p) = k p |p/p0|^(n-1) (docs/physics/plane-general.md section 1) with this
    /// k, n and p0: the punch recedes at V F(p).
    pub fn wear_law(&self) -> WearLaw {
        WearLaw {
            coefficient: self.wear,
            exponent: self.wear_exponent,
            reference_pressure: self.reference_pressure,
        }
    }

    /// True for the linear law (n = 1), whose running-in in complete contact has the closed form
    /// of docs/physics/spatial.md section 3; for n != 1 it is simulated on the grid.
    pub fn linear_wear(&self) -> bool {
        self.wear_law().is_linear()
    }

    /// Why the closed form of the harmonics does not hold whatever the contact, in words: a
    /// nonlinear wear law (None for the linear one).
    pub fn simulated(&self) -> Option<String> {
        (!self.linear_wear()).then(|| {
            format!(
                "wear exponent n = {}: the running-in is simulated on the grid; the closed form \
                 holds for n = 1 only",
                limits::show(self.wear_exponent)
            )
        })
    }

    /// F(p)/k = p |p/p0|^(n-1) [Pa]: the pressure at which the linear law wears as fast as the
    /// law at p [Pa] (the punch recedes at k_w times it); exactly p for n = 1.
    pub fn worn_pressure(&self, p: f64) -> f64 {
        self.unit_law().rate(p)
    }

    /// d/dp of [`SpatialInputs::worn_pressure`] = n |p/p0|^(n-1) (dimensionless); 1 for n = 1.
    pub fn worn_pressure_slope(&self, p: f64) -> f64 {
        self.unit_law().rate_slope(p)
    }

    fn unit_law(&self) -> WearLaw {
        WearLaw {
            coefficient: 1.0,
            ..self.wear_law()
        }
    }
}
