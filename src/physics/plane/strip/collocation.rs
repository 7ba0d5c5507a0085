//! The collocation system of the strip of any thickness at one contact width (docs/physics/plane.md
//! section 6): q2 = w(t) phi(t) with w = (1-t)^(1/2+theta) (1+t)^(1/2-theta) on s = c + (L/2) t,
//! unknowns phi at the zeros t_i of P_N^(1/2+theta, 1/2-theta), collocation at the zeros xi_k of
//! P_{N+1}^(-1/2-theta, -1/2+theta), where (1/pi) sum W_i phi_i/(t_i - xi_k) is exactly
//! tan(pi theta) q2 + (1/pi) p.v. int q2/(t - xi). For a fixed L the shift c = (b-a)/2 enters as
//! the constant -c/R: N + 1 equations for phi and c, one linear solve per L.
//!
//! The unknowns are scaled to v_i = W_i phi_i R/(m L/2) (quadrature-weighted) and v_N = c/(L/2):
//!   sum_i [1/(pi (t_i - xi_k)) + (L/2)/(pi h) K((L/2)(t_i - xi_k)/h)] v_i + v_N/pi
//!     = -xi_k/pi - (tau0 R/(m L/2)) [chi + (chi l12((L/2)(1-xi_k)/h) + chi l12((L/2)(1+xi_k)/h))/pi],
//! K = R2 + mu chi B12, and each row is divided by its largest entry. Unscaled, LU with partial
//! pivoting gives a growth factor of 1e11 at (a+b)/h = 56 with k m = 0.5 and loses 5 digits
//! (plane.md section 6 reports 1e15 for strong wear); scaled, the growth stayed below 2 in every
//! case tried, so LU is the rule and Householder QR the fallback when the growth exceeds 1e6
//! (`factors`). The factors are kept and reused at nearby widths by iterative refinement
//! (residual with the new matrix, correction with the old factors: O(N^2) per width instead of
//! O(N^3)), and rebuilt when the refinement stops contracting. A system lent the coarse search's
//! factors (`two_grid`, an operating point with many nodes) refines from those instead and
//! factors its own matrix only where that does not converge.

use std::rc::Rc;
use std::sync::Arc;

use nalgebra::{DMatrix, DVector};

use crate::physics::plane::PlaneInputs;
use crate::physics::plane::strip::factors::{Factors, refine};
use crate::physics::plane::strip::kernels::{ColumnKernel, Kernels};
use crate::physics::plane::strip::two_grid::Coarse;

pub use crate::physics::plane::strip::rules::Rules;

/// Two-grid solves for a system whose tolerance is this or finer refine to round-off
/// (`TWO_GRID_TOLERANCE`): they contract by some 1e-3 a step, so that stopping at an estimated
/// 1e-14 left errors of that order in P(L), and a width search to 1e-15 took one more width (one
/// more assembly) to settle than after a factorization. A coarser tolerance (a width to 1e-9 for
/// a measurement) is its own.
const ROUND_OFF_FROM: f64 = 1e-12;
const TWO_GRID_TOLERANCE: f64 = 1e-16;

/// The collocation solution at one contact width.
#[derive(Clone, Debug, PartialEq)]
pub struct Collocation {
    /// Contact width L [m].
    pub l: f64,
    /// Shift c = (b - a)/2 [m].
    pub c: f64,
    /// Exponent shift theta.
    pub theta: f64,
    /// phi_i = q2/w at the nodes [Pa].
    pub phi: Vec<f64>,
    /// Q2 [N/m].
    pub q2: f64,
    /// psi [N/m].
    pub psi: f64,
    /// Delta_g [m].
    pub delta_g: f64,
    /// P [N/m] from (3.11).
    pub load: f64,
    rules: Arc<Rules>,
    /// Barycentric weight times phi at each node.
    bary_phi: Vec<f64>,
}

impl Collocation {
    /// The Jacobi nodes t_i in (-1, 1).
    pub fn nodes(&self) -> &[f64] {
        self.rules.nodes()
    }

    /// phi at t by barycentric interpolation through the nodes (`Rules::interpolate`).
    pub fn phi_at(&self, t: f64) -> f64 {
        self.rules.interpolate(&self.bary_phi, &self.phi, t)
    }

    /// q2 at distance u from the trailing edge [Pa].
    pub fn pressure_from_trailing_edge(&self, u: f64) -> f64 {
        let t = (2.0 * u / self.l - 1.0).clamp(-1.0, 1.0);
        let weight = ((0.5 + self.theta) * (-t).ln_1p() + (0.5 - self.theta) * t.ln_1p()).exp();
        weight * self.phi_at(t)
    }
}

