//! Standard errors from the Jacobian at the minimum (Seber & Wild (1989) chapter 2): the
//! covariance of the estimates is s^2 (J^T J)^-1, s^2 the residual variance (1 when the data give
//! their standard deviations). A Jacobian whose columns are dependent (rank-deficient, Golub &
//! Van Loan (2013) section 5.5) leaves the parameters of its null direction undetermined.

use nalgebra::DMatrix;

/// Singular values below this fraction of the largest count as zero (a relative change of the
/// residuals 1e-8 times smaller than the best determined direction's: below the differences'
/// precision).
const RANK_TOLERANCE: f64 = 1e-8;

/// What the Jacobian says of each parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct Errors {
    /// The standard error of each parameter's coordinate (None where the Jacobian cannot tell).
    pub standard: Vec<Option<f64>>,
    /// True for a parameter in a null direction of the Jacobian.
    pub deficient: Vec<bool>,
}

/// The standard errors of the parameters from the Jacobian `jac` (rows: residuals) and the
/// residual variance `s2`. The columns are scaled to unit length before the rank is judged, so
/// that the units of the parameters do not decide it; the parameters of a null direction are
/// left out and the others' errors come from the rest of the columns.
pub fn errors(jac: &DMatrix<f64>, s2: f64) -> Errors {
    let p = jac.ncols();
    let norms: Vec<f64> = (0..p).map(|j| jac.column(j).norm()).collect();
    let largest = norms.iter().cloned().fold(0.0, f64::max);
    let mut deficient: Vec<bool> = norms
        .iter()
        .map(|n| n.is_nan() || *n <= RANK_TOLERANCE * largest || *n == 0.0)
        .collect();
    let kept: Vec<usize> = (0..p).filter(|j| !deficient[*j]).collect();
    if !kept.is_empty() {
        let scaled = DMatrix::from_fn(jac.nrows(), kept.len(), |i, k| {
            jac[(i, kept[k])] / norms[kept[k]]
        });
        let svd = scaled.svd(false, true);
        let top = svd.singular_values.max();
        if let Some(v_t) = &svd.v_t {
            for (s, sv) in svd.singular_values.iter().enumerate() {
                if *sv < RANK_TOLERANCE * top {
                    for (k, j) in kept.iter().enumerate() {
                        if v_t[(s, k)].abs() > 0.1 {
                            deficient[*j] = true;
                        }
                    }
                }
            }
        }
    }
    let kept: Vec<usize> = (0..p).filter(|j| !deficient[*j]).collect();
    let mut standard = vec![None; p];
    if !kept.is_empty() {
        let sub = DMatrix::from_fn(jac.nrows(), kept.len(), |i, k| jac[(i, kept[k])]);
        if let Some(inverse) = (sub.transpose() * &sub).try_inverse() {
            for (k, j) in kept.iter().enumerate() {
                let variance = s2 * inverse[(k, k)];
                standard[*j] = (variance.is_finite() && variance >= 0.0).then(|| variance.sqrt());
            }
        }
    }
    Errors {
        standard,
        deficient,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_straight_line_has_the_textbook_errors() {
        // y = a + b x at x = 0..4: Var(b) = s2/Sxx = s2/10, Var(a) = s2 (1/n + xbar^2/Sxx) = 0.6 s2
        let jac = DMatrix::from_fn(5, 2, |i, j| if j == 0 { 1.0 } else { i as f64 });
        let e = errors(&jac, 4.0);
        assert_eq!(e.deficient, vec![false, false]);
        assert!((e.standard[1].unwrap() - (0.4f64).sqrt()).abs() < 1e-12);
        assert!((e.standard[0].unwrap() - (2.4f64).sqrt()).abs() < 1e-12);
    }

    #[test]
    fn a_parameter_the_residuals_do_not_feel_is_deficient() {
        let jac = DMatrix::from_fn(5, 2, |i, j| if j == 0 { 1.0 + i as f64 } else { 0.0 });
        let e = errors(&jac, 1.0);
        assert_eq!(e.deficient, vec![false, true]);
        assert!(e.standard[0].is_some() && e.standard[1].is_none());
        // two columns in proportion: both in the null direction
        let jac = DMatrix::from_fn(5, 2, |i, j| (1.0 + i as f64) * (1.0 + j as f64));
        assert_eq!(errors(&jac, 1.0).deficient, vec![true, true]);
    }
}
