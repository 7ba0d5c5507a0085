//! The flat punch with sharp corners on the strip of any thickness (docs/physics/plane-general.md
//! section 6): the contact is the face [-c, c], the linear wear law (or none) and no shear cap.
//! On the face g' = 0 and the contact condition (E) is linear in q2:
//!
//!   gamma q2 + H[q2]/m + (1/(m h)) int q2(s) [R2(z) + mu chi B12(z)] ds
//!     + (tau0/m) [chi l12((c-x)/h) + chi l12((c+x)/h)] + pi chi tau0/m = 0,   z = (s - x)/h,
//!
//! gamma = pi chi mu/m - k (4.3). The kernel is the half-plane's Cauchy kernel plus a regular part,
//! so the corner exponents are the half-plane's: q2 ~ (c+x)^(-1/2-theta) (c-x)^(-1/2+theta),
//! unbounded at both corners (index 1). With x = c t, q2 = rho(t) phi(t),
//! rho = (1-t)^(-1/2+theta) (1+t)^(-1/2-theta): phi at the N zeros t_i of
//! P_N^(-1/2+theta, -1/2-theta), collocation at the N - 1 zeros xi_k of
//! P_{N-1}^(1/2-theta, 1/2+theta), where (1/pi) sum W_i phi_i/(t_i - xi_k) is exactly
//! tan(pi theta) q2 + (1/pi) p.v. int q2/(t - xi) dt for polynomial phi (Erdogan, Gupta & Cook
//! 1973, the index-1 case). The N - 1 equations leave one solution free (the half-plane's
//! homogeneous Z); the load condition P = Q2 = c sum W_i phi_i fixes it. One linear solve.

use nalgebra::{DMatrix, DVector};

use crate::physics::SolveError;
use crate::physics::plane::strip::{self, Kernels};
use crate::physics::plane::{PlaneInputs, exponent};
use crate::physics::quadrature::{gauss_jacobi, jacobi_zeros};

/// q2 = rho(t) phi(t) on the face, phi interpolated through its values at the nodes.
#[derive(Clone, Debug, PartialEq)]
pub struct CornerPressure {
    /// Face width L = 2c [m].
    pub l: f64,
    /// Exponent shift theta (4.5).
    pub theta: f64,
    /// The nodes t_i in (-1, 1), increasing.
    pub nodes: Vec<f64>,
    /// phi_i = q2/rho at the nodes [Pa].
    pub phi: Vec<f64>,
    /// The Gauss-Jacobi weights W_i of the nodes (weight rho).
    pub weights: Vec<f64>,
    bary: Vec<f64>,
}

impl CornerPressure {
    /// phi at t by barycentric interpolation through the nodes.
    pub fn phi_at(&self, t: f64) -> f64 {
        let (mut num, mut den) = (0.0, 0.0);
        for ((x, b), p) in self.nodes.iter().zip(&self.bary).zip(&self.phi) {
            if t == *x {
                return *p;
            }
            let r = b / (t - x);
            num += r * p;
            den += r;
        }
        num / den
    }

    /// q2 [Pa] at the distance u [m] from the trailing corner, 0 < u < L; 0 outside.
    pub fn pressure_from_trailing_edge(&self, u: f64) -> f64 {
        if !(u > 0.0 && u < self.l) {
            return 0.0;
        }
        // 1 - t and 1 + t from the distances to each corner, exact near both
        let (plus, minus) = (2.0 * u / self.l, 2.0 * (self.l - u) / self.l);
        let t = plus - 1.0;
        let rho = ((-0.5 + self.theta) * minus.ln() + (-0.5 - self.theta) * plus.ln()).exp();
        rho * self.phi_at(t)
    }

    /// Q2 = c sum W_i phi_i [N/m], exact for the polynomial phi.
    pub fn normal_force(&self) -> f64 {
        0.5 * self.l
            * self
                .phi
                .iter()
                .zip(&self.weights)
                .map(|(p, w)| p * w)
                .sum::<f64>()
    }
}

/// The node count for a face of width L on a strip of thickness h: the strip solver's
/// (`strip::nodes_for`, a multiple of 16, the kernels varying on the scale h), times `factor`.
pub fn node_count(l_over_h: f64, factor: usize) -> Result<usize, SolveError> {
    let n = strip::nodes_for(l_over_h).div_ceil(16) * 16;
    if n > strip::MAX_NODES {
        return Err(SolveError::NoSolution(format!(
            "the face is {l_over_h:.0} strip thicknesses wide: beyond the {} nodes the strip \
             model resolves; the narrow model answers a face this wide",
            strip::MAX_NODES
        )));
    }
    Ok(n * factor.max(1))
}

/// The pressure on the face [-c, c] (`half_width` c [m]) of the strip with the given kernels,
/// with `nodes` unknowns; the inputs are validated (linear wear law, no shear cap).
pub fn solve(
    inputs: &PlaneInputs,
    kernels: &dyn Kernels,
    half_width: f64,
    nodes: usize,
) -> Result<CornerPressure, SolveError> {
    let (m, _, theta) = exponent(inputs);
    let (c, h, n) = (half_width, inputs.material.thickness, nodes.max(2));
    let (mu, tau0) = (inputs.friction.coefficient, inputs.friction.adhesion);
    let chi = inputs.material.chi();
    let rule = gauss_jacobi(n, -0.5 + theta, -0.5 - theta);
    let points = jacobi_zeros(n - 1, 0.5 - theta, 0.5 + theta);
    let t = &rule.nodes;
    // unknowns y_i = W_i phi_i/m: rows k < n - 1 are (E) at xi_k, the last the load
    let mut matrix = DMatrix::from_fn(n, n, |k, i| {
        if k + 1 == n {
            c * m
        } else {
            let d = t[i] - points[k];
            1.0 / d + c / h * kernels.regular(c * d / h, mu)
        }
    });
    let mut rhs = DVector::from_fn(n, |k, _| {
        if k + 1 == n {
            return inputs.load;
        }
        let xi = points[k];
        let ends = kernels.chi_l12(c * (1.0 - xi) / h) + kernels.chi_l12(c * (1.0 + xi) / h);
        -(std::f64::consts::PI * chi * tau0 / m + tau0 / m * ends)
    });
    for k in 0..n {
        let big = matrix.row(k).amax();
        if !(big > 0.0 && big.is_finite()) {
            return Err(unsolved());
        }
        matrix.row_mut(k).scale_mut(1.0 / big);
        rhs[k] /= big;
    }
    let y = matrix.lu().solve(&rhs).ok_or_else(unsolved)?;
    let phi: Vec<f64> = y
        .iter()
        .zip(&rule.weights)
        .map(|(y, w)| m * y / w)
        .collect();
    if !phi.iter().all(|p| p.is_finite()) {
        return Err(unsolved());
    }
    Ok(CornerPressure {
        l: 2.0 * c,
        theta,
        nodes: rule.nodes.clone(),
        bary: rule.barycentric_weights(),
        weights: rule.weights,
        phi,
    })
}

fn unsolved() -> SolveError {
    SolveError::NoSolution(
        "the strip model's collocation for the flat punch with sharp corners is singular at \
         these inputs"
            .into(),
    )
}
