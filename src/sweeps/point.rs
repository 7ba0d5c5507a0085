//! One point of a sweep or a map: a preset solved through the library's own pipeline, the same
//! functions `wearlab solve` reports from, so that every number is bit for bit the one
//! `wearlab solve --set` prints at the same inputs.
//!
//! - plane: `plane::solve` and `validity::estimate`, the stages of `plane::operating_point`; the
//!   verdict measured against the strip model, the energy identity (its costly quadrature), the
//!   largest pressure and the wear at the tip are computed only when a quantity asks for them.
//! - spatial: `spatial::pipeline::solve` (complete contact in closed form, partial contact
//!   through the running-in), without the mean-pressure sweep, which no quantity reads.

use std::cell::OnceCell;

use crate::physics::SolveError;
use crate::physics::plane::energy::{Energy, Undefined, energy};
use crate::physics::plane::strip_check::verdict;
use crate::physics::plane::validity::{Validity, estimate};
use crate::physics::plane::{self, PlaneSolution};
use crate::physics::quadrature::tanh_sinh;
use crate::physics::spatial::SpatialInputs;
use crate::physics::spatial::partial::running_in::Stopped;
use crate::physics::spatial::pipeline;
use crate::physics::spatial::result::SpatialResult;
use crate::physics::stop::Stop;
use crate::preset::{Preset, Problem};

/// A solved plane point.
#[derive(Debug)]
pub struct PlanePoint {
    /// The solution.
    pub solution: PlaneSolution,
    /// The study's estimate of the model's validity at this point (`validity::estimate`); the
    /// verdict is `verdict`.
    pub validity: Validity,
    verdict: OnceCell<Validity>,
    energy: OnceCell<Result<Energy, Undefined>>,
}

/// A solved spatial point.
#[derive(Debug)]
pub struct SpatialPoint {
    /// The inputs.
    pub inputs: SpatialInputs,
    /// The problem at the preset's time, as `wearlab solve` reports it (without its `sweep`).
    pub result: SpatialResult,
}

/// A solved point of either problem.
#[derive(Debug)]
pub enum Point {
    /// The plane problem.
    Plane(Box<PlanePoint>),
    /// The spatial problem.
    Spatial(Box<SpatialPoint>),
}

/// Solves the preset's problem at its own values.
pub fn solve(preset: &Preset) -> Result<Point, SolveError> {
    solve_until(preset, Stop::Never).map_err(SolveError::from)
}

/// As [`solve`], told to stop by `stop`: a spatial point asks it before every time step and
/// every active-set iteration of its running-in (`Stopped::Cancelled`); a plane point is solved
/// whole.
pub fn solve_until(preset: &Preset, stop: Stop) -> Result<Point, Stopped> {
    match preset.problem {
        Problem::Plane => {
            let solution = plane::solve(&preset.plane_inputs(), preset.plane.model)?;
            Ok(Point::Plane(Box::new(PlanePoint {
                validity: estimate(&solution),
                solution,
                verdict: OnceCell::new(),
                energy: OnceCell::new(),
            })))
        }
        Problem::Spatial => {
            let inputs = preset.spatial_inputs();
            let at = preset.spatial_state_at();
            let result = pipeline::solve_until(&inputs, &at, &[], false, stop)?;
            Ok(Point::Spatial(Box::new(SpatialPoint { inputs, result })))
        }
    }
}

impl PlanePoint {
    /// The verdict `wearlab solve` reports (`strip_check::verdict`: measured against the strip
    /// model where the estimate doubts the model), computed on first use.
    pub fn verdict(&self) -> &Validity {
        self.verdict.get_or_init(|| verdict(&self.solution))
    }

    /// How far the verdict is from changing where the measurement against the strip model
    /// decides it: 1 minus the larger deviation over its tolerance (`Deviation::ratios`),
    /// dimensionless, positive where the model holds; None where the study's estimate or an
    /// assumption decides.
    pub fn verdict_margin(&self) -> Option<f64> {
        let verdict = self.verdict();
        let [width, mu] = verdict.measured_error?.ratios();
        let margin = 1.0 - width.max(mu);
        (verdict.ok == (margin > 0.0)).then_some(margin)
    }

    /// The two sides of the energy identity (2.9), computed on first use.
    pub fn energy(&self) -> Result<Energy, Undefined> {
        *self.energy.get_or_init(|| energy(&self.solution))
    }

    /// The largest contact pressure max q2 [Pa]: a scan of 64 intervals of [-a, b], then a golden
    /// section search of the best one (100 steps at most, to 1e-12 of the width).
    pub fn max_pressure(&self) -> f64 {
        const SCAN: usize = 64;
        let sol = &self.solution;
        let l = sol.contact_width();
        let q = |u: f64| sol.pressure_from_trailing_edge(u);
        let at = |i: usize| l * i as f64 / SCAN as f64;
        let best = (1..SCAN)
            .max_by(|i, j| q(at(*i)).total_cmp(&q(at(*j))))
            .unwrap_or(1);
        let (mut lo, mut hi) = (at(best - 1), at(best + 1));
        let ratio = 0.5 * (5f64.sqrt() - 1.0);
        let mut x1 = hi - ratio * (hi - lo);
        let mut x2 = lo + ratio * (hi - lo);
        let (mut q1, mut q2) = (q(x1), q(x2));
        for _ in 0..100 {
            if hi - lo <= 1e-12 * l {
                break;
            }
            if q1 < q2 {
                (lo, x1, q1) = (x1, x2, q2);
                x2 = lo + ratio * (hi - lo);
                q2 = q(x2);
            } else {
                (hi, x2, q2) = (x2, x1, q1);
                x1 = hi - ratio * (hi - lo);
                q1 = q(x1);
            }
        }
        q1.max(q2).max(q(at(best)))
    }

    /// The wear per pass at the punch tip [m]: k times the integral of q2 from the tip (x = 0, or
    /// the nearer end of the contact when the tip lies outside it) to the leading edge b, the
    /// depth a strip point under the tip's track loses in one pass (tanh-sinh, step 1/16).
    pub fn tip_wear(&self) -> f64 {
        let sol = &self.solution;
        let from = 0f64.clamp(-sol.a, sol.b);
        let rule = tanh_sinh(1.0 / 16.0);
        sol.inputs.wear.coefficient * rule.integrate(from, sol.b, |x| sol.pressure(x))
    }
}
