//! The punch's slope g' in (E) as the collocation takes it when g' is not a polynomial: at each
//! collocation point xi_k the value of p_N, the projection of g' onto the polynomials of degree N
//! in the weight rho(t) = (1-t)^(-1/2-theta) (1+t)^(-1/2+theta) of the points, instead of g'(xi_k).
//!
//! Why: for polynomial phi the collocation of (E)'s dominant part is exact (`system`), so the
//! discrete pressure is the exact one of the problem whose slope is the polynomial the N + 1
//! values at xi_k describe. Point values interpolate g', and where g'' jumps or is singular inside
//! the contact (a rounded flat's face ends, a power punch's tip, n < 2) the interpolant converges
//! like N^-2 or slower and so does every output. The projection's error is rho-orthogonal to the
//! polynomials of degree N, so the outputs, integrals of the pressure against smooth weights,
//! see it only through the product of two such errors (Galerkin's superconvergence).
//!
//! Computed as p_N(xi_k) = <g', l_k>/<1, l_k> (l_k the Lagrange polynomial of xi_k, <f, v> the
//! rho-weighted integral; the N + 1 point Gauss rule of rho is exact for l_j l_k, so
//! <p_N, l_k> = W_k p_N(xi_k) and <1, l_k> = W_k). The integrals are split at the kinks: a
//! Gauss-Jacobi rule takes rho's end of each end piece, and each side of a kink is graded
//! quadratically (t - t0 proportional to u^2), which turns g' ~ |x|^(n-1) into a smooth function.

use nalgebra::DMatrix;

use crate::physics::quadrature::{GaussRule, gauss_jacobi, gauss_legendre};

/// Quadrature points per piece beyond the degree N of the Lagrange polynomials.
const EXTRA_POINTS: usize = 24;

/// The rules of the projection for one (theta, N).
pub struct SlopeProjection {
    points: Vec<f64>,
    bary: Vec<f64>,
    alpha: f64,
    beta: f64,
    /// Weight rho on [-1, 1]: the contact without kinks.
    whole: GaussRule,
    /// Weight (1 - u)^alpha: a piece that ends at the leading end.
    leading: GaussRule,
    /// Weight (1 + u)^beta: a piece that starts at the trailing end.
    trailing: GaussRule,
    /// Weight 1: a piece between two kinks.
    inner: GaussRule,
}

impl SlopeProjection {
    /// The projection onto the polynomials through the points `points` (the zeros of
    /// P_{N+1}^(-1/2-theta, -1/2+theta)).
    pub fn new(points: &[f64], theta: f64) -> SlopeProjection {
        let (alpha, beta) = (-0.5 - theta, -0.5 + theta);
        let of_points = gauss_jacobi(points.len(), alpha, beta);
        let m = points.len() + EXTRA_POINTS;
        SlopeProjection {
            points: points.to_vec(),
            bary: of_points.barycentric_weights(),
            alpha,
            beta,
            whole: gauss_jacobi(m, alpha, beta),
            leading: gauss_jacobi(m, alpha, 0.0),
            trailing: gauss_jacobi(m, 0.0, beta),
            inner: gauss_legendre(m),
        }
    }

    /// The nodes t and weights (rho and the map's dt/du included) of the split rule on [-1, 1]
    /// for the kinks `kinks` (t in (-1, 1), increasing).
    fn rule(&self, kinks: &[f64]) -> Vec<(f64, f64)> {
        let mut ends = vec![-1.0];
        ends.extend(kinks.iter().copied().filter(|t| t.abs() < 1.0));
        ends.push(1.0);
        if ends.len() == 2 {
            return self
                .whole
                .nodes
                .iter()
                .copied()
                .zip(self.whole.weights.iter().copied())
                .collect();
        }
        let (alpha, beta) = (self.alpha, self.beta);
        let last = ends.len() - 2;
        let mut out = Vec::new();
        for (i, piece) in ends.windows(2).enumerate() {
            let (lo, hi) = (piece[0], piece[1]);
            let d = hi - lo;
            if i == 0 {
                // t = hi - d v^2, v = (1 - u)/2: 1 + t = d (1 + u)/2 (3 - u)/2
                for (u, w) in self.trailing.nodes.iter().zip(&self.trailing.weights) {
                    let v = 0.5 * (1.0 - u);
                    let t = hi - d * v * v;
                    let rest = (0.5 * d).powf(beta) * (0.5 * (3.0 - u)).powf(beta);
                    out.push((t, w * rest * (1.0 - t).powf(alpha) * d * v));
                }
            } else if i == last {
                // t = lo + d v^2, v = (1 + u)/2: 1 - t = d (1 - u)/2 (3 + u)/2
                for (u, w) in self.leading.nodes.iter().zip(&self.leading.weights) {
                    let v = 0.5 * (1.0 + u);
                    let t = lo + d * v * v;
                    let rest = (0.5 * d).powf(alpha) * (0.5 * (3.0 + u)).powf(alpha);
                    out.push((t, w * rest * (1.0 + t).powf(beta) * d * v));
                }
            } else {
                // t = mid + (d/2) (3u - u^3)/2: graded at both kinks
                for (u, w) in self.inner.nodes.iter().zip(&self.inner.weights) {
                    let t = 0.5 * (lo + hi) + 0.25 * d * (3.0 * u - u * u * u);
                    let jac = 0.75 * d * (1.0 - u * u);
                    let rho = (1.0 - t).powf(alpha) * (1.0 + t).powf(beta);
                    out.push((t, w * rho * jac));
                }
            }
        }
        out
    }

