//! The production contact solver: primal–dual active set with restarted GMRES on FFT products
//! (docs/physics/spatial-partial.md section 3).
//!
//! For a contact set C, the bordered non-symmetric system
//!   (K + D)_CC p_C + d 1 = U_C + tau0 T[1_C]_C,   sum p_C = N pbar,
//! (D a diagonal: uniform c, or per node) is solved matrix-free with p/pbar and d/(pbar max A) as
//! unknowns, the load row scaled to unit norm and the full-cell inverse (K + c)^-1 (c the mean of
//! D) as right preconditioner. Then
//!   C <- {i in C: p_i > 0} u {i not in C: gap_i < 0},
//! until C repeats. A set seen before is a cycle: the state of the cycle with the smallest natural
//! residual is kept and the cycle reported. The first sets are solved to a loose tolerance; once
//! a set repeats, it is solved again to the full tolerance before it is accepted.
//!
//! With adhesion, the full update can jump back and forth across a wide strip at an edge, or
//! wander among its nodes without ever repeating. At the first cycle, or when the smallest
//! residual has not improved for `STALL` iterations, the iteration restarts from the set of
//! smallest residual with the update limited to the ends of the contact zones
//! ([`zone_ends::limit`]): each end moves by at most a reach of nodes, which starts at one, doubles
//! while the residual falls and halves when it grows, until the set converges or cycles.

use crate::physics::SolveError;
use crate::physics::spatial::partial::gmres::{Preconditioned, gmres};
use crate::physics::spatial::partial::operator::{Diagonal, Operator};
use crate::physics::spatial::partial::zone_ends;
use crate::physics::stop::{STOPPED, Stop};

/// Most active-set iterations.
pub const MAX_ACTIVE_SET_ITERATIONS: usize = 100;
/// Iterations without a smaller residual after which the update is limited to the zone ends.
const STALL: usize = 12;
/// GMRES restart length.
const RESTART: usize = 40;
/// Most GMRES products per active-set iteration.
const MAX_LINEAR_ITERATIONS: usize = 4000;
/// GMRES tolerance, relative to the norm of the scaled right-hand side.
const LINEAR_TOLERANCE: f64 = 1e-13;
/// The looser tolerance of the first sets (inexact Newton): a set is accepted only after a solve
/// to `LINEAR_TOLERANCE` reproduces it.
const LOOSE_TOLERANCE: f64 = 1e-6;

/// One contact problem: the shape and the load, with the operator K + D.
#[derive(Clone, Copy, Debug)]
pub struct ContactProblem<'a> {
    /// U [m] at the nodes (zero mean).
    pub shape: &'a [f64],
    /// pbar [Pa] > 0.
    pub mean_pressure: f64,
    /// tau0 [Pa], acting only in contact.
    pub adhesion: f64,
    /// D [m/Pa] >= 0 added to K (c dt k_w in an implicit wear step; uniform 0 for a plain
    /// contact). Complete contact is returned without iterating only for a uniform D.
    pub diagonal: Diagonal<'a>,
    /// Asked before every active-set iteration and every product of its linear solve: when it
    /// says so, the solve ends with the error `stop::STOPPED`.
    pub stop: Stop<'a>,
}

/// The solution of one contact problem.
#[derive(Clone, Debug, PartialEq)]
pub struct ContactSolution {
    /// p [Pa] at the nodes.
    pub pressure: Vec<f64>,
    /// d [m]: the rigid offset of the problem with K + D (the mean gap when D = 0).
    pub offset: f64,
    /// True when p_cc >= 0 at every node and the closed form was returned.
    pub complete: bool,
    /// Active-set iterations (0 for complete contact).
    pub iterations: usize,
    /// GMRES products in all.
    pub linear_iterations: usize,
    /// True when the active set cycled: the state of smallest residual is returned, with any
    /// negative nodal pressure clipped to 0 and the rest scaled to keep the load.
    pub cycled: bool,
    /// True when the update was limited to the ends of the contact zones (the sets had cycled or
    /// stalled).
    pub damped: bool,
    /// max |min(p/pbar, gap/(pbar max A))| over the nodes (before the clipping of a cycle).
    pub residual: f64,
}

impl ContactSolution {
    /// The contact set {p > 0}.
    pub fn contact(&self) -> Vec<bool> {
        self.pressure.iter().map(|p| *p > 0.0).collect()
    }
}

/// The bordered system on the contact nodes `active`.
struct Bordered<'a> {
    op: &'a mut Operator,
    active: &'a [usize],
    diagonal: Diagonal<'a>,
    scale: f64,
    full: Vec<f64>,
    image: Vec<f64>,
}

impl Bordered<'_> {
    /// Writes x onto the contact nodes of `full` (zero elsewhere since construction).
    fn extend(&mut self, x: &[f64]) {
        for (k, &i) in self.active.iter().enumerate() {
            self.full[i] = x[k];
        }
    }
}

