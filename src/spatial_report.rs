//! The spatial report of `wearlab solve` (JSON keys of the command-line contract, `docs/cli.md`;
//! the partial-contact keys of docs/physics/spatial-partial.md section 7). All values SI.
//!
//! When the contact is complete at t = 0 the closed form of docs/physics/spatial.md holds at every
//! time. Otherwise the punch is worn through the running-in on the period cell
//! (`physics::spatial::partial`) and every output comes from the contact solution at t.

use std::ops::ControlFlow;

use serde::Serialize;

use crate::physics::spatial::contact::{self, Contact, NotCertified};
use crate::physics::spatial::partial::Setup;
use crate::physics::spatial::partial::running_in::{MAX_STEPS, run_in};
use crate::physics::spatial::partial::state::State;
use crate::physics::spatial::partial::sweep::load_curve;
use crate::physics::spatial::state::{SpatialState, StateAt};
use crate::physics::spatial::{self, SpatialInputs, SpatialSolution, solve_with, state_at};
use crate::physics::{SolveError, limits};
use crate::preset::Preset;

/// One harmonic in the spatial report: its closed form (docs/physics/spatial.md section 3).
#[derive(Clone, Debug, Serialize)]
pub struct HarmonicReport {
    /// |(wx, wy)| [rad/m].
    pub k: f64,
    /// beta [1/s].
    pub decay_rate: f64,
    /// c [m/s], positive along +x.
    pub drift_velocity: f64,
    /// Omega [rad/s].
    pub phase_rate: f64,
    /// phi [rad].
    pub phase_lead: f64,
    /// 1/M [Pa/m].
    pub pressure_per_amplitude: f64,
    /// A(t) [m] of the closed form.
    pub amplitude: f64,
    /// rho_x(t) [rad] of the closed form.
    pub phase_x: f64,
    /// rho_y [rad].
    pub phase_y: f64,
}

/// The fields at one point.
#[derive(Clone, Debug, Serialize)]
pub struct Probe {
    /// x [m].
    pub x: f64,
    /// y [m].
    pub y: f64,
    /// p [Pa] (at the nearest node when the contact was partial at t = 0).
    pub pressure: f64,
    /// tau [Pa] on the layer, along +x (0 out of contact).
    pub shear: f64,
    /// U [m].
    pub shape: f64,
}

/// The contact at time t.
#[derive(Clone, Debug, Serialize)]
pub struct ContactReport {
    /// True when the contact is complete (p > 0 over the whole cell).
    pub complete: bool,
    /// Fraction of the cell in contact (p > 0).
    pub fraction: f64,
    /// The simulated time [s] at which the running-in makes the contact complete; null when it is
    /// complete at t = 0, or still partial at the end of the running-in (README, partial contact).
    pub time_to_complete: Option<f64>,
    /// The estimated time-stepping error of the running-in at t: the sum of its steps' local
    /// error estimates, relative to the rms of the punch shape at t = 0 (it bounds the relative
    /// time-stepping error of max_pressure, mu_star and time_to_complete, and that of mean_gap
    /// relative to the shape's rms; `spatial.time_tolerance` sets it); null when nothing is
    /// stepped (complete at t = 0, no wear).
    pub time_error: Option<f64>,
    /// min of the complete-contact pressure p_cc [Pa] of the shape at t: negative when partial.
    pub min_pressure: f64,
    /// Where [x, y] [m] (null when only the bound is known).
    pub at: Option<[f64; 2]>,
    /// pbar - sum A_n(t)/M_n [Pa] with the closed-form amplitudes.
    pub lower_bound: f64,
    /// True when `min_pressure` is the certified cell minimum; false for the bound or a minimum
    /// over the grid's nodes.
    pub exact: bool,
    /// Why the closed form's cell minimum was not certified (null when it was, or when
    /// `min_pressure` is over the grid's nodes).
    pub not_certified: Option<NotCertified>,
    /// The formal closed-form time [s] after which the bound guarantees complete contact (null
    /// without wear); not the running-in time, which is `time_to_complete`.
    pub complete_after: Option<f64>,
}

/// mu* against the mean pressure, for the punch as it is at time t.
#[derive(Clone, Debug, Serialize)]
pub struct SweepReport {
    /// pbar [Pa].
    pub mean_pressure: Vec<f64>,
    /// P [Pa].
    pub load: Vec<f64>,
    /// mu*; null where P <= 0, and, without a period cell (incommensurate wavenumbers), where the
    /// contact is partial.
    pub mu_star: Vec<Option<f64>>,
    /// Fraction of the cell in contact (null without a period cell).
    pub contact_fraction: Option<Vec<f64>>,
    /// The smallest pbar [Pa] with complete contact (null when unknown).
    pub complete_mean_pressure: Option<f64>,
}

