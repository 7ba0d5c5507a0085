//! The second algorithm, with a convergence proof for tau0 = 0: the projected fixed point in the
//! metric of the symmetric part S (docs/physics/spatial-partial.md section 3),
//!
//!   b = (1 - w) S[p] + w (U - W[p]),   p <- frictionless contact of "shape" b under S,
//!   w = 1/(1 + t^2),  t = tan phi_max,
//!
//! which contracts in the S-norm by at most sin phi_max. Each frictionless contact is solved by
//! the conjugate gradients of Polonsky and Keer under load control (I. A. Polonsky, L. M. Keer,
//! "A numerical method for solving rough contact problems based on the multi-level multi-summation
//! and conjugate gradient techniques", Wear 231 (1999) 206–219, section 3), warm-started from the
//! previous p. It is the independent check of the active-set solver in the tests.

use crate::physics::SolveError;
use crate::physics::spatial::partial::operator::Operator;

/// Most conjugate-gradient iterations of one frictionless contact.
const MAX_CG_ITERATIONS: usize = 20_000;

/// The frictionless contact under S with shape `b` [m] and mean pressure `pbar` [Pa], from the
/// start `p` (>= 0, mean pbar), to max |dp| <= `tol` pbar between iterations. Returns the CG
/// iterations.
pub fn frictionless(
    op: &mut Operator,
    b: &[f64],
    pbar: f64,
    p: &mut [f64],
    tol: f64,
) -> Result<usize, SolveError> {
    let n = b.len();
    let total = pbar * n as f64;
    let (mut g, mut t, mut r) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut g_old = 1.0;
    let mut conjugate = false;
    for iteration in 1..=MAX_CG_ITERATIONS {
        op.symmetric(p, &mut g);
        g.iter_mut().zip(b).for_each(|(g, b)| *g -= b);
        let in_contact = |i: usize, p: &[f64]| p[i] > 0.0;
        let count = (0..n).filter(|&i| in_contact(i, p)).count() as f64;
        let g_mean = (0..n)
            .filter(|&i| in_contact(i, p))
            .map(|i| g[i])
            .sum::<f64>()
            / count;
        g.iter_mut().for_each(|v| *v -= g_mean);
        let big_g: f64 = (0..n)
            .filter(|&i| in_contact(i, p))
            .map(|i| g[i] * g[i])
            .sum();
        let ratio = if conjugate { big_g / g_old } else { 0.0 };
        for i in 0..n {
            t[i] = if in_contact(i, p) {
                g[i] + ratio * t[i]
            } else {
                0.0
            };
        }
        g_old = big_g;
        op.symmetric(&t, &mut r);
        let r_mean = (0..n)
            .filter(|&i| in_contact(i, p))
            .map(|i| r[i])
            .sum::<f64>()
            / count;
        let (num, den) = (0..n)
            .filter(|&i| in_contact(i, p))
            .fold((0.0, 0.0), |s, i| {
                (s.0 + g[i] * t[i], s.1 + (r[i] - r_mean) * t[i])
            });
        let tau = if den > 0.0 { num / den } else { 0.0 };
        let old = p.to_vec();
        for i in 0..n {
            if old[i] > 0.0 {
                p[i] = (p[i] - tau * t[i]).max(0.0);
            }
        }
        // overlapping nodes out of contact join it
        let mut overlap = false;
        for i in 0..n {
            if p[i] == 0.0 && g[i] < 0.0 {
                p[i] = -tau * g[i];
                overlap = true;
            }
        }
        conjugate = !overlap;
        let sum: f64 = p.iter().sum();
        p.iter_mut().for_each(|v| *v *= total / sum);
        let change = p
            .iter()
            .zip(&old)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        if change <= tol * pbar {
            return Ok(iteration);
        }
    }
    Err(SolveError::NoSolution(format!(
        "the frictionless contact (Polonsky–Keer) did not converge in {MAX_CG_ITERATIONS} iterations"
    )))
}

/// The contact pressure [Pa] by the S-metric projected fixed point (tau0 = 0, c = 0): stops when
/// max |dp| <= `tol` (1 - q) pbar between outer iterations (q = sin phi_max, the contraction
/// factor, so the distance to the fixed point is about `tol` pbar), after at most
/// `max_iterations`. Returns the pressure and the outer iterations.
pub fn solve(
    op: &mut Operator,
    shape: &[f64],
    pbar: f64,
    tol: f64,
    max_iterations: usize,
) -> Result<(Vec<f64>, usize), SolveError> {
    let n = shape.len();
    let t = op.multipliers.tan_phi_max();
    let omega = 1.0 / (1.0 + t * t);
    let q = t / (1.0 + t * t).sqrt();
    let mut p = vec![pbar; n];
    let (mut kp, mut sp, mut b) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    for iteration in 1..=max_iterations {
        op.apply(&p, &mut kp, 0.0);
        op.symmetric(&p, &mut sp);
        // b = S p - w (K p - U)
        for i in 0..n {
            b[i] = sp[i] - omega * (kp[i] - shape[i]);
        }
        let old = p.clone();
        frictionless(op, &b, pbar, &mut p, 0.01 * tol * (1.0 - q))?;
        let change = p
            .iter()
            .zip(&old)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        if change <= tol * (1.0 - q) * pbar {
            return Ok((p, iteration));
        }
    }
    Err(SolveError::NoSolution(format!(
        "the projected fixed point did not converge in {max_iterations} iterations"
    )))
}
