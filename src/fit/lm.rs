//! Weighted least squares by Levenberg-Marquardt (Marquardt (1963); the damping update of
//! Nielsen (1999), as in Madsen, Nielsen & Tingleff (2004) section 3.2): minimise S = |r(x)|^2
//! over x, r the weighted residuals. The Jacobian is taken by central differences (one-sided where
//! a step leaves the allowed values). Every loop is bounded.

use nalgebra::{DMatrix, DVector};

/// Residuals at a point, or why the model has none there (a value out of its range, a solver
/// that cannot answer): the minimiser steps back from such points.
pub type Residuals<'a> = dyn Fn(&DVector<f64>) -> Result<DVector<f64>, String> + 'a;

/// Most iterations of one minimisation.
pub const MAX_ITERATIONS: usize = 200;
/// Most trial steps within one iteration (each a larger damping).
const MAX_TRIALS: usize = 40;
/// Relative step of the central differences: the truncation error goes as its square (1e-8),
/// the model's rounding (about 1e-13) is magnified by its inverse (1e-9).
const DIFF_STEP: f64 = 1e-4;
/// The largest change of a coordinate in one step: a factor e^5 (about 150) of a logarithmic
/// one, so that a parameter the residuals hardly feel does not run off over hundreds of decades.
const MAX_STEP: f64 = 5.0;

/// The minimum found.
#[derive(Clone, Debug)]
pub struct Minimum {
    /// The parameters.
    pub x: DVector<f64>,
    /// The residuals there.
    pub r: DVector<f64>,
    /// Their Jacobian there, d r_i / d x_j.
    pub jacobian: DMatrix<f64>,
    /// S = |r|^2.
    pub sum_of_squares: f64,
    /// Iterations taken.
    pub iterations: usize,
}

/// The Jacobian of `f` at `x` (where `f(x) = r`), by central differences with step
/// `DIFF_STEP * max(|x_j|, 1)`, one-sided when one side has no residuals.
pub fn jacobian(f: &Residuals, x: &DVector<f64>, r: &DVector<f64>) -> Result<DMatrix<f64>, String> {
    let mut jac = DMatrix::zeros(r.len(), x.len());
    for j in 0..x.len() {
        let h = DIFF_STEP * x[j].abs().max(1.0);
        let at = |d: f64| {
            let mut y = x.clone();
            y[j] += d;
            f(&y)
        };
        let column = match (at(h), at(-h)) {
            (Ok(up), Ok(down)) => (up - down) / (2.0 * h),
            (Ok(up), Err(_)) => (up - r) / h,
            (Err(_), Ok(down)) => (r - down) / h,
            (Err(why), Err(_)) => return Err(why),
        };
        jac.set_column(j, &column);
    }
    Ok(jac)
}

/// Minimises |f(x)|^2 from `x0`. Converged when the gradient or the step or the relative fall of
/// S is negligible; Err says why not (no residuals at `x0`, no step that lowers S, or
/// `max_iterations` spent while S still falls).
pub fn minimize(f: &Residuals, x0: DVector<f64>, max_iterations: usize) -> Result<Minimum, String> {
    let (m, jacobian_at_x) = descend(f, x0, max_iterations)?;
    let jacobian = match jacobian_at_x {
        Some(jacobian) => jacobian,
        None => jacobian(f, &m.x, &m.r)?,
    };
    Ok(Minimum { jacobian, ..m })
}

/// As [`minimize`], the point and its sum of squares only, for a refit whose Jacobian at the
/// minimum nobody reads (a profile's, the fit with some parameters held): where the last step
/// ends the iterations, the Jacobian after it (2 evaluations of `f` per parameter) is not
/// computed. The point is the one `minimize` finds.
pub fn minimize_point(
    f: &Residuals,
    x0: DVector<f64>,
    max_iterations: usize,
) -> Result<(DVector<f64>, f64), String> {
    let (m, _) = descend(f, x0, max_iterations)?;
    Ok((m.x, m.sum_of_squares))
}

