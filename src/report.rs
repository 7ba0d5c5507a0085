//! The reports of `wearlab solve`: JSON and CSV, with the keys of the command-line contract
//! (`design.md`). All values SI.

use serde::Serialize;

use crate::physics::SolveError;
use crate::physics::plane::Model;
use crate::physics::plane::energy::Energy;
use crate::physics::plane::operating_point;
use crate::physics::plane::profile::Profile;
use crate::physics::plane::sweep::{Sweep, sweep};
use crate::physics::plane::validity::Validity;
use crate::physics::spatial::contact::Contact;
use crate::physics::spatial::field::Field;
use crate::physics::spatial::history::MeanPressureSweep;
use crate::physics::spatial::{self, state_at};
use crate::preset::Preset;

/// The full plane report.
#[derive(Clone, Debug, Serialize)]
pub struct PlaneReport {
    /// Always "plane".
    pub problem: &'static str,
    /// The model used.
    pub model: Model,
    /// P [N/m].
    pub load: f64,
    /// Q2 [N/m].
    pub normal_force: f64,
    /// T [N/m].
    pub tangential_force: f64,
    /// a [m].
    pub a: f64,
    /// b [m].
    pub b: f64,
    /// theta (wide model only).
    pub theta: Option<f64>,
    /// gamma [1/Pa] (wide model only).
    pub gamma: Option<f64>,
    /// psi [N/m].
    pub psi: f64,
    /// Delta_g [m].
    pub delta_g: f64,
    /// mu*.
    pub mu_star: f64,
    /// I, J of (2.9).
    pub energy: Energy,
    /// Validity flags.
    pub validity: Validity,
    /// Profiles on [-a, b].
    pub profile: Profile,
    /// mu*(P) over the preset's sweep.
    pub sweep: Sweep,
}

/// Solves a plane preset and gathers everything `wearlab solve` prints.
pub fn plane_report(preset: &Preset, points: usize) -> Result<PlaneReport, SolveError> {
    let inputs = preset.plane_inputs();
    let model = preset.plane.model;
    let point = operating_point(&inputs, model, points)?;
    let sol = &point.solution;
    Ok(PlaneReport {
        problem: "plane",
        model,
        load: inputs.load,
        normal_force: sol.normal_force,
        tangential_force: sol.tangential_force,
        a: sol.a,
        b: sol.b,
        theta: sol.theta,
        gamma: sol.gamma,
        psi: sol.psi,
        delta_g: sol.delta_g,
        mu_star: sol.mu_star,
        energy: point.energy,
        validity: point.validity,
        profile: point.profile,
        sweep: sweep(&inputs, model, &preset.plane.sweep),
    })
}

/// One harmonic in the spatial report.
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
    /// A(t) [m].
    pub amplitude: f64,
    /// rho_x(t) [rad].
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
    /// p [Pa].
    pub pressure: f64,
    /// tau [Pa].
    pub shear: f64,
    /// U [m].
    pub shape: f64,
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
    /// P [Pa].
    pub load: f64,
    /// mu*.
    pub mu_star: f64,
    /// psi [Pa].
    pub psi: f64,
    /// Per harmonic.
    pub harmonics: Vec<HarmonicReport>,
    /// The complete-contact check.
    pub contact: Contact,
    /// Fields at the requested points.
    pub probes: Vec<Probe>,
    /// mu* against pbar.
    pub sweep: MeanPressureSweep,
    /// The fields over the cell (not in the JSON; the CSV output).
    #[serde(skip)]
    pub field: Field,
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
    let state = state_at(&inputs, &spatial::evolutions(&inputs), &at)?;
    let sol = &state.solution;
    Ok(SpatialReport {
        problem: "spatial",
        time: at.time,
        mean_pressure: inputs.mean_pressure,
        load: sol.load,
        mu_star: sol.mu_star,
        psi: sol.psi,
        harmonics: sol
            .harmonics
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
            .collect(),
        contact: state.contact,
        probes: probes
            .iter()
            .map(|&[x, y]| Probe {
                x,
                y,
                pressure: sol.pressure(x, y),
                shear: sol.shear(x, y),
                shape: sol.shape(x, y),
            })
            .collect(),
        sweep: state.sweep,
        field: state.field,
    })
}

/// The spatial field over the cell as CSV: x,y,pressure,shear,shape,wear.
pub fn field_csv(report: &SpatialReport, friction: &crate::physics::Friction) -> String {
    let f = &report.field;
    let mut out = String::from("x,y,pressure,shear,shape,wear\n");
    for (j, y) in f.y.iter().enumerate() {
        for (i, x) in f.x.iter().enumerate() {
            let k = j * f.n + i;
            let p = f.pressure[k];
            out.push_str(&format!(
                "{x:e},{y:e},{p:e},{:e},{:e},{:e}\n",
                friction.coefficient * p + friction.adhesion,
                f.shape[k],
                f.wear[k]
            ));
        }
    }
    out
}

/// Pretty JSON of any report.
pub fn to_json(report: &impl Serialize) -> String {
    serde_json::to_string_pretty(report).expect("reports hold only numbers and strings")
}

/// The profile as CSV: a header line, then one row per point.
pub fn profile_csv(p: &Profile) -> String {
    let mut out = String::from("x,pressure,shear,wear_rate,wear\n");
    for i in 0..p.x.len() {
        out.push_str(&format!(
            "{:e},{:e},{:e},{:e},{:e}\n",
            p.x[i], p.pressure[i], p.shear[i], p.wear_rate[i], p.wear[i]
        ));
    }
    out
}
