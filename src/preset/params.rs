//! The parameter registry: every input of a preset, by its preset key (`material.thickness`,
//! `spatial.harmonics.N.amplitude`, `plane.model`), with its symbol, a short label, its unit, its
//! allowed values (`physics::limits`, the one place for ranges) and how it is read and written.
//! `preset::Key` addresses one parameter in a preset and holds the checked getter and setters.
//!
//! Harmonic keys count from 0 (`spatial.harmonics.0.*` is the first harmonic, "harmonic 1" in
//! messages and in the explorer), like the `harmonics` array of `wearlab solve`'s JSON.

use crate::materials;
use crate::physics::Spacing;
use crate::physics::limits::{self, Limit};
use crate::physics::plane::Model;
use crate::physics::spatial::harmonic::Harmonic;
use crate::physics::spatial::surface;
use crate::preset::{Preset, Problem, material_rows, shape_rows, surface_rows};

/// How a parameter's value is read and written.
#[derive(Clone, Copy, Debug)]
pub enum Access {
    /// A number of the preset, allowed by `limit`.
    Number {
        /// The allowed values.
        limit: Limit,
        /// A typical magnitude: where a default range or a nudge from 0 starts.
        typical: f64,
        /// Reads it.
        get: fn(&Preset) -> f64,
        /// Writes it (unchecked: `Preset::set` checks).
        set: fn(&mut Preset, f64),
    },
    /// A number of one harmonic (the key says which), allowed by `limit`.
    Harmonic {
        /// The allowed values.
        limit: Limit,
        /// A typical magnitude: where a default range or a nudge from 0 starts.
        typical: f64,
        /// Reads it.
        get: fn(&Harmonic) -> f64,
        /// Writes it (unchecked).
        set: fn(&mut Harmonic, f64),
    },
    /// One of a few names; the value is the index into `names`.
    Choice {
        /// The names, as written in preset files.
        names: &'static [&'static str],
        /// Reads the index.
        get: fn(&Preset) -> usize,
        /// Writes the index (< names.len()); Err says why that choice cannot be made here.
        set: fn(&mut Preset, usize) -> Result<(), String>,
    },
    /// A key of the punch's height map (`spatial.surface.NAME`, `surface_rows`): a generated
    /// surface's number, set by generating the surface again with the checks of `--set`; a
    /// height-map file's name, grid and lengths, shown and not set.
    Surface {
        /// A typical magnitude: where a nudge from 0 starts.
        typical: f64,
    },
    /// A text the preset file gives that is shown but cannot be set here (a measured profile's
    /// file and x range).
    Fixed {
        /// Reads it.
        show: fn(&Preset) -> String,
    },
}

/// One parameter.
#[derive(Clone, Copy, Debug)]
pub struct Param {
    /// The preset key; harmonic keys have `N` in place of the index
    /// (`spatial.harmonics.N.amplitude`).
    pub key: &'static str,
    /// The symbol shown in the explorer and in messages ("E", "h", "P min").
    pub symbol: &'static str,
    /// What it is, in a few words.
    pub label: &'static str,
    /// The SI unit ("" for dimensionless numbers, counts and choices).
    pub unit: &'static str,
    /// How it is read and written.
    pub access: Access,
}

impl Param {
    /// The allowed values of a number (None for a choice).
    pub fn limit(&self) -> Option<&Limit> {
        match &self.access {
            Access::Number { limit, .. } | Access::Harmonic { limit, .. } => Some(limit),
            Access::Choice { .. } | Access::Fixed { .. } | Access::Surface { .. } => None,
        }
    }

    /// A typical magnitude of a number (None for a choice): where a default range or a nudge
    /// from 0 starts.
    pub fn typical(&self) -> Option<f64> {
        match self.access {
            Access::Number { typical, .. }
            | Access::Harmonic { typical, .. }
            | Access::Surface { typical } => Some(typical),
            Access::Choice { .. } | Access::Fixed { .. } => None,
        }
    }

