//! The natural cubic spline through a measured punch profile (x_i, g_i): piecewise cubic, twice
//! continuously differentiable, with g'' = 0 at both ends (Press et al., Numerical Recipes,
//! section 3.3, `docs/references.md`). It passes through exactly the given points.

use crate::physics::SolveError;

/// Fewest rows a profile may have: three points are the least that carry a curvature.
pub const MIN_ROWS: usize = 3;

/// A natural cubic spline g(x) [m] through strictly increasing knots x_i [m].
#[derive(Clone, Debug, PartialEq)]
pub struct Spline {
    x: Vec<f64>,
    y: Vec<f64>,
    /// Second derivatives g''(x_i) [1/m] at the knots, zero at both ends.
    m: Vec<f64>,
}

impl Spline {
    /// The spline through the points (x_i, y_i). Refused, in words naming the first bad row
    /// (1-based), when there are fewer than `MIN_ROWS` points, a value is not finite, or x does
    /// not increase strictly.
    pub fn new(x: Vec<f64>, y: Vec<f64>) -> Result<Spline, SolveError> {
        let bad = |reason: String| Err(SolveError::InvalidInput(reason));
        if x.len() != y.len() {
            return bad(format!(
                "the profile has {} x values and {} g values",
                x.len(),
                y.len()
            ));
        }
        if x.len() < MIN_ROWS {
            return bad(format!(
                "the profile has {} row(s): at least {MIN_ROWS} are needed for a curve",
                x.len()
            ));
        }
        if let Some(i) = (0..x.len()).find(|&i| !x[i].is_finite() || !y[i].is_finite()) {
            return bad(format!(
                "row {} of the profile is not a finite number (x = {}, g = {})",
                i + 1,
                x[i],
                y[i]
            ));
        }
        if let Some(i) = (1..x.len()).find(|&i| x[i] <= x[i - 1]) {
            return bad(format!(
                "row {} of the profile: x = {} m does not exceed the previous row's x = {} m (x \
                 must increase strictly)",
                i + 1,
                x[i],
                x[i - 1]
            ));
        }
        let m = second_derivatives(&x, &y);
        if m.iter().any(|v| !v.is_finite()) {
            return bad("the profile's curvature is not finite (rows too close together)".into());
        }
        Ok(Spline { x, y, m })
    }

    /// The knots' range [x_0, x_last] [m].
    pub fn range(&self) -> (f64, f64) {
        (self.x[0], self.x[self.x.len() - 1])
    }

    /// The knots x_i [m], increasing.
    pub fn knots(&self) -> &[f64] {
        &self.x
    }

    /// (g, g', g'') at x: value [m], slope (dimensionless), curvature [1/m]. Beyond the range the
    /// end interval's cubic is continued: callers check the range first (`Shape::covers`).
    pub fn eval(&self, x: f64) -> (f64, f64, f64) {
        let last = self.x.len() - 2;
        let i = self
            .x
            .partition_point(|&k| k <= x)
            .saturating_sub(1)
            .min(last);
        let (x0, x1) = (self.x[i], self.x[i + 1]);
        let (y0, y1) = (self.y[i], self.y[i + 1]);
        let (m0, m1) = (self.m[i], self.m[i + 1]);
        let h = x1 - x0;
        let (s, t) = ((x1 - x) / h, (x - x0) / h);
        let value = s * y0 + t * y1 + ((s * s * s - s) * m0 + (t * t * t - t) * m1) * h * h / 6.0;
        let slope =
            (y1 - y0) / h - (3.0 * s * s - 1.0) * h / 6.0 * m0 + (3.0 * t * t - 1.0) * h / 6.0 * m1;
        (value, slope, s * m0 + t * m1)
    }
}

/// The knots' second derivatives of the natural spline: the tridiagonal system
/// h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1} = 6 (d_i - d_{i-1}), M_0 = M_last = 0
/// (Numerical Recipes eq. 3.3.7), solved by the Thomas algorithm (diagonally dominant, stable).
fn second_derivatives(x: &[f64], y: &[f64]) -> Vec<f64> {
    let n = x.len();
    let mut m = vec![0.0; n];
    let inner = n - 2;
    let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
    let d: Vec<f64> = (0..n - 1).map(|i| (y[i + 1] - y[i]) / h[i]).collect();
    let mut diag = vec![0.0; inner];
    let mut rhs = vec![0.0; inner];
    for j in 0..inner {
        diag[j] = 2.0 * (h[j] + h[j + 1]);
        rhs[j] = 6.0 * (d[j + 1] - d[j]);
        if j > 0 {
            let w = h[j] / diag[j - 1];
            diag[j] -= w * h[j];
            rhs[j] -= w * rhs[j - 1];
        }
    }
    for j in (0..inner).rev() {
        let upper = if j + 1 < inner {
            h[j + 1] * m[j + 2]
        } else {
            0.0
        };
        m[j + 1] = (rhs[j] - upper) / diag[j];
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_a_cubic_with_zero_end_curvature_and_passes_through_the_knots() {
        // A natural spline is exact for a straight line (M = 0 solves the system).
        let x: Vec<f64> = (0..7).map(|i| -0.3 + 0.1 * i as f64).collect();
        let y: Vec<f64> = x.iter().map(|v| 2.0 * v - 0.5).collect();
        let s = Spline::new(x.clone(), y.clone()).unwrap();
        for v in [-0.3, -0.17, 0.0, 0.21, 0.3] {
            let (g, dg, ddg) = s.eval(v);
            assert!((g - (2.0 * v - 0.5)).abs() < 1e-14 && (dg - 2.0).abs() < 1e-13);
            assert!(ddg.abs() < 1e-12);
        }
        let p: Vec<f64> = x.iter().map(|v| v * v).collect();
        let s = Spline::new(x.clone(), p.clone()).unwrap();
        for (xi, pi) in x.iter().zip(&p) {
            assert!((s.eval(*xi).0 - pi).abs() < 1e-15);
        }
    }

    #[test]
    fn converges_to_a_smooth_curve_at_fourth_order_inside() {
        // g = x^2/(2R) sampled on a fine grid: the interior error of a natural spline decays as
        // h^4 away from the ends (Numerical Recipes section 3.3), so 201 knots give < 1e-9 R.
        let r = 0.05;
        let x: Vec<f64> = (0..201).map(|i| -1e-3 + 1e-5 * i as f64).collect();
        let y: Vec<f64> = x.iter().map(|v| v * v / (2.0 * r)).collect();
        let s = Spline::new(x, y).unwrap();
        let (g, dg, ddg) = s.eval(1.234e-4);
        assert!((g - 1.234e-4f64.powi(2) / (2.0 * r)).abs() < 1e-15);
        assert!((dg - 1.234e-4 / r).abs() < 1e-10);
        assert!((ddg - 1.0 / r).abs() < 1e-6 / r);
    }

    #[test]
    fn refuses_short_unsorted_repeated_and_nan_tables_in_words() {
        let err = |x: Vec<f64>, y: Vec<f64>| Spline::new(x, y).unwrap_err().to_string();
        assert!(err(vec![0.0], vec![0.0]).contains("at least 3"));
        assert!(err(vec![0.0, 2.0, 1.0], vec![0.0; 3]).contains("row 3"));
        assert!(err(vec![0.0, 1.0, 1.0], vec![0.0; 3]).contains("increase strictly"));
        assert!(err(vec![0.0, 1.0, 2.0], vec![0.0, f64::NAN, 0.0]).contains("row 2"));
    }
}
