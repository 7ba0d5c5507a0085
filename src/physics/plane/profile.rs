//! Profiles along the contact: pressure, shear, wear rate and wear per pass.

use serde::Serialize;

use crate::physics::plane::PlaneSolution;
use crate::physics::quadrature::{gauss_legendre, tanh_sinh};

/// Values at evenly spaced points of [-a, b], both ends included.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Profile {
    /// x [m] (moving frame, punch tip at 0, b leading).
    pub x: Vec<f64>,
    /// q2(x) [Pa].
    pub pressure: Vec<f64>,
    /// q1(x) = min(mu q2 + tau0, tau_max) [Pa], positive in +x.
    pub shear: Vec<f64>,
    /// F(q2(x)) = k q2 (q2/p0)^(n-1): wear depth per unit sliding distance (dimensionless).
    pub wear_rate: Vec<f64>,
    /// Integral from x to b of F(q2) [m]: the wear a strip point collects in one pass.
    pub wear: Vec<f64>,
    /// The punch's shape g(x) [m] at each x.
    pub shape: Vec<f64>,
    /// The strip surface's normal displacement v(x) [m], positive towards the punch (Soldatenkov
    /// (2007) section 1), placed where it meets the punch at the leading edge b, where the strip
    /// has not worn yet: v(x) - v(b) + g(b). In contact v - W = g - delta (1.11), W the depth worn
    /// (its x-derivative -F(q2), 0 at b: the wear per pass), so this is g(x) + wear(x): the loaded
    /// strip takes the punch's shape, above it by the layer worn away.
    pub surface: Vec<f64>,
}

/// The profile at `points` >= 2 points.
pub fn profile(sol: &PlaneSolution, points: usize) -> Profile {
    let points = points.max(2);
    let (lo, hi) = (-sol.a, sol.b);
    let step = (hi - lo) / (points - 1) as f64;
    let x: Vec<f64> = (0..points)
        .map(|i| {
            if i == points - 1 {
                hi
            } else {
                lo + step * i as f64
            }
        })
        .collect();
    let pressure: Vec<f64> = x.iter().map(|&x| sol.pressure(x)).collect();
    let law = sol.inputs.wear;
    // Wear per pass, accumulated from the leading edge; the end segments carry the edge
    // singularities of q2 and get the tanh–sinh rule.
    let interior = gauss_legendre(8);
    let edge = tanh_sinh(1.0 / 8.0);
    let q2 = |s: f64| sol.pressure(s);
    let mut wear = vec![0.0; points];
    for i in (0..points - 1).rev() {
        let rule = if i == 0 || i == points - 2 {
            &edge
        } else {
            &interior
        };
        wear[i] = wear[i + 1]
            + if law.is_linear() {
                law.coefficient * rule.integrate(x[i], x[i + 1], q2)
            } else {
                rule.integrate(x[i], x[i + 1], |s| law.rate(q2(s)))
            };
    }
    let shape: Vec<f64> = x.iter().map(|&x| sol.inputs.shape.g(x)).collect();
    Profile {
        shear: x.iter().map(|&x| sol.shear(x)).collect(),
        wear_rate: pressure.iter().map(|&q| law.rate(q)).collect(),
        surface: shape.iter().zip(&wear).map(|(g, w)| g + w).collect(),
        shape,
        x,
        pressure,
        wear,
    }
}
