//! Jacobi polynomial transforms of one rule pair of the strip's collocation (`rules`), for
//! the two-grid solve (`two_grid`): alpha = 1/2 + theta, beta = 1/2 - theta (alpha + beta = 1).
//!
//! The Cauchy part of the scaled system, C y with C_ki = 1/(pi (t_i - xi_k)) for the unknowns
//! v_i = W_i g(t_i) (g a polynomial of degree < N) and C_kN = 1/pi for v_N, is diagonal in Jacobi
//! polynomials: by the spectral relation of Erdogan, Gupta & Cook (in G. C. Sih, ed., Methods of
//! Analysis and Solutions of Crack Problems, Noordhoff 1973, ch. 7, eq. 7.36 with kappa = -1),
//!   tan(pi theta) w P_n^(alpha,beta)(x) + (1/pi) p.v. int w P_n^(alpha,beta)/(t - x) dt
//!     = -(2/cos(pi theta)) P_{n+1}^(-alpha,-beta)(x),
//! which the Gauss sum (1/pi) sum_i W_i P_n(t_i)/(t_i - xi_k) gives exactly at the collocation
//! points (docs/physics/plane.md section 6), and the constant column is P_0^(-alpha,-beta)/pi. So a
//! right side f at the N + 1 points xi_k (the nodes of the Gauss rule for (1 - x)^-alpha
//! (1 + x)^-beta) has the coefficients c_m = sum_k lambda_k f_k P_m(xi_k)/h'_m in
//! P_m^(-alpha,-beta), m <= N, and C^-1 f has v_N = pi c_0 and
//! g = sum_n -(cos(pi theta)/2) c_{n+1} P_n^(alpha,beta). The polynomials come from the three-term
//! recurrence (DLMF 18.9.1-2, `quadrature::jacobi_recurrence`), evaluated at all points at once:
//! O(N^2) a transform, no stored tables.

use crate::physics::quadrature::jacobi_recurrence as recurrence;

/// Lanes of the recurrences over points (independent sums, so that the loops vectorize).
const LANES: usize = 8;

/// `values` followed by zeros up to a multiple of LANES.
fn padded(values: &[f64]) -> Vec<f64> {
    let mut out = values.to_vec();
    out.resize(values.len().div_ceil(LANES) * LANES, 0.0);
    out
}

/// sum_k u_k P_m(x_k) for m = 0..degrees (P by `rec`): on 4-wide vectors where the processor has
/// AVX2 (the same operations in the same order, so the same numbers).
fn project(xs: &[f64], u: &[f64], rec: &[[f64; 3]], degrees: usize) -> Vec<f64> {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor has AVX2 (checked just above).
        return unsafe { project_avx2(xs, u, rec, degrees) };
    }
    project_with(xs, u, rec, degrees)
}

/// `project` compiled for AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn project_avx2(xs: &[f64], u: &[f64], rec: &[[f64; 3]], degrees: usize) -> Vec<f64> {
    project_with(xs, u, rec, degrees)
}

#[inline(always)]
fn project_with(xs: &[f64], u: &[f64], rec: &[[f64; 3]], degrees: usize) -> Vec<f64> {
    let (xs, u) = (padded(xs), padded(u));
    // P_{m-1} and P_m at the points; each step overwrites P_{m-1} by P_{m+1} and swaps
    let (mut older, mut newer) = (vec![0.0; xs.len()], vec![1.0; xs.len()]);
    let mut out = Vec::with_capacity(degrees);
    out.push(u.iter().sum());
    for &[a, b, c] in &rec[..degrees - 1] {
        for ((p, q), x) in older.iter_mut().zip(&newer).zip(&xs) {
            *p = (a * x + b) * q - c * *p;
        }
        std::mem::swap(&mut older, &mut newer);
        let mut sums = [0.0; LANES];
        for (p, u) in newer.chunks_exact(LANES).zip(u.chunks_exact(LANES)) {
            for k in 0..LANES {
                sums[k] += u[k] * p[k];
            }
        }
        out.push(sums.iter().sum());
    }
    out
}

/// sum_m coefficients_m P_m(x) at each x (P by `rec`), on 4-wide vectors where the processor
/// has AVX2 (as `project`).
fn evaluate(xs: &[f64], rec: &[[f64; 3]], coefficients: &[f64]) -> Vec<f64> {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor has AVX2 (checked just above).
        return unsafe { evaluate_avx2(xs, rec, coefficients) };
    }
    evaluate_with(xs, rec, coefficients)
}

/// `evaluate` compiled for AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn evaluate_avx2(xs: &[f64], rec: &[[f64; 3]], coefficients: &[f64]) -> Vec<f64> {
    evaluate_with(xs, rec, coefficients)
}

#[inline(always)]
fn evaluate_with(xs: &[f64], rec: &[[f64; 3]], coefficients: &[f64]) -> Vec<f64> {
    let (mut older, mut newer) = (vec![0.0; xs.len()], vec![1.0; xs.len()]);
    let mut out = vec![coefficients[0]; xs.len()];
    for (&[a, b, c], &w) in rec.iter().zip(&coefficients[1..]) {
        for (((p, q), x), o) in older.iter_mut().zip(&newer).zip(xs).zip(out.iter_mut()) {
            *p = (a * x + b) * q - c * *p;
            *o += w * *p;
        }
        std::mem::swap(&mut older, &mut newer);
    }
    out
}

