//! The punch shape g(x) [m] of the plane problem, measured from the punch tip (g(0) = 0 for the
//! analytic shapes), positive away from the strip: Soldatenkov (2007) section 1 states the problem
//! for any g; the shapes offered are those of `docs/physics/plane.md` ("General shapes and laws").

use std::sync::Arc;

use crate::physics::plane::laws::power;
use crate::physics::plane::spline::Spline;
use crate::physics::{SolveError, limits};

/// A measured profile: the file it was read from (as given in the preset) and the natural cubic
/// spline through its rows.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// The file as the preset names it (relative to the preset's folder).
    pub file: String,
    /// The spline through exactly the file's points.
    pub spline: Spline,
}

/// The punch's shape.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// g = x^2/(2R), radius R [m] > 0: the paper's worked example.
    Parabola { radius: f64 },
    /// g = (R/n)(|x|/R)^n, radius R [m] > 0, exponent 1 < n <= 10 (n = 2 is the parabola).
    Power { radius: f64, exponent: f64 },
    /// A flat face |x| <= c (half_width c [m] > 0) with rounded edges g = (|x| - c)^2/(2r)
    /// beyond it (edge_radius r [m]); r = 0 is a flat punch with sharp corners, whose contact is
    /// exactly the face [-c, c].
    Flat { half_width: f64, edge_radius: f64 },
    /// A measured profile, interpolated by a natural cubic spline; a contact may not leave it.
    Table(Arc<Table>),
}

