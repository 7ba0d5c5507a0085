//! Restarted GMRES with a right preconditioner (Saad, Iterative Methods for Sparse Linear Systems,
//! 2nd ed., SIAM 2003, algorithms 6.9 and 9.5): modified Gram–Schmidt, Givens rotations.

use crate::physics::stop::Stop;

/// A matrix-free linear system A x = b with a right preconditioner M^-1 ~ A^-1.
pub(crate) trait Preconditioned {
    /// y = A x.
    fn apply(&mut self, x: &[f64], y: &mut [f64]);
    /// z = M^-1 r.
    fn precondition(&mut self, r: &[f64], z: &mut [f64]);
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn norm(a: &[f64]) -> f64 {
    dot(a, a).sqrt()
}

/// How a solve ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Gmres {
    /// Products with A.
    pub iterations: usize,
    /// The final true residual |b - A x|.
    pub residual: f64,
    /// True when |b - A x| <= tol.
    pub converged: bool,
    /// True when `stop` ended the solve before it converged (x is then that of the last restart).
    pub stopped: bool,
}

/// Improves x towards A x = b until |b - A x| <= `tol` (absolute), with restarts every `restart`
/// iterations and at most `max_iterations` products in all. `stop` is asked before every product
/// but the first (the caller asks before the solve): a long solve on a fine grid ends within one
/// product of being told.
pub(crate) fn gmres(
    sys: &mut impl Preconditioned,
    b: &[f64],
    x: &mut [f64],
    restart: usize,
    max_iterations: usize,
    tol: f64,
    stop: Stop,
) -> Gmres {
    let n = b.len();
    let mut r = vec![0.0; n];
    let mut w = vec![0.0; n];
    let mut z = vec![0.0; n];
    let mut basis: Vec<Vec<f64>> = Vec::with_capacity(restart + 1);
    let mut h = vec![vec![0.0; restart]; restart + 1];
    let (mut cs, mut sn, mut g) = (
        vec![0.0; restart],
        vec![0.0; restart],
        vec![0.0; restart + 1],
    );
    let mut iterations = 0;
    loop {
        sys.apply(x, &mut r);
        r.iter_mut().zip(b).for_each(|(r, b)| *r = b - *r);
        let beta = norm(&r);
        if beta <= tol || iterations >= max_iterations || !beta.is_finite() {
            return Gmres {
                iterations,
                residual: beta,
                converged: beta <= tol,
                stopped: false,
            };
        }
        basis.clear();
        basis.push(r.iter().map(|v| v / beta).collect());
        g.iter_mut().for_each(|v| *v = 0.0);
        g[0] = beta;
        let mut k = 0;
        while k < restart && iterations < max_iterations {
            if iterations > 0 && stop.now() {
                return Gmres {
                    iterations,
                    residual: beta,
                    converged: false,
                    stopped: true,
                };
            }
            sys.precondition(&basis[k], &mut z);
            sys.apply(&z, &mut w);
            iterations += 1;
            for (i, v) in basis.iter().enumerate() {
                h[i][k] = dot(&w, v);
                w.iter_mut().zip(v).for_each(|(w, v)| *w -= h[i][k] * v);
            }
            h[k + 1][k] = norm(&w);
            for i in 0..k {
                let t = cs[i] * h[i][k] + sn[i] * h[i + 1][k];
                h[i + 1][k] = -sn[i] * h[i][k] + cs[i] * h[i + 1][k];
                h[i][k] = t;
            }
            let rho = h[k][k].hypot(h[k + 1][k]);
            let next = h[k + 1][k];
            if rho == 0.0 {
                break;
            }
            (cs[k], sn[k]) = (h[k][k] / rho, next / rho);
            h[k][k] = rho;
            h[k + 1][k] = 0.0;
            g[k + 1] = -sn[k] * g[k];
            g[k] *= cs[k];
            if next > 0.0 {
                basis.push(w.iter().map(|v| v / next).collect());
            }
            k += 1;
            if g[k].abs() <= tol || next == 0.0 {
                break;
            }
        }
        // y = H^-1 g (upper triangular), x += M^-1 (V y)
        let mut y = vec![0.0; k];
        for i in (0..k).rev() {
            let s: f64 = (i + 1..k).map(|j| h[i][j] * y[j]).sum();
            y[i] = (g[i] - s) / h[i][i];
        }
        w.iter_mut().for_each(|v| *v = 0.0);
        for (v, yi) in basis.iter().zip(&y) {
            w.iter_mut().zip(v).for_each(|(w, v)| *w += yi * v);
        }
        sys.precondition(&w, &mut z);
        x.iter_mut().zip(&z).for_each(|(x, z)| *x += z);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small non-symmetric tridiagonal system with a Jacobi preconditioner.
    struct Tridiagonal;

    impl Preconditioned for Tridiagonal {
        fn apply(&mut self, x: &[f64], y: &mut [f64]) {
            let n = x.len();
            for i in 0..n {
                let left = if i > 0 { -1.5 * x[i - 1] } else { 0.0 };
                let right = if i + 1 < n { 0.5 * x[i + 1] } else { 0.0 };
                y[i] = 4.0 * x[i] + left + right;
            }
        }
        fn precondition(&mut self, r: &[f64], z: &mut [f64]) {
            z.iter_mut().zip(r).for_each(|(z, r)| *z = r / 4.0);
        }
    }

    #[test]
    fn solves_a_non_symmetric_system_across_restarts() {
        let n = 50;
        let exact: Vec<f64> = (0..n).map(|i| (i as f64 * 0.37).sin()).collect();
        let mut b = vec![0.0; n];
        Tridiagonal.apply(&exact, &mut b);
        let mut x = vec![0.0; n];
        let out = gmres(&mut Tridiagonal, &b, &mut x, 5, 500, 1e-13, Stop::Never);
        assert!(out.converged, "{out:?}");
        let err = x
            .iter()
            .zip(&exact)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(err < 1e-12, "{err}");
    }

    #[test]
    fn a_stop_ends_the_solve_before_its_next_product() {
        let n = 50;
        let b: Vec<f64> = (0..n).map(|i| (i as f64 * 0.37).sin()).collect();
        let mut x = vec![0.0; n];
        let asked = std::sync::atomic::AtomicUsize::new(0);
        let stop = || {
            asked.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            true
        };
        let out = gmres(
            &mut Tridiagonal,
            &b,
            &mut x,
            5,
            500,
            1e-13,
            Stop::Asked(&stop),
        );
        // the first product, then the question before the second
        assert!(out.stopped && !out.converged, "{out:?}");
        assert_eq!((out.iterations, asked.into_inner()), (1, 1));
    }
}
