//! A height-map punch (`spatial.surface`) in the explorer. A map has no closed form of a few
//! harmonics: every value comes from the nodes of its own grid, as `wearlab solve` answers it
//! (`pipeline::solve`): the running-in on the cell, stepped with progress and stopped by a newer
//! request (`cell`), and the surface's statistics and PSD as given and at the state shown.

use std::sync::Arc;

use crate::engine::cell::{Ask, CellKey};
use crate::engine::{CellOutput, Engine, Output, Proceed, Request};
use crate::physics::spatial::SpatialInputs;
use crate::physics::spatial::partial::state::State;
use crate::physics::spatial::pipeline;
use crate::physics::spatial::result::SurfaceResult;
use crate::physics::stop::Stop;
use crate::physics::{SolveError, limits};

/// What is known of a height-map punch.
#[derive(Clone, Debug)]
pub struct SurfaceOutput {
    /// The contact on the map's grid (the running-in that leads to the preset's time); Err: why
    /// it is not solved.
    pub cell: Result<CellOutput, SolveError>,
    /// The preset's time t [s].
    pub time: f64,
    /// The sliding friction coefficient mu of the inputs [-].
    pub mu: f64,
    /// k V of the inputs [m/(Pa s)]: punch wear depth per unit time per unit pressure.
    pub wear_rate: f64,
    /// The surface as given (t = 0): statistics, bearing-area curve and PSD.
    pub initial: Arc<SurfaceResult>,
    /// The same of the shape of the state shown (the cell's, at t once the running-in has
    /// reached it); None while there is none.
    pub shown: Option<Arc<SurfaceResult>>,
}

impl SurfaceOutput {
    /// The running-in's output, when the contact is solved.
    pub fn running_in(&self) -> Option<&CellOutput> {
        self.cell.as_ref().ok()
    }
}

impl Engine {
    /// The answer for validated inputs of a height map: at once what the running-in's start
    /// gives (one contact solve), then its progress, then the rest as for harmonics on a cell.
    pub(super) fn surface(
        &mut self,
        request: &Request,
        inputs: &SpatialInputs,
        cancelled: &dyn Fn() -> bool,
        stop: Stop,
        mut deliver: impl FnMut(Output, bool) -> Proceed,
    ) {
        let preset = &request.preset;
        let at = preset.spatial_state_at();
        let Some(surface) = inputs.surface() else {
            return;
        };
        if let Err(why) = limits::TIME.check("time", at.time) {
            deliver(Output::Surface(Err(SolveError::InvalidInput(why))), true);
            return;
        }
        let initial = Arc::new(SurfaceResult::of(surface));
        let key = CellKey {
            inputs: inputs.clone(),
            grid: at.grid,
            time_tolerance: at.time_tolerance,
        };
        let pressures = pipeline::sweep_pressures(&at);
        let ask = Ask {
            key: &key,
            time: at.time,
            duration: preset.spatial.duration,
            curve: request
                .overlays
                .then_some((&at.sweep, pressures.as_slice())),
            stop,
        };
        // the statistics of a state are computed once, not at every delivery of the same state
        let mut last: Option<(Arc<State>, Arc<SurfaceResult>)> = None;
        let mut output = |cell: Result<CellOutput, SolveError>| {
            let state = cell.as_ref().ok().and_then(|c| c.state.as_ref().ok());
            let shown = state.map(|s| match &last {
                Some((of, r)) if Arc::ptr_eq(of, s) => Arc::clone(r),
                _ => {
                    let r = Arc::new(pipeline::surface_at(s));
                    last = Some((Arc::clone(s), Arc::clone(&r)));
                    r
                }
            });
            Output::Surface(Ok(SurfaceOutput {
                cell,
                time: at.time,
                mu: inputs.friction.coefficient,
                wear_rate: inputs.wear_rate(),
                initial: Arc::clone(&initial),
                shown,
            }))
        };
        let cell = self.cell_now(&ask);
        // told to stop inside the first contact solve: a newer request waits
        if cell.is_err() && stop.now() {
            return;
        }
        let done = cell.as_ref().map_or(true, |c| c.done(ask.curve.is_some()));
        if !deliver(output(cell), done) || done {
            return;
        }
        self.cell_rest(&ask, cancelled, &mut |cell, complete| {
            deliver(output(Ok(cell)), complete)
        });
    }
}
