//! The nonlinear terms of (E), Nl(q2) = (pi chi/m) (Pi(q2) - mu q2 - tau0) - (F(q2) - k1 q2)
//! (`system`), at the collocation points, and their Jacobian in the unknowns y_i = W_i phi_i/m.
//!
//! Without a shear cap Nl is a smooth function of q2 inside the contact and is taken at the
//! points. With a cap Pi has a kink where mu q2 + tau0 crosses tau_max, inside the contact, and
//! point values would converge like N^-2 there: Nl is projected as the punch's slope is
//! (`projection`), the rule split where the cap starts to hold (`Problem::splits`).

use nalgebra::{DMatrix, DVector};

use crate::physics::plane::general::Problem;
use crate::physics::plane::general::pressure::Pressure;
use crate::physics::plane::general::projection::SlopeProjection;

/// Nl(q) and dNl/dq at q [Pa] (dimensionless and 1/Pa).
fn nl(problem: &Problem, q: f64) -> (f64, f64) {
    let (friction, wear) = (&problem.friction, &problem.wear);
    let pi_chi_m = std::f64::consts::PI * problem.material.chi() / problem.m();
    let (k1, mu, tau0) = (
        problem.linear_wear(),
        friction.coefficient(),
        friction.adhesion(),
    );
    let value = pi_chi_m * (friction.shear(q) - mu * q - tau0) - (wear.rate(q) - k1 * q);
    let slope = pi_chi_m * (friction.shear_slope(q) - mu) - (wear.rate_slope(q) - k1);
    (value, slope)
}

/// Nl at the collocation points from q2 there (`q`, which is `to_points` times phi), and its
/// Jacobian in y (`weights` the W_i of y_i = W_i phi_i/m): without a cap.
pub fn at_points(
    problem: &Problem,
    to_points: &DMatrix<f64>,
    weights: &[f64],
    q: &DVector<f64>,
) -> (DVector<f64>, DMatrix<f64>) {
    let (rows, n, m) = (to_points.nrows(), to_points.ncols(), problem.m());
    let (mut values, mut jac) = (DVector::zeros(rows), DMatrix::zeros(rows, n));
    for k in 0..rows {
        let (value, slope) = nl(problem, q[k]);
        values[k] = value;
        for i in 0..n {
            jac[(k, i)] = slope * to_points[(k, i)] * m / weights[i];
        }
    }
    (values, jac)
}

/// Nl at the collocation points projected (module note) for the pressure `p` with its splits
/// `splits` (`Problem::splits`), whose nodes have the barycentric weights `bary` and the weights
/// `weights` W_i; with its Jacobian in y.
pub fn projected(
    problem: &Problem,
    projection: &SlopeProjection,
    (p, splits): (&Pressure, &[f64]),
    (bary, weights): (&[f64], &[f64]),
) -> (DVector<f64>, DMatrix<f64>) {
    let (n, m) = (weights.len(), problem.m());
    let (ts, b) = projection.matrix(splits);
    // q2 at the rule's nodes t_j, w(t_j) times phi interpolated, and dq2(t_j)/dy_i
    let mut values = DVector::zeros(ts.len());
    let mut jac = DMatrix::zeros(ts.len(), n);
    for (j, &t) in ts.iter().enumerate() {
        let mut row: Vec<f64> = p
            .nodes()
            .iter()
            .zip(bary)
            .map(|(x, b)| b / (t - x))
            .collect();
        if let Some(i) = p.nodes().iter().position(|x| *x == t) {
            row.iter_mut().for_each(|v| *v = 0.0);
            row[i] = 1.0;
        }
        let scale = p.weight(t) / row.iter().sum::<f64>();
        let q: f64 = row.iter().zip(&p.phi).map(|(r, f)| r * f).sum::<f64>() * scale;
        let (value, slope) = nl(problem, q);
        values[j] = value;
        for (i, r) in row.iter().enumerate() {
            jac[(j, i)] = r * scale * slope * m / weights[i];
        }
    }
    (&b * values, &b * jac)
}
