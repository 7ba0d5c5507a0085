//! The factorizations of the strip's scaled collocation matrix (`collocation`): LU with partial
//! pivoting, blocked so that most of its work is one matrix product per block of columns
//! (nalgebra's `gemm`, which runs on the `matrixmultiply` kernels), and Householder QR as the
//! fallback where LU's growth factor is large (strong wear); iterative refinement from the factors
//! of a nearby matrix.
//!
//! Blocked LU (Golub & Van Loan, Matrix Computations, 4th ed., algorithm 3.4.2 with the row
//! interchanges of section 3.4.3): for each block of NB columns, the panel below the diagonal is
//! factored column by column with partial pivoting (the row interchanges applied across the whole
//! matrix), the block row to its right is solved with the panel's unit lower triangle, and the
//! trailing matrix is updated by one product A22 -= L21 U12. It chooses the same pivots as the
//! unblocked algorithm up to round-off in the trailing sums, and does the same 2n^3/3 operations,
//! all but O(n^2 NB) of them in the product.

use nalgebra::{DMatrix, DVector, Dyn, QR};

/// LU is used while max|U|/max|A| stays below this; QR above.
const MAX_GROWTH: f64 = 1e6;
/// Refinement steps before the factors are rebuilt.
const MAX_REFINEMENTS: usize = 12;
/// Columns per block of the LU factorization.
const NB: usize = 16;

/// LU with partial pivoting of a square matrix: L (unit lower) and U packed in one matrix, and
/// the row interchanged with row j at step j.
pub struct Lu {
    packed: DMatrix<f64>,
    pivots: Vec<usize>,
}

impl Lu {
    /// The factors of `a` (square), or None when a pivot is zero or not finite.
    fn new(mut a: DMatrix<f64>) -> Option<Lu> {
        let n = a.nrows();
        let mut pivots = Vec::with_capacity(n);
        for k0 in (0..n).step_by(NB) {
            let k1 = (k0 + NB).min(n);
            for j in k0..k1 {
                let pivot = pivot_row(a.column(j).as_slice(), j);
                let value = a[(pivot, j)];
                if value == 0.0 || !value.is_finite() {
                    return None;
                }
                pivots.push(pivot);
                if pivot != j {
                    a.swap_rows(j, pivot);
                }
                let column = &mut a.column_mut(j);
                for entry in &mut column.as_mut_slice()[j + 1..] {
                    *entry /= value;
                }
                // rank-one update of the rest of the panel
                for c in j + 1..k1 {
                    eliminate(&mut a, j, c, j + 1..n);
                }
            }
            if k1 == n {
                break;
            }
            // U12 = L11^-1 A12, by the inverse of the small unit lower triangle L11
            let (kb, m) = (k1 - k0, n - k1);
            let u12 = unit_lower_inverse(&a.view((k0, k0), (kb, kb)).into_owned())
                * a.view((k0, k1), (kb, m));
            a.view_mut((k0, k1), (kb, m)).copy_from(&u12);
            // A22 -= L21 U12
            let l21 = a.view((k1, k0), (m, kb)).into_owned();
            a.view_mut((k1, k1), (m, m)).gemm(-1.0, &l21, &u12, 1.0);
        }
        Some(Lu { packed: a, pivots })
    }

    /// The largest entry of U.
    fn growth(&self) -> f64 {
        let a = &self.packed;
        (0..a.ncols())
            .map(|j| {
                a.column(j).as_slice()[..=j]
                    .iter()
                    .fold(0.0, |m: f64, v| m.max(v.abs()))
            })
            .fold(0.0, f64::max)
    }

    /// x with A x = b: forward and back substitution two columns of the factors at a time (one
    /// pass over x per pair).
    fn solve(&self, b: &DVector<f64>) -> DVector<f64> {
        let n = self.packed.nrows();
        let mut x = b.clone();
        let xs = x.as_mut_slice();
        for (j, &p) in self.pivots.iter().enumerate() {
            xs.swap(j, p);
        }
        let data = self.packed.as_slice();
        let column = |j: usize| &data[j * n..(j + 1) * n];
        let mut j = 0;
        while j + 1 < n {
            let (c0, c1) = (column(j), column(j + 1));
            xs[j + 1] -= c0[j + 1] * xs[j];
            let (x0, x1) = (xs[j], xs[j + 1]);
            for ((xi, l0), l1) in xs[j + 2..].iter_mut().zip(&c0[j + 2..]).zip(&c1[j + 2..]) {
                *xi -= l0 * x0 + l1 * x1;
            }
            j += 2;
        }
        let mut j = n;
        while j >= 2 {
            let (c0, c1) = (column(j - 2), column(j - 1));
            xs[j - 1] /= c1[j - 1];
            xs[j - 2] = (xs[j - 2] - c1[j - 2] * xs[j - 1]) / c0[j - 2];
            let (x0, x1) = (xs[j - 2], xs[j - 1]);
            for ((xi, u0), u1) in xs[..j - 2].iter_mut().zip(c0).zip(c1) {
                *xi -= u0 * x0 + u1 * x1;
            }
            j -= 2;
        }
        if j == 1 {
            xs[0] /= data[0];
        }
        x
    }
}