impl Shape {
    /// The preset's name of the shape's kind.
    pub fn kind(&self) -> &'static str {
        match self {
            Shape::Parabola { .. } => "parabola",
            Shape::Power { .. } => "power",
            Shape::Flat { .. } => "flat",
            Shape::Table(_) => "table",
        }
    }

    /// Checks the shape's parameters against their ranges (`physics::limits`).
    pub fn validate(&self) -> Result<(), SolveError> {
        match self {
            Shape::Parabola { radius } => {
                limits::check_all(&[(&limits::RADIUS, "radius", *radius)])
            }
            Shape::Power { radius, exponent } => limits::check_all(&[
                (&limits::RADIUS, "radius", *radius),
                (&limits::POWER_EXPONENT, "shape exponent", *exponent),
            ]),
            Shape::Flat {
                half_width,
                edge_radius,
            } => limits::check_all(&[
                (&limits::HALF_WIDTH, "half_width", *half_width),
                (&limits::EDGE_RADIUS, "edge_radius", *edge_radius),
            ]),
            Shape::Table(_) => Ok(()),
        }
        .map_err(SolveError::InvalidInput)
    }

    /// The parabola's radius R [m]; None for the other shapes.
    pub fn parabola_radius(&self) -> Option<f64> {
        match self {
            Shape::Parabola { radius } => Some(*radius),
            _ => None,
        }
    }

    /// The punch's radius R [m] as the closed forms, the dimensionless groups and the validity
    /// criteria use it: the parabola's and the power punch's R, the flat's edge radius (its
    /// half-width when the corners are sharp), half a table's x range.
    pub fn radius(&self) -> f64 {
        match self {
            Shape::Parabola { radius } | Shape::Power { radius, .. } => *radius,
            Shape::Flat {
                half_width,
                edge_radius,
            } => {
                if *edge_radius > 0.0 {
                    *edge_radius
                } else {
                    *half_width
                }
            }
            Shape::Table(t) => {
                let (lo, hi) = t.spline.range();
                (hi - lo) / 2.0
            }
        }
    }

    /// True for the flat punch with sharp corners (edge_radius = 0): its contact is the face.
    pub fn is_sharp(&self) -> bool {
        self.sharp_half_width().is_some()
    }

    /// The face's half-width c [m] of a flat punch with sharp corners; None for every other shape.
    pub fn sharp_half_width(&self) -> Option<f64> {
        match self {
            Shape::Flat {
                half_width,
                edge_radius,
            } if *edge_radius == 0.0 => Some(*half_width),
            _ => None,
        }
    }

    /// The points x [m] where g'' jumps or is infinite (a solution's q2 has kinks there):
    /// the power punch's tip, the flat's face ends; none for the parabola, nor for a table,
    /// whose natural cubic spline keeps g'' continuous at its knots (only the third derivative
    /// steps there, which the quadratures resolve without a split; a split at each of a hundred
    /// knots would make every integral over the contact a hundred rules long).
    pub fn kinks(&self) -> Vec<f64> {
        match self {
            Shape::Parabola { .. } | Shape::Table(_) => Vec::new(),
            Shape::Power { .. } => vec![0.0],
            Shape::Flat { half_width, .. } => vec![-*half_width, *half_width],
        }
    }

    /// The x range [m] the shape is known on: a table's first and last x; None when unbounded.
    pub fn range(&self) -> Option<(f64, f64)> {
        match self {
            Shape::Table(t) => Some(t.spline.range()),
            _ => None,
        }
    }

    /// Ok when the contact [-a, b] [m] lies where the shape is known, else an error that says
    /// the contact runs off the measured profile (never an extrapolation).
    pub fn covers(&self, a: f64, b: f64) -> Result<(), SolveError> {
        match self.range() {
            Some((lo, hi)) if !(-a >= lo && b <= hi) => Err(SolveError::NoSolution(format!(
                "the contact [{}, {}] m runs off the measured profile, which covers [{}, {}] m: \
                 give a profile that covers the contact",
                limits::show(-a),
                limits::show(b),
                limits::show(lo),
                limits::show(hi)
            ))),
            _ => Ok(()),
        }
    }

    /// g(x) [m]. Sharp corners: +inf beyond the face (the punch's side walls). A table beyond
    /// its range continues its end cubic: callers check `covers` first.
    pub fn g(&self, x: f64) -> f64 {
        self.eval(x).0
    }

    /// g'(x), the slope (dimensionless; sign(x) times the rise away from the tip). Sharp corners:
    /// +-inf beyond the face.
    pub fn slope(&self, x: f64) -> f64 {
        match self {
            Shape::Power { radius, exponent } => {
                x.signum() * power(x.abs() / radius, exponent - 1.0)
            }
            _ => self.eval(x).1,
        }
    }

    /// g''(x) [1/m], the curvature. Power punch with n < 2: +inf at the tip; the flat's edges:
    /// the value on the side of x away from the face (1/r at |x| = c).
    pub fn curvature(&self, x: f64) -> f64 {
        self.eval(x).2
    }

    /// (g, g', g'') at x.
    pub fn eval(&self, x: f64) -> (f64, f64, f64) {
        match self {
            Shape::Parabola { radius } => (x * x / (2.0 * radius), x / radius, 1.0 / radius),
            Shape::Power { radius, exponent } => {
                let n = *exponent;
                let u = x.abs() / radius;
                let curvature = if u == 0.0 && n < 2.0 {
                    f64::INFINITY
                } else {
                    (n - 1.0) * power(u, n - 2.0) / radius
                };
                (
                    radius / n * power(u, n),
                    x.signum() * power(u, n - 1.0),
                    curvature,
                )
            }
            Shape::Flat {
                half_width,
                edge_radius,
            } => {
                let beyond = x.abs() - half_width;
                if beyond <= 0.0 {
                    (0.0, 0.0, 0.0)
                } else if *edge_radius == 0.0 {
                    (f64::INFINITY, x.signum() * f64::INFINITY, f64::INFINITY)
                } else {
                    (
                        beyond * beyond / (2.0 * edge_radius),
                        x.signum() * beyond / edge_radius,
                        1.0 / edge_radius,
                    )
                }
            }
            Shape::Table(t) => t.spline.eval(x),
        }
    }
}

