//! The incremental engine behind the explorer: the library's pipeline stages
//! (`plane::operating_point`, `strip_check::strip_check`, `sweep`, `spatial::evolutions`,
//! `spatial::state_at`, `history`, `dispersion`, and on the period cell the running-in and
//! mu*(pbar) of `spatial::partial`, the only stages of a height-map punch), each cached by the
//! typed inputs it depends on, so an edit recomputes only what it touches; and two background
//! workers on the newest request (`latest`): the solve worker (`Worker`), which answers in
//! stages, what the status shows first, and the sweep worker (`sweep_worker`). Long work (the
//! running-in, a sweep) reports progress and stops when a newer request arrives.

mod cache;
mod cell;
pub mod fit_worker;
mod footprint;
pub mod latest;
mod output;
mod solve_worker;
mod surface;
pub mod sweep_worker;
mod validity;

use std::sync::Arc;
use std::time::Duration;

use crate::physics::plane::strip_check::StripCheck;
use crate::physics::plane::sweep::{self, EnergySweep, Sweep, energy_sweep};
use crate::physics::plane::yield_onset::{Strength, YieldCheck};
use crate::physics::plane::{Model, OperatingPoint, PlaneInputs, operating_point};
use crate::physics::spatial::harmonic::Evolution;
use crate::physics::spatial::history::{Dispersion, History, dispersion, history};
use crate::physics::spatial::partial::history::History as RunHistory;
use crate::physics::spatial::partial::state::State;
use crate::physics::spatial::partial::sweep::LoadCurve;
use crate::physics::spatial::{self, SpatialInputs, SpatialState, StateAt, pipeline, state_at};
use crate::physics::stop::Stop;
use crate::physics::{Friction, Material, SolveError, SweepRange};
use crate::preset::Problem;
use cache::Cache;
use cell::{Ask, CellKey, Run};

pub use cache::{RUN_BYTES, STAGE_BYTES};
pub use cell::{CellOutput, Progress};
pub use output::{Answer, Output, PlaneOutput, Request, SpatialOutput, StageCounts};
pub use solve_worker::Worker;
pub use surface::SurfaceOutput;

/// Points of the plane profile drawn by the explorer.
pub const PROFILE_POINTS: usize = 201;
/// Points of the dispersion curves.
pub const DISPERSION_POINTS: usize = 120;
/// Points of the spatial time history (and of the closed-form part of a running-in's).
pub const HISTORY_POINTS: usize = 200;
/// Progress of long work is delivered at most this often.
pub const PROGRESS_EVERY: Duration = Duration::from_millis(100);

/// What the harmonic responses and the dispersion curves depend on.
#[derive(Clone, Debug, PartialEq)]
struct ResponseKey {
    material: Material,
    friction: Friction,
    wear_rate: f64,
    waves: Vec<(f64, f64)>,
}

impl ResponseKey {
    fn of(inputs: &SpatialInputs) -> ResponseKey {
        ResponseKey {
            material: inputs.material,
            friction: inputs.friction,
            wear_rate: inputs.wear_rate(),
            waves: inputs
                .harmonics()
                .iter()
                .map(|h| (h.wavenumber_x, h.wavenumber_y))
                .collect(),
        }
    }
}

type Responses = Arc<(Vec<Evolution>, Arc<Dispersion>)>;

/// The staged, cached solver.
pub struct Engine {
    points: Cache<(PlaneInputs, Model), Result<Arc<OperatingPoint>, SolveError>>,
    strip_checks: Cache<(PlaneInputs, Model), StripCheck>,
    yield_checks: Cache<(PlaneInputs, Model, Strength), Option<YieldCheck>>,
    /// Keyed by the inputs at unit load: a sweep does not depend on the load.
    sweeps: Cache<(PlaneInputs, Model, SweepRange), Arc<Sweep>>,
    /// Keyed like the sweeps.
    energies: Cache<(PlaneInputs, Model, SweepRange), Arc<EnergySweep>>,
    responses: Cache<ResponseKey, Responses>,
    histories: Cache<(SpatialInputs, f64), Arc<History>>,
    states: Cache<(SpatialInputs, StateAt), Result<Arc<SpatialState>, SolveError>>,
    runs: Cache<CellKey, Result<Run, SolveError>>,
    contact_states: Cache<(CellKey, f64), Result<Arc<State>, SolveError>>,
    run_histories: Cache<(CellKey, f64), Result<Arc<RunHistory>, SolveError>>,
    load_curves: Cache<(CellKey, f64, SweepRange), Result<Arc<LoadCurve>, SolveError>>,
    /// Stage evaluation counts.
    pub counts: StageCounts,
    /// Progress of long work is delivered at most this often (`PROGRESS_EVERY`).
    pub progress_every: Duration,
}

impl Default for Engine {
    fn default() -> Self {
        Self::new()
    }
}