/// The fields on a grid over the cell, row-major (x fastest).
#[derive(Clone, Debug, Default)]
pub struct FieldTable {
    /// x [m] of the columns.
    pub x: Vec<f64>,
    /// y [m] of the rows.
    pub y: Vec<f64>,
    /// p [Pa].
    pub pressure: Vec<f64>,
    /// tau [Pa].
    pub shear: Vec<f64>,
    /// U [m].
    pub shape: Vec<f64>,
    /// W [m].
    pub wear: Vec<f64>,
}

/// The full spatial report.
#[derive(Clone, Debug, Serialize)]
pub struct SpatialReport {
    /// Always "spatial".
    pub problem: &'static str,
    /// t [s].
    pub time: f64,
    /// pbar [Pa].
    pub mean_pressure: f64,
    /// P = pbar - mu psi - tau0 Delta [Pa]: the vertical force per unit area.
    pub load: f64,
    /// T = mu pbar + tau0 fraction + psi [Pa]: the holding force per unit area along x.
    pub tangential_force: f64,
    /// mu* = (T - tau0 fraction)/P.
    pub mu_star: f64,
    /// psi = -<p g_x> [Pa].
    pub psi: f64,
    /// Delta = -<1_C g_x> (0 in complete contact).
    pub delta: f64,
    /// p_max [Pa].
    pub max_pressure: f64,
    /// The mean gap <gap> [m] (0 in complete contact).
    pub mean_gap: f64,
    /// When the per-harmonic closed form holds: "now", or "after complete contact".
    pub harmonics_hold: &'static str,
    /// Per harmonic.
    pub harmonics: Vec<HarmonicReport>,
    /// The contact.
    pub contact: ContactReport,
    /// Fields at the requested points.
    pub probes: Vec<Probe>,
    /// mu* against pbar.
    pub sweep: SweepReport,
    /// The fields over the cell (not in the JSON; the CSV output).
    #[serde(skip)]
    pub field: FieldTable,
}

/// Solves a spatial preset at time `time` (the preset's own when None) with probes at `probes`.
pub fn spatial_report(
    preset: &Preset,
    time: Option<f64>,
    probes: &[[f64; 2]],
) -> Result<SpatialReport, SolveError> {
    let inputs = preset.spatial_inputs();
    inputs.validate()?;
    let mut at = preset.spatial_state_at();
    if let Some(t) = time {
        at.time = t;
    }
    spatial::validate_grid(&inputs.harmonics, at.grid)?;
    let evolutions = spatial::evolutions(&inputs);
    let setup = Setup::new(&inputs, at.grid);
    // with a period cell the fields come from its nodes: the closed-form field is not reported
    let field_grid = if setup.is_ok() { 8 } else { at.grid };
    let closed = state_at(
        &inputs,
        &evolutions,
        &StateAt {
            grid: field_grid,
            ..at
        },
    )?;
    match setup {
        Ok(setup) => on_the_cell(&setup, &closed, &at, probes),
        Err(why) => {
            let initial = contact::check(&solve_with(&inputs, &evolutions, 0.0), &closed.cell);
            let Some(lost) = closed.contact.failure().or(initial.failure()) else {
                return Ok(closed_form(&inputs, closed, probes));
            };
            // a coarse grid stays an input error (exit 2), no period cell has no answer (exit 3)
            Err(match why {
                SolveError::InvalidInput(w) => SolveError::InvalidInput(format!("{lost}; {w}")),
                SolveError::NoSolution(w) => SolveError::NoSolution(format!("{lost}; {w}")),
            })
        }
    }
}

