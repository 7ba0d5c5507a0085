//! The Gauss–Jacobi rules of the strip's collocation (`collocation`, docs/physics/plane.md section
//! 6): nodes and weights for q2 = w phi, w = (1-t)^(1/2+theta) (1+t)^(1/2-theta), the collocation
//! points (zeros of P_{N+1}^(-1/2-theta, -1/2+theta)), the barycentric weights of the nodes and,
//! when a two-grid solve first asks, the Jacobi polynomial tables (`two_grid`) and, when the
//! general solver first asks, the grid on which it looks for the shear cap's crossings; kept for
//! the last few (theta, N) used.

use std::sync::{Arc, Mutex, OnceLock};

use nalgebra::DMatrix;

use crate::physics::plane::strip::jacobi_transforms::Spectral;
use crate::physics::quadrature::{GaussRule, gauss_jacobi, jacobi_zeros};

/// Rules kept by `Rules::cached`.
const CACHED_RULES: usize = 128;
/// Intervals of the uniform grid on [-1, 1] of `Rules::crossing_grid`.
const CROSSING_SAMPLES: usize = 256;

/// The Gauss–Jacobi nodes and weights and the collocation points for n unknowns at one theta.
#[derive(Debug, PartialEq)]
pub struct Rules {
    theta: f64,
    rule: GaussRule,
    bary: Vec<f64>,
    points: Vec<f64>,
    /// The Jacobi polynomial tables of the two-grid solve, built when first asked for.
    spectral: OnceLock<Spectral>,
    /// The crossing grid's points and its matrix, built when first asked for.
    crossing_grid: OnceLock<(Vec<f64>, DMatrix<f64>)>,
}

impl Rules {
    fn new(theta: f64, n: usize) -> Rules {
        let rule = gauss_jacobi(n, 0.5 + theta, 0.5 - theta);
        Rules {
            theta,
            bary: rule.barycentric_weights(),
            points: jacobi_zeros(n + 1, -0.5 - theta, -0.5 + theta),
            rule,
            spectral: OnceLock::new(),
            crossing_grid: OnceLock::new(),
        }
    }

    /// The rules for theta and n, built once and kept (the last few used).
    pub fn cached(theta: f64, n: usize) -> Arc<Rules> {
        static CACHE: OnceLock<Mutex<Vec<Arc<Rules>>>> = OnceLock::new();
        let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
        let mut list = cache.lock().unwrap_or_else(|p| p.into_inner());
        let hit = list
            .iter()
            .position(|r| r.theta.to_bits() == theta.to_bits() && r.len() == n);
        let rules = match hit {
            Some(i) => list.remove(i),
            None => Arc::new(Rules::new(theta, n)),
        };
        list.insert(0, Arc::clone(&rules));
        list.truncate(CACHED_RULES);
        rules
    }

    /// The number of unknowns phi_i.
    pub fn len(&self) -> usize {
        self.rule.nodes.len()
    }

    /// Never empty (n >= 1); here for clippy's len_without_is_empty.
    pub fn is_empty(&self) -> bool {
        self.rule.nodes.is_empty()
    }

    /// The nodes t_i, increasing.
    pub fn nodes(&self) -> &[f64] {
        &self.rule.nodes
    }

    /// The Gauss–Jacobi weights W_i of the nodes.
    pub fn weights(&self) -> &[f64] {
        &self.rule.weights
    }

    /// The collocation points xi_k, increasing.
    pub fn points(&self) -> &[f64] {
        &self.points
    }

    /// The exponent shift theta.
    pub fn theta(&self) -> f64 {
        self.theta
    }

    /// The barycentric weights of the nodes.
    pub fn bary(&self) -> &[f64] {
        &self.bary
    }

    /// phi at t by barycentric interpolation through the nodes, from `bary_phi` (the barycentric
    /// weight times phi at each node) and `phi`; four independent sums, so that the loop
    /// vectorizes (the profiles, the energy check and the general solver's integrals call it
    /// some 10^5 times).
    pub fn interpolate(&self, bary_phi: &[f64], phi: &[f64], t: f64) -> f64 {
        let (mut num, mut den) = ([0.0; 4], [0.0; 4]);
        let nodes = self.nodes().chunks_exact(4);
        let bary = self.bary.chunks_exact(4);
        let bary_phi = bary_phi.chunks_exact(4);
        let tails = (nodes.remainder(), bary.remainder(), bary_phi.remainder());
        for ((x, b), bp) in nodes.zip(bary).zip(bary_phi) {
            for k in 0..4 {
                let r = 1.0 / (t - x[k]);
                num[k] += bp[k] * r;
                den[k] += b[k] * r;
            }
        }
        for ((x, b), bp) in tails.0.iter().zip(tails.1).zip(tails.2) {
            let r = 1.0 / (t - x);
            num[0] += bp * r;
            den[0] += b * r;
        }
        let (num, den) = (
            (num[0] + num[1]) + (num[2] + num[3]),
            (den[0] + den[1]) + (den[2] + den[3]),
        );
        if num.is_finite() && den.is_finite() {
            return num / den;
        }
        // t is a node (or next to one: 1/(t - x) overflowed)
        let nearest = self
            .nodes()
            .iter()
            .enumerate()
            .min_by(|a, b| (t - a.1).abs().total_cmp(&(t - b.1).abs()))
            .map_or(0, |(j, _)| j);
        phi[nearest]
    }

    /// The uniform grid t_j = -1 + 2j/256 on which the general solver looks for the points where
    /// the shear cap starts to hold, and the matrix of w(t_j) l_i(t_j) (l_i the Lagrange
    /// polynomials of the nodes, w = (1-t)^(1/2+theta) (1+t)^(1/2-theta)): q2 at the grid is this
    /// matrix times phi, as barycentric interpolation gives it at each point.
    pub fn crossing_grid(&self) -> (&[f64], &DMatrix<f64>) {
        let (grid, matrix) = self.crossing_grid.get_or_init(|| {
            let theta = self.theta;
            let grid: Vec<f64> = (0..=CROSSING_SAMPLES)
                .map(|j| -1.0 + 2.0 * j as f64 / CROSSING_SAMPLES as f64)
                .collect();
            let mut matrix = DMatrix::zeros(grid.len(), self.len());
            for (j, &t) in grid.iter().enumerate() {
                let weight = ((0.5 + theta) * (-t).ln_1p() + (0.5 - theta) * t.ln_1p()).exp();
                match self.nodes().iter().position(|x| *x == t) {
                    Some(i) => matrix[(j, i)] = weight,
                    None => {
                        let sum: f64 = self
                            .nodes()
                            .iter()
                            .zip(&self.bary)
                            .map(|(x, b)| b / (t - x))
                            .sum();
                        for (i, (x, b)) in self.nodes().iter().zip(&self.bary).enumerate() {
                            matrix[(j, i)] = weight * b / (t - x) / sum;
                        }
                    }
                }
            }
            (grid, matrix)
        });
        (grid, matrix)
    }

    /// The Jacobi polynomial tables of these rules (`two_grid`).
    pub fn spectral(&self) -> &Spectral {
        self.spectral
            .get_or_init(|| Spectral::new(self.theta, self.len(), &self.points))
    }
}