/// The inverse of the unit lower triangle of `l` (its diagonal taken as 1, its upper part
/// ignored), by forward substitution on each column of the identity.
fn unit_lower_inverse(l: &DMatrix<f64>) -> DMatrix<f64> {
    let n = l.nrows();
    let mut x = DMatrix::identity(n, n);
    for c in 0..n {
        for j in c..n {
            let xj = x[(j, c)];
            for i in j + 1..n {
                x[(i, c)] -= l[(i, j)] * xj;
            }
        }
    }
    x
}

/// The row (at or below `from`) of the largest magnitude in a column.
fn pivot_row(column: &[f64], from: usize) -> usize {
    let mut best = from;
    for (i, v) in column.iter().enumerate().skip(from + 1) {
        if v.abs() > column[best].abs() {
            best = i;
        }
    }
    best
}

/// a[rows, c] -= a[rows, j] a[j, c] (one elimination step on one column; rows below row j).
fn eliminate(a: &mut DMatrix<f64>, j: usize, c: usize, rows: std::ops::Range<usize>) {
    let u = a[(j, c)];
    if u == 0.0 {
        return;
    }
    let n = a.nrows();
    let data = a.as_mut_slice();
    let (left, right) = data.split_at_mut(c * n);
    let l = &left[j * n + rows.start..j * n + rows.end];
    let target = &mut right[rows];
    for (t, l) in target.iter_mut().zip(l) {
        *t -= l * u;
    }
}

/// A factorization of the matrix at some width.
pub enum Factors {
    Lu(Lu),
    Qr(QR<f64, Dyn, Dyn>),
}

impl Factors {
    /// LU when its growth factor is moderate, else QR; None when the matrix is singular.
    pub fn new(a: &DMatrix<f64>) -> Option<Factors> {
        let scale = a.amax();
        if let Some(lu) = Lu::new(a.clone()) {
            if lu.growth() < MAX_GROWTH * scale {
                return Some(Factors::Lu(lu));
            }
        }
        let qr = a.clone().qr();
        qr.is_invertible().then_some(Factors::Qr(qr))
    }

    /// Whether these are LU factors (QR otherwise).
    #[cfg(test)]
    fn is_lu(&self) -> bool {
        matches!(self, Factors::Lu(_))
    }

    /// x with A x = b; None when it is not finite.
    pub fn solve(&self, b: &DVector<f64>) -> Option<DVector<f64>> {
        let y = match self {
            Factors::Lu(lu) => lu.solve(b),
            Factors::Qr(qr) => qr.solve(b)?,
        };
        y.iter().all(|v| v.is_finite()).then_some(y)
    }

    /// Solves a y = b by refinement from these factors (of a nearby matrix), starting at `guess`:
    /// None when a step does not contract the correction by half (above round-off) or more than
    /// MAX_REFINEMENTS steps are needed. Stops when the next correction, estimated from the
    /// contraction so far, is below `tolerance` of y. Returns y and the steps taken.
    pub fn refine(
        &self,
        a: &DMatrix<f64>,
        b: &DVector<f64>,
        y: DVector<f64>,
        tolerance: f64,
    ) -> Option<(DVector<f64>, usize)> {
        refine(a, b, y, tolerance, |r| self.solve(r))
    }
}

/// Solves a y = b by refinement from `guess` with `solve`, an approximate inverse of a (the
/// factors of a nearby matrix, or a two-grid step): None when a step does not contract the
/// correction by half (above round-off), a correction is not finite (nalgebra's `amax` passes
/// NaN by) or more than MAX_REFINEMENTS steps are needed. Stops when
/// the next correction, estimated from the contraction so far, is below `tolerance` of y.
/// Returns y and the steps taken.
pub fn refine(
    a: &DMatrix<f64>,
    b: &DVector<f64>,
    mut y: DVector<f64>,
    tolerance: f64,
    solve: impl Fn(&DVector<f64>) -> Option<DVector<f64>>,
) -> Option<(DVector<f64>, usize)> {
    let mut last = f64::INFINITY;
    for steps in 1..=MAX_REFINEMENTS {
        let dy = solve(&residual(a, &y, b))?;
        if !dy.iter().all(|v| v.is_finite()) {
            return None;
        }
        y += &dy;
        let (step, size) = (dy.amax(), y.amax());
        // the contraction per step, unknown after the first
        let ratio = if last.is_finite() { step / last } else { 0.0 };
        if step <= 1e-15 * size
            || (last.is_finite() && ratio < 0.5 && step * ratio <= tolerance * size)
        {
            return Some((y, steps));
        }
        if ratio >= 0.5 {
            // stalled: converged if at round-off, else these factors are too far off
            return (step <= 1e-13 * size).then_some((y, steps));
        }
        last = step;
    }
    None
}