/// Whether the engine should go on to the next stage after a delivery.
pub type Proceed = bool;

impl Engine {
    /// An engine with empty caches, each bounded in entries and in bytes (`STAGE_BYTES`, the
    /// running-ins `RUN_BYTES`): 8 operating points, their checks against the strip model and for
    /// yield, 6
    /// sweeps (two settings of three models), 2 energy sweeps, 4 sets of harmonic responses, 4
    /// histories and 2 spatial states (a 512-point grid holds 6 MB); on the period cell 2
    /// running-ins, 4 contact states, 4 running-in histories and 4 mu*(pbar) curves.
    pub fn new() -> Engine {
        Engine {
            points: Cache::new(8, STAGE_BYTES),
            strip_checks: Cache::new(8, STAGE_BYTES),
            yield_checks: Cache::new(8, STAGE_BYTES),
            sweeps: Cache::new(6, STAGE_BYTES),
            energies: Cache::new(2, STAGE_BYTES),
            responses: Cache::new(4, STAGE_BYTES),
            histories: Cache::new(4, STAGE_BYTES),
            states: Cache::new(2, STAGE_BYTES),
            runs: Cache::new(2, RUN_BYTES),
            contact_states: Cache::new(4, STAGE_BYTES),
            run_histories: Cache::new(4, STAGE_BYTES),
            load_curves: Cache::new(4, STAGE_BYTES),
            counts: StageCounts::default(),
            progress_every: PROGRESS_EVERY,
        }
    }

    /// Solves a request to the end, reusing every stage whose inputs did not change.
    pub fn run(&mut self, request: &Request) -> Output {
        let mut last = None;
        self.run_staged(request, |output, _| {
            last = Some(output);
            true
        });
        last.expect("every request is answered at least once")
    }

    /// Solves a request stage by stage: `deliver(output, complete)` gets what is known after the
    /// stage the status needs (the operating point, the state at t), the progress of long work,
    /// and again when the rest is done; when it returns false, the remaining stages are skipped.
    pub fn run_staged(&mut self, request: &Request, deliver: impl FnMut(Output, bool) -> Proceed) {
        self.run_cancellable(request, &|| false, deliver);
    }

    /// As [`Engine::run_staged`], and long work also stops between two of its steps when
    /// `cancelled()` (a newer request waits); what it did is kept for the next request.
    pub fn run_cancellable(
        &mut self,
        request: &Request,
        cancelled: &dyn Fn() -> bool,
        deliver: impl FnMut(Output, bool) -> Proceed,
    ) {
        match request.preset.problem {
            Problem::Plane => self.plane(request, deliver),
            Problem::Spatial => self.spatial(request, cancelled, Stop::Never, deliver),
        }
    }

    /// As [`Engine::run_cancellable`] with `stop` also asked inside every contact solve of the
    /// running-in (before each active-set iteration and linear-solve product): a newer request ends
    /// even a long step, which is not taken (the next request tries it again).
    pub fn run_stoppable(
        &mut self,
        request: &Request,
        stop: Stop,
        deliver: impl FnMut(Output, bool) -> Proceed,
    ) {
        match request.preset.problem {
            Problem::Plane => self.plane(request, deliver),
            Problem::Spatial => self.spatial(request, &|| stop.now(), stop, deliver),
        }
    }

