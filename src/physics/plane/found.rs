//! What each model's solver finds and how a `PlaneSolution` is assembled from it: the forces,
//! phi and mu* (3.13) derived the same way for every model.

use crate::physics::Friction;
use crate::physics::plane::{Model, PlaneInputs, PlaneSolution, PressureLaw};

/// What each model's solver finds; `PlaneSolution::assemble` derives the forces and mu* from it
/// the same way for every model.
pub(crate) struct Found {
    /// Trailing and leading half-widths a, b [m].
    pub a: f64,
    pub b: f64,
    /// The contact width L [m] the solver's root search settled on (a + b up to round-off).
    pub width: f64,
    /// Q2 [N/m].
    pub q2: f64,
    /// psi [N/m].
    pub psi: f64,
    /// Delta_g [m].
    pub delta_g: f64,
    /// theta and gamma of the wide and strip models; None for the narrow model.
    pub theta: Option<f64>,
    pub gamma: Option<f64>,
    /// Q1 = int Pi(q2) dx [N/m] and phi = int Pi(q2) g' dx [N/m] (2.1) where the solver
    /// integrates them (a capped friction law); None: mu Q2 + tau0 L and mu psi + tau0 Delta_g.
    pub friction_integrals: Option<(f64, f64)>,
}

impl PlaneSolution {
    /// The solution from what a model's solver found: Q1 = mu Q2 + tau0 L, T = Q1 + psi (3.11)
    /// and mu* (3.13).
    pub(crate) fn assemble(
        model: Model,
        inputs: &PlaneInputs,
        found: Found,
        law: PressureLaw,
    ) -> PlaneSolution {
        let (mu, tau0) = (inputs.friction.coefficient, inputs.friction.adhesion);
        let (friction_force, phi) = found.friction_integrals.unwrap_or((
            mu * found.q2 + tau0 * found.width,
            mu * found.psi + tau0 * found.delta_g,
        ));
        PlaneSolution {
            model,
            inputs: inputs.clone(),
            normal_force: found.q2,
            friction_force,
            tangential_force: friction_force + found.psi,
            a: found.a,
            b: found.b,
            theta: found.theta,
            gamma: found.gamma,
            psi: found.psi,
            delta_g: found.delta_g,
            phi,
            mu_star: match found.friction_integrals {
                // (3.13) as T - tau0 L over P, which holds with the cap too
                Some((q1, _)) => (q1 + found.psi - tau0 * found.width) / inputs.load,
                None => total_friction(&inputs.friction, found.psi, found.delta_g, inputs.load),
            },
            law,
        }
    }
}

/// mu* = mu + [(1 + mu^2) psi + mu Delta_g tau0]/P, Soldatenkov (2007) eq. (3.13).
fn total_friction(friction: &Friction, psi: f64, delta_g: f64, load: f64) -> f64 {
    let mu = friction.coefficient;
    mu + ((1.0 + mu * mu) * psi + mu * delta_g * friction.adhesion) / load
}
