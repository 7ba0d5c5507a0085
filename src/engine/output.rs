//! What the engine is asked (`Request`) and what it answers, stage by stage (`Answer`, the
//! plane and spatial outputs), and how often each stage was computed (`StageCounts`).

use std::sync::Arc;

use crate::physics::SolveError;
use crate::physics::plane::strip_check::StripCheck;
use crate::physics::plane::sweep::{EnergySweep, Sweep};
use crate::physics::plane::yield_onset::YieldCheck;
use crate::physics::plane::{Model, OperatingPoint};
use crate::physics::spatial::history::{Dispersion, History};
use crate::physics::spatial::{SpatialState, pipeline};
use crate::preset::Preset;

use super::cell::CellOutput;
use super::surface::SurfaceOutput;

/// What the explorer asks the engine for.
#[derive(Clone, Debug, PartialEq)]
pub struct Request {
    /// The preset to solve; its `problem` says which.
    pub preset: Preset,
    /// Also compute what only one chart draws, asked only while it is visible: the plane models
    /// other than the preset's (the overlays of mu*(P)); the spatial mu*(pbar) on the period
    /// cell.
    pub overlays: bool,
    /// Also compute the energy losses along the plane load sweep (asked only while the energy
    /// chart is visible).
    pub energies: bool,
}

/// What is known of the plane problem.
#[derive(Clone, Debug)]
pub struct PlaneOutput {
    /// The operating point, or why there is none.
    pub point: Result<Arc<OperatingPoint>, SolveError>,
    /// The point's model against the exact strip model; None until computed, and when there is
    /// no point.
    pub strip_check: Option<StripCheck>,
    /// The point's largest von Mises stress against the strip's yield stress; None until
    /// computed, without a point, and where the preset gives neither Y nor H.
    pub yield_check: Option<YieldCheck>,
    /// The preset's model swept over the preset's loads; None until computed, its verdicts
    /// not yet measured while `judged` is false.
    pub sweep: Option<Arc<Sweep>>,
    /// The other models' sweeps, when asked for and computed.
    pub overlays: Vec<(Model, Arc<Sweep>)>,
    /// The energy losses along the preset's load sweep, when asked for and computed.
    pub energies: Option<Arc<EnergySweep>>,
}

impl PlaneOutput {
    /// Sets the sweep of model `m` (`own`: the preset's model) or replaces it among the overlays.
    pub(super) fn put_sweep(&mut self, own: Model, m: Model, sweep: Arc<Sweep>) {
        if m == own {
            self.sweep = Some(sweep);
        } else if let Some(o) = self.overlays.iter_mut().find(|(o, _)| *o == m) {
            o.1 = sweep;
        } else {
            self.overlays.push((m, sweep));
        }
    }
}

/// What is known of the spatial problem.
#[derive(Clone, Debug)]
pub struct SpatialOutput {
    /// Everything at the preset's time.
    pub state: Arc<SpatialState>,
    /// A_n(t), mu*(t) over the duration; None until computed.
    pub history: Option<Arc<History>>,
    /// Drift velocity against wavenumber and direction.
    pub dispersion: Arc<Dispersion>,
    /// The contact solved on the period cell (partial contact, the running-in); Err: why it is
    /// not (no period cell, a grid too coarse), and the closed form alone is known.
    pub cell: Result<CellOutput, SolveError>,
    /// Without a period cell, whether the harmonics as given are in complete contact at t = 0
    /// (`pipeline::contact_at_start`); None where the cell is solved (it says so itself).
    pub complete_at_start: Option<bool>,
}

impl SpatialOutput {
    /// True when the closed form of the harmonics holds at t (`pipeline::closed_form_holds`):
    /// the linear wear law, the contact complete from t = 0 on and at t. Every chart and status asks this.
    pub fn closed_form_holds(&self) -> bool {
        let from_start = match (&self.cell, self.complete_at_start) {
            (Ok(c), _) => c.complete_from_start,
            (Err(_), at_start) => at_start.unwrap_or(false),
        };
        let inputs = &self.state.solution.inputs;
        pipeline::closed_form_holds(inputs, from_start, self.state.contact.complete)
    }
}

/// The engine's answer to one request, at one stage.
#[derive(Clone, Debug)]
pub enum Output {
    /// Plane problem.
    Plane(PlaneOutput),
    /// Spatial problem, or why its inputs cannot be solved.
    Spatial(Result<SpatialOutput, SolveError>),
    /// Spatial problem of a height-map punch (`spatial.surface`), or why it cannot be solved.
    Surface(Result<SurfaceOutput, SolveError>),
}

/// One delivery of the worker: the request it answers, what is known so far, and whether it is
/// the last delivery for that request.
#[derive(Clone, Debug)]
pub struct Answer {
    /// The generation number the request was submitted with.
    pub generation: u64,
    /// The request answered (the inputs every value in `output` was computed from).
    pub request: Arc<Request>,
    /// The results so far.
    pub output: Output,
    /// True when nothing more comes for this request.
    pub complete: bool,
}

/// How often each stage has been computed (for tests of the caching).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StageCounts {
    /// Plane operating points.
    pub operating_point: usize,
    /// Plane operating points checked against the strip model.
    pub strip_check: usize,
    /// Plane operating points checked for yield (`plane::yield_onset::judge`).
    pub yield_check: usize,
    /// Plane load sweeps.
    pub load_sweep: usize,
    /// Plane energy losses along the load sweep.
    pub energy_sweep: usize,
    /// Spatial harmonic responses (with the dispersion curves).
    pub responses: usize,
    /// Spatial histories.
    pub history: usize,
    /// Spatial states at time t (with field, contact check and mean-pressure sweep).
    pub state: usize,
    /// Running-ins started on the period cell (each one contact solve at t = 0).
    pub running_in: usize,
    /// Wear steps of the running-ins.
    pub wear_steps: usize,
    /// Contact states at time t on the period cell (replayed from a running-in).
    pub contact_state: usize,
    /// Running-in histories over the duration, once the stepping is over.
    pub cell_history: usize,
    /// mu*(pbar) curves on the period cell.
    pub load_curve: usize,
}