/// b - a y, two columns at a time over contiguous slices (so that it vectorizes, one pass over
/// the result per pair).
fn residual(a: &DMatrix<f64>, y: &DVector<f64>, b: &DVector<f64>) -> DVector<f64> {
    let mut r = b.clone();
    let rows = a.nrows();
    let mut pairs = a.as_slice().chunks_exact(2 * rows);
    let mut ys = y.as_slice().chunks_exact(2);
    for (columns, y2) in (&mut pairs).zip(&mut ys) {
        let (c0, c1) = columns.split_at(rows);
        for ((ri, a0), a1) in r.as_mut_slice().iter_mut().zip(c0).zip(c1) {
            *ri -= a0 * y2[0] + a1 * y2[1];
        }
    }
    for (column, yi) in pairs.remainder().chunks_exact(rows).zip(ys.remainder()) {
        for (ri, aki) in r.as_mut_slice().iter_mut().zip(column) {
            *ri -= aki * yi;
        }
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Entries in [-1, 1] from a fixed linear congruential sequence (Knuth's MMIX constants).
    fn scrambled(n: usize, seed: u64) -> DMatrix<f64> {
        let mut state = seed;
        DMatrix::from_fn(n, n, |_, _| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        })
    }

    #[test]
    fn blocked_lu_solves_as_nalgebras_unblocked_lu() {
        // sizes around the block width, and the strip's smallest and a mid node count
        for (n, seed) in [
            (1, 1),
            (2, 2),
            (15, 3),
            (16, 4),
            (17, 5),
            (33, 6),
            (49, 7),
            (130, 8),
        ] {
            let a = scrambled(n, seed);
            let x = DVector::from_fn(n, |i, _| 1.0 + i as f64 / n as f64);
            let b = &a * &x;
            let ours = Lu::new(a.clone()).unwrap().solve(&b);
            let theirs = a.clone().lu().solve(&b).unwrap();
            // independent route: nalgebra's unblocked LU; both near the exact x
            assert!((&ours - &theirs).amax() < 1e-11 * x.amax(), "n = {n}");
            assert!((&ours - &x).amax() < 1e-10 * x.amax(), "n = {n}");
        }
    }

    #[test]
    fn pivots_past_a_zero_leading_entry_and_refuses_a_singular_matrix() {
        let swap = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 1.0, 0.0]);
        let y = Lu::new(swap)
            .unwrap()
            .solve(&DVector::from_column_slice(&[3.0, 4.0]));
        assert_eq!(y.as_slice(), [4.0, 3.0]);
        // a zero column stays exactly zero through the elimination: a zero pivot
        let mut singular = scrambled(20, 9);
        singular.column_mut(11).fill(0.0);
        assert!(Lu::new(singular.clone()).is_none());
        assert!(Factors::new(&singular).is_none());
    }

    #[test]
    fn refinement_refuses_a_correction_that_is_not_finite() {
        // an approximate inverse that answers NaN (amax would pass it by) or infinity: None, so
        // that the caller factors the matrix (collocation.rs) instead of returning a NaN
        let a = scrambled(8, 10);
        let b = DVector::from_element(8, 1.0);
        for bad in [f64::NAN, f64::INFINITY] {
            let solve = |r: &DVector<f64>| Some(r.map(|_| bad));
            assert!(refine(&a, &b, DVector::zeros(8), 1e-14, solve).is_none());
        }
    }

    #[test]
    fn large_growth_falls_back_to_qr() {
        // Wilkinson's matrix: 1 on the diagonal and in the last column, -1 below the diagonal;
        // partial pivoting doubles the last column at every step, growth 2^(n-1) (Golub & Van
        // Loan, Matrix Computations, 4th ed., section 3.4.5)
        let n = 40;
        let a = DMatrix::from_fn(n, n, |i, j| match (i, j) {
            _ if i == j || j == n - 1 => 1.0,
            _ if i > j => -1.0,
            _ => 0.0,
        });
        let lu = Lu::new(a.clone()).unwrap();
        assert_eq!(lu.growth(), 2f64.powi(n as i32 - 1));
        let x = DVector::from_fn(n, |i, _| (i as f64).sin());
        let b = &a * &x;
        let factors = Factors::new(&a).unwrap();
        assert!(!factors.is_lu());
        assert!((factors.solve(&b).unwrap() - &x).amax() < 1e-12);
    }
}
