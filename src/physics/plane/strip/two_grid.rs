//! A two-grid solve of the strip's collocation system (`collocation`) at an operating point,
//! instead of factoring the fine matrix (O(N^3)): refinement from the coarse search's factors for
//! the smooth part of the solution and the exact inverse of the Cauchy part for the rest, O(N^2)
//! a step.
//!
//! The dominant (Cauchy) part of the scaled system, C_ki = 1/(pi (t_i - xi_k)) and the constant
//! column 1/pi, is diagonal in Jacobi polynomials (`jacobi_transforms`: P_n^(alpha,beta) of the
//! unknowns' g to P_{n+1}^(-alpha,-beta) of the right side, the constant column to P_0), so its
//! inverse is two polynomial transforms and a scaling.
//!
//! The regular kernel (L/(2h)) K((L/2)(t - xi)/h) varies on the scale h and acts on the low
//! modes; on modes much shorter than h it is exponentially small (the strip's transfer functions
//! tend to the half-plane's). The preconditioner therefore splits a residual by degree: the
//! degrees the coarse system carries (N_c + 1 of them, N_c about N/2) go through the coarse
//! factors (values at the coarse points, coarse solve, coefficients of its g), the higher ones
//! through C^-1. Refinement with it (`factors::refine`) contracts the error by about 1e-3 a
//! step at (a+b)/h = 86 (6, 3 and 1 steps at the width search's three widths; at most 10 at a
//! width over nu = 0.3-0.499, k m = 0-5, tau0 = 0-1 MPa); where it does not converge (seen on a
//! nearly incompressible layer without friction) the caller factors the fine matrix.

use std::sync::Arc;

use nalgebra::DVector;

use crate::physics::plane::strip::factors::Factors;
use crate::physics::plane::strip::rules::Rules;

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
    /// were scaled by `scale` (module note); None when the coarse solve is not finite, or the
    /// coarse system does not have fewer nodes than the fine one or another theta.
    pub fn precondition(
        &self,
        fine: &Rules,
        scale: &[f64],
        r: &DVector<f64>,
    ) -> Option<DVector<f64>> {
        let nc = self.rules.len();
        if nc >= fine.len() || self.rules.theta().to_bits() != fine.theta().to_bits() {
            return None;
        }
        let (spectral, coarse) = (fine.spectral(), self.rules.spectral());
        let f: Vec<f64> = r.iter().zip(scale).map(|(r, s)| r / s).collect();
        let c = spectral.analyse(fine.points(), &f);
        let low = coarse.at_points(self.rules.points(), &c[..=nc]);
        let g = DVector::from_iterator(nc + 1, low.iter().zip(&self.scale).map(|(f, s)| f * s));
        let y = self.factors.solve(&g)?;
        let mut a = coarse.node_coefficients(self.rules.nodes(), &y.as_slice()[..nc]);
        a.extend(
            c[nc + 1..]
                .iter()
                .map(|c| spectral.cauchy_inverse_factor() * c),
        );
        let g = spectral.at_nodes(fine.nodes(), &a);
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
    let a: Vec<f64> = (c[1..].iter())
        .map(|c| spectral.cauchy_inverse_factor() * c)
        .collect();
    let g = spectral.at_nodes(rules.nodes(), &a);
    let mut z: Vec<f64> = g.iter().zip(rules.weights()).map(|(g, w)| g * w).collect();
    z.push(std::f64::consts::PI * c[0]);
    z
}

#[cfg(test)]
mod tests {
    use std::rc::Rc;

    use nalgebra::DMatrix;

    use super::*;
    use crate::physics::plane::strip::collocation::{Collocation, System};
    use crate::physics::plane::strip::{Kernels, kernels_for};
    use crate::physics::plane::{PlaneInputs, exponent};
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
            shear_strength: f64::INFINITY,
            wear: crate::physics::plane::WearLaw::linear(km / m),
            shape: crate::physics::plane::Shape::Parabola { radius: 0.05 },
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
        // coarse factors with more nodes than the fine system: refused, factored
        let (_, factored, _) = both(&inp, l, 64, (l, 80));
        assert!(factored);
    }
}