impl Preconditioned for Bordered<'_> {
    fn apply(&mut self, x: &[f64], y: &mut [f64]) {
        let n = self.active.len();
        self.extend(&x[..n]);
        self.op
            .apply_diagonal(&self.full, &mut self.image, self.diagonal);
        for (k, &i) in self.active.iter().enumerate() {
            y[k] = self.image[i] / self.scale + x[n];
        }
        y[n] = x[..n].iter().sum::<f64>() / (n as f64).sqrt();
    }

    fn precondition(&mut self, r: &[f64], z: &mut [f64]) {
        let n = self.active.len();
        self.extend(&r[..n]);
        self.op
            .inverse(&self.full, &mut self.image, self.diagonal.mean());
        for (k, &i) in self.active.iter().enumerate() {
            z[k] = self.image[i] * self.scale;
        }
        let shift = (r[n] * (n as f64).sqrt() - z[..n].iter().sum::<f64>()) / n as f64;
        z[..n].iter_mut().for_each(|v| *v += shift);
        z[n] = r[..n].iter().sum::<f64>() / n as f64;
    }
}

/// A contact set as bits, to recognise a set seen before.
fn bits(set: &[bool]) -> Vec<u64> {
    set.chunks(64)
        .map(|c| {
            c.iter()
                .enumerate()
                .fold(0u64, |w, (b, &on)| w | (u64::from(on) << b))
        })
        .collect()
}

/// p_cc = pbar + (K + c)^-1 [U] at the nodes (c the mean of D): the complete-contact pressure
/// (tau0 drops out) for a uniform D, a first guess for a nodal one.
pub fn complete_pressure(op: &mut Operator, prob: &ContactProblem) -> Vec<f64> {
    let mut p = vec![0.0; prob.shape.len()];
    op.inverse(prob.shape, &mut p, prob.diagonal.mean());
    p.iter_mut().for_each(|v| *v += prob.mean_pressure);
    p
}

