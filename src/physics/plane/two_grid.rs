//! A two-grid solve of the strip's collocation system (`collocation`) at an operating point,
//! instead of factoring the fine matrix (O(N^3)): refinement from the coarse search's factors for
//! the smooth part of the solution and the exact inverse of the Cauchy part for the rest, O(N^2)
//! a step.
//!
//! The dominant (Cauchy) part of the scaled system, C y with C_ki = 1/(pi (t_i - xi_k)) for the
//! unknowns v_i = W_i g(t_i) (g a polynomial of degree < N) and C_kN = 1/pi for v_N, is diagonal
//! in Jacobi polynomials (alpha = 1/2 + theta, beta = 1/2 - theta, alpha + beta = 1): by the
//! spectral relation of Erdogan, Gupta & Cook (in G. C. Sih, ed., Methods of Analysis and
//! Solutions of Crack Problems, Noordhoff 1973, ch. 7, eq. 7.36 with kappa = -1),
//!   tan(pi theta) w P_n^(alpha,beta)(x) + (1/pi) p.v. int w P_n^(alpha,beta)/(t - x) dt
//!     = -(2/cos(pi theta)) P_{n+1}^(-alpha,-beta)(x),
//! which the Gauss sum (1/pi) sum_i W_i P_n(t_i)/(t_i - xi_k) gives exactly at the collocation
//! points (plane.md section 6), and the constant column is P_0^(-alpha,-beta)/pi. So a right side
//! f at the N + 1 points xi_k (the nodes of the Gauss rule for (1 - x)^-alpha (1 + x)^-beta) has
//! the coefficients c_m = sum_k lambda_k f_k P_m(xi_k)/h'_m in P_m^(-alpha,-beta), m <= N, and
//! C^-1 f has v_N = pi c_0 and g = sum_n -(cos(pi theta)/2) c_{n+1} P_n^(alpha,beta).
//!
//! The regular kernel (L/(2h)) K((L/2)(t - xi)/h) varies on the scale h and acts on the low
//! modes; on modes much shorter than h it is exponentially small (the strip's transfer functions
//! tend to the half-plane's). The preconditioner therefore splits a residual by degree: the
//! degrees the coarse system carries (N_c + 1 of them, N_c about N/2) go through the coarse
//! factors (values at the coarse points, coarse solve, coefficients of its g), the higher ones
//! through C^-1. Refinement with it (`strip_factors::refine`) contracts by 1e-3 to 1e-6 a step in
//! the cases tested; where it does not converge the caller factors the fine matrix.

use std::sync::Arc;

use nalgebra::DVector;

use crate::physics::plane::collocation::Rules;
use crate::physics::plane::strip_factors::Factors;
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
    fn analyse(&self, points: &[f64], f: &[f64]) -> Vec<f64> {
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
    fn node_coefficients(&self, nodes: &[f64], v: &[f64]) -> Vec<f64> {
        let mut a = project(nodes, v, &self.node_rec, nodes.len());
        // 1/h_n = 1/(4 h'_{n+1})
        a.iter_mut()
            .zip(&self.inv_point_norms[1..])
            .for_each(|(a, inv)| *a *= 0.25 * inv);
        a
    }
}

/// The coarse search's factorization, lent to the fine system of an operating point.
pub struct Coarse {
    factors: Factors,
    rules: Arc<Rules>,
    /// The factored matrix's row scales (1/largest entry of each row).
    scale: Vec<f64>,
}

impl Coarse {
    /// Factors of the coarse system with these rules, whose rows were scaled by `scale`.
    pub fn new(factors: Factors, rules: Arc<Rules>, scale: Vec<f64>) -> Coarse {
        Coarse {
            factors,
            rules,
            scale,
        }
    }

