//! The spatial problem at time t, decided once (docs/physics/spatial.md,
//! docs/physics/spatial-partial.md): when the wear law is linear and the contact is complete at
//! t = 0 and at t, the closed form of the harmonics holds; otherwise, on a period cell, the punch
//! is worn through the running-in (`partial::running_in`) and every output comes from the
//! contact solution at t;
//! a nonlinear wear law is simulated there to t even in complete contact; without a period cell
//! (incommensurate wavenumbers) partial contact and a nonlinear wear law have no answer.
//!
//! `solve` answers `wearlab solve` and every spatial sweep point; the explorer's engine steps the
//! same running-in progressively and its charts ask `closed_form_holds` what they draw.

use std::ops::ControlFlow;

use crate::physics::spatial::contact::{self, Contact};
use crate::physics::spatial::harmonic::Evolution;
use crate::physics::spatial::partial::Setup;
use crate::physics::spatial::partial::running_in::{
    MAX_STEPS, RunningIn, Stopped, cancelled_or, run_in_to,
};
use crate::physics::spatial::partial::state::State;
use crate::physics::spatial::partial::sweep::load_curve;
use crate::physics::spatial::result::{
    ContactResult, FieldTable, HarmonicResult, Probe, SpatialResult, SurfaceResult, SweepResult,
};
use crate::physics::spatial::state::{SpatialState, StateAt};
use crate::physics::spatial::surface::Surface;
use crate::physics::spatial::{self, SpatialInputs, SpatialSolution, solve_with, state_at};
use crate::physics::stop::Stop;
use crate::physics::{SolveError, limits};

/// True when the contact is complete from t = 0 on: `complete_from` is the time [s] from which
/// the running-in finds it complete (None: not complete within it).
pub fn complete_from_start(complete_from: Option<f64>) -> bool {
    complete_from == Some(0.0)
}

/// True when the closed form of the harmonics holds at t: the wear law of `inputs` is linear
/// (n = 1), the contact is complete from t = 0 on and the closed form's contact is complete at t.
pub fn closed_form_holds(
    inputs: &SpatialInputs,
    complete_from_start: bool,
    complete_at_t: bool,
) -> bool {
    inputs.linear_wear() && complete_from_start && complete_at_t
}

/// The complete-contact check of the harmonics as given, at t = 0, on the cell of `closed` (the
/// state at t): without a period cell the closed form holds at t only where both are complete.
pub fn contact_at_start(
    inputs: &SpatialInputs,
    evolutions: &[Evolution],
    closed: &SpatialState,
) -> Contact {
    contact::check(&solve_with(inputs, evolutions, 0.0), &closed.cell)
}

/// The spatial problem at `at.time` with the fields at `probes` [m], and mu* against pbar over
/// `at.sweep` when `sweep` is true (the costly part on the cell: one contact solve per pressure).
pub fn solve(
    inputs: &SpatialInputs,
    at: &StateAt,
    probes: &[[f64; 2]],
    sweep: bool,
) -> Result<SpatialResult, SolveError> {
    solve_until(inputs, at, probes, sweep, Stop::Never).map_err(SolveError::from)
}