/// The shape as the preset gives it (`wearlab solve`'s `shape`): its kind and parameters, SI.
impl serde::Serialize for Shape {
    fn serialize<S: serde::Serializer>(&self, out: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = out.serialize_map(None)?;
        map.serialize_entry("kind", self.kind())?;
        match self {
            Shape::Parabola { radius } => map.serialize_entry("radius", radius)?,
            Shape::Power { radius, exponent } => {
                map.serialize_entry("radius", radius)?;
                map.serialize_entry("exponent", exponent)?;
            }
            Shape::Flat {
                half_width,
                edge_radius,
            } => {
                map.serialize_entry("half_width", half_width)?;
                map.serialize_entry("edge_radius", edge_radius)?;
            }
            Shape::Table(t) => {
                map.serialize_entry("file", &t.file)?;
                map.serialize_entry("range", &t.spline.range())?;
            }
        }
        map.end()
    }
}

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
    /// Whether g' is a polynomial in x (a parabola's), which the collocation takes exactly at
    /// its points.
    fn slope_is_polynomial(&self) -> bool {
        false
    }
    /// The x range [m] the shape is known on (a measured profile's); None when unbounded.
    fn known_range(&self) -> Option<(f64, f64)>;
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

    fn slope_is_polynomial(&self) -> bool {
        matches!(self, Shape::Parabola { .. })
    }

    fn known_range(&self) -> Option<(f64, f64)> {
        self.range()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(r: f64) -> Shape {
        let x: Vec<f64> = (0..401).map(|i| -2e-3 + 1e-5 * i as f64).collect();
        let g = x.iter().map(|v| v * v / (2.0 * r)).collect();
        Shape::Table(Arc::new(Table {
            file: "p.csv".into(),
            spline: Spline::new(x, g).unwrap(),
        }))
    }

    #[test]
    fn power_two_and_rounded_flat_of_zero_width_are_the_parabola() {
        let r = 0.05;
        let parabola = Shape::Parabola { radius: r };
        let power = Shape::Power {
            radius: r,
            exponent: 2.0,
        };
        let flat = Shape::Flat {
            half_width: 0.0,
            edge_radius: r,
        };
        for x in [-1e-3, -2e-4, 0.0, 3e-4, 1.5e-3] {
            let want = parabola.eval(x);
            for got in [power.eval(x), flat.eval(x)] {
                assert!((got.0 - want.0).abs() <= 1e-15 * want.0.abs().max(1e-12));
                assert!((got.1 - want.1).abs() <= 1e-15);
                // the flat's curvature at its (empty) face is the face's, 0
                assert!(x == 0.0 || (got.2 - want.2).abs() <= 1e-12);
            }
        }
    }

    #[test]
    fn slopes_are_the_derivatives_of_g() {
        // Central differences, step 1e-7 m: error ~ h^2 g''' < 1e-9 relative.
        let shapes = [
            Shape::Power {
                radius: 0.01,
                exponent: 3.5,
            },
            Shape::Flat {
                half_width: 5e-4,
                edge_radius: 1e-3,
            },
            table(0.02),
        ];
        let h = 1e-7;
        for s in &shapes {
            for x in [-1.1e-3, -7e-4, 2e-4, 9e-4] {
                let numeric = (s.g(x + h) - s.g(x - h)) / (2.0 * h);
                assert!((numeric - s.slope(x)).abs() < 1e-8, "{s:?} at {x}");
            }
        }
    }

    #[test]
    fn a_sharp_flat_is_known_only_on_its_face_and_a_table_only_on_its_range() {
        let sharp = Shape::Flat {
            half_width: 1e-3,
            edge_radius: 0.0,
        };
        assert!(sharp.is_sharp() && sharp.g(5e-4) == 0.0 && sharp.g(1.1e-3).is_infinite());
        let t = table(0.02);
        assert!(t.covers(1e-3, 2e-3).is_ok());
        let err = t.covers(1e-3, 2.5e-3).unwrap_err().to_string();
        assert!(err.contains("runs off the measured profile"), "{err}");
    }

    #[test]
    fn out_of_range_parameters_say_what_is_allowed() {
        let err = Shape::Power {
            radius: 0.01,
            exponent: 1.0,
        }
        .validate()
        .unwrap_err()
        .to_string();
        assert!(err.contains("1 < n <= 10"), "{err}");
        let err = Shape::Flat {
            half_width: 1e-3,
            edge_radius: -1.0,
        }
        .validate()
        .unwrap_err()
        .to_string();
        assert!(err.contains("edge_radius"), "{err}");
    }
}
