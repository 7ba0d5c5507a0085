//! Gauss rules on [-1, 1] with the Jacobi weight (1 - t)^alpha (1 + t)^beta.
//!
//! Golub–Welsch (eigenvalues of the Jacobi matrix, nalgebra) for first guesses, Newton polish on
//! the three-term recurrence (DLMF 18.9.2), and the Christoffel weights (DLMF 18.2.?/Szegő 15.3.5).
//! Not the `gauss-quad` crate: its Jacobi rule sets the middle node of every odd-degree rule to 0,
//! which is right only when alpha = beta, and the contact solvers need alpha != beta.

use nalgebra::{DMatrix, SymmetricEigen};

/// Nodes and weights of a Gauss rule on [-1, 1].
#[derive(Clone, Debug, PartialEq)]
pub struct GaussRule {
    /// Nodes in increasing order.
    pub nodes: Vec<f64>,
    /// Weights (including the Jacobi weight function).
    pub weights: Vec<f64>,
}

impl GaussRule {
    /// Integral over [lo, hi] of weight * f, the rule mapped linearly onto [lo, hi]
    /// (the weight is that of the rule, in the mapped variable).
    pub fn integrate(&self, lo: f64, hi: f64, mut f: impl FnMut(f64) -> f64) -> f64 {
        let half = 0.5 * (hi - lo);
        let mid = 0.5 * (hi + lo);
        half * self
            .nodes
            .iter()
            .zip(&self.weights)
            .map(|(t, w)| w * f(mid + half * t))
            .sum::<f64>()
    }
}

/// P_n^(alpha,beta)(x) and P_{n-1}^(alpha,beta)(x) by the three-term recurrence (n >= 1).
fn jacobi_pair(n: usize, alpha: f64, beta: f64, x: f64) -> (f64, f64) {
    let ab = alpha + beta;
    let mut prev = 1.0;
    let mut cur = 0.5 * (alpha - beta + (ab + 2.0) * x);
    for k in 2..=n {
        let k = k as f64;
        let c = 2.0 * k + ab;
        let a1 = 2.0 * k * (k + ab) * (c - 2.0);
        let a2 = (c - 1.0) * (c * (c - 2.0) * x + alpha * alpha - beta * beta);
        let a3 = 2.0 * (k + alpha - 1.0) * (k + beta - 1.0) * c;
        let next = (a2 * cur - a3 * prev) / a1;
        prev = cur;
        cur = next;
    }
    (cur, prev)
}

/// P_n(x) and its derivative, from (2n+a+b)(1-x^2) P_n' = n[(a-b) - (2n+a+b) x] P_n + 2(n+a)(n+b) P_{n-1}.
fn jacobi_with_derivative(n: usize, alpha: f64, beta: f64, x: f64) -> (f64, f64) {
    let (p, pm) = jacobi_pair(n, alpha, beta, x);
    let nf = n as f64;
    let c = 2.0 * nf + alpha + beta;
    let dp = (nf * ((alpha - beta) - c * x) * p + 2.0 * (nf + alpha) * (nf + beta) * pm)
        / (c * (1.0 - x * x));
    (p, dp)
}

/// The n zeros of P_n^(alpha, beta), increasing; alpha, beta > -1, n >= 1.
pub fn jacobi_zeros(n: usize, alpha: f64, beta: f64) -> Vec<f64> {
    let ab = alpha + beta;
    let diag = |k: usize| {
        if k == 0 {
            (beta - alpha) / (ab + 2.0)
        } else {
            let c = 2.0 * k as f64 + ab;
            (beta * beta - alpha * alpha) / (c * (c + 2.0))
        }
    };
    let off = |k: usize| {
        // between rows k-1 and k, k >= 1
        let kf = k as f64;
        let c = 2.0 * kf + ab;
        if k == 1 {
            (4.0 * (1.0 + alpha) * (1.0 + beta) / ((2.0 + ab) * (2.0 + ab) * (3.0 + ab))).sqrt()
        } else {
            (4.0 * kf * (kf + alpha) * (kf + beta) * (kf + ab) / (c * c * (c + 1.0) * (c - 1.0)))
                .sqrt()
        }
    };
    let mut jac = DMatrix::<f64>::zeros(n, n);
    for k in 0..n {
        jac[(k, k)] = diag(k);
        if k >= 1 {
            jac[(k, k - 1)] = off(k);
            jac[(k - 1, k)] = off(k);
        }
    }
    let mut nodes: Vec<f64> = SymmetricEigen::new(jac)
        .eigenvalues
        .iter()
        .copied()
        .collect();
    nodes.sort_by(f64::total_cmp);
    for x in &mut nodes {
        for _ in 0..3 {
            let (p, dp) = jacobi_with_derivative(n, alpha, beta, *x);
            let step = p / dp;
            if step.is_finite() {
                *x -= step;
            }
        }
    }
    nodes
}

