//! Preset files (schema 1, TOML, SI units; `docs/presets.md`): the validated preset, its defaults and
//! its errors. The file format is in `file`, the checks in `check`, the bundled list in `bundled`.

mod as_written;
mod bundled;
mod check;
mod disk;
mod explore_check;
mod explore_section;
mod file;
#[cfg(test)]
mod hand_written_tests;
mod key;
mod law_rules;
mod lesson;
#[cfg(test)]
mod lesson_tests;
mod material_check;
mod material_rows;
mod params;
mod plausible;
mod profile_csv;
mod save_edited;
mod save_path;
mod shape_check;
mod shape_rows;
mod spatial_check;
mod surface_file;
mod surface_key;
mod surface_rows;
mod surface_set;
mod text_edit;
mod wording;
mod written;

use std::fmt;
use std::path::PathBuf;
use std::sync::Arc;

use serde::{Deserialize, Serialize};

use crate::physics::plane::shape::Table;
use crate::physics::plane::yield_onset::Strength;
use crate::physics::plane::{Model, PlaneInputs, Shape, WearLaw};
use crate::physics::spatial::harmonic::Harmonic;
use crate::physics::spatial::surface::SurfaceShape;
use crate::physics::spatial::{PunchShape, SpatialInputs, StateAt};
use crate::physics::{Friction, Material, Spacing, SweepRange};

pub use bundled::{BUNDLED, BUNDLED_DATA, Bundled, bundled, default_preset};
pub use check::{load, load_with_warnings, parse, parse_with_warnings};
pub use disk::{Links, MAX_PRESET_BYTES, leads_into, write_atomically};
pub use explore_section::Explore;
pub use file::{save, save_with, to_toml};
pub use key::Key;
pub use lesson::{DEFAULT_TOLERANCE, Lesson, Question, Tolerance, grade};
pub use params::{Access, PARAMS, Param};
pub use plausible::{settings_warnings, warnings};
pub use save_edited::{Origin, save_edited, saved_text, with_data_files_of};
pub use save_path::{SaveTarget, resolve_save_path};
pub use surface_rows::from_file as surface_from_file;

/// The schema version this build reads and writes.
pub const SCHEMA: i64 = 1;

/// Which problem a preset opens on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, strum::IntoStaticStr)]
#[serde(rename_all = "lowercase")]
#[strum(serialize_all = "lowercase")]
pub enum Problem {
    /// The plane problem (parabolic punch on a strip).
    Plane,
    /// The spatial problem (wavy punch on a layer).
    Spatial,
}

impl Problem {
    /// The name used in preset files ("plane", "spatial").
    pub fn name(self) -> &'static str {
        self.into()
    }
}

/// The `[plane]` section.
#[derive(Clone, Debug, PartialEq)]
pub struct PlaneSection {
    /// Which model solves it.
    pub model: Model,
    /// Punch radius R [m] of the parabola, the shape when `shape` is None.
    pub radius: f64,
    /// The punch's shape when the file gives `plane.shape` (other than a parabola).
    pub shape: Option<Shape>,
    /// The measured profile the file gave, kept while another kind of shape is chosen so that
    /// the form can return to it.
    pub measured: Option<Arc<Table>>,
    /// Load per unit length P [N/m].
    pub load: f64,
    /// The loads of the mu*(P) sweep.
    pub sweep: SweepRange,
}

/// The `[spatial]` section.
#[derive(Clone, Debug, PartialEq)]
pub struct SpatialSection {
    /// Mean pressure pbar [Pa].
    pub mean_pressure: f64,
    /// Sliding speed V [m/s].
    pub sliding_speed: f64,
    /// The instant shown t [s].
    pub time: f64,
    /// Extent of the time charts [s]; a file without one gets `Preset::auto_duration`.
    pub duration: f64,
    /// Points per side of the field grid.
    pub grid: usize,
    /// The time tolerance of the running-in (see `limits::TIME_TOLERANCE`).
    pub time_tolerance: f64,
    /// The mean pressures of the mu*(pbar) sweep.
    pub sweep: SweepRange,
    /// The punch harmonics at t = 0 (none when `surface` is given).
    pub harmonics: Vec<Harmonic>,
    /// The punch as a height map (`spatial.surface`), in place of the harmonics.
    pub surface: Option<Arc<SurfaceShape>>,
}

/// A validated preset.
#[derive(Clone, Debug, PartialEq)]
pub struct Preset {
    /// Short title.
    pub name: String,
    /// What the preset shows and what to look at.
    pub description: String,
    /// The problem the explorer opens on.
    pub problem: Problem,
    /// The strip / layer.
    pub material: Material,
    /// Friction law.
    pub friction: Friction,
    /// Wear coefficient k [1/Pa].
    pub wear: f64,
    /// Exponent n of the wear law W' = -k q2 (q2/p0)^(n-1), 1 (the linear law) by default.
    pub wear_exponent: f64,
    /// Reference pressure p0 [Pa] of the wear law, required when n != 1.
    pub reference_pressure: Option<f64>,
    /// Shear strength tau_max [Pa] capping the friction stress, inf (no cap) by default.
    pub shear_strength: f64,
    /// The strip's yield strength or hardness (`material.yield_strength`, `material.hardness`),
    /// which enable the plane problem's yield check; neither by default.
    pub strength: Strength,
    /// The plane problem (defaults when the file has no `[plane]`).
    pub plane: PlaneSection,
    /// The spatial problem (defaults when the file has no `[spatial]`).
    pub spatial: SpatialSection,
    /// The sweep or map the preset's lesson is about (`[explore]`, optional).
    pub explore: Option<Explore>,
    /// The view to open on, the locked keys and the questions (`[lesson]`, optional).
    pub lesson: Option<Lesson>,
}