/// The collocation system of one set of inputs and rules, keeping the last factorization.
pub struct System<'a> {
    inputs: PlaneInputs,
    kernels: &'a dyn Kernels,
    /// Relative accuracy of solutions by refinement.
    tolerance: f64,
    /// R2 + mu chi B12 over a column, for the inputs' mu (shared by the systems of one search).
    regular: Rc<ColumnKernel<'a>>,
    rules: Arc<Rules>,
    /// The scaled matrix at the last width assembled (its storage reused from width to width).
    matrix: DMatrix<f64>,
    factors: Option<Factors>,
    /// The row scales (1/largest entry) of the matrix `factors` factored.
    factored_scale: Vec<f64>,
    /// The coarse factors of a two-grid solve (`two_grid`), used while `factors` is None.
    coarse: Option<Rc<Coarse>>,
    /// The last collocation (root finders evaluate their answer again).
    last: Option<Collocation>,
    /// The last four solutions (width, scaled unknowns), newest first.
    history: Vec<(f64, DVector<f64>)>,
    /// Scratch: one column of kernel arguments and values, and the rows' largest entries.
    scratch: (Vec<f64>, Vec<f64>, Vec<f64>),
}

impl<'a> System<'a> {
    /// The system for these inputs with these rules (their theta must be the inputs') and the
    /// regular kernel `regular` over columns (`Kernels::regular_columns` of the inputs' mu);
    /// solutions by refinement stop when the next correction is estimated below `tolerance`
    /// (relative).
    pub fn new(
        inputs: &PlaneInputs,
        kernels: &'a dyn Kernels,
        regular: &Rc<ColumnKernel<'a>>,
        rules: Arc<Rules>,
        tolerance: f64,
    ) -> System<'a> {
        let n = rules.len();
        System {
            inputs: inputs.clone(),
            kernels,
            tolerance,
            regular: Rc::clone(regular),
            rules,
            matrix: DMatrix::zeros(n + 1, n + 1),
            factors: None,
            factored_scale: Vec::new(),
            coarse: None,
            last: None,
            history: Vec::new(),
            scratch: (vec![0.0; n + 1], vec![0.0; n + 1], vec![0.0; n + 1]),
        }
    }

    /// The number of unknowns phi_i.
    pub fn nodes(&self) -> usize {
        self.rules.len()
    }

    /// The last collocation solved, if any.
    pub fn last(&self) -> Option<&Collocation> {
        self.last.as_ref()
    }

    /// Solve by two-grid refinement with `coarse` (the factors of a coarse system at a nearby
    /// width) until that fails once; then factor this system's matrix.
    pub fn set_coarse(&mut self, coarse: Rc<Coarse>) {
        self.coarse = Some(coarse);
    }

    /// This system's factors, for a two-grid solve with more nodes (None before any solve).
    pub fn into_coarse(self) -> Option<Coarse> {
        Some(Coarse::new(self.factors?, self.rules, self.factored_scale))
    }

    /// Whether this system has factored its own matrix.
    #[cfg(test)]
    pub fn factored(&self) -> bool {
        self.factors.is_some()
    }

    /// The scaled, row-equilibrated matrix at width l (into `matrix`) and the right side (module
    /// note).
    fn assemble(&mut self, l: f64) -> DVector<f64> {
        let n = self.rules.len();
        let inputs = &self.inputs;
        let h = inputs.material.thickness;
        let half = 0.5 * l;
        let (nodes, points) = (self.rules.nodes(), self.rules.points());
        let inv_pi = std::f64::consts::FRAC_1_PI;
        let a = &mut self.matrix;
        a.column_mut(n).fill(inv_pi);
        let (zs, ks, row_max) = &mut self.scratch;
        let regular = &self.regular;
        row_max.fill(inv_pi);
        let (z_scale, k_scale) = (half / h, inv_pi * half / h);
        for (column, t) in a.as_mut_slice().chunks_exact_mut(n + 1).zip(nodes) {
            for (z, xi) in zs.iter_mut().zip(points) {
                *z = (t - xi) * z_scale;
            }
            regular(zs, ks);
            for (((entry, xi), k), big) in column
                .iter_mut()
                .zip(points)
                .zip(&*ks)
                .zip(row_max.iter_mut())
            {
                *entry = inv_pi / (t - xi) + k_scale * k;
                *big = big.max(entry.abs());
            }
        }
        let m = inputs.material.plane_modulus();
        let (chi, tau0, r) = (
            inputs.material.chi(),
            inputs.friction.adhesion,
            inputs.radius(),
        );
        let adhesion = tau0 * r / (m * half);
        let b = DVector::from_iterator(
            n + 1,
            points.iter().zip(&*row_max).map(|(&xi, big)| {
                let ends = if tau0 == 0.0 {
                    0.0
                } else {
                    self.kernels.chi_l12(half * (1.0 - xi) / h)
                        + self.kernels.chi_l12(half * (1.0 + xi) / h)
                };
                (-xi * inv_pi - adhesion * (chi + ends * inv_pi)) / big
            }),
        );
        for big in row_max.iter_mut() {
            *big = 1.0 / *big;
        }
        for column in a.as_mut_slice().chunks_exact_mut(n + 1) {
            for (entry, scale) in column.iter_mut().zip(&*row_max) {
                *entry *= scale;
            }
        }
        b
    }

    /// A first guess of the scaled unknowns at width l: the polynomial in l through the last
    /// solutions (up to four, fewer where the extrapolation would amplify them more than 16 times:
    /// the root finders' widths can be nearly equal), or the last one.
    fn guess(&self, l: f64) -> Option<DVector<f64>> {
        let newest = &self.history.first()?.1;
        for count in (2..=self.history.len()).rev() {
            let known = &self.history[..count];
            let weights: Vec<f64> = (0..count)
                .map(|j| {
                    (0..count)
                        .filter(|&k| k != j)
                        .map(|k| (l - known[k].0) / (known[j].0 - known[k].0))
                        .product()
                })
                .collect();
            if weights.iter().map(|w| w.abs()).sum::<f64>() <= 16.0 {
                let mut guess = newest * 0.0;
                for (w, (_, y)) in weights.iter().zip(known) {
                    guess.axpy(*w, y, 1.0);
                }
                return Some(guess);
            }
        }
        Some(newest.clone())
    }

    /// The collocation at width l: refinement from the kept factors when it converges, else a new
    /// factorization. None when the matrix is singular.
    pub fn at(&mut self, l: f64) -> Option<Collocation> {
        if let Some(last) = self.last.as_ref().filter(|c| c.l.to_bits() == l.to_bits()) {
            return Some(last.clone());
        }
        let b = self.assemble(l);
        let (a, guess) = (&self.matrix, self.guess(l));
        let reused = match (&self.factors, &self.coarse) {
            (Some(factors), _) => guess.and_then(|g| factors.refine(a, &b, g, self.tolerance)),
            (None, Some(coarse)) => {
                let (rules, scale) = (&self.rules, &self.scratch.2);
                let start = guess.unwrap_or_else(|| DVector::zeros(b.len()));
                let tolerance = if self.tolerance <= ROUND_OFF_FROM {
                    TWO_GRID_TOLERANCE
                } else {
                    self.tolerance
                };
                refine(a, &b, start, tolerance, |r| {
                    coarse.precondition(rules, scale, r)
                })
            }
            _ => None,
        };
        let y = match reused {
            Some((y, _)) => y,
            None => {
                self.factored_scale.clone_from(&self.scratch.2);
                let factors = Factors::new(&self.matrix)?;
                let y = factors.solve(&b)?;
                self.factors = Some(factors);
                y
            }
        };
        self.history.truncate(3);
        self.history.insert(0, (l, y.clone()));
        let col = self.collocation(l, &y);
        self.last = Some(col.clone());
        Some(col)
    }

    fn collocation(&self, l: f64, y: &DVector<f64>) -> Collocation {
        let inputs = &self.inputs;
        let n = self.rules.len();
        let (mu, tau0, r) = (
            inputs.friction.coefficient,
            inputs.friction.adhesion,
            inputs.radius(),
        );
        let half = 0.5 * l;
        let p0 = inputs.material.plane_modulus() * half / r;
        let c = half * y[n];
        let (mut q2, mut moment) = (0.0, 0.0);
        for (v, t) in y.iter().zip(self.rules.nodes()) {
            q2 += p0 * v;
            moment += p0 * v * (c + half * t);
        }
        let phi: Vec<f64> = y
            .iter()
            .zip(self.rules.weights())
            .map(|(v, w)| p0 * v / w)
            .collect();
        let (q2, psi) = (half * q2, half * moment / r);
        let delta_g = l * c / r;
        let bary_phi = self
            .rules
            .bary()
            .iter()
            .zip(&phi)
            .map(|(b, p)| b * p)
            .collect();
        Collocation {
            l,
            c,
            theta: self.rules.theta(),
            phi,
            q2,
            psi,
            delta_g,
            load: q2 - mu * psi - tau0 * delta_g,
            bary_phi,
            rules: Arc::clone(&self.rules),
        }
    }
}