/// The iterations of [`minimize`]: the minimum with the last Jacobian computed (of the point
/// before the last step when the second value is None, else the Jacobian at the minimum).
fn descend(
    f: &Residuals,
    x0: DVector<f64>,
    max_iterations: usize,
) -> Result<(Minimum, Option<DMatrix<f64>>), String> {
    let mut x = x0;
    let mut r = f(&x)?;
    let mut s = r.norm_squared();
    let mut lambda: Option<f64> = None;
    let mut nu = 2.0;
    for iteration in 0..max_iterations {
        let jac = jacobian(f, &x, &r)?;
        let a = jac.transpose() * &jac;
        let g = jac.transpose() * &r;
        let scale = a.diagonal().max().max(f64::MIN_POSITIVE);
        let done = |x: DVector<f64>, r: DVector<f64>, s: f64, jacobian: DMatrix<f64>| Minimum {
            x,
            r,
            jacobian,
            sum_of_squares: s,
            iterations: iteration,
        };
        if g.amax() <= 1e-14 * scale.sqrt() * s.sqrt().max(f64::MIN_POSITIVE) || s == 0.0 {
            return Ok((done(x, r, s, jac.clone()), Some(jac)));
        }
        // Marquardt's scaling by diag(J^T J), floored so that a parameter the residuals do not
        // feel still gets a damped (zero) step
        let d = a.diagonal().map(|v| v.max(1e-12 * scale));
        let mut l = *lambda.get_or_insert(1e-3);
        let mut accepted = None;
        for _ in 0..MAX_TRIALS {
            let mut m = a.clone();
            for j in 0..m.nrows() {
                m[(j, j)] += l * d[j];
            }
            let Some(mut step) = m.cholesky().map(|c| c.solve(&(-&g))) else {
                l *= nu;
                nu *= 2.0;
                continue;
            };
            if step.amax() > MAX_STEP {
                step *= MAX_STEP / step.amax();
            }
            let trial = &x + &step;
            let predicted = step.dot(&(step.component_mul(&d) * l - &g));
            match f(&trial) {
                Ok(rt) if rt.norm_squared() < s => {
                    let st = rt.norm_squared();
                    let rho = (s - st) / predicted.max(f64::MIN_POSITIVE);
                    l *= (1.0 - (2.0 * rho - 1.0).powi(3)).max(1.0 / 3.0);
                    nu = 2.0;
                    accepted = Some((trial, rt, st, step));
                    break;
                }
                _ => {
                    l *= nu;
                    nu *= 2.0;
                }
            }
        }
        lambda = Some(l);
        let Some((trial, rt, st, step)) = accepted else {
            // no step lowers S: x is a minimum to the precision of the residuals
            return Ok((done(x, r, s, jac.clone()), Some(jac)));
        };
        let small_step = step.amax() <= 1e-10 * (1.0 + x.amax());
        let small_fall = s - st <= 1e-12 * s;
        x = trial;
        r = rt;
        s = st;
        if small_step || small_fall {
            return Ok((done(x, r, s, jac), None));
        }
    }
    Err(format!(
        "the fit did not converge in {max_iterations} iterations (the sum of squares was still \
         falling, at {s:.6e}): the data may not fit the model at all"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rosenbrock's function as residuals (10 (y - x^2), 1 - x): minimum 0 at (1, 1), a curved
    /// valley that plain Gauss-Newton steps overshoot.
    #[test]
    fn finds_the_minimum_of_rosenbrocks_valley() {
        let f = |x: &DVector<f64>| {
            Ok(DVector::from_vec(vec![
                10.0 * (x[1] - x[0] * x[0]),
                1.0 - x[0],
            ]))
        };
        let m = minimize(&f, DVector::from_vec(vec![-1.2, 1.0]), MAX_ITERATIONS).unwrap();
        assert!(
            (m.x[0] - 1.0).abs() < 1e-6 && (m.x[1] - 1.0).abs() < 1e-6,
            "{}",
            m.x
        );
        assert!(m.sum_of_squares < 1e-12);
    }

    /// A straight line through noisy points: the minimum is the normal equations' solution.
    #[test]
    fn agrees_with_the_normal_equations_for_a_line() {
        let xs = [0.0, 1.0, 2.0, 3.0, 4.0];
        let ys = [1.1, 2.9, 5.2, 6.8, 9.1];
        let f = |p: &DVector<f64>| {
            Ok(DVector::from_iterator(
                5,
                xs.iter().zip(ys).map(|(x, y)| p[0] + p[1] * x - y),
            ))
        };
        let m = minimize(&f, DVector::from_vec(vec![0.0, 0.0]), MAX_ITERATIONS).unwrap();
        // least squares by hand: slope = Sxy/Sxx = 19.9/10 = 1.99, intercept = 5.02 - 2 * 1.99
        assert!((m.x[1] - 1.99).abs() < 1e-9, "{}", m.x);
        assert!((m.x[0] - 1.04).abs() < 1e-9, "{}", m.x);
    }

    /// Points where the model has no answer are stepped around: sqrt(x) - 2 with x >= 0 only.
    #[test]
    fn steps_back_from_points_without_residuals() {
        let f = |x: &DVector<f64>| {
            if x[0] < 0.0 {
                Err("x < 0".to_string())
            } else {
                Ok(DVector::from_vec(vec![x[0].sqrt() - 2.0]))
            }
        };
        let m = minimize(&f, DVector::from_vec(vec![0.5]), MAX_ITERATIONS).unwrap();
        assert!((m.x[0] - 4.0).abs() < 1e-6, "{}", m.x);
        let e = minimize(&f, DVector::from_vec(vec![-1.0]), MAX_ITERATIONS).unwrap_err();
        assert_eq!(e, "x < 0");
    }
}
