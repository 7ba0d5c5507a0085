//! The problem's dimensionless groups at one solution, for the explorer's dimensionless view
//! (`D`). The formulas are the physics' (`plane::groups`, `spatial::groups`); the quantity table
//! (`quantity_table`) evaluates the same functions on a solved point, so a group has one definition;
//! its symbol and its description are the table's.

use crate::physics::plane::PlaneSolution;
use crate::physics::plane::groups::{friction_number, load_number, wear_number, width_over_radius};
use crate::physics::plane::validity::Validity;
use crate::physics::spatial::groups::{decay_exponent, kh, pressure_ratio, pressure_ratio_sum};
use crate::physics::spatial::{HarmonicSolution, SpatialSolution};
use crate::preset::{Preset, Problem};
use crate::sweeps::quantity::QuantityKey;
use crate::sweeps::quantity_table::QUANTITIES;

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