    /// An approximate solution z of A z = r for the fine system with rules `fine` whose rows
    /// were scaled by `scale` (module note); None when the coarse solve is not finite.
    pub fn precondition(
        &self,
        fine: &Rules,
        scale: &[f64],
        r: &DVector<f64>,
    ) -> Option<DVector<f64>> {
        let nc = self.rules.len();
        let (spectral, coarse) = (fine.spectral(), self.rules.spectral());
        let f: Vec<f64> = r.iter().zip(scale).map(|(r, s)| r / s).collect();
        let c = spectral.analyse(fine.points(), &f);
        let low = evaluate(self.rules.points(), &coarse.point_rec, &c[..=nc]);
        let g = DVector::from_iterator(nc + 1, low.iter().zip(&self.scale).map(|(f, s)| f * s));
        let y = self.factors.solve(&g)?;
        let mut a = coarse.node_coefficients(self.rules.nodes(), &y.as_slice()[..nc]);
        a.extend(c[nc + 1..].iter().map(|c| -0.5 * spectral.cos * c));
        let g = evaluate(fine.nodes(), &spectral.node_rec, &a);
        let mut z: Vec<f64> = g.iter().zip(fine.weights()).map(|(g, w)| g * w).collect();
        z.push(y[nc]);
        Some(DVector::from_vec(z))
    }
}

/// C^-1 f (module note) for the rules' Cauchy part alone.
#[cfg(test)]
pub fn cauchy_inverse(rules: &Rules, f: &[f64]) -> Vec<f64> {
    let spectral = rules.spectral();
    let c = spectral.analyse(rules.points(), f);
    let a: Vec<f64> = c[1..].iter().map(|c| -0.5 * spectral.cos * c).collect();
    let g = evaluate(rules.nodes(), &spectral.node_rec, &a);
    let mut z: Vec<f64> = g.iter().zip(rules.weights()).map(|(g, w)| g * w).collect();
    z.push(std::f64::consts::PI * c[0]);
    z
}

#[cfg(test)]
mod tests {
    use std::rc::Rc;

    use nalgebra::DMatrix;

    use super::*;
    use crate::physics::plane::collocation::{Collocation, System};
    use crate::physics::plane::strip::{Kernels, kernels_for};
    use crate::physics::plane::{PlaneInputs, exponent};
    use crate::physics::quadrature::gauss_jacobi;
    use crate::physics::{Friction, Material};

    /// Entries in [-1, 1] from a fixed linear congruential sequence (Knuth's MMIX constants).
    fn scrambled(n: usize, seed: u64) -> Vec<f64> {
        let mut state = seed;
        (0..n)
            .map(|_| {
                state = state
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
            })
            .collect()
    }

    #[test]
    fn the_spectral_inverse_undoes_the_assembled_cauchy_matrix() {
        // independent route: the Cauchy part built entry by entry as `System::assemble` does,
        // C_ki = 1/(pi (t_i - xi_k)), C_kN = 1/pi; C^-1 from the Jacobi relation must undo it
        for (theta, n) in [
            (0.0, 5),
            (0.2, 16),
            (-0.35, 33),
            (0.45, 130),
            (-0.45, 130),
            (-0.1, 401),
            (0.1, 1008),
        ] {
            let rules = Rules::cached(theta, n);
            let c = DMatrix::from_fn(n + 1, n + 1, |k, i| {
                let xi = rules.points()[k];
                std::f64::consts::FRAC_1_PI / if i < n { rules.nodes()[i] - xi } else { 1.0 }
            });
            let y = DVector::from_vec(scrambled(n + 1, n as u64));
            let z = cauchy_inverse(&rules, (&c * &y).as_slice());
            let error = (DVector::from_vec(z) - &y).amax();
            // the relation is exact at the exact zeros; the rounded ones, 1/N^2 apart near the
            // ends, leave entries off by some eps N^2 relative (measured 2e-9 at N = 130 with
            // |theta| = 0.45, 2e-8 at N = 1008), which a wrong factor or sign would exceed by far
            let bound = 2e-13 * (n * n) as f64;
            assert!(error < bound * y.amax(), "theta {theta}, n {n}: {error:e}");
        }
    }

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

