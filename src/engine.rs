//! The incremental engine behind the explorer: cached stages, so an edit recomputes only what it
//! touches, and a background worker that always works on the newest request (design.md).

use std::collections::HashMap;
use std::sync::mpsc::{Receiver, Sender, channel};
use std::sync::{Arc, Condvar, Mutex};
use std::thread;

use crate::physics::SolveError;
use crate::physics::plane::energy::{Energy, energy};
use crate::physics::plane::profile::{Profile, profile};
use crate::physics::plane::sweep::{Sweep, sweep};
use crate::physics::plane::validity::{Validity, check};
use crate::physics::plane::{Model, PlaneSolution, solve};
use crate::physics::spatial::contact::{self, Contact};
use crate::physics::spatial::field::{Field, field};
use crate::physics::spatial::harmonic::{Evolution, Harmonic, evolution};
use crate::physics::spatial::history::{
    Dispersion, History, MeanPressureSweep, dispersion, history, pressure_sweep,
};
use crate::physics::spatial::{Cell, SpatialSolution, solve_with};
use crate::preset::{Preset, Problem};

/// Points of the plane profile drawn by the explorer.
pub const PROFILE_POINTS: usize = 201;
/// Points of the dispersion curves.
pub const DISPERSION_POINTS: usize = 120;
/// Points of the spatial time history.
pub const HISTORY_POINTS: usize = 200;

/// The plane operating point with everything derived from it.
#[derive(Clone, Debug)]
pub struct PlanePoint {
    /// The solution.
    pub solution: PlaneSolution,
    /// Its profile.
    pub profile: Profile,
    /// I, J.
    pub energy: Energy,
    /// Validity verdict.
    pub validity: Validity,
}

/// Everything the explorer shows for the plane problem.
#[derive(Clone, Debug)]
pub struct PlaneOutput {
    /// The operating point, or why there is none.
    pub point: Result<Arc<PlanePoint>, SolveError>,
    /// mu*(P) etc. for every model, the preset's model first.
    pub sweeps: Vec<(Model, Arc<Sweep>)>,
}

/// Everything the explorer shows for the spatial problem.
#[derive(Clone, Debug)]
pub struct SpatialOutput {
    /// The solution at time t.
    pub solution: SpatialSolution,
    /// The period cell.
    pub cell: Cell,
    /// Complete-contact check.
    pub contact: Contact,
    /// Fields over the cell.
    pub field: Field,
    /// A_n(t), mu*(t) over the duration.
    pub history: Arc<History>,
    /// mu* against pbar.
    pub sweep: MeanPressureSweep,
    /// Drift velocity against wavenumber and direction.
    pub dispersion: Arc<Dispersion>,
}

/// The engine's answer to one request.
#[derive(Clone, Debug)]
pub enum Output {
    /// Plane problem.
    Plane(PlaneOutput),
    /// Spatial problem.
    Spatial(Result<Box<SpatialOutput>, SolveError>),
}

/// How often each stage has been computed (for tests of the caching).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StageCounts {
    /// Plane operating points.
    pub operating_point: usize,
    /// Plane load sweeps.
    pub load_sweep: usize,
    /// Spatial harmonic responses.
    pub responses: usize,
    /// Spatial histories.
    pub history: usize,
    /// Spatial states at time t (with field and contact check).
    pub state: usize,
}

/// A cache of one value per key, keeping only the latest few keys.
struct Cache<V> {
    entries: HashMap<String, V>,
}

impl<V: Clone> Cache<V> {
    fn new() -> Self {
        Cache {
            entries: HashMap::new(),
        }
    }

    fn get_or(&mut self, key: String, counter: &mut usize, compute: impl FnOnce() -> V) -> V {
        if let Some(v) = self.entries.get(&key) {
            return v.clone();
        }
        *counter += 1;
        let v = compute();
        if self.entries.len() > 8 {
            self.entries.clear();
        }
        self.entries.insert(key, v.clone());
        v
    }
}

/// The staged, cached solver.
pub struct Engine {
    points: Cache<Result<Arc<PlanePoint>, SolveError>>,
    sweeps: Cache<Arc<Sweep>>,
    responses: Cache<Arc<(Vec<Evolution>, Arc<Dispersion>)>>,
    histories: Cache<Arc<History>>,
    /// Stage evaluation counts.
    pub counts: StageCounts,
}

impl Default for Engine {
    fn default() -> Self {
        Self::new()
    }
}

impl Engine {
    /// An engine with empty caches.
    pub fn new() -> Engine {
        Engine {
            points: Cache::new(),
            sweeps: Cache::new(),
            responses: Cache::new(),
            histories: Cache::new(),
            counts: StageCounts::default(),
        }
    }

    /// Solves the preset's problem, reusing every stage whose inputs did not change.
    pub fn run(&mut self, preset: &Preset) -> Output {
        match preset.problem {
            Problem::Plane => Output::Plane(self.plane(preset)),
            Problem::Spatial => Output::Spatial(self.spatial(preset)),
        }
    }

