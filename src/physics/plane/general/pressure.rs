//! The pressure of the general plane solver: q2 = w(t) phi(t) on x = c + (L/2) t, t in [-1, 1],
//! w = (1-t)^(1/2+theta) (1+t)^(1/2-theta) (docs/physics/plane-general.md section 3), phi the
//! polynomial through its values at the Gauss–Jacobi nodes; and the integrals over the contact
//! that the solver and its outputs need, by tanh–sinh rules split where the integrand has a kink.

use std::sync::{Arc, OnceLock};

use nalgebra::DVector;

use crate::physics::plane::strip::collocation::Rules;
use crate::physics::quadrature::{GaussRule, tanh_sinh};
use crate::physics::roots::brent;

/// q2 on the contact: the width, the shift, the edge exponents and phi at the nodes.
#[derive(Clone, Debug, PartialEq)]
pub struct Pressure {
    /// Contact width L = a + b [m].
    pub l: f64,
    /// Shift c = (b - a)/2 [m] of the contact's middle from the punch tip.
    pub c: f64,
    /// Exponent shift theta: q2 ~ (a+x)^(1/2-theta) at the trailing end, (b-x)^(1/2+theta) at the
    /// leading end.
    pub theta: f64,
    /// phi_i = q2/w at the nodes [Pa].
    pub phi: Vec<f64>,
    rules: Arc<Rules>,
    /// Barycentric weight times phi at each node.
    bary_phi: Vec<f64>,
}

impl Pressure {
    /// The pressure with these values phi_i [Pa] at the nodes of `rules`.
    pub fn new(rules: Arc<Rules>, l: f64, c: f64, phi: Vec<f64>) -> Pressure {
        let bary_phi = rules.bary().iter().zip(&phi).map(|(b, p)| b * p).collect();
        Pressure {
            l,
            c,
            theta: rules.theta(),
            phi,
            rules,
            bary_phi,
        }
    }

    /// The rules of its nodes.
    pub fn rules(&self) -> &Arc<Rules> {
        &self.rules
    }

    /// The Jacobi nodes t_i in (-1, 1).
    pub fn nodes(&self) -> &[f64] {
        self.rules.nodes()
    }

    /// x [m] at t.
    pub fn x(&self, t: f64) -> f64 {
        self.c + 0.5 * self.l * t
    }

    /// phi at t [Pa], by barycentric interpolation through the nodes.
    pub fn phi_at(&self, t: f64) -> f64 {
        self.rules.interpolate(&self.bary_phi, &self.phi, t)
    }

    /// The weight w(t) = (1-t)^(1/2+theta) (1+t)^(1/2-theta).
    pub fn weight(&self, t: f64) -> f64 {
        ((0.5 + self.theta) * (-t).ln_1p() + (0.5 - self.theta) * t.ln_1p()).exp()
    }

    /// q2 at t in [-1, 1] [Pa].
    pub fn at(&self, t: f64) -> f64 {
        let t = t.clamp(-1.0, 1.0);
        self.weight(t) * self.phi_at(t)
    }

    /// q2 [Pa] at distance u [m] from the trailing edge, u in [0, L].
    pub fn pressure_from_trailing_edge(&self, u: f64) -> f64 {
        self.at(2.0 * u / self.l - 1.0)
    }

    /// Q2 = integral of q2 [N/m]: (L/2) sum W_i phi_i, exact for polynomial phi.
    pub fn normal_force(&self) -> f64 {
        let sum: f64 = self
            .rules
            .weights()
            .iter()
            .zip(&self.phi)
            .map(|(w, p)| w * p)
            .sum();
        0.5 * self.l * sum
    }

    /// The points of (-1, 1), increasing, where an integrand of x has a kink: the punch's kinks
    /// `kinks` [m] inside the contact and the points where `crosses` (a function of q2) changes
    /// sign, found on the rules' grid (`Rules::crossing_grid`, q2 there by one product with phi)
    /// and refined by Brent.
    pub fn splits(&self, kinks: &[f64], crosses: Option<&dyn Fn(f64) -> f64>) -> Vec<f64> {
        let mut out: Vec<f64> = kinks
            .iter()
            .map(|&x| 2.0 * (x - self.c) / self.l)
            .filter(|t| t.abs() < 1.0)
            .collect();
        if let Some(f) = crosses {
            let g = |t: f64| f(self.at(t));
            let (grid, on_grid) = self.rules.crossing_grid();
            let sampled = on_grid * DVector::from_column_slice(&self.phi);
            for (t, q) in grid.windows(2).zip(sampled.as_slice().windows(2)) {
                if (f(q[0]) > 0.0) != (f(q[1]) > 0.0) {
                    out.extend(brent(t[0], t[1], g));
                }
            }
        }
        out.sort_by(f64::total_cmp);
        out.dedup();
        out
    }

    /// The rule on [-1, 1] split at `splits`: nodes t and weights for integrals in t. Step 1/64:
    /// the nodes away from the ends (spaced some pi h/2 in t) follow a polynomial of 128 nodes
    /// (with 1/16, psi of 128 nodes was 5e-6 of T off on a power punch with n = 1.5).
    pub fn rule(splits: &[f64]) -> GaussRule {
        static BASE: OnceLock<GaussRule> = OnceLock::new();
        let base = BASE.get_or_init(|| tanh_sinh(1.0 / 64.0));
        let mut ends = vec![-1.0];
        ends.extend(splits.iter().copied().filter(|t| t.abs() < 1.0));
        ends.push(1.0);
        let (mut nodes, mut weights) = (Vec::new(), Vec::new());
        for piece in ends.windows(2) {
            let (lo, hi) = (piece[0], piece[1]);
            let half = 0.5 * (hi - lo);
            for (t, w) in base.nodes.iter().zip(&base.weights) {
                nodes.push(0.5 * (hi + lo) + half * t);
                weights.push(half * w);
            }
        }
        GaussRule { nodes, weights }
    }

    /// Integral over the contact of f(x, q2(x)) dx with the split rule `rule` (from `Pressure::rule`).
    pub fn integrate(&self, rule: &GaussRule, f: impl Fn(f64, f64) -> f64) -> f64 {
        let [integral] = self.integrate_each(rule, |x, q| [f(x, q)]);
        integral
    }

    /// The integrals of each of the K functions f returns, as `integrate` gives each, with q2
    /// interpolated once per node.
    pub fn integrate_each<const K: usize>(
        &self,
        rule: &GaussRule,
        f: impl Fn(f64, f64) -> [f64; K],
    ) -> [f64; K] {
        let half = 0.5 * self.l;
        let mut sums = [0.0; K];
        for (&t, w) in rule.nodes.iter().zip(&rule.weights) {
            let values = f(self.x(t), self.at(t));
            for (sum, v) in sums.iter_mut().zip(values) {
                *sum += w * v;
            }
        }
        sums.map(|sum| sum * half)
    }
}
