//! One implicit wear step of the zero-mean shape U (docs/physics/spatial-partial.md section 5),
//! from t_k to t_{k+1} = t_k + h, as one contact solve with the operator K + c k_w:
//!   BE (first step, c = h):  U1 = U0 - h k_w (p1 - pbar),
//!   BDF2 with variable step, w = h/h1 (h1 = t_k - t_{k-1}), c = h (1 + w)/(1 + 2w):
//!     U_{k+1} = ((1 + w)^2 U_k - w^2 U_{k-1})/(1 + 2w) - c k_w (p_{k+1} - pbar)
//! (Hairer, Norsett, Wanner, Solving ODEs I, section III.5, the variable-step BDF; w = 1 gives
//! the constant-step (4 U_k - U_{k-1})/3 - (2/3) h k_w (p - pbar)). (U_{k+1}, p_{k+1}) then
//! solves the true contact problem for U_{k+1}. A nonlinear wear law (n != 1) replaces p - pbar by
//! F(p) - <F(p)> and solves the step by Newton's method ([`super::nonlinear`]).
//!
//! The local error is estimated by comparison with a predictor (Milne's device, Hairer, Norsett,
//! Wanner, section III.7): the quadratic through U_{k-1} at t_{k-1} and U_k at t_k with the slope
//! U'_k = -k_w (p_k - pbar), extrapolated to t_{k+1}. For a smooth U the predictor misses by
//! -(1/6) h^2 (h + h1) U''' and BDF2 by +(1/6) h^2 (h + h1)^2/(2h + h1) U''', so the error of
//! BDF2 is (h + h1)/(3h + 2h1) times the difference (2/5 at constant step); after the first step
//! (BE against explicit Euler, misses of +-h^2 U''/2) it is half the difference.

use crate::physics::SolveError;
use crate::physics::spatial::partial::Setup;
use crate::physics::spatial::partial::active_set::{ContactProblem, ContactSolution, solve};
use crate::physics::spatial::partial::operator::{Diagonal, Operator};
use crate::physics::spatial::partial::running_in::nonlinear;
use crate::physics::stop::Stop;

/// The implicit stepper at step k: t_{k-1} and U_{k-1}, t_k and U_k, its contact set and slope.
pub struct Stepper<'a> {
    /// The problem.
    pub setup: &'a Setup,
    /// The operator (its buffers are reused by every step).
    pub op: Operator,
    /// k: the steps done.
    pub step: usize,
    /// t_k [s].
    pub time: f64,
    /// t_{k-1} [s] and U_{k-1} [m] (None at k = 0: the next step is BE).
    pub previous: Option<(f64, Vec<f64>)>,
    /// U_k [m].
    pub current: Vec<f64>,
    /// The contact set of step k (the next step starts from it).
    pub contact: Vec<bool>,
    /// U'_k = -k_w (p_k - pbar) [m/s], for the error estimate (None: steps are not estimated).
    pub slope: Option<Vec<f64>>,
    /// Asked before every active-set iteration of a step (`Stop::Never` from `new`).
    pub stop: Stop<'a>,
}

/// A step tried but not yet taken.
pub struct Trial {
    /// t_{k+1} [s].
    pub time: f64,
    /// U_{k+1} [m].
    pub shape: Vec<f64>,
    /// The step's contact solution (for K + c k_w).
    pub solution: ContactSolution,
    /// The mean gap [m] of the true problem for U_{k+1}.
    pub mean_gap: f64,
    /// False when the Newton iterates of a nonlinear wear law did not converge: the step is
    /// refused.
    pub converged: bool,
}