/// Gauss–Jacobi rule of n points for the weight (1 - t)^alpha (1 + t)^beta, alpha, beta > -1.
pub fn gauss_jacobi(n: usize, alpha: f64, beta: f64) -> GaussRule {
    let nodes = jacobi_zeros(n, alpha, beta);
    let nf = n as f64;
    let ln_c = (alpha + beta + 1.0) * std::f64::consts::LN_2
        + libm::lgamma(nf + alpha + 1.0)
        + libm::lgamma(nf + beta + 1.0)
        - libm::lgamma(nf + alpha + beta + 1.0)
        - libm::lgamma(nf + 1.0);
    let weights = nodes
        .iter()
        .map(|&x| {
            let (_, dp) = jacobi_with_derivative(n, alpha, beta, x);
            ln_c.exp() / ((1.0 - x * x) * dp * dp)
        })
        .collect();
    GaussRule { nodes, weights }
}

/// Gauss–Legendre rule of n points (weight 1).
pub fn gauss_legendre(n: usize) -> GaussRule {
    gauss_jacobi(n, 0.0, 0.0)
}

/// Tanh–sinh (double-exponential) rule on [-1, 1] with step `h` in the sinh variable: exponential
/// convergence for integrands with algebraic or logarithmic end-point singularities. Nodes closer
/// than 1e-14 to an end are dropped, so a mapped node never lands on the end itself; an integrand
/// that blows up like (1 - t)^-p loses its tail (1e-14)^(1-p)/(1-p), so use it for bounded or
/// logarithmic ends (all the contact integrands are).
pub fn tanh_sinh(h: f64) -> GaussRule {
    let half_pi = std::f64::consts::FRAC_PI_2;
    let mut pairs = vec![(0.0, half_pi)];
    for k in 1.. {
        let u = k as f64 * h;
        let s = half_pi * u.sinh();
        let gap = 2.0 / (1.0 + (2.0 * s).exp()); // 1 - t, computed without cancellation
        if gap < 1e-14 {
            break;
        }
        let c = s.cosh();
        let w = half_pi * u.cosh() / (c * c);
        pairs.push((1.0 - gap, w));
        pairs.push((gap - 1.0, w));
    }
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
    GaussRule {
        nodes: pairs.iter().map(|p| p.0).collect(),
        weights: pairs.iter().map(|p| p.1 * h).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tanh_sinh_handles_end_point_singularities() {
        let rule = tanh_sinh(1.0 / 16.0);
        // integral_{-1}^{1} (1-t)^{0.9} (1+t)^{0.1} dt = 2^2 B(1.9, 1.1) (a pressure with theta = 0.4)
        let exact = 4.0 * (libm::lgamma(1.9) + libm::lgamma(1.1) - libm::lgamma(3.0)).exp();
        let got = rule.integrate(-1.0, 1.0, |t| (1.0 - t).powf(0.9) * (1.0 + t).powf(0.1));
        assert!((got - exact).abs() < 1e-13 * exact, "{got} vs {exact}");
        // integral_0^1 ln x dx = -1
        let got = rule.integrate(0.0, 1.0, f64::ln);
        assert!((got + 1.0).abs() < 1e-12, "{got}");
    }

    #[test]
    fn legendre_integrates_polynomials_exactly() {
        let rule = gauss_legendre(7);
        // integral of x^12 over [-1, 1] = 2/13; degree 2n - 1 = 13 is exact.
        assert!((rule.integrate(-1.0, 1.0, |x| x.powi(12)) - 2.0 / 13.0).abs() < 1e-15);
        assert!((rule.weights.iter().sum::<f64>() - 2.0).abs() < 1e-14);
    }

    #[test]
    fn asymmetric_jacobi_moments_match_the_beta_function() {
        // integral (1-t)^a (1+t)^b t dt over [-1,1] = mu0 (b - a)/(a + b + 2), mu0 = 2^{a+b+1} B(a+1, b+1).
        for n in [1, 2, 5, 8, 9, 40] {
            let (a, b) = (0.5 + 0.2, 0.5 - 0.2);
            let rule = gauss_jacobi(n, a, b);
            let mu0 = 2f64.powf(a + b + 1.0)
                * (libm::lgamma(a + 1.0) + libm::lgamma(b + 1.0) - libm::lgamma(a + b + 2.0)).exp();
            let s0: f64 = rule.weights.iter().sum();
            assert!((s0 - mu0).abs() < 1e-13 * mu0, "n={n}");
            if n > 1 {
                let s1 = rule.integrate(-1.0, 1.0, |t| t);
                assert!((s1 - mu0 * (b - a) / (a + b + 2.0)).abs() < 1e-13, "n={n}");
            }
            for &x in &rule.nodes {
                assert!(jacobi_pair(n, a, b, x).0.abs() < 1e-9);
            }
        }
    }

    #[test]
    fn zeros_with_negative_exponents_summing_to_minus_one() {
        // P_1^(a,b) has its zero at (b - a)/(a + b + 2); the collocation points of the plane solvers
        // use exponents (-1/2 - theta, -1/2 + theta).
        let (a, b) = (-0.5 - 0.3, -0.5 + 0.3);
        let z = jacobi_zeros(1, a, b);
        assert!((z[0] - (b - a) / (a + b + 2.0)).abs() < 1e-15);
        let z = jacobi_zeros(30, a, b);
        assert!(z.windows(2).all(|w| w[0] < w[1]));
        for x in z {
            let (p, dp) = jacobi_with_derivative(30, a, b, x);
            assert!((p / dp).abs() < 1e-14);
        }
    }
}