/// As [`solve`], told to stop by `stop`: every contact solve asks it before each active-set
/// iteration and each product of its linear solve, the running-in before every time step, the
/// mean-pressure sweep before every pressure, so the work ends within one step of being told
/// (`Stopped::Cancelled`).
pub fn solve_until(
    inputs: &SpatialInputs,
    at: &StateAt,
    probes: &[[f64; 2]],
    sweep: bool,
    stop: Stop,
) -> Result<SpatialResult, Stopped> {
    inputs.validate()?;
    if inputs.surface().is_some() {
        // a height map is solved on its own grid, every mode by the same operators
        limits::TIME
            .check("time", at.time)
            .map_err(SolveError::InvalidInput)?;
        let setup = Setup::new(inputs, at.grid)?;
        let pressures = sweep.then(|| sweep_pressures(at));
        return on_the_cell(&setup, None, at, probes, pressures, stop);
    }
    spatial::validate_grid(inputs.harmonics(), at.grid)?;
    let evolutions = spatial::evolutions(inputs);
    let setup = Setup::new(inputs, at.grid);
    // with a period cell the fields come from its nodes: the closed-form field is not reported
    let field_grid = if setup.is_ok() { 8 } else { at.grid };
    let closed = state_at(
        inputs,
        &evolutions,
        &StateAt {
            grid: field_grid,
            ..*at
        },
    )?;
    let pressures = sweep.then(|| sweep_pressures(at));
    match setup {
        Ok(setup) => on_the_cell(&setup, Some(&closed), at, probes, pressures, stop),
        Err(why) => {
            let initial = contact_at_start(inputs, &evolutions, &closed);
            if closed_form_holds(inputs, initial.complete, closed.contact.complete) {
                return Ok(closed_form(inputs, closed, probes, sweep));
            }
            // the closed form does not hold: a nonlinear wear law, or the contact is lost at
            // t = 0 or at t
            let lost = inputs
                .simulated()
                .or(closed.contact.failure())
                .or(initial.failure());
            let lost = lost.unwrap_or_default();
            // a coarse grid stays an input error (exit 2), no period cell has no answer (exit 3)
            Err(Stopped::Failed(match why {
                SolveError::InvalidInput(w) => SolveError::InvalidInput(format!("{lost}; {w}")),
                SolveError::NoSolution(w) => SolveError::NoSolution(format!("{lost}; {w}")),
            }))
        }
    }
}

/// The result from the running-in on the period cell; `closed` is the closed form of the
/// harmonics (None for a height map: every value from the nodes).
fn on_the_cell(
    setup: &Setup,
    closed: Option<&SpatialState>,
    at: &StateAt,
    probes: &[[f64; 2]],
    pressures: Option<Vec<f64>>,
    stop: Stop,
) -> Result<SpatialResult, Stopped> {
    let run = run_in_for(setup, at, stop)?;
    from_the_run(&run, closed, at, probes, pressures, stop)
}

/// The running-in of `setup` that answers the state at `at.time` (`run_in_to`), refused where it
/// reached its bound of steps.
pub(crate) fn run_in_for(setup: &Setup, at: &StateAt, stop: Stop) -> Result<RunningIn, Stopped> {
    let run = run_in_to(setup, at.time_tolerance, at.time, stop)?;
    if run.step_bound_reached() {
        let partial = if setup.inputs.linear_wear() {
            " with the contact still partial"
        } else {
            ""
        };
        return Err(Stopped::Failed(SolveError::NoSolution(format!(
            "the running-in reached its bound of {MAX_STEPS} time steps at t = {:.6e} s{partial}: \
             the time tolerance {:.1e} asks for more steps than that (raise \
             spatial.time_tolerance)",
            run.end_time(),
            at.time_tolerance
        ))));
    }
    Ok(run)
}