impl<'a> Stepper<'a> {
    /// A stepper at step `step`, time `time` with U_k = `current` and its contact set; `previous`
    /// is (t_{k-1}, U_{k-1}).
    pub fn new(
        setup: &'a Setup,
        step: usize,
        time: f64,
        previous: Option<(f64, Vec<f64>)>,
        current: Vec<f64>,
        contact: Vec<bool>,
    ) -> Stepper<'a> {
        Stepper {
            op: setup.operator(),
            setup,
            step,
            time,
            previous,
            current,
            contact,
            slope: None,
            stop: Stop::Never,
        }
    }

    /// The step to `time` > t_k (BE when k = 0, BDF2 after), not taken.
    pub fn trial(&mut self, time: f64) -> Result<Trial, SolveError> {
        let inputs = &self.setup.inputs;
        let (pbar, k_w) = (inputs.mean_pressure, inputs.wear_rate());
        let h = time - self.time;
        let (base, c) = match &self.previous {
            None => (self.current.clone(), h * k_w),
            Some((before, u0)) => {
                let w = h / (self.time - before);
                let (a, b) = ((1.0 + w) * (1.0 + w), w * w);
                let d = 1.0 + 2.0 * w;
                let base = self
                    .current
                    .iter()
                    .zip(u0)
                    .map(|(u1, u0)| (a * u1 - b * u0) / d)
                    .collect();
                (base, h * (1.0 + w) / d * k_w)
            }
        };
        if !inputs.linear_wear() {
            let step = nonlinear::step(self, &base, c)?;
            return Ok(Trial {
                time,
                shape: step.shape,
                solution: step.solution,
                mean_gap: step.mean_gap,
                converged: step.converged,
            });
        }
        let problem = ContactProblem {
            shape: &base,
            mean_pressure: pbar,
            adhesion: inputs.friction.adhesion,
            diagonal: Diagonal::Uniform(c),
            stop: self.stop,
        };
        let solution = solve(&mut self.op, &problem, Some(&self.contact))?;
        let shape = base
            .iter()
            .zip(&solution.pressure)
            .map(|(u, p)| u - c * (p - pbar))
            .collect();
        let mean_gap = solution.offset + c * pbar;
        Ok(Trial {
            time,
            shape,
            solution,
            mean_gap,
            converged: true,
        })
    }

    /// The local error estimate of `trial` as a vector [m] (None without the slope U'_k).
    pub fn local_error(&self, trial: &Trial) -> Option<Vec<f64>> {
        let slope = self.slope.as_ref()?;
        if !trial.converged {
            return Some(vec![f64::INFINITY; slope.len()]);
        }
        let h = trial.time - self.time;
        let u1 = &self.current;
        Some(match &self.previous {
            None => (0..u1.len())
                .map(|i| 0.5 * (trial.shape[i] - (u1[i] + h * slope[i])))
                .collect(),
            Some((before, u0)) => {
                let h1 = self.time - before;
                let (r, factor) = ((h / h1) * (h / h1), (h + h1) / (3.0 * h + 2.0 * h1));
                (0..u1.len())
                    .map(|i| {
                        let predicted = u1[i] + h * slope[i] + r * (u0[i] - u1[i] + h1 * slope[i]);
                        factor * (trial.shape[i] - predicted)
                    })
                    .collect()
            }
        })
    }

    /// Takes the step `trial`.
    pub fn accept(&mut self, trial: Trial) {
        if self.slope.is_some() {
            self.slope = Some(slope(self.setup, &trial.solution.pressure));
        }
        let before = std::mem::replace(&mut self.current, trial.shape);
        self.previous = Some((self.time, before));
        self.time = trial.time;
        self.contact = trial.solution.contact();
        self.step += 1;
    }

    /// The step to `time` taken: its contact solution and mean gap [m].
    pub fn advance(&mut self, time: f64) -> Result<(ContactSolution, f64), SolveError> {
        let trial = self.trial(time)?;
        if !trial.converged {
            return Err(nonlinear::unconverged(time));
        }
        let out = (trial.solution.clone(), trial.mean_gap);
        self.accept(trial);
        Ok(out)
    }
}

/// U' = -k_w (F(p) - <F(p)>) [m/s] for the pressure p [Pa] (F(p) = p, <F(p)> = pbar for the
/// linear law).
pub(super) fn slope(setup: &Setup, pressure: &[f64]) -> Vec<f64> {
    let inputs = &setup.inputs;
    let (pbar, k_w) = (inputs.mean_pressure, inputs.wear_rate());
    if inputs.linear_wear() {
        return pressure.iter().map(|p| -k_w * (p - pbar)).collect();
    }
    let worn: Vec<f64> = pressure.iter().map(|p| inputs.worn_pressure(*p)).collect();
    let mean = worn.iter().sum::<f64>() / worn.len() as f64;
    worn.iter().map(|f| -k_w * (f - mean)).collect()
}
