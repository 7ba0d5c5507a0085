//! The plane problem in the paper's generality on the half-plane and the wide strip: any smooth
//! punch shape g(x), the wear law F(q2) = k q2 (q2/p0)^(n-1) and the friction law
//! Pi(q2) = min(mu q2 + tau0, tau_max) (Soldatenkov (2007) sections 1-2; the formulation, edge
//! exponents and verification routes in docs/physics/plane-general.md).
//!
//! The contact condition (1.11) differentiated, with (4.1) for v' and q1 = Pi(q2), is the
//! nonlinear singular integral equation (E) on [-a, b] (`system`), bounded at both ends; the load
//! fixes the width: P = Q2 - phi, phi = integral of Pi(q2) g' (2.1). For each width the
//! collocation is solved by Newton (`system`), then the width by Brent's method on P (`width`).

pub mod answer;
pub mod nonlinear;
pub mod pressure;
pub mod projection;
pub mod system;
pub mod width;

use nalgebra::DVector;

use crate::physics::elastic::chi_c12;
use crate::physics::plane::WearLaw;
use crate::physics::plane::general::pressure::Pressure;
use crate::physics::plane::general::system::Discretisation;
use crate::physics::plane::general::width::Width;
use crate::physics::plane::laws::FrictionLaw;
use crate::physics::plane::shape::Punch;
use crate::physics::plane::strip::{self, Kernels};
use crate::physics::{Material, SolveError};

/// The node count of an operating point.
pub const NODES: usize = 64;
/// The node count of the first, coarse width search.
const COARSE_NODES: usize = 16;

/// One general plane problem: the strip (half-plane when h = inf; the wide-strip limit
/// otherwise), the laws, the punch and the load.
#[derive(Clone, Copy)]
pub struct Problem<'a> {
    /// The elastic strip.
    pub material: Material,
    /// q1 = Pi(q2).
    pub friction: FrictionLaw,
    /// W' = -F(q2).
    pub wear: WearLaw,
    /// g(x).
    pub shape: &'a dyn Punch,
    /// The exact strip's kernels (the strip of any thickness), or None for the wide strip
    /// (thickness correction c12) and the half-plane.
    pub strip: Option<&'a dyn Kernels>,
    /// Normal load per unit length P [N/m], > 0.
    pub load: f64,
}

impl Problem<'_> {
    /// m = pi E/(2(1 - nu^2)) [Pa].
    pub fn m(&self) -> f64 {
        self.material.plane_modulus()
    }

    /// chi c12/h [1/m] of the wide strip's thickness correction; 0 on the half-plane and on the
    /// strip of any thickness, whose kernels hold it.
    pub fn c12_over_h(&self) -> f64 {
        if self.material.is_half_space() || self.strip.is_some() {
            0.0
        } else {
            chi_c12(self.material.poisson_ratio) / self.material.thickness
        }
    }

    /// gamma0 = pi chi mu/m - k [n = 1] [1/Pa], the coefficient of q2 in the dominant part of (E).
    pub fn gamma(&self) -> f64 {
        std::f64::consts::PI * self.material.chi() * self.friction.coefficient() / self.m()
            - self.linear_wear()
    }

    /// The edge exponents' theta = arctan(m gamma0/pi)/pi (docs/physics/plane-general.md
    /// section 3: for n > 1 the wear does not shift them).
    pub fn theta(&self) -> f64 {
        use std::f64::consts::PI;
        (self.m() * self.gamma() / PI).atan() / PI
    }

    /// The linear part k [1/Pa] of the wear law that the edge exponents carry: k for n = 1, else 0.
    pub fn linear_wear(&self) -> f64 {
        if self.wear.is_linear() {
            self.wear.coefficient
        } else {
            0.0
        }
    }

    /// Whether the shear cap can be reached (tau_max finite).
    fn capped(&self) -> bool {
        self.friction.shear_strength.is_finite()
    }

    /// The split points in t of integrals over the contact: the punch's kinks and where the cap
    /// starts to hold.
    pub fn splits(&self, p: &Pressure) -> Vec<f64> {
        let f = &self.friction;
        let crosses = |q: f64| f.coefficient() * q + f.adhesion() - f.shear_strength;
        let crosses: Option<&dyn Fn(f64) -> f64> = self.capped().then_some(&crosses);
        p.splits(&self.shape.kinks(), crosses)
    }

    /// Q1 = integral of Pi(q2) [N/m] = mu Q2 + tau0 L minus what the cap takes off.
    pub fn friction_force(&self, p: &Pressure) -> f64 {
        self.friction_force_split(p, &self.splits(p))
    }

    /// `friction_force` with the splits of `p` already found (`splits`).
    pub fn friction_force_split(&self, p: &Pressure, splits: &[f64]) -> f64 {
        let f = &self.friction;
        let coulomb = f.coefficient() * p.normal_force() + f.adhesion() * p.l;
        if !self.capped() {
            return coulomb;
        }
        let rule = Pressure::rule(splits);
        coulomb - p.integrate(&rule, |_, q| f.excess(q))
    }

    /// dQ1/dy_i with y_i = W_i phi_i/m (`system`), `splits` the splits of `p`.
    pub fn friction_force_gradient(
        &self,
        p: &Pressure,
        splits: &[f64],
        d: &Discretisation,
    ) -> DVector<f64> {
        let (m, half, mu) = (self.m(), 0.5 * p.l, self.friction.coefficient());
        let mut g = DVector::from_element(d.len(), mu * half * m);
        if !self.capped() {
            return g;
        }
        let rules = d.rules();
        let rule = Pressure::rule(splits);
        for (&t, &w) in rule.nodes.iter().zip(&rule.weights) {
            if self.friction.excess(p.at(t)) <= 0.0 {
                continue;
            }
            let basis: Vec<f64> = rules
                .nodes()
                .iter()
                .zip(rules.bary())
                .map(|(x, b)| b / (t - x))
                .collect();
            let sum: f64 = basis.iter().sum();
            let scale = mu * half * w * p.weight(t) * m / sum;
            for (gi, (bi, wi)) in g.iter_mut().zip(basis.iter().zip(rules.weights())) {
                *gi -= scale * bi / wi;
            }
        }
        g
    }
}