    /// The names of a choice (None for a number).
    pub fn choices(&self) -> Option<&'static [&'static str]> {
        match self.access {
            Access::Choice { names, .. } => Some(names),
            _ => None,
        }
    }

    /// The text of a value that is shown but cannot be set (None for a number or a choice).
    pub fn fixed(&self) -> Option<fn(&Preset) -> String> {
        match self.access {
            Access::Fixed { show } => Some(show),
            _ => None,
        }
    }

    /// True for a number that is a count (points, grid) or a surface's seed.
    pub fn is_whole(&self) -> bool {
        match self.access {
            Access::Surface { .. } => matches!(self.surface_name(), Some("grid" | "seed")),
            _ => self.limit().is_some_and(Limit::is_whole),
        }
    }

    /// The last part of a surface's key (`hurst` of `spatial.surface.hurst`); None for the
    /// other parameters.
    pub fn surface_name(&self) -> Option<&'static str> {
        match self.access {
            Access::Surface { .. } => self.key.strip_prefix(surface_rows::PREFIX),
            _ => None,
        }
    }

    /// The problem it belongs to, from its section (`plane.`, `spatial.`); None for both.
    pub fn problem(&self) -> Option<Problem> {
        match self.key.split('.').next() {
            Some("plane") => Some(Problem::Plane),
            Some("spatial") => Some(Problem::Spatial),
            _ => None,
        }
    }

    /// True when it matters for `problem` (the preset holds both problems; only one is solved).
    pub fn applies_to(&self, problem: Problem) -> bool {
        self.problem().is_none_or(|p| p == problem)
    }

    /// True for a key a preset may leave out, which `none` clears: the yield strength, the
    /// hardness (without both, no yield check) and the wear law's reference pressure.
    pub fn optional(&self) -> bool {
        matches!(
            self.key,
            "material.yield_strength" | "material.hardness" | "wear.reference_pressure"
        )
    }

    /// What may be written, in words: the limit's text (and `none` for an optional key), or the
    /// choices.
    pub fn allowed(&self) -> String {
        if let Some(name) = self.surface_name() {
            return surface::allowed(name).into();
        }
        match (self.limit(), self.choices()) {
            (Some(limit), _) if self.optional() => {
                format!("{}, or none to clear it", limit.allowed)
            }
            (Some(limit), _) => limit.allowed.to_string(),
            (None, Some(names)) => format!("one of {}", names.join(", ")),
            (None, None) => "nothing: it is read from the preset file".into(),
        }
    }
}

const MODELS: &[&str] = Model::NAMES;
const SCALES: &[&str] = &["log", "linear"];

fn model_index(model: Model) -> usize {
    Model::ALL.iter().position(|m| *m == model).unwrap_or(0)
}

fn scale_index(spacing: Spacing) -> usize {
    match spacing {
        Spacing::Log => 0,
        Spacing::Linear => 1,
    }
}

fn scale(index: usize) -> Spacing {
    [Spacing::Log, Spacing::Linear][index]
}