/// The result at `at.time` from `run` (of `run_in_for` at that time or a later one); `closed` as
/// for `on_the_cell`.
pub(crate) fn from_the_run(
    run: &RunningIn,
    closed: Option<&SpatialState>,
    at: &StateAt,
    probes: &[[f64; 2]],
    pressures: Option<Vec<f64>>,
    stop: Stop,
) -> Result<SpatialResult, Stopped> {
    let setup = &run.setup;
    let state = run
        .state_at_until(at.time, stop)
        .map_err(|why| cancelled_or(why, stop))?;
    let o = state.outputs;
    // a height map's state at t, when given, is complete (`RunningIn::state_at`)
    let from_start = closed_form_holds(
        &setup.inputs,
        complete_from_start(run.complete_from),
        closed.is_none_or(|c| c.contact.complete),
    );
    // the harmonics' closed form when it holds from the start (None for a height map)
    let exact = closed.filter(|_| from_start);
    // the shape at t is still the harmonics' closed form (t = 0, no wear, or complete from t = 0):
    // the certified minimum of its p_cc holds, not only the nodes'
    let closed_contact = closed
        .filter(|_| from_start || at.time == 0.0 || run.stepping.is_none())
        .map(|c| &c.contact);
    let friction = setup.inputs.friction;
    // the bound pbar - sum A/M and its time hold for the closed-form amplitudes: of the linear
    // law, and of any law while the shape is still the preset's
    let linear = setup.inputs.linear_wear();
    let bound = closed
        .filter(|_| linear || closed_contact.is_some())
        .map(|c| &c.contact);
    let contact = ContactResult {
        complete: o.complete,
        fraction: o.contact_fraction,
        time_to_complete: run.time_to_complete,
        time_error: run.time_error(at.time),
        min_pressure: closed_contact.map_or(o.min_pressure_complete, |c| c.min_pressure),
        at: closed_contact.map_or(Some(o.min_pressure_complete_at), |c| c.at),
        lower_bound: bound.map_or(o.min_pressure_complete, |c| c.lower_bound),
        exact: closed_contact.is_some_and(|c| c.exact),
        not_certified: closed_contact.and_then(|c| c.not_certified),
        complete_after: closed
            .filter(|_| linear)
            .and_then(|c| c.contact.complete_after),
    };
    let shear = state.shear(&friction);
    let probes = probes
        .iter()
        .map(|&[x, y]| {
            if let Some(closed) = exact {
                exact_probe(&closed.solution, x, y)
            } else {
                let k = state.grid.nearest(x, y);
                Probe {
                    x,
                    y,
                    pressure: state.pressure[k],
                    shear: shear[k],
                    shape: state.shape[k],
                }
            }
        })
        .collect();
    // complete from the start: the global values of the closed form, exact (psi = 0 for mu = 0)
    let (load, tangential, mu_star, psi) = match exact.map(|c| &c.solution) {
        Some(sol) => (sol.load, sol.tangential, sol.mu_star, sol.psi),
        None => (o.normal_force, o.holding_force, o.mu_star, o.psi),
    };
    let sweep = match pressures {
        Some(pressures) => Some(cell_sweep(setup, exact, &state, pressures, stop)?),
        None => None,
    };
    Ok(SpatialResult {
        problem: "spatial",
        time: at.time,
        mean_pressure: setup.inputs.mean_pressure,
        load,
        tangential_force: tangential,
        mu_star,
        psi,
        delta: o.delta,
        max_pressure: o.max_pressure,
        mean_gap: o.mean_gap,
        harmonics_hold: if from_start {
            "now"
        } else if setup.inputs.linear_wear() {
            "after complete contact"
        } else {
            "for n = 1 only"
        },
        running_in: setup.inputs.simulated(),
        harmonics: closed.map_or_else(Vec::new, |c| harmonics(&c.solution)),
        contact,
        probes,
        sweep,
        surface: setup.inputs.surface().map(|_| surface_at(&state)),
        field: nodal_fields(&state, shear),
    })
}

/// The statistics, bearing-area curve and PSD of the shape of `state` on the grid of a height
/// map (a profile's cell has ly = 0).
pub fn surface_at(state: &State) -> SurfaceResult {
    let g = state.grid;
    SurfaceResult::of(&Surface {
        nx: g.nx,
        ny: g.ny,
        lx: g.lx,
        ly: if g.ny == 1 { 0.0 } else { g.ly },
        heights: state.shape.clone(),
    })
}