impl Preset {
    /// The plane solver's inputs at the preset's load.
    pub fn plane_inputs(&self) -> PlaneInputs {
        let wear = WearLaw::linear(self.wear);
        PlaneInputs {
            material: self.material,
            friction: self.friction,
            shear_strength: self.shear_strength,
            wear: WearLaw {
                exponent: self.wear_exponent,
                reference_pressure: self.reference_pressure.unwrap_or(wear.reference_pressure),
                ..wear
            },
            shape: self.plane.shape.clone().unwrap_or(Shape::Parabola {
                radius: self.plane.radius,
            }),
            load: self.plane.load,
        }
    }
}

impl Preset {
    /// The spatial solver's inputs.
    pub fn spatial_inputs(&self) -> SpatialInputs {
        SpatialInputs {
            material: self.material,
            friction: self.friction,
            wear: self.wear,
            wear_exponent: self.wear_exponent,
            reference_pressure: self.reference_pressure.unwrap_or(1.0),
            sliding_speed: self.spatial.sliding_speed,
            mean_pressure: self.spatial.mean_pressure,
            shape: match &self.spatial.surface {
                Some(surface) => PunchShape::Surface(Arc::clone(surface)),
                None => PunchShape::Harmonics(self.spatial.harmonics.clone()),
            },
        }
    }

    /// The duration [s] of a preset that gives none: five of the slowest decay times 1/beta
    /// (`docs/physics/spatial.md`, section 3), so that the time charts show the run-in; the
    /// default section's 200 s when nothing decays (no wear); within `limits::DURATION`. A wear
    /// law n != 1 decays a small wave at the linear law's rate times F'(pbar)/k =
    /// n (pbar/p0)^(n-1), its slope at the mean pressure.
    pub fn auto_duration(&self) -> f64 {
        let inputs = self.spatial_inputs();
        let linearised = inputs.worn_pressure_slope(inputs.mean_pressure);
        let slowest = crate::physics::spatial::evolutions(&inputs)
            .iter()
            .map(|e| e.decay_rate * linearised)
            .filter(|b| b.is_finite() && *b > 0.0)
            .fold(f64::INFINITY, f64::min);
        if slowest.is_finite() {
            let d = &crate::physics::limits::DURATION;
            (5.0 / slowest).clamp(d.min, d.max)
        } else {
            default_spatial_section().duration
        }
    }

    /// Where the spatial state is evaluated: the preset's time, grid and mean-pressure sweep.
    pub fn spatial_state_at(&self) -> StateAt {
        StateAt {
            time: self.spatial.time,
            grid: self.spatial.grid,
            time_tolerance: self.spatial.time_tolerance,
            sweep: self.spatial.sweep,
        }
    }
}

/// The `[plane]` section a preset without one gets: a wide strip, R = 50 mm, P = 1e4 N/m.
pub fn default_plane_section() -> PlaneSection {
    PlaneSection {
        model: Model::Wide,
        radius: 0.05,
        shape: None,
        measured: None,
        load: 1e4,
        sweep: default_load_sweep(1e4),
    }
}

/// The `[spatial]` section a preset without one gets: pbar = 50 MPa, V = 1 m/s, one 1-D wave of
/// 1 mm wavelength and 40 nm amplitude, t = 0, duration 200 s, a 64-point grid, a time tolerance
/// of 1e-6 (time-stepping errors of the running-in's outputs below about 1e-6 relative).
pub fn default_spatial_section() -> SpatialSection {
    SpatialSection {
        mean_pressure: 5e7,
        sliding_speed: 1.0,
        time: 0.0,
        duration: 200.0,
        grid: 64,
        time_tolerance: 1e-6,
        sweep: default_pressure_sweep(5e7),
        harmonics: vec![Harmonic {
            amplitude: 4e-8,
            wavenumber_x: 2.0 * std::f64::consts::PI / 1e-3,
            wavenumber_y: 0.0,
            phase_x: 0.0,
            phase_y: std::f64::consts::FRAC_PI_2,
        }],
        surface: None,
    }
}

/// The default mean-pressure sweep: pbar/10 to 10 pbar, 60 points, log.
pub fn default_pressure_sweep(mean_pressure: f64) -> SweepRange {
    SweepRange {
        min: mean_pressure / 10.0,
        max: mean_pressure * 10.0,
        points: 60,
        spacing: Spacing::Log,
    }
}

/// The default sweep when a preset gives none: P/100 to 100 P, 60 points, log.
pub fn default_load_sweep(load: f64) -> SweepRange {
    SweepRange {
        min: load / 100.0,
        max: load * 100.0,
        points: 60,
        spacing: Spacing::Log,
    }
}

/// What is wrong with a preset file, and where.
#[derive(Debug, Clone, PartialEq)]
pub struct PresetError {
    /// The file.
    pub path: PathBuf,
    /// 1-based line, when the problem has one.
    pub line: Option<usize>,
    /// What is wrong and what is allowed.
    pub reason: String,
}

impl fmt::Display for PresetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(line) => write!(f, "{}:{}: {}", self.path.display(), line, self.reason),
            None => write!(f, "{}: {}", self.path.display(), self.reason),
        }
    }
}

impl std::error::Error for PresetError {}