/// Solves the contact problem by the primal–dual active set, starting from `start` (a previous
/// contact set) or from {p_cc > 0}. Complete contact (min p_cc >= 0) returns p_cc without
/// iterating when D is uniform; a nodal D starts from every node in contact.
pub fn solve(
    op: &mut Operator,
    prob: &ContactProblem,
    start: Option<&[bool]>,
) -> Result<ContactSolution, SolveError> {
    let n = prob.shape.len();
    let pbar = prob.mean_pressure;
    let p_cc = complete_pressure(op, prob);
    let c = prob.diagonal.mean();
    let uniform = matches!(prob.diagonal, Diagonal::Uniform(_));
    if uniform && p_cc.iter().all(|p| *p >= 0.0) {
        return Ok(ContactSolution {
            pressure: p_cc,
            // the mean of the rows: c pbar + d = <U> = 0 (written so that c = 0 gives +0)
            offset: 0.0 - c * pbar,
            complete: true,
            iterations: 0,
            linear_iterations: 0,
            cycled: false,
            damped: false,
            residual: 0.0,
        });
    }
    let scale = op.multipliers.max_normal() + c;
    let gap_scale = pbar * scale;
    let mut set: Vec<bool> = match start {
        Some(s) if s.iter().any(|v| *v) => s.to_vec(),
        _ if !uniform => vec![true; n],
        _ => p_cc.iter().map(|p| *p > 0.0).collect(),
    };
    let mut pressure = p_cc;
    let mut offset = 0.0 - c * pbar;
    let mut seen: Vec<Vec<u64>> = Vec::new();
    let mut best: Option<ContactSolution> = None;
    // the set of the state `best` and the iterations since `best` last improved
    let mut best_set: Vec<bool> = Vec::new();
    let mut stalled = 0;
    let mut damped = false;
    // the damped update's reach [nodes] and the residual of the previous damped iteration
    let (mut reach, mut last_residual) = (1, f64::INFINITY);
    let mut linear_iterations = 0;
    let (mut full, mut image, mut gap) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut relative_tolerance = LOOSE_TOLERANCE;
    for iteration in 1..=MAX_ACTIVE_SET_ITERATIONS {
        if prob.stop.now() {
            return Err(SolveError::NoSolution(STOPPED.into()));
        }
        let active: Vec<usize> = (0..n).filter(|&i| set[i]).collect();
        let m = active.len();
        // tau0 T[1_C]: the adhesive shear of this contact set
        let mut lift = vec![0.0; n];
        if prob.adhesion > 0.0 {
            let ones: Vec<f64> = set.iter().map(|&on| f64::from(u8::from(on))).collect();
            op.shear(&ones, &mut lift);
            lift.iter_mut().for_each(|v| *v *= prob.adhesion);
        }
        let mut rhs: Vec<f64> = active
            .iter()
            .map(|&i| (prob.shape[i] + lift[i]) / gap_scale)
            .collect();
        rhs.push(n as f64 / (m as f64).sqrt());
        let mut x: Vec<f64> = active.iter().map(|&i| pressure[i] / pbar).collect();
        x.push(offset / gap_scale);
        let rhs_norm = rhs.iter().map(|v| v * v).sum::<f64>().sqrt();
        let tol = relative_tolerance * rhs_norm;
        let mut sys = Bordered {
            op,
            active: &active,
            diagonal: prob.diagonal,
            scale,
            full: {
                full.iter_mut().for_each(|v| *v = 0.0);
                std::mem::take(&mut full)
            },
            image: std::mem::take(&mut image),
        };
        let out = gmres(
            &mut sys,
            &rhs,
            &mut x,
            RESTART,
            MAX_LINEAR_ITERATIONS,
            tol,
            prob.stop,
        );
        (full, image) = (sys.full, sys.image);
        linear_iterations += out.iterations;
        if out.stopped {
            return Err(SolveError::NoSolution(STOPPED.into()));
        }
        if !out.converged {
            return Err(SolveError::NoSolution(format!(
                "the contact solver's linear solve did not converge in {MAX_LINEAR_ITERATIONS} \
                 GMRES iterations (relative residual {:.1e})",
                out.residual / rhs_norm
            )));
        }
        pressure.iter_mut().for_each(|v| *v = 0.0);
        for (k, &i) in active.iter().enumerate() {
            pressure[i] = x[k] * pbar;
        }
        offset = x[m] * gap_scale;
        // gap = d - U + (K + c) p - tau0 T[1_C]
        op.apply_diagonal(&pressure, &mut gap, prob.diagonal);
        for i in 0..n {
            gap[i] += offset - prob.shape[i] - lift[i];
        }
        let residual = (0..n)
            .map(|i| (pressure[i] / pbar).min(gap[i] / gap_scale).abs())
            .fold(0.0, f64::max);
        let mut next: Vec<bool> = (0..n)
            .map(|i| {
                if set[i] {
                    pressure[i] > 0.0
                } else {
                    gap[i] < 0.0
                }
            })
            .collect();
        let state = |cycled| ContactSolution {
            pressure: pressure.clone(),
            offset,
            complete: false,
            iterations: iteration,
            linear_iterations,
            cycled,
            damped,
            residual,
        };
        let loose = relative_tolerance > LINEAR_TOLERANCE;
        if next == set || (loose && seen.contains(&bits(&next))) {
            if loose {
                // solve this set again, tightly, before accepting it or calling it a cycle
                relative_tolerance = LINEAR_TOLERANCE;
                seen.clear();
                best = None;
                continue;
            }
            if next == set {
                return Ok(state(false));
            }
        }
        if best.as_ref().is_none_or(|b| residual < b.residual) {
            best = Some(state(false));
            best_set.clone_from(&set);
            stalled = 0;
        } else {
            stalled += 1;
        }
        if !damped && stalled >= STALL {
            // restart from the set of smallest residual, tightly, with the damped update
            (damped, stalled, relative_tolerance) = (true, 0, LINEAR_TOLERANCE);
            set = std::mem::take(&mut best_set);
            (seen, best) = (Vec::new(), None);
            continue;
        }
        if damped {
            let violation: Vec<f64> = (0..n)
                .map(|i| {
                    let v = if set[i] {
                        -pressure[i] / pbar
                    } else {
                        -gap[i] / gap_scale
                    };
                    v.max(0.0)
                })
                .collect();
            if last_residual.is_finite() {
                reach = if residual < last_residual {
                    (2 * reach).min(n)
                } else {
                    (reach / 2).max(1)
                };
            }
            last_residual = residual;
            next = zone_ends::limit(op.grid(), &set, &next, &violation, reach);
        }
        if seen.contains(&bits(&next)) && !damped {
            // a cycle of the full update: walk from the set of smallest residual again with the
            // damped update, keeping that state in case no better one comes
            (damped, stalled) = (true, 0);
            set = std::mem::take(&mut best_set);
            seen.clear();
            continue;
        }
        if seen.contains(&bits(&next)) {
            let mut b = best.expect("set after the first iteration");
            (b.cycled, b.iterations, b.linear_iterations) = (true, iteration, linear_iterations);
            b.damped = true;
            // a node of the ill-posed zone may hold a small negative pressure: clip it, keeping
            // the load (the outputs change by O(tau0 w), section 8)
            b.pressure.iter_mut().for_each(|v| *v = v.max(0.0));
            let scale = pbar * n as f64 / b.pressure.iter().sum::<f64>();
            b.pressure.iter_mut().for_each(|v| *v *= scale);
            return Ok(b);
        }
        seen.push(bits(&set));
        set = next;
    }
    Err(SolveError::NoSolution(if damped {
        format!(
            "the contact set did not settle within {MAX_ACTIVE_SET_ITERATIONS} active-set \
             iterations (the bound was reached; the last ones, moving only the ends of the contact \
             zones, neither converged nor cycled)"
        )
    } else {
        format!(
            "the contact set did not settle within {MAX_ACTIVE_SET_ITERATIONS} active-set \
             iterations (the bound was reached)"
        )
    }))
}