    /// The Lagrange polynomials l_k of the points at t, into `out`.
    fn basis(&self, t: f64, out: &mut [f64]) {
        let mut sum = 0.0;
        for ((x, b), l) in self.points.iter().zip(&self.bary).zip(out.iter_mut()) {
            if t == *x {
                out.iter_mut().for_each(|l| *l = 0.0);
                if let Some(k) = self.points.iter().position(|p| *p == t) {
                    out[k] = 1.0;
                }
                return;
            }
            *l = b / (t - x);
            sum += *l;
        }
        out.iter_mut().for_each(|l| *l /= sum);
    }

    /// p_N(xi_k) of each of the functions `f` returns (module note), with its kinks at `kinks`.
    pub fn project<const K: usize>(
        &self,
        kinks: &[f64],
        f: impl Fn(f64) -> [f64; K],
    ) -> [Vec<f64>; K] {
        let n = self.points.len();
        let mut num: [Vec<f64>; K] = std::array::from_fn(|_| vec![0.0; n]);
        let mut den = vec![0.0; n];
        let mut basis = vec![0.0; n];
        for (t, w) in self.rule(kinks) {
            self.basis(t, &mut basis);
            let values = f(t);
            for (k, l) in basis.iter().enumerate() {
                den[k] += w * l;
                for (acc, v) in num.iter_mut().zip(&values) {
                    acc[k] += w * l * v;
                }
            }
        }
        for acc in &mut num {
            acc.iter_mut().zip(&den).for_each(|(a, d)| *a /= d);
        }
        num
    }

    /// The split rule's nodes t_j for the kinks `kinks` and the matrix B of the projection:
    /// p_N(xi_k) = sum_j B[(k, j)] f(t_j).
    pub fn matrix(&self, kinks: &[f64]) -> (Vec<f64>, DMatrix<f64>) {
        let rule = self.rule(kinks);
        let n = self.points.len();
        let mut b = DMatrix::zeros(n, rule.len());
        let mut basis = vec![0.0; n];
        for (j, (t, w)) in rule.iter().enumerate() {
            self.basis(*t, &mut basis);
            for (k, l) in basis.iter().enumerate() {
                b[(k, j)] = w * l;
            }
        }
        for mut row in b.row_iter_mut() {
            let den = row.sum();
            row /= den;
        }
        (rule.into_iter().map(|(t, _)| t).collect(), b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::quadrature::jacobi_zeros;

    #[test]
    fn polynomials_are_their_own_projection() {
        // a polynomial of degree <= N is reproduced at the points, split or not
        let theta = 0.07;
        let points = jacobi_zeros(9, -0.5 - theta, -0.5 + theta);
        let p = SlopeProjection::new(&points, theta);
        let f = |t: f64| [1.0 - 2.0 * t + 0.5 * t.powi(5) - t.powi(8)];
        for kinks in [vec![], vec![0.3], vec![-0.6, 0.1]] {
            let [got] = p.project(&kinks, f);
            for (g, x) in got.iter().zip(&points) {
                assert!(
                    (g - f(*x)[0]).abs() < 1e-13,
                    "{kinks:?}: {g} vs {}",
                    f(*x)[0]
                );
            }
        }
    }

    #[test]
    fn the_projection_is_orthogonal_to_low_degrees() {
        // <|t - t0|, P> = <p_N, P> for every P of degree <= N: checked against 1, t, t^2 by a
        // rule of 400 points on each side of the kink (an independent route)
        let theta = -0.1;
        let points = jacobi_zeros(13, -0.5 - theta, -0.5 + theta);
        let p = SlopeProjection::new(&points, theta);
        let t0 = 0.27;
        let [proj] = p.project(&[t0], |t: f64| [(t - t0).abs()]);
        let fine = SlopeProjection::new(&jacobi_zeros(400, -0.5 - theta, -0.5 + theta), theta);
        let rule = fine.rule(&[t0]);
        let of_points = gauss_jacobi(points.len(), -0.5 - theta, -0.5 + theta);
        for power in 0..3 {
            let exact: f64 = rule
                .iter()
                .map(|(t, w)| w * (t - t0).abs() * t.powi(power))
                .sum();
            let discrete: f64 = proj
                .iter()
                .zip(&of_points.nodes)
                .zip(&of_points.weights)
                .map(|((v, t), w)| w * v * t.powi(power))
                .sum();
            assert!(
                (exact - discrete).abs() < 1e-12,
                "t^{power}: {exact} vs {discrete}"
            );
        }
    }
}