/// The report from the running-in on the period cell.
fn on_the_cell(
    setup: &Setup,
    closed: &SpatialState,
    at: &StateAt,
    probes: &[[f64; 2]],
) -> Result<SpatialReport, SolveError> {
    let run = run_in(setup, at.time_tolerance, &mut |_| ControlFlow::Continue(()))?;
    if run.step_bound_reached() {
        return Err(SolveError::NoSolution(format!(
            "the running-in reached its bound of {MAX_STEPS} time steps at t = {:.6e} s with the \
             contact still partial: the time tolerance {:.1e} asks for more steps than that \
             (raise spatial.time_tolerance)",
            run.end_time(),
            at.time_tolerance
        )));
    }
    let state = run.state_at(at.time)?;
    let o = state.outputs;
    // complete from t = 0: the closed form of the original harmonics holds exactly
    let from_start = run.complete_from == Some(0.0) && closed.contact.complete == o.complete;
    // the shape at t is still the harmonics' closed form (t = 0, no wear, or complete from t = 0):
    // the certified minimum of its p_cc holds, not only the nodes'
    let closed_shape = from_start || at.time == 0.0 || run.stepping.is_none();
    let friction = setup.inputs.friction;
    let pressures = sweep_pressures(at);
    let curve = load_curve(setup, &state.shape, &pressures, &mut |_| {
        ControlFlow::Continue(())
    })?;
    let c = &closed.contact;
    let contact = ContactReport {
        complete: o.complete,
        fraction: o.contact_fraction,
        time_to_complete: run.time_to_complete,
        time_error: run.time_error(at.time),
        min_pressure: if closed_shape {
            c.min_pressure
        } else {
            o.min_pressure_complete
        },
        at: if closed_shape {
            c.at
        } else {
            Some(o.min_pressure_complete_at)
        },
        lower_bound: c.lower_bound,
        exact: closed_shape && c.exact,
        not_certified: if closed_shape { c.not_certified } else { None },
        complete_after: c.complete_after,
    };
    let shear = state.shear(&friction);
    let probes = probes
        .iter()
        .map(|&[x, y]| {
            if from_start {
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
    let sol = &closed.solution;
    let (load, tangential, mu_star, psi) = if from_start {
        (sol.load, sol.tangential, sol.mu_star, sol.psi)
    } else {
        (o.normal_force, o.holding_force, o.mu_star, o.psi)
    };
    let closed_sweep = |i: usize| {
        let s = &closed.sweep;
        (from_start && s.mean_pressure.get(i) == Some(&pressures[i]))
            .then(|| s.mu_star[i].map(|m| (s.load[i], m)))
            .flatten()
    };
    let (sweep_load, sweep_mu_star) = (0..pressures.len())
        .map(|i| match closed_sweep(i) {
            Some((p, m)) => (p, Some(m)),
            None => (curve.load[i], curve.mu_star[i]),
        })
        .unzip();
    Ok(SpatialReport {
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
        } else {
            "after complete contact"
        },
        harmonics: harmonics(&closed.solution),
        contact,
        probes,
        sweep: SweepReport {
            mean_pressure: pressures,
            load: sweep_load,
            mu_star: sweep_mu_star,
            contact_fraction: Some(curve.contact_fraction),
            complete_mean_pressure: Some(curve.complete_mean_pressure),
        },
        field: nodal_fields(&state, shear),
    })
}

/// The report of a contact complete at every time, without a period cell (incommensurate
/// wavenumbers): the closed form alone.
fn closed_form(inputs: &SpatialInputs, closed: SpatialState, probes: &[[f64; 2]]) -> SpatialReport {
    let sol = &closed.solution;
    let c: Contact = closed.contact;
    let f = &closed.field;
    let friction = inputs.friction;
    let sweep = &closed.sweep;
    SpatialReport {
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
        harmonics: harmonics(sol),
        contact: ContactReport {
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
        sweep: SweepReport {
            mean_pressure: sweep.mean_pressure.clone(),
            load: sweep.load.clone(),
            mu_star: sweep.mu_star.clone(),
            contact_fraction: None,
            complete_mean_pressure: c.exact.then_some(inputs.mean_pressure - c.min_pressure),
        },
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

/// The preset's sweep pressures (none when the range is outside `limits::MEAN_PRESSURE`, as in
/// the closed-form sweep).
fn sweep_pressures(at: &StateAt) -> Vec<f64> {
    match at
        .sweep
        .check(["pressure_min", "pressure_max"], &limits::MEAN_PRESSURE)
    {
        Ok(()) => at.sweep.values(),
        Err(_) => Vec::new(),
    }
}

fn harmonics(sol: &SpatialSolution) -> Vec<HarmonicReport> {
    sol.harmonics
        .iter()
        .map(|h| HarmonicReport {
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

/// The spatial field over the cell as CSV: x,y,pressure,shear,shape,wear.
pub fn field_csv(report: &SpatialReport) -> String {
    let f = &report.field;
    let mut out = String::from("x,y,pressure,shear,shape,wear\n");
    for (j, y) in f.y.iter().enumerate() {
        for (i, x) in f.x.iter().enumerate() {
            let k = j * f.x.len() + i;
            out.push_str(&format!(
                "{x:e},{y:e},{:e},{:e},{:e},{:e}\n",
                f.pressure[k], f.shear[k], f.shape[k], f.wear[k]
            ));
        }
    }
    out
}