/// The Jacobi polynomials of one rule pair (N nodes, N + 1 collocation points, theta).
#[derive(Debug, PartialEq)]
pub struct Spectral {
    /// cos(pi theta).
    cos: f64,
    /// P_n^(alpha,beta), n < N.
    node_rec: Vec<[f64; 3]>,
    /// P_m^(-alpha,-beta), m <= N.
    point_rec: Vec<[f64; 3]>,
    /// 1/h'_m = 1/int (1 - x)^-alpha (1 + x)^-beta P_m^(-alpha,-beta)^2, m <= N; h_n = 4 h'_{n+1}
    /// is P_n^(alpha,beta)'s (DLMF 18.3, table 18.3.1, with alpha + beta = 1).
    inv_point_norms: Vec<f64>,
    /// Gauss weights lambda_k of the collocation points for (1 - x)^-alpha (1 + x)^-beta.
    christoffel: Vec<f64>,
}

impl Spectral {
    /// The tables at theta for n nodes and the n + 1 collocation points `points`.
    pub fn new(theta: f64, n: usize, points: &[f64]) -> Spectral {
        let (alpha, beta) = (0.5 + theta, 0.5 - theta);
        let cos = (std::f64::consts::PI * theta).cos();
        // h'_0 = Gamma(1 - alpha) Gamma(1 - beta) = pi/cos(pi theta); h'_{m+1}/h'_m =
        // (m + 1 - alpha)(m + 1 - beta)/(m + 1)^2 for m >= 1, h'_1 = (1 - alpha)(1 - beta) h'_0/2
        let mut norm = std::f64::consts::PI / cos;
        let inv_point_norms: Vec<f64> = (0..=n)
            .map(|m| {
                let inv = 1.0 / norm;
                let next = m as f64 + 1.0;
                norm *=
                    (next - alpha) * (next - beta) / (next * next) * if m == 0 { 0.5 } else { 1.0 };
                inv
            })
            .collect();
        let point_rec = recurrence(n, -alpha, -beta);
        // Christoffel numbers: 1/lambda_k = sum_m P_m(xi_k)^2/h'_m (Szegő 3.4.8)
        let (mut prev, mut cur) = (vec![0.0; points.len()], vec![1.0; points.len()]);
        let mut sums = vec![inv_point_norms[0]; points.len()];
        for (&[a, b, c], inv) in point_rec.iter().zip(&inv_point_norms[1..]) {
            for (((p, q), x), s) in prev
                .iter_mut()
                .zip(cur.iter_mut())
                .zip(points)
                .zip(sums.iter_mut())
            {
                let next = (a * x + b) * *q - c * *p;
                (*p, *q) = (*q, next);
                *s += inv * next * next;
            }
        }
        Spectral {
            cos,
            node_rec: recurrence(n.saturating_sub(1), alpha, beta),
            point_rec,
            inv_point_norms,
            christoffel: sums.iter().map(|s| 1.0 / s).collect(),
        }
    }

    /// The coefficients c_m, m <= N, of the polynomial of degree N through f at the points.
    pub fn analyse(&self, points: &[f64], f: &[f64]) -> Vec<f64> {
        let u: Vec<f64> = f
            .iter()
            .zip(&self.christoffel)
            .map(|(f, l)| f * l)
            .collect();
        let mut c = project(points, &u, &self.point_rec, points.len());
        c.iter_mut()
            .zip(&self.inv_point_norms)
            .for_each(|(c, inv)| *c *= inv);
        c
    }

    /// The coefficients in P_n^(alpha,beta), n < N, of the polynomial g with v_i = W_i g(t_i).
    pub fn node_coefficients(&self, nodes: &[f64], v: &[f64]) -> Vec<f64> {
        let mut a = project(nodes, v, &self.node_rec, nodes.len());
        // 1/h_n = 1/(4 h'_{n+1})
        a.iter_mut()
            .zip(&self.inv_point_norms[1..])
            .for_each(|(a, inv)| *a *= 0.25 * inv);
        a
    }

    /// sum_m coefficients_m P_m^(-alpha,-beta) at the points.
    pub fn at_points(&self, points: &[f64], coefficients: &[f64]) -> Vec<f64> {
        evaluate(points, &self.point_rec, coefficients)
    }

    /// sum_n coefficients_n P_n^(alpha,beta) at the nodes.
    pub fn at_nodes(&self, nodes: &[f64], coefficients: &[f64]) -> Vec<f64> {
        evaluate(nodes, &self.node_rec, coefficients)
    }

    /// -cos(pi theta)/2: the coefficient of P_n^(alpha,beta) in C^-1 f per unit coefficient of
    /// P_{n+1}^(-alpha,-beta) in f.
    pub fn cauchy_inverse_factor(&self) -> f64 {
        -0.5 * self.cos
    }
}

#[cfg(test)]
mod tests {
    use crate::physics::plane::strip::collocation::Rules;
    use crate::physics::quadrature::gauss_jacobi;

    #[test]
    fn christoffel_numbers_are_the_gauss_weights_of_the_collocation_points() {
        // independent route: Szegő's (15.3.5) weights of `gauss_jacobi` for (1-x)^-alpha (1+x)^-beta
        for (theta, n) in [(0.1, 8), (-0.3, 64), (0.4, 272)] {
            let rules = Rules::cached(theta, n);
            let gauss = gauss_jacobi(n + 1, -0.5 - theta, -0.5 + theta);
            let worst = (rules.spectral().christoffel.iter())
                .zip(&gauss.weights)
                .fold(0.0, |w: f64, (a, b)| w.max((a - b).abs() / b));
            // both rounded: (15.3.5) through P'(x)^2 at rounded zeros, ours through N sums of
            // squares (measured 1.8e-11 at theta = 0.4, N = 272)
            assert!(worst < 1e-10, "theta {theta}, n {n}: {worst:e}");
        }
    }
}