    fn plane(&mut self, preset: &Preset) -> PlaneOutput {
        let inputs = preset.plane_inputs();
        let model = preset.plane.model;
        let point = self.points.get_or(
            format!("{inputs:?}{model:?}"),
            &mut self.counts.operating_point,
            || {
                solve(&inputs, model).map(|solution| {
                    Arc::new(PlanePoint {
                        profile: profile(&solution, PROFILE_POINTS),
                        energy: energy(&solution),
                        validity: check(&solution),
                        solution,
                    })
                })
            },
        );
        // the sweep does not depend on the load: key it without
        let unloaded = inputs.with_load(1.0);
        let mut models = vec![model];
        models.extend(Model::ALL.iter().filter(|m| {
            **m != model && !(**m == Model::Narrow && unloaded.material.is_half_space())
        }));
        let sweeps = models
            .into_iter()
            .map(|m| {
                let key = format!("{unloaded:?}{m:?}{:?}", preset.plane.sweep);
                let s = self.sweeps.get_or(key, &mut self.counts.load_sweep, || {
                    Arc::new(sweep(&unloaded, m, &preset.plane.sweep))
                });
                (m, s)
            })
            .collect();
        PlaneOutput { point, sweeps }
    }

    fn spatial(&mut self, preset: &Preset) -> Result<Box<SpatialOutput>, SolveError> {
        let inputs = preset.spatial_inputs();
        inputs.validate()?;
        let sp = &preset.spatial;
        let waves: Vec<(f64, f64)> = inputs
            .harmonics
            .iter()
            .map(|h| (h.wavenumber_x, h.wavenumber_y))
            .collect();
        let key = format!(
            "{:?}{:?}{}{waves:?}",
            inputs.material,
            inputs.friction,
            inputs.wear_rate()
        );
        let responses = self.responses.get_or(key, &mut self.counts.responses, || {
            let evolutions = inputs
                .harmonics
                .iter()
                .map(|h: &Harmonic| {
                    evolution(&inputs.material, &inputs.friction, inputs.wear_rate(), h)
                })
                .collect();
            Arc::new((evolutions, Arc::new(dispersion(&inputs, DISPERSION_POINTS))))
        });
        let evolutions = &responses.0;
        let key = format!("{inputs:?}{}", sp.duration);
        let hist = self.histories.get_or(key, &mut self.counts.history, || {
            Arc::new(history(&inputs, evolutions, sp.duration, HISTORY_POINTS))
        });
        self.counts.state += 1;
        let solution = solve_with(&inputs, evolutions, sp.time);
        let cell = Cell::of(&inputs.harmonics);
        let contact = contact::check(&solution, &cell);
        let field = field(&solution, &cell, sp.grid);
        let sweep = pressure_sweep(
            &inputs,
            evolutions,
            sp.time,
            contact.min_pressure - inputs.mean_pressure,
            &sp.sweep,
        );
        Ok(Box::new(SpatialOutput {
            solution,
            cell,
            contact,
            field,
            history: hist,
            sweep,
            dispersion: Arc::clone(&responses.1),
        }))
    }
}

type Slot = Arc<(Mutex<Option<(u64, Preset)>>, Condvar)>;

/// A background thread running the engine: one job at a time, one pending slot that a newer
/// request overwrites (older pending work is dropped unseen).
pub struct Worker {
    slot: Slot,
    results: Receiver<(u64, Output)>,
}

impl Worker {
    /// Starts the worker thread.
    pub fn spawn() -> Worker {
        let slot: Slot = Arc::new((Mutex::new(None), Condvar::new()));
        let (tx, results): (Sender<(u64, Output)>, _) = channel();
        let thread_slot = Arc::clone(&slot);
        thread::spawn(move || {
            let mut engine = Engine::new();
            loop {
                let (generation, preset) = {
                    let (lock, cvar) = &*thread_slot;
                    let mut pending = lock.lock().expect("the UI never panics holding the slot");
                    while pending.is_none() {
                        pending = cvar
                            .wait(pending)
                            .expect("the UI never panics holding the slot");
                    }
                    pending.take().expect("checked above")
                };
                let output = engine.run(&preset);
                if tx.send((generation, output)).is_err() {
                    return; // the UI is gone
                }
            }
        });
        Worker { slot, results }
    }

    /// Asks for a solve; replaces any request not yet started.
    pub fn submit(&self, generation: u64, preset: Preset) {
        let (lock, cvar) = &*self.slot;
        *lock
            .lock()
            .expect("the worker never panics holding the slot") = Some((generation, preset));
        cvar.notify_one();
    }

    /// A finished result, if any (never blocks).
    pub fn try_recv(&self) -> Option<(u64, Output)> {
        self.results.try_recv().ok()
    }
}