    fn inputs(nu: f64, km: f64, tau0: f64) -> PlaneInputs {
        let m = crate::physics::elastic::plane_modulus(1e10, nu);
        PlaneInputs {
            material: Material {
                youngs_modulus: 1e10,
                poisson_ratio: nu,
                thickness: 1e-5,
            },
            friction: Friction {
                coefficient: 0.3,
                adhesion: tau0,
            },
            wear: km / m,
            radius: 0.05,
            load: 1.0,
        }
    }

    /// The collocation at l by two-grid refinement with the factors of a coarse system of nc
    /// nodes solved at `coarse_l`, whether that system factored its own matrix after all, and
    /// the collocation by a factorization of the fine matrix.
    fn both(
        inp: &PlaneInputs,
        l: f64,
        n: usize,
        (coarse_l, nc): (f64, usize),
    ) -> (Collocation, bool, Collocation) {
        let kernels = kernels_for(inp.material.poisson_ratio);
        let regular = Rc::new(kernels.regular_columns(inp.friction.coefficient));
        let theta = exponent(inp).2;
        let system = |n| {
            System::new(
                inp,
                kernels.as_ref(),
                &regular,
                Rules::cached(theta, n),
                1e-14,
            )
        };
        let mut coarse = system(nc);
        coarse.at(coarse_l).unwrap();
        let mut fine = system(n);
        fine.set_coarse(Rc::new(coarse.into_coarse().unwrap()));
        let ours = fine.at(l).unwrap();
        (ours, fine.factored(), system(n).at(l).unwrap())
    }

    /// The largest difference in phi, relative to the largest phi.
    fn phi_off(ours: &Collocation, direct: &Collocation) -> f64 {
        let worst = ours
            .phi
            .iter()
            .zip(&direct.phi)
            .fold(0.0, |w: f64, (a, b)| w.max((a - b).abs()));
        worst / direct.phi.iter().fold(0.0, |m: f64, p| m.max(p.abs()))
    }

    #[test]
    fn two_grid_refinement_solves_as_the_factorization() {
        // (nu, k m, tau0, L/h, N, N_c) at the node counts the width search uses, coarse
        // factors from a width 1e-3 narrower (the coarse search's P is within 1e-3)
        for (nu, km, tau0, lh, n, nc) in [
            (0.3, 0.5, 0.0, 10.0, 80, 40),
            (0.45, 0.0, 1e6, 30.0, 160, 80),
            (0.3, 5.0, 0.0, 56.0, 272, 128),
            (0.499, 0.5, 1e6, 86.0, 400, 192),
        ] {
            let (inp, l) = (inputs(nu, km, tau0), lh * 1e-5);
            let (ours, factored, direct) = both(&inp, l, n, (l * (1.0 - 1e-3), nc));
            assert!(!factored, "L/h {lh}: fell back");
            // LU's own rounding: 2.8e-12 with strong wear (k m = 5)
            assert!(phi_off(&ours, &direct) < 1e-11, "L/h {lh}: phi");
            assert!((ours.c - direct.c).abs() < 1e-12 * l, "L/h {lh}: c");
            assert!(
                (ours.load - direct.load).abs() < 1e-13 * direct.load,
                "L/h {lh}: P"
            );
        }
    }

    #[test]
    fn falls_back_to_a_factorization_where_the_coarse_factors_are_too_far_off() {
        // coarse factors of a contact four times narrower: its kernel's scale h is off by 4 in
        // the low modes, the refinement does not contract, the fine matrix is factored
        let (inp, l) = (inputs(0.3, 0.5, 0.0), 60e-5);
        let (ours, factored, direct) = both(&inp, l, 288, (0.25 * l, 144));
        assert!(factored);
        assert!(phi_off(&ours, &direct) < 1e-14);
        assert_eq!(ours.load, direct.load);
    }
}
