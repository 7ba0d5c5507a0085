//! Gauss rules on [-1, 1] with the Jacobi weight (1 - t)^alpha (1 + t)^beta.
//!
//! Nodes: Newton's method on P_n^(alpha,beta), evaluated with its derivative by the three-term
//! recurrence (DLMF 18.9.1 with the Jacobi coefficients of 18.9.2, and the same recurrence
//! differentiated in x), from the leading-order asymptotic starts
//! theta_k = (k + alpha/2 - 1/4) pi/(n + (alpha + beta + 1)/2), x_k = cos theta_k, each Newton step
//! deflated by the zeros already found so that no zero is found twice: O(n^2) work, no matrix.
//! Weights: the Christoffel numbers of Szegő (15.3.5),
//!   w_k = 2^(alpha+beta+1) Gamma(n+alpha+1) Gamma(n+beta+1) / (Gamma(n+alpha+beta+1) n!)
//!         / ((1 - x_k^2) P_n'(x_k)^2).
//! Not the `gauss-quad` crate: its Jacobi rule sets the middle node of every odd-degree rule to 0,
//! which is right only when alpha = beta, and the contact solvers need alpha != beta.

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

    /// Barycentric interpolation weights of the nodes of a Gauss–Jacobi rule, up to a common
    /// factor: 1/prod_{k != j}(t_j - t_k) is proportional to 1/P_n'(t_j), and by Szegő (15.3.5)
    /// 1/P_n'(t_j)^2 is proportional to (1 - t_j^2) w_j; the signs alternate along the nodes.
    pub fn barycentric_weights(&self) -> Vec<f64> {
        self.nodes
            .iter()
            .zip(&self.weights)
            .enumerate()
            .map(|(j, (t, w))| {
                let magnitude = ((1.0 - t) * (1.0 + t) * w).sqrt();
                if j % 2 == 0 { magnitude } else { -magnitude }
            })
            .collect()
    }
}

/// P_k^(alpha,beta) = (a_k x + b_k) P_{k-1} - c_k P_{k-2} for k = 1..=n (DLMF 18.9.1, with the
/// coefficients of 18.9.2 at degree k - 1; P_1 = (alpha - beta)/2 + (alpha + beta + 2) x/2).
struct Recurrence {
    abc: Vec<[f64; 3]>,
}

/// The coefficients [a_k, b_k, c_k], k = 1..=n, of `Recurrence`.
pub(crate) fn jacobi_recurrence(n: usize, alpha: f64, beta: f64) -> Vec<[f64; 3]> {
    let ab = alpha + beta;
    (1..=n)
        .map(|k| {
            if k == 1 {
                return [0.5 * (ab + 2.0), 0.5 * (alpha - beta), 0.0];
            }
            let k = k as f64;
            let c = 2.0 * k + ab;
            let den = 2.0 * k * (k + ab) * (c - 2.0);
            [
                (c - 1.0) * c * (c - 2.0) / den,
                (c - 1.0) * (alpha * alpha - beta * beta) / den,
                2.0 * (k + alpha - 1.0) * (k + beta - 1.0) * c / den,
            ]
        })
        .collect()
}

impl Recurrence {
    fn new(n: usize, alpha: f64, beta: f64) -> Recurrence {
        Recurrence {
            abc: jacobi_recurrence(n, alpha, beta),
        }
    }

    /// P_n(x) and P_n'(x), the derivative by the recurrence differentiated in x.
    fn eval(&self, x: f64) -> (f64, f64) {
        let (mut p0, mut p1, mut d0, mut d1) = (0.0, 1.0, 0.0, 0.0);
        for &[a, b, c] in &self.abc {
            let t = a * x + b;
            let p = t * p1 - c * p0;
            let d = a * p1 + t * d1 - c * d0;
            (p0, p1, d0, d1) = (p1, p, d1, d);
        }
        (p1, d1)
    }

    /// The n zeros, increasing: Newton from the asymptotic starts, which lie within 4% of a
    /// spacing of their zeros for alpha, beta in (-1, 1) and n up to 400 (measured); should two
    /// ever land on one zero, again with each step deflated by the zeros already found.
    fn zeros(&self, alpha: f64, beta: f64) -> Vec<f64> {
        let plain = self.newton(alpha, beta, false);
        if plain.windows(2).all(|w| w[0] > w[1]) {
            plain.into_iter().rev().collect()
        } else {
            let mut deflated = self.newton(alpha, beta, true);
            deflated.sort_by(f64::total_cmp);
            deflated
        }
    }

    /// Newton's method for each zero from its asymptotic start, largest first; with `deflate`,
    /// on P_n / prod (x - zeros found), so that no zero can be found twice.
    fn newton(&self, alpha: f64, beta: f64, deflate: bool) -> Vec<f64> {
        const NEWTON_STEPS: usize = 100;
        let n = self.abc.len();
        let rho = n as f64 + 0.5 * (alpha + beta + 1.0);
        let mut zeros: Vec<f64> = Vec::with_capacity(n);
        for k in 1..=n {
            let mut x = ((k as f64 + 0.5 * alpha - 0.25) * std::f64::consts::PI / rho).cos();
            for _ in 0..NEWTON_STEPS {
                let (p, dp) = self.eval(x);
                let deflation: f64 = if deflate {
                    zeros.iter().map(|z| 1.0 / (x - z)).sum()
                } else {
                    0.0
                };
                let step = p / (dp - p * deflation);
                if !step.is_finite() {
                    break;
                }
                x -= step;
                if step.abs() <= 2.0 * f64::EPSILON {
                    break;
                }
            }
            zeros.push(x);
        }
        zeros
    }
}