/// The general solution at one load.
#[derive(Clone, Debug, PartialEq)]
pub struct Solution {
    /// Trailing half-width a [m]: the contact is [-a, b].
    pub a: f64,
    /// Leading half-width b [m].
    pub b: f64,
    /// q2 on the contact.
    pub pressure: Pressure,
    /// Q2 = integral of q2 [N/m].
    pub normal_force: f64,
    /// Q1 = integral of Pi(q2) [N/m], the friction force on the strip in +x.
    pub friction_force: f64,
    /// psi = integral of q2 g' [N/m] (2.2), the deformation component of friction.
    pub psi: f64,
    /// phi = integral of Pi(q2) g' [N/m] (2.1): P = Q2 - phi.
    pub phi: f64,
    /// Delta_g = g(b) - g(-a) [m].
    pub delta_g: f64,
    /// T = Q1 + psi [N/m], the tangential force that drives the punch (2.1).
    pub tangential_force: f64,
    /// mu* = (T - tau0 (a + b))/P (3.13), dimensionless.
    pub mu_star: f64,
    /// The edge exponents' theta.
    pub theta: f64,
}

/// Solves the problem at its load with `nodes` collocation nodes: the width first with
/// `COARSE_NODES` nodes, then refined with `nodes`, or on the strip of any thickness with the
/// strip solver's count if that is more (`strip::nodes_for`: the kernels vary on the scale h).
pub fn solve(problem: &Problem, nodes: usize) -> Result<Solution, SolveError> {
    solve_refined(problem, nodes, 1)
}

/// `solve` with the final node count (the one it would choose) multiplied by `factor` >= 1: the
/// same problem on a finer discretisation, whose difference from `solve`'s answer measures the
/// discretisation error.
pub fn solve_refined(
    problem: &Problem,
    nodes: usize,
    factor: usize,
) -> Result<Solution, SolveError> {
    let theta = problem.theta();
    let (near, nodes) = match problem.strip {
        None => {
            let coarse = Discretisation::cached(theta, COARSE_NODES);
            (width::solve(problem, &coarse, None)?, nodes)
        }
        Some(_) => {
            let near = strip_width(problem, theta)?;
            let h = problem.material.thickness;
            let wanted = strip::nodes_for(near.l / h).div_ceil(16) * 16;
            if wanted > strip::MAX_NODES {
                return Err(SolveError::NoSolution(format!(
                    "the contact is {:.0} strip thicknesses wide: beyond the {} nodes the strip \
                     model resolves",
                    near.l / h,
                    strip::MAX_NODES
                )));
            }
            (near, wanted.max(nodes))
        }
    };
    let d = Discretisation::cached(theta, nodes * factor.max(1));
    let found = width::solve(problem, &d, Some(&near))?;
    Ok(assemble(
        problem,
        found.unknowns.pressure(&d, problem, found.l),
    ))
}