const fn number(
    key: &'static str,
    [symbol, label]: [&'static str; 2],
    unit: &'static str,
    limit: Limit,
    typical: f64,
    get: fn(&Preset) -> f64,
    set: fn(&mut Preset, f64),
) -> Param {
    Param {
        key,
        symbol,
        label,
        unit,
        access: Access::Number {
            limit,
            typical,
            get,
            set,
        },
    }
}

const fn wave(
    key: &'static str,
    [symbol, label]: [&'static str; 2],
    unit: &'static str,
    limit: Limit,
    typical: f64,
    get: fn(&Harmonic) -> f64,
    set: fn(&mut Harmonic, f64),
) -> Param {
    Param {
        key,
        symbol,
        label,
        unit,
        access: Access::Harmonic {
            limit,
            typical,
            get,
            set,
        },
    }
}

const fn fixed(
    key: &'static str,
    [symbol, label]: [&'static str; 2],
    show: fn(&Preset) -> String,
) -> Param {
    Param {
        key,
        symbol,
        label,
        unit: "",
        access: Access::Fixed { show },
    }
}

const fn rough(
    key: &'static str,
    [symbol, label]: [&'static str; 2],
    unit: &'static str,
    typical: f64,
) -> Param {
    Param {
        key,
        symbol,
        label,
        unit,
        access: Access::Surface { typical },
    }
}

const fn choice(
    key: &'static str,
    [symbol, label]: [&'static str; 2],
    names: &'static [&'static str],
    get: fn(&Preset) -> usize,
    set: fn(&mut Preset, usize) -> Result<(), String>,
) -> Param {
    Param {
        key,
        symbol,
        label,
        unit: "",
        access: Access::Choice { names, get, set },
    }
}

/// Every parameter, in the order of the preset file.
#[rustfmt::skip]
pub const PARAMS: &[Param] = &[
    choice("material.name", ["material", "material from the table (sets E, nu, Y, H)"], &materials::CHOICES, material_rows::name_index, material_rows::set_name),
    number("material.youngs_modulus", ["E", "Young's modulus"], "Pa", limits::YOUNGS_MODULUS, 1e9, |p| p.material.youngs_modulus, |p, v| p.material.youngs_modulus = v),
    number("material.poisson_ratio", ["nu", "Poisson's ratio"], "", limits::POISSON_RATIO, 0.3, |p| p.material.poisson_ratio, |p, v| p.material.poisson_ratio = v),
    number("material.thickness", ["h", "thickness of the strip / layer"], "m", limits::THICKNESS, 1e-3, |p| p.material.thickness, |p, v| p.material.thickness = v),
    number("material.yield_strength", ["Y", "yield strength of the strip"], "Pa", limits::YIELD_STRENGTH, 1e8, |p| p.strength.yield_strength.unwrap_or(0.0), |p, v| p.strength.yield_strength = Some(v)),
    number("material.hardness", ["H", "hardness of the strip"], "Pa", limits::HARDNESS, 3e8, |p| p.strength.hardness.unwrap_or(0.0), |p, v| p.strength.hardness = Some(v)),
    number("friction.coefficient", ["mu", "friction coefficient"], "", limits::FRICTION, 0.3, |p| p.friction.coefficient, |p, v| p.friction.coefficient = v),
    number("friction.adhesion", ["tau0", "adhesive shear stress"], "Pa", limits::ADHESION, 1e4, |p| p.friction.adhesion, |p, v| p.friction.adhesion = v),
    number("friction.shear_strength", ["tau_max", "shear strength capping the friction stress"], "Pa", limits::SHEAR_STRENGTH, 1e7, |p| p.shear_strength, |p, v| p.shear_strength = v),
    number("wear.coefficient", ["k", "wear coefficient"], "1/Pa", limits::WEAR, 1e-15, |p| p.wear, |p, v| p.wear = v),
    number("wear.archard_coefficient", ["K", "Archard's wear coefficient (k = K/H)"], "", limits::ARCHARD, 1e-4, material_rows::archard, material_rows::set_archard),
    number("wear.exponent", ["n", "exponent of the wear law"], "", limits::WEAR_EXPONENT, 2.0, |p| p.wear_exponent, |p, v| p.wear_exponent = v),
    number("wear.reference_pressure", ["p0", "reference pressure of the wear law"], "Pa", limits::REFERENCE_PRESSURE, 1e6, |p| p.reference_pressure.unwrap_or(0.0), |p, v| p.reference_pressure = Some(v)),
    choice("plane.model", ["model", "plane model"], MODELS, |p| model_index(p.plane.model), |p, i| { p.plane.model = Model::ALL[i]; Ok(()) }),
    choice("plane.shape.kind", ["shape", "punch shape"], shape_rows::KINDS, shape_rows::kind, shape_rows::set_kind),
    number("plane.radius", ["R", "punch radius"], "m", limits::RADIUS, 0.01, |p| p.plane.radius, |p, v| p.plane.radius = v),
    number("plane.shape.radius", ["R", "radius of the power punch"], "m", limits::RADIUS, 0.01, shape_rows::power_radius, shape_rows::set_power_radius),
    number("plane.shape.exponent", ["n punch", "exponent of the power punch"], "", limits::POWER_EXPONENT, 2.0, shape_rows::power_exponent, shape_rows::set_power_exponent),
    number("plane.shape.half_width", ["c", "half-width of the flat face"], "m", limits::HALF_WIDTH, 1e-3, shape_rows::half_width, shape_rows::set_half_width),
    number("plane.shape.edge_radius", ["r", "radius of the rounded edges (0: sharp)"], "m", limits::EDGE_RADIUS, 1e-3, shape_rows::edge_radius, shape_rows::set_edge_radius),
    fixed("plane.shape.file", ["file", "the measured profile's file"], shape_rows::file),
    fixed("plane.shape.range", ["x range", "x range of the measured profile"], shape_rows::range),
    number("plane.load", ["P", "load per unit length"], "N/m", limits::LINE_LOAD, 1e3, |p| p.plane.load, |p, v| p.plane.load = v),
    number("plane.sweep.load_min", ["P min", "smallest load of the mu*(P) curve"], "N/m", limits::LINE_LOAD, 1e2, |p| p.plane.sweep.min, |p, v| p.plane.sweep.min = v),
    number("plane.sweep.load_max", ["P max", "largest load of the mu*(P) curve"], "N/m", limits::LINE_LOAD, 1e5, |p| p.plane.sweep.max, |p, v| p.plane.sweep.max = v),
    number("plane.sweep.points", ["points", "points of the mu*(P) curve"], "", limits::SWEEP_POINTS, 60.0, |p| p.plane.sweep.points as f64, |p, v| p.plane.sweep.points = v as usize),
    choice("plane.sweep.scale", ["scale", "spacing of the mu*(P) curve"], SCALES, |p| scale_index(p.plane.sweep.spacing), |p, i| { p.plane.sweep.spacing = scale(i); Ok(()) }),
    number("spatial.mean_pressure", ["pbar", "mean pressure"], "Pa", limits::MEAN_PRESSURE, 1e6, |p| p.spatial.mean_pressure, |p, v| p.spatial.mean_pressure = v),
    number("spatial.sliding_speed", ["V", "sliding speed"], "m/s", limits::SPEED, 0.1, |p| p.spatial.sliding_speed, |p, v| p.spatial.sliding_speed = v),
    number("spatial.time", ["t", "the instant shown"], "s", limits::TIME, 10.0, |p| p.spatial.time, |p, v| p.spatial.time = v),
    number("spatial.duration", ["duration", "extent of the time charts"], "s", limits::DURATION, 100.0, |p| p.spatial.duration, |p, v| p.spatial.duration = v),
    number("spatial.grid", ["grid", "points per side of the field"], "", limits::GRID, 64.0, |p| p.spatial.grid as f64, |p, v| p.spatial.grid = v as usize),
    number("spatial.sweep.pressure_min", ["pbar min", "smallest mean pressure of the mu*(pbar) curve"], "Pa", limits::MEAN_PRESSURE, 1e5, |p| p.spatial.sweep.min, |p, v| p.spatial.sweep.min = v),
    number("spatial.sweep.pressure_max", ["pbar max", "largest mean pressure of the mu*(pbar) curve"], "Pa", limits::MEAN_PRESSURE, 1e8, |p| p.spatial.sweep.max, |p, v| p.spatial.sweep.max = v),
    number("spatial.sweep.points", ["points", "points of the mu*(pbar) curve"], "", limits::SWEEP_POINTS, 60.0, |p| p.spatial.sweep.points as f64, |p, v| p.spatial.sweep.points = v as usize),
    choice("spatial.sweep.scale", ["scale", "spacing of the mu*(pbar) curve"], SCALES, |p| scale_index(p.spatial.sweep.spacing), |p, i| { p.spatial.sweep.spacing = scale(i); Ok(()) }),
    rough("spatial.surface.file", ["file", "the height map's file"], "", 0.0),
    rough("spatial.surface.hurst", ["H", "Hurst exponent of the self-affine spectrum"], "", 0.8),
    rough("spatial.surface.rms_height", ["h rms", "rms height the surface is scaled to"], "m", 1e-6),
    rough("spatial.surface.rms_slope", ["slope", "rms slope along x the surface is scaled to"], "", 0.1),
    rough("spatial.surface.rolloff_wavelength", ["lam_r", "roll-off wavelength (flat spectrum above it)"], "m", 1e-4),
    rough("spatial.surface.cutoff_wavelength", ["lam_s", "cutoff wavelength (no shorter waves)"], "m", 1e-5),
    rough("spatial.surface.length_x", ["Lx", "cell length along the sliding line"], "m", 1e-3),
    rough("spatial.surface.length_y", ["Ly", "cell width across it (0: a profile)"], "m", 1e-3),
    rough("spatial.surface.grid", ["grid", "nodes per side of the surface's grid"], "", 256.0),
    rough("spatial.surface.seed", ["seed", "seed of the random phases"], "", 1.0),
    wave("spatial.harmonics.N.amplitude", ["A", "amplitude of the harmonic"], "m", limits::AMPLITUDE, 1e-7, |h| h.amplitude, |h, v| h.amplitude = v),
    wave("spatial.harmonics.N.wavenumber_x", ["wx", "wavenumber along the sliding line"], "rad/m", limits::WAVENUMBER, 1e3, |h| h.wavenumber_x, |h, v| h.wavenumber_x = v),
    wave("spatial.harmonics.N.wavenumber_y", ["wy", "wavenumber across the sliding line"], "rad/m", limits::WAVENUMBER, 1e3, |h| h.wavenumber_y, |h, v| h.wavenumber_y = v),
    wave("spatial.harmonics.N.phase_x", ["rho_x", "phase along x at t = 0"], "rad", limits::PHASE, 1.0, |h| h.phase_x, |h, v| h.phase_x = v),
    wave("spatial.harmonics.N.phase_y", ["rho_y", "phase along y"], "rad", limits::PHASE, 1.0, |h| h.phase_y, |h, v| h.phase_y = v),
];