/// The n zeros of P_n^(alpha, beta), increasing; alpha, beta > -1, n >= 1.
pub fn jacobi_zeros(n: usize, alpha: f64, beta: f64) -> Vec<f64> {
    Recurrence::new(n, alpha, beta).zeros(alpha, beta)
}

/// Gauss–Jacobi rule of n points for the weight (1 - t)^alpha (1 + t)^beta, alpha, beta > -1.
/// The weights are Szegő's (15.3.5) up to their common factor, which is fixed by their sum: a
/// Gauss rule integrates 1 exactly, to mu0 = 2^(alpha+beta+1) Gamma(alpha+1) Gamma(beta+1) /
/// Gamma(alpha+beta+2) (the Gamma functions of degree n in (15.3.5) lose 1e-12 to rounding at
/// n = 400; these do not).
pub fn gauss_jacobi(n: usize, alpha: f64, beta: f64) -> GaussRule {
    let recurrence = Recurrence::new(n, alpha, beta);
    let nodes = recurrence.zeros(alpha, beta);
    let mut weights: Vec<f64> = nodes
        .iter()
        .map(|&x| {
            let (_, dp) = recurrence.eval(x);
            1.0 / ((1.0 - x) * (1.0 + x) * dp * dp)
        })
        .collect();
    let mu0 = ((alpha + beta + 1.0) * std::f64::consts::LN_2
        + libm::lgamma(alpha + 1.0)
        + libm::lgamma(beta + 1.0)
        - libm::lgamma(alpha + beta + 2.0))
    .exp();
    let scale = mu0 / weights.iter().sum::<f64>();
    weights.iter_mut().for_each(|w| *w *= scale);
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
            let recurrence = Recurrence::new(n, a, b);
            for &x in &rule.nodes {
                assert!(recurrence.eval(x).0.abs() < 1e-9);
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
        let recurrence = Recurrence::new(30, a, b);
        for x in z {
            let (p, dp) = recurrence.eval(x);
            assert!((p / dp).abs() < 1e-14);
        }
    }

    /// Golub–Welsch: the zeros as eigenvalues of the symmetric Jacobi matrix (an independent
    /// route, O(n^3)).
    fn eigenvalue_zeros(n: usize, alpha: f64, beta: f64) -> Vec<f64> {
        let ab = alpha + beta;
        let mut jac = nalgebra::DMatrix::<f64>::zeros(n, n);
        for k in 0..n {
            let c = 2.0 * k as f64 + ab;
            jac[(k, k)] = if k == 0 {
                (beta - alpha) / (ab + 2.0)
            } else {
                (beta * beta - alpha * alpha) / (c * (c + 2.0))
            };
            if k >= 1 {
                let kf = k as f64;
                let off = if k == 1 {
                    4.0 * (1.0 + alpha) * (1.0 + beta) / ((2.0 + ab) * (2.0 + ab) * (3.0 + ab))
                } else {
                    4.0 * kf * (kf + alpha) * (kf + beta) * (kf + ab)
                        / (c * c * (c + 1.0) * (c - 1.0))
                };
                jac[(k, k - 1)] = off.sqrt();
                jac[(k - 1, k)] = off.sqrt();
            }
        }
        let mut z: Vec<f64> = jac.symmetric_eigenvalues().iter().copied().collect();
        z.sort_by(f64::total_cmp);
        z
    }

    #[test]
    fn newton_zeros_agree_with_the_eigenvalues_of_the_jacobi_matrix() {
        // the exponents of the strip solver's nodes and collocation points over theta's range
        for theta in [-0.49, -0.3, 0.0, 0.1, 0.45, 0.499] {
            for (alpha, beta) in [(0.5 + theta, 0.5 - theta), (-0.5 - theta, -0.5 + theta)] {
                for n in [1, 2, 3, 10, 41, 97, 160] {
                    let newton = jacobi_zeros(n, alpha, beta);
                    let eigen = eigenvalue_zeros(n, alpha, beta);
                    assert!(newton.windows(2).all(|w| w[0] < w[1]) && newton[0] > -1.0);
                    let worst = newton
                        .iter()
                        .zip(&eigen)
                        .map(|(a, b)| (a - b).abs())
                        .fold(0.0, f64::max);
                    assert!(worst < 1e-13, "theta={theta} n={n}: {worst:e}");
                }
            }
        }
    }

    #[test]
    fn deflated_newton_finds_the_same_zeros() {
        // the fallback when two plain Newton runs meet: each zero found once, whatever the start
        for (n, alpha, beta) in [(7, 0.7, 0.3), (60, -0.9, -0.1), (200, 0.95, 0.05)] {
            let recurrence = Recurrence::new(n, alpha, beta);
            let mut deflated = recurrence.newton(alpha, beta, true);
            deflated.sort_by(f64::total_cmp);
            let plain = jacobi_zeros(n, alpha, beta);
            let worst = deflated
                .iter()
                .zip(&plain)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            assert!(worst < 1e-14, "n={n}: {worst:e}");
        }
    }

    #[test]
    fn barycentric_weights_interpolate_polynomials() {
        let rule = gauss_jacobi(25, 0.8, 0.2);
        let bary = rule.barycentric_weights();
        let f = |t: f64| 3.0 * t.powi(24) - t.powi(7) + 0.5;
        for x in [-0.999, -0.3, 0.123, 0.98] {
            let (mut num, mut den) = (0.0, 0.0);
            for (j, t) in rule.nodes.iter().enumerate() {
                num += bary[j] / (x - t) * f(*t);
                den += bary[j] / (x - t);
            }
            assert!((num / den - f(x)).abs() < 1e-13, "{x}");
        }
    }
}