/// `solve` on the half-plane or the wide strip from `from`, the solution of the same problem on
/// `NODES` nodes at another load `from_load` [N/m] (a load sweep's previous point): the secant
/// steps on the width start from its width, the first with the slope d ln P/d ln L `log_slope`
/// where known (a sweep's last two points) and else the first guess's, and each width's Newton
/// from its pressure, without the coarse search. The discrete problem is `solve`'s, and so is
/// the answer, within the width's tolerance.
pub fn solve_from(
    problem: &Problem,
    (from, from_load): (&Pressure, f64),
    log_slope: Option<f64>,
) -> Result<Solution, SolveError> {
    let d = Discretisation::cached(problem.theta(), NODES);
    let mut near = Width::of(problem, from, from_load);
    if let Some(k) = log_slope {
        near.log_slope = k;
    }
    let found = width::solve(problem, &d, Some(&near))?;
    Ok(assemble(
        problem,
        found.unknowns.pressure(&d, problem, found.l),
    ))
}

/// The strip's coarse width: the node count doubled from one that resolves the first guess
/// (16 + 2 L/h, the strip solver's coarse count, at the half-plane-like guess of `width`, which a
/// strip's width does not exceed) until the width changes by less than 1 % and the nodes resolve
/// it; a count that does not converge is passed over. At most `strip::MAX_NODES / 2` nodes.
/// (With too few nodes for L/h the discrete P(L) has roots of its own, at L/h near 6 N.)
fn strip_width(problem: &Problem, theta: f64) -> Result<Width, SolveError> {
    let h = problem.material.thickness;
    let guess = width::first_guess(problem)?;
    let first =
        ((16.0 + 2.0 * guess / h).min(strip::MAX_NODES as f64 / 2.0) as usize).div_ceil(16) * 16;
    let (mut n, mut last, mut why) = (first.max(COARSE_NODES), None::<Width>, None);
    while n <= strip::MAX_NODES / 2 {
        match width::solve(problem, &Discretisation::cached(theta, n), last.as_ref()) {
            Ok(found) => {
                let l = found.l;
                let settled = last.as_ref().is_some_and(|p| (l - p.l).abs() < 1e-2 * l);
                if settled && n as f64 >= 16.0 + 2.0 * l / h {
                    return Ok(found);
                }
                last = Some(found);
            }
            Err(e) => {
                last = None;
                why = Some(e);
            }
        }
        n *= 2;
    }
    Err(why.unwrap_or_else(|| {
        SolveError::NoSolution(format!(
            "the general solver's contact width on the strip did not settle with up to {} nodes",
            strip::MAX_NODES / 2
        ))
    }))
}

/// The forces and mu* of the pressure `p`.
fn assemble(problem: &Problem, p: Pressure) -> Solution {
    let (a, b) = (0.5 * p.l - p.c, 0.5 * p.l + p.c);
    let rule = Pressure::rule(&problem.splits(&p));
    let shape = problem.shape;
    let f = &problem.friction;
    let [psi, phi, excess] = p.integrate_each(&rule, |x, q| {
        let slope = shape.slope(x);
        [q * slope, f.shear(q) * slope, f.excess(q)]
    });
    let coulomb = f.coefficient() * p.normal_force() + f.adhesion() * p.l;
    // as `Problem::friction_force`, on the same rule
    let friction_force = if problem.capped() {
        coulomb - excess
    } else {
        coulomb
    };
    let tangential_force = friction_force + psi;
    Solution {
        a,
        b,
        normal_force: p.normal_force(),
        friction_force,
        psi,
        phi,
        delta_g: shape.height(b) - shape.height(-a),
        tangential_force,
        mu_star: (tangential_force - f.adhesion() * (a + b)) / problem.load,
        theta: p.theta,
        pressure: p,
    }
}
