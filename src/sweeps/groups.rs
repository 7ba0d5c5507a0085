//! The problem's dimensionless groups at one solution, for the explorer's dimensionless view
//! (`D`). The quantity table (`quantities`) evaluates the same functions on a solved point, so a
//! group has one definition; its symbol and its description are the table's. The formulas are
//! those of `docs/physics/plane.md` and `docs/physics/spatial.md`.

use crate::physics::plane::validity::Validity;
use crate::physics::plane::{PlaneInputs, PlaneSolution};
use crate::physics::spatial::{HarmonicSolution, SpatialSolution};
use crate::preset::{Preset, Problem};
use crate::sweeps::quantities::QUANTITIES;
use crate::sweeps::quantity::QuantityKey;

/// One group's value.
#[derive(Clone, Debug, PartialEq)]
pub struct Group {
    /// The quantity's name in the table (`width_over_radius`, `harmonics.N.kh`).
    pub name: &'static str,
    /// Its symbol ("(a+b)/R").
    pub symbol: &'static str,
    /// Its value, dimensionless; +inf only for kh on a half-space.
    pub value: f64,
}

/// (a+b)/R: the contact width a + b over the punch radius R. The small-slope theory needs it
/// small; for a half-plane without friction or wear (Hertz) it is sqrt(8 P/(m R)).
pub fn width_over_radius(s: &PlaneSolution) -> f64 {
    s.contact_width() / s.inputs.radius
}

/// k m: the wear coefficient k [1/Pa] times the plane modulus m = pi E/(2(1 - nu^2)) [Pa], how
/// strongly wear shifts the pressure forwards (gamma m = pi mu chi - k m, eq. 4.3).
pub fn wear_number(i: &PlaneInputs) -> f64 {
    i.wear * i.material.plane_modulus()
}

/// mu chi: the friction coefficient times chi = (1 - 2 nu)/(2(1 - nu)), how strongly friction
/// shifts the pressure backwards; theta = 0 where mu chi = k m/pi (eq. 4.3, 4.5).
pub fn friction_number(i: &PlaneInputs) -> f64 {
    i.friction.coefficient * i.material.chi()
}

/// P/(m R): the load per unit length P [N/m] over the plane modulus m [Pa] times the radius R
/// [m]; (a+b)/R grows like its square root.
pub fn load_number(i: &PlaneInputs) -> f64 {
    i.load / (i.material.plane_modulus() * i.radius)
}

/// kh: the harmonic's wavenumber k = |(wx, wy)| [rad/m] times the layer thickness h [m]; below
/// about 1 the layer is thin for this wave, above about 3 it acts as a half-space. +inf on a
/// half-space (h = inf).
pub fn kh(k: f64, h: f64) -> f64 {
    k * h
}

/// beta t: the decay rate beta = k V A_c/M^2 [1/s] times the time t [s], the decay exponent
/// A(t)/A(0) = e^(-beta t) (`docs/physics/spatial.md`); without friction beta t = k V t/A_c.
pub fn decay_exponent(decay_rate: f64, time: f64) -> f64 {
    decay_rate * time
}

/// A/(M pbar): the pressure amplitude A/M [Pa] of a harmonic of shape amplitude A [m] over the
/// mean pressure pbar [Pa]; the contact is surely complete while these sum below 1.
pub fn pressure_ratio(amplitude: f64, pressure_per_amplitude: f64, mean_pressure: f64) -> f64 {
    amplitude * pressure_per_amplitude / mean_pressure
}

fn group(name: &'static str, value: f64) -> Group {
    let symbol = QUANTITIES
        .iter()
        .find(|q| q.name == name)
        .map_or(name, |q| q.symbol);
    Group {
        name,
        symbol,
        value,
    }
}

/// The plane problem's groups at a solution, in the order the status shows them: (a+b)/h (0 for
/// the half-plane, from the validity verdict), (a+b)/R, P/(m R), k m, mu chi, theta (wide and
/// strip models only), mu* and mu* - mu (the deformation part of friction).
pub fn plane(s: &PlaneSolution, validity: &Validity) -> Vec<Group> {
    let i = &s.inputs;
    let mut groups = vec![
        group(
            "validity.contact_width_over_thickness",
            validity.contact_width_over_thickness,
        ),
        group("width_over_radius", width_over_radius(s)),
        group("load_number", load_number(i)),
        group("wear_number", wear_number(i)),
        group("friction_number", friction_number(i)),
    ];
    groups.extend(s.theta.map(|t| group("theta", t)));
    groups.push(group("mu_star", s.mu_star));
    groups.push(group(
        "mu_star_minus_mu",
        s.mu_star - i.friction.coefficient,
    ));
    groups
}

/// The spatial problem's groups of the whole contact: mu*, mu* - mu and the sum of A/(M pbar)
/// over the harmonics (`pressure_ratio_sum`).
pub fn spatial(s: &SpatialSolution) -> Vec<Group> {
    vec![
        group("mu_star", s.mu_star),
        group(
            "mu_star_minus_mu",
            s.mu_star - s.inputs.friction.coefficient,
        ),
        Group {
            name: "pressure_ratio_sum",
            symbol: "sum A/(M pbar)",
            value: pressure_ratio_sum(s),
        },
    ]
}

/// One harmonic's groups: kh, beta t, A/(M pbar) and the phase lead phi [rad] of the pressure
/// over the shape (tan phi = mu sx B/A, a ratio of compliances).
pub fn harmonic(s: &SpatialSolution, h: &HarmonicSolution) -> Vec<Group> {
    let e = &h.evolution;
    vec![
        group(
            "harmonics.N.kh",
            kh(h.initial.wavenumber(), s.inputs.material.thickness),
        ),
        group(
            "harmonics.N.decay_exponent",
            decay_exponent(e.decay_rate, s.time),
        ),
        group(
            "harmonics.N.pressure_ratio",
            pressure_ratio(
                h.state.amplitude,
                e.pressure_per_amplitude(),
                s.inputs.mean_pressure,
            ),
        ),
        group("harmonics.N.phase_lead", e.phase_lead),
    ]
}

/// The sum over the harmonics of A/(M pbar), 1 - (pbar - sum A/M)/pbar: the contact is surely
/// complete while it is below 1 (the lower bound of the pressure is then positive).
pub fn pressure_ratio_sum(s: &SpatialSolution) -> f64 {
    s.harmonics
        .iter()
        .map(|h| {
            pressure_ratio(
                h.state.amplitude,
                h.evolution.pressure_per_amplitude(),
                s.inputs.mean_pressure,
            )
        })
        .sum()
}

/// The group a swept input is the natural variable of, for the sweep chart's x axis in the
/// dimensionless view: plane h -> (a+b)/h, P -> P/(m R), k -> k m, mu -> mu chi, R -> (a+b)/R;
/// spatial h -> kh of the first harmonic. None for an input without one (E, nu, tau0, V, pbar, a
/// harmonic's A, wx, wy, and h on the spatial problem without harmonics): its axis stays
/// dimensional.
pub fn of_input(preset: &Preset, input: &str) -> Option<QuantityKey> {
    let name = match (preset.problem, input) {
        (Problem::Plane, "material.thickness") => "validity.contact_width_over_thickness",
        (Problem::Plane, "plane.load") => "load_number",
        (Problem::Plane, "wear.coefficient") => "wear_number",
        (Problem::Plane, "friction.coefficient") => "friction_number",
        (Problem::Plane, "plane.radius") => "width_over_radius",
        (Problem::Spatial, "material.thickness") => "harmonics.0.kh",
        _ => return None,
    };
    QuantityKey::parse(name, preset).ok()
}