    fn plane(&mut self, request: &Request, mut deliver: impl FnMut(Output, bool) -> Proceed) {
        let preset = &request.preset;
        let inputs = preset.plane_inputs();
        let model = preset.plane.model;
        let point = self.points.get_or(
            (inputs.clone(), model),
            &mut self.counts.operating_point,
            || operating_point(&inputs, model, PROFILE_POINTS).map(Arc::new),
        );
        let unloaded = inputs.with_load(1.0);
        let range = preset.plane.sweep;
        let others: Vec<Model> = Model::ALL
            .iter()
            .copied()
            .filter(|m| *m != model && !(*m == Model::Narrow && inputs.material.is_half_space()))
            .filter(|_| request.overlays)
            .collect();
        let strength = preset.strength;
        let judged = (inputs.clone(), model, strength);
        let mut out = PlaneOutput {
            strip_check: self.strip_checks.get(&(inputs.clone(), model)),
            yield_check: self.yield_checks.get(&judged).flatten(),
            point,
            sweep: self.sweeps.get(&(unloaded.clone(), model, range)),
            overlays: Vec::new(),
            energies: self.energies.get(&(unloaded.clone(), model, range)),
        };
        let energies_done = !request.energies || out.energies.is_some();
        let cached: Vec<_> = others
            .iter()
            .map_while(|m| Some((*m, self.sweeps.get(&(unloaded.clone(), *m, range))?)))
            .collect();
        let yield_done = out.yield_check.is_some() || strength.yield_stress().is_none();
        let checked = (out.strip_check.is_some() && yield_done) || out.point.is_err();
        if checked && out.sweep.is_some() && cached.len() == others.len() && energies_done {
            out.overlays = cached;
            deliver(Output::Plane(out), true);
            return;
        }
        if !deliver(Output::Plane(out.clone()), false) {
            return;
        }
        // the check against the strip model follows the point, before the slower sweeps
        if let (Ok(point), None) = (&out.point, &out.strip_check) {
            out.strip_check = Some(self.strip_check(inputs.clone(), model, point));
            if !deliver(Output::Plane(out.clone()), false) {
                return;
            }
        }
        if let (Ok(point), None) = (&out.point, &out.yield_check) {
            out.yield_check = self.yield_check(judged, point);
            if out.yield_check.is_some() && !deliver(Output::Plane(out.clone()), false) {
                return;
            }
        }
        // each model's curve is delivered as soon as it is solved; its verdicts, which measure
        // it against the strip model where the study's estimate doubts it, follow
        for m in std::iter::once(model).chain(others) {
            let key = (unloaded.clone(), m, range);
            let judged = match self.sweeps.get(&key) {
                Some(judged) => judged,
                None => {
                    self.counts.load_sweep += 1;
                    let solved = sweep::solve(&unloaded, m, &range);
                    out.put_sweep(model, m, Arc::new(solved.unjudged()));
                    if !deliver(Output::Plane(out.clone()), false) {
                        return;
                    }
                    let judged = Arc::new(solved.judged());
                    self.sweeps.insert(key, Arc::clone(&judged));
                    judged
                }
            };
            out.put_sweep(model, m, judged);
        }
        if request.energies {
            if !deliver(Output::Plane(out.clone()), false) {
                return;
            }
            out.energies = Some(self.energies.get_or(
                (unloaded.clone(), model, range),
                &mut self.counts.energy_sweep,
                || Arc::new(energy_sweep(&unloaded, model, &range)),
            ));
        }
        deliver(Output::Plane(out), true);
    }

    fn spatial(
        &mut self,
        request: &Request,
        cancelled: &dyn Fn() -> bool,
        stop: Stop,
        mut deliver: impl FnMut(Output, bool) -> Proceed,
    ) {
        let preset = &request.preset;
        let inputs = preset.spatial_inputs();
        if let Err(e) = inputs.validate() {
            deliver(Output::Spatial(Err(e)), true);
            return;
        }
        if inputs.surface().is_some() {
            self.surface(request, &inputs, cancelled, stop, deliver);
            return;
        }
        let responses =
            self.responses
                .get_or(ResponseKey::of(&inputs), &mut self.counts.responses, || {
                    let evolutions = spatial::evolutions(&inputs);
                    Arc::new((evolutions, Arc::new(dispersion(&inputs, DISPERSION_POINTS))))
                });
        let at = preset.spatial_state_at();
        let state = self
            .states
            .get_or((inputs.clone(), at), &mut self.counts.state, || {
                state_at(&inputs, &responses.0, &at).map(Arc::new)
            });
        let state = match state {
            Ok(s) => s,
            Err(e) => {
                deliver(Output::Spatial(Err(e)), true);
                return;
            }
        };
        let duration = preset.spatial.duration;
        let key = CellKey {
            inputs: inputs.clone(),
            grid: at.grid,
            time_tolerance: at.time_tolerance,
        };
        let sweep = &at.sweep;
        let pressures = state.sweep.mean_pressure.clone();
        let ask = Ask {
            key: &key,
            time: at.time,
            duration,
            curve: request.overlays.then_some((sweep, pressures.as_slice())),
            stop,
        };
        let cell = self.cell_now(&ask);
        if cell.is_err() && stop.now() {
            return;
        }
        let complete_at_start = cell
            .is_err()
            .then(|| pipeline::contact_at_start(&inputs, &responses.0, &state).complete);
        let mut out = SpatialOutput {
            history: self.histories.get(&(inputs.clone(), duration)),
            dispersion: Arc::clone(&responses.1),
            cell,
            complete_at_start,
            state,
        };
        let cell_done = |out: &SpatialOutput| {
            out.cell
                .as_ref()
                .map_or(true, |c| c.done(ask.curve.is_some()))
        };
        if out.history.is_some() && cell_done(&out) {
            deliver(Output::Spatial(Ok(out)), true);
            return;
        }
        if !deliver(Output::Spatial(Ok(out.clone())), false) {
            return;
        }
        let evolutions = &responses.0;
        out.history = Some(self.histories.get_or(
            (inputs.clone(), duration),
            &mut self.counts.history,
            || Arc::new(history(&inputs, evolutions, duration, HISTORY_POINTS)),
        ));
        if cell_done(&out) {
            deliver(Output::Spatial(Ok(out)), true);
            return;
        }
        self.cell_rest(&ask, cancelled, &mut |cell, complete| {
            out.cell = Ok(cell);
            deliver(Output::Spatial(Ok(out.clone())), complete)
        });
    }
}