/// mu* against pbar for the shape at t on the cell: the closed form's values (`exact`: the
/// harmonics' closed form when it holds from the start) at the same pressure, the nodes'
/// elsewhere.
fn cell_sweep(
    setup: &Setup,
    exact: Option<&SpatialState>,
    state: &State,
    pressures: Vec<f64>,
    stop: Stop,
) -> Result<SweepResult, Stopped> {
    let curve = load_curve(setup, &state.shape, &pressures, stop, &mut |_| {
        if stop.now() {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    })?;
    let closed_sweep = |i: usize| {
        let s = &exact?.sweep;
        (s.mean_pressure.get(i) == Some(&pressures[i]))
            .then(|| s.mu_star[i].map(|m| (s.load[i], m)))
            .flatten()
    };
    let (load, mu_star) = (0..pressures.len())
        .map(|i| match closed_sweep(i) {
            Some((p, m)) => (p, Some(m)),
            None => (curve.load[i], curve.mu_star[i]),
        })
        .unzip();
    Ok(SweepResult {
        mean_pressure: pressures,
        load,
        mu_star,
        contact_fraction: Some(curve.contact_fraction),
        complete_mean_pressure: Some(curve.complete_mean_pressure),
    })
}

/// The result of a contact complete at every time, without a period cell (incommensurate
/// wavenumbers): the closed form alone.
fn closed_form(
    inputs: &SpatialInputs,
    closed: SpatialState,
    probes: &[[f64; 2]],
    sweep: bool,
) -> SpatialResult {
    let sol = &closed.solution;
    let c: Contact = closed.contact;
    let f = &closed.field;
    let friction = inputs.friction;
    let s = &closed.sweep;
    SpatialResult {
        problem: "spatial",
        time: sol.time,
        mean_pressure: inputs.mean_pressure,
        load: sol.load,
        tangential_force: sol.tangential,
        mu_star: sol.mu_star,
        psi: sol.psi,
        delta: 0.0,
        max_pressure: f.pressure.iter().copied().fold(0.0, f64::max),
        mean_gap: 0.0,
        harmonics_hold: "now",
        running_in: None,
        harmonics: harmonics(sol),
        contact: ContactResult {
            complete: true,
            fraction: 1.0,
            time_to_complete: None,
            time_error: None,
            min_pressure: c.min_pressure,
            at: c.at,
            lower_bound: c.lower_bound,
            exact: c.exact,
            not_certified: c.not_certified,
            complete_after: c.complete_after,
        },
        probes: probes
            .iter()
            .map(|&[x, y]| exact_probe(sol, x, y))
            .collect(),
        sweep: sweep.then(|| SweepResult {
            mean_pressure: s.mean_pressure.clone(),
            load: s.load.clone(),
            mu_star: s.mu_star.clone(),
            contact_fraction: None,
            complete_mean_pressure: c.exact.then_some(inputs.mean_pressure - c.min_pressure),
        }),
        surface: None,
        field: FieldTable {
            x: f.x.clone(),
            y: f.y.clone(),
            shear: f
                .pressure
                .iter()
                .map(|p| friction.coefficient * p + friction.adhesion)
                .collect(),
            pressure: f.pressure.clone(),
            shape: f.shape.clone(),
            wear: f.wear.clone(),
        },
    }
}

/// The sweep's mean pressures [Pa] (none when the range is outside `limits::MEAN_PRESSURE`, as
/// in the closed-form sweep).
pub fn sweep_pressures(at: &StateAt) -> Vec<f64> {
    match at
        .sweep
        .check(["pressure_min", "pressure_max"], &limits::MEAN_PRESSURE)
    {
        Ok(()) => at.sweep.values(),
        Err(_) => Vec::new(),
    }
}

fn harmonics(sol: &SpatialSolution) -> Vec<HarmonicResult> {
    sol.harmonics
        .iter()
        .map(|h| HarmonicResult {
            k: h.initial.wavenumber(),
            decay_rate: h.evolution.decay_rate,
            drift_velocity: h.evolution.drift_velocity,
            phase_rate: h.evolution.phase_rate,
            phase_lead: h.evolution.phase_lead,
            pressure_per_amplitude: h.evolution.pressure_per_amplitude(),
            amplitude: h.state.amplitude,
            phase_x: h.state.phase_x,
            phase_y: h.state.phase_y,
        })
        .collect()
}

fn exact_probe(sol: &SpatialSolution, x: f64, y: f64) -> Probe {
    Probe {
        x,
        y,
        pressure: sol.pressure(x, y),
        shear: sol.shear(x, y),
        shape: sol.shape(x, y),
    }
}

fn nodal_fields(state: &State, shear: Vec<f64>) -> FieldTable {
    FieldTable {
        x: state.grid.xs(),
        y: state.grid.ys(),
        pressure: state.pressure.clone(),
        shear,
        shape: state.shape.clone(),
        wear: state.wear.clone(),
    }
}
