//! The physics: pure functions of validated parameter structs, SI units throughout.

pub mod elastic;
pub mod limits;
pub mod plane;
pub mod quadrature;
pub mod roots;
pub mod spatial;
pub mod stop;

use thiserror::Error;

/// The elastic strip (plane problem) or layer (spatial problem), bonded to a rigid base.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Young's modulus E [Pa], > 0.
    pub youngs_modulus: f64,
    /// Poisson's ratio nu, 0 <= nu < 1/2.
    pub poisson_ratio: f64,
    /// Thickness h [m], > 0; `f64::INFINITY` is the half-plane (half-space).
    pub thickness: f64,
}

impl Material {
    /// m = pi E / (2 (1 - nu^2)) [Pa].
    pub fn plane_modulus(&self) -> f64 {
        elastic::plane_modulus(self.youngs_modulus, self.poisson_ratio)
    }
    /// chi = (1 - 2 nu)/(2 (1 - nu)).
    pub fn chi(&self) -> f64 {
        elastic::chi(self.poisson_ratio)
    }
    /// Shear modulus G = E / (2 (1 + nu)) [Pa].
    pub fn shear_modulus(&self) -> f64 {
        self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
    }
    /// True for the half-plane / half-space (h = inf).
    pub fn is_half_space(&self) -> bool {
        self.thickness.is_infinite()
    }
}

/// Coulomb friction with adhesion: q1 = mu q2 + tau0 (Soldatenkov (2007) eq. (3.10), the wavy-punch paper eq. (1.1)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Friction {
    /// Sliding friction coefficient mu (dimensionless), >= 0.
    pub coefficient: f64,
    /// Adhesive shear stress tau0 [Pa], >= 0.
    pub adhesion: f64,
}

/// Checks what both problems share: the material, the friction law and the wear coefficient.
pub(crate) fn validate_common(
    material: &Material,
    friction: &Friction,
    wear: f64,
) -> Result<(), SolveError> {
    limits::check_all(&[
        (
            &limits::YOUNGS_MODULUS,
            "youngs_modulus",
            material.youngs_modulus,
        ),
        (
            &limits::POISSON_RATIO,
            "poisson_ratio",
            material.poisson_ratio,
        ),
        (&limits::THICKNESS, "thickness", material.thickness),
        (
            &limits::FRICTION,
            "friction coefficient",
            friction.coefficient,
        ),
        (&limits::ADHESION, "adhesion", friction.adhesion),
        (&limits::WEAR, "wear coefficient", wear),
    ])
    .map_err(SolveError::InvalidInput)
}

/// Why a solver could not answer. The text is meant for the user.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum SolveError {
    /// A parameter is outside the range where the model is defined.
    #[error("invalid input: {0}")]
    InvalidInput(String),
    /// The model has no physical solution for these inputs.
    #[error("{0}")]
    NoSolution(String),
}

/// Ok when every named value is finite, else `SolveError::NoSolution` naming the first that is
/// not: the first of the physical checks (`plane::checks`, `spatial::checks`).
pub(crate) fn check_finite(what: &str, fields: &[(&str, f64)]) -> Result<(), SolveError> {
    match fields.iter().find(|(_, v)| !v.is_finite()) {
        Some((name, v)) => Err(SolveError::NoSolution(format!(
            "{what} is not a finite number: {name} = {v} (these inputs are beyond what the \
             solver can represent)"
        ))),
        None => Ok(()),
    }
}

/// How the points of a sweep are spaced.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Spacing {
    /// Evenly in the logarithm (min > 0).
    Log,
    /// Evenly.
    Linear,
}

impl Spacing {
    /// `points` values from `min` to `max`, both included exactly (points >= 2), so that a range
    /// ending on a parameter's limit never steps past it by round-off.
    pub fn points(self, min: f64, max: f64, points: usize) -> Vec<f64> {
        let n = points.max(2);
        (0..n)
            .map(|i| {
                let t = i as f64 / (n - 1) as f64;
                match self {
                    _ if i == 0 => min,
                    _ if i == n - 1 => max,
                    Spacing::Log => (min.ln() + t * (max / min).ln()).exp(),
                    Spacing::Linear => min + t * (max - min),
                }
            })
            .collect()
    }
}

/// The range of a sweep (loads P [N/m] of the plane mu*(P) sweep, mean pressures pbar [Pa] of
/// the spatial mu*(pbar) sweep): `points` values from `min` to `max`, both included.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepRange {
    /// Smallest value (unit of the swept quantity), > 0 for a log sweep.
    pub min: f64,
    /// Largest value, > min.
    pub max: f64,
    /// Number of values, >= 2 (`limits::SWEEP_POINTS`).
    pub points: usize,
    /// Log or linear spacing.
    pub spacing: Spacing,
}

impl SweepRange {
    /// The swept values.
    pub fn values(&self) -> Vec<f64> {
        self.spacing.points(self.min, self.max, self.points)
    }

    /// Ok when both ends are within `limit` (so max/min stays finite), min < max and the number
    /// of points is allowed; the error names the first fault.
    pub fn check(&self, names: [&str; 2], limit: &limits::Limit) -> Result<(), String> {
        limits::check_all(&[
            (limit, names[0], self.min),
            (limit, names[1], self.max),
            (&limits::SWEEP_POINTS, "points", self.points as f64),
        ])?;
        self.check_order(names, limits::show)
    }

    /// The one rule between the two ends: min < max. `names` are what the caller calls the ends
    /// (e.g. `["load_min", "load_max"]`), `show` how it writes a value; the error says which end
    /// must move.
    pub fn check_order(
        &self,
        names: [&str; 2],
        show: impl Fn(f64) -> String,
    ) -> Result<(), String> {
        if self.min < self.max {
            Ok(())
        } else {
            Err(format!(
                "{} = {} must be larger than {} = {}",
                names[1],
                show(self.max),
                names[0],
                show(self.min)
            ))
        }
    }
}
