//! The preset file format (schema 1, TOML, SI units; `docs/presets.md`): the file's layout with the
//! spans kept for error messages, reading, writing as TOML, and the atomic save (where a typed
//! name saves to: `save_path`).

use std::io::Write;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};
use toml::Spanned;

use crate::materials::{self, MATERIALS};
use crate::physics::Spacing;
use crate::physics::plane::{Model, Shape};
use crate::preset::explore_section::Explore;
use crate::preset::lesson::{self, FileLesson};
use crate::preset::written::Written;
use crate::preset::{
    Preset, Problem, SCHEMA, SpatialSection, default_spatial_section, disk, surface_file,
};
use crate::sweeps::axis::Axis;

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileMaterial {
    /// A material of the bundled table, whose values fill those not written.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) name: Option<Spanned<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) youngs_modulus: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) poisson_ratio: Option<Spanned<Written>>,
    pub(super) thickness: Spanned<Written>,
    /// Absent: no yield check (unless the hardness is given).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) yield_strength: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) hardness: Option<Spanned<Written>>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileFriction {
    #[serde(default = "zero")]
    pub(super) coefficient: Spanned<Written>,
    #[serde(default = "zero")]
    pub(super) adhesion: Spanned<Written>,
    /// Absent: no cap (inf).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) shear_strength: Option<Spanned<Written>>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileWear {
    /// Absent with `archard_coefficient` absent too: no wear.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) coefficient: Option<Spanned<Written>>,
    /// Archard's K = k H, in place of `coefficient`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) archard_coefficient: Option<Spanned<Written>>,
    /// Absent: 1, the linear law.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) exponent: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) reference_pressure: Option<Spanned<Written>>,
}

/// `plane.shape`: the kind and the keys of that kind (the checks say which belong to which).
#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileShape {
    pub(super) kind: Spanned<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) radius: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) exponent: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) half_width: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) edge_radius: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) file: Option<Spanned<String>>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileLoadSweep {
    pub(super) load_min: Spanned<Written>,
    pub(super) load_max: Spanned<Written>,
    pub(super) points: Spanned<i64>,
    pub(super) scale: Spacing,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FilePlane {
    pub(super) model: Model,
    /// The parabola's radius; absent when `shape` is given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) radius: Option<Spanned<Written>>,
    pub(super) load: Spanned<Written>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) shape: Option<Spanned<FileShape>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) sweep: Option<Spanned<FileLoadSweep>>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FilePressureSweep {
    pub(super) pressure_min: Spanned<Written>,
    pub(super) pressure_max: Spanned<Written>,
    pub(super) points: Spanned<i64>,
    pub(super) scale: Spacing,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileHarmonic {
    pub(super) amplitude: Spanned<Written>,
    pub(super) wavenumber_x: Spanned<Written>,
    pub(super) wavenumber_y: Spanned<Written>,
    pub(super) phase_x: Spanned<Written>,
    pub(super) phase_y: Spanned<Written>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileSpatial {
    pub(super) mean_pressure: Spanned<Written>,
    pub(super) sliding_speed: Spanned<Written>,
    #[serde(default = "zero")]
    pub(super) time: Spanned<Written>,
    /// Absent: five of the slowest decay times (`Preset::auto_duration`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) duration: Option<Spanned<Written>>,
    /// Absent: the default section's; refused beside a height map, which has its own grid.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) grid: Option<Spanned<i64>>,
    /// Absent: the default section's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) time_tolerance: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) sweep: Option<Spanned<FilePressureSweep>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) surface: Option<Spanned<surface_file::FileSurface>>,
    #[serde(default)]
    pub(super) harmonics: Vec<Spanned<FileHarmonic>>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FilePreset {
    pub(super) schema: Spanned<i64>,
    #[serde(default)]
    pub(super) name: String,
    #[serde(default)]
    pub(super) description: String,
    pub(super) problem: Spanned<Problem>,
    pub(super) material: Option<Spanned<FileMaterial>>,
    pub(super) friction: Option<FileFriction>,
    pub(super) wear: Option<FileWear>,
    pub(super) plane: Option<Spanned<FilePlane>>,
    pub(super) spatial: Option<Spanned<FileSpatial>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) explore: Option<Spanned<FileExplore>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) lesson: Option<Spanned<FileLesson>>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileAxis {
    pub(super) key: Spanned<String>,
    pub(super) from: Spanned<Written>,
    pub(super) to: Spanned<Written>,
    #[serde(default)]
    pub(super) points: Option<Spanned<i64>>,
    #[serde(default)]
    pub(super) scale: Option<Spacing>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileExplore {
    pub(super) quantity: Spanned<String>,
    pub(super) x: Spanned<FileAxis>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) y: Option<Spanned<FileAxis>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) data: Option<Spanned<String>>,
}

pub(super) fn zero() -> Spanned<Written> {
    num(0.0)
}

/// A number to write.
fn num(value: f64) -> Spanned<Written> {
    plain(Written::Number(value))
}

pub(super) fn plain<T>(value: T) -> Spanned<T> {
    Spanned::new(0..0, value)
}

/// The preset as TOML text (schema 1).
pub fn to_toml(preset: &Preset) -> String {
    let sw = &preset.plane.sweep;
    let file = FilePreset {
        schema: plain(SCHEMA),
        name: preset.name.clone(),
        description: preset.description.clone(),
        problem: plain(preset.problem),
        material: Some(plain(FileMaterial {
            name: materials::matching(
                preset.material.youngs_modulus,
                preset.material.poisson_ratio,
                preset.strength,
            )
            .map(|i| plain(MATERIALS[i].name.to_string())),
            youngs_modulus: Some(num(preset.material.youngs_modulus)),
            poisson_ratio: Some(num(preset.material.poisson_ratio)),
            thickness: num(preset.material.thickness),
            yield_strength: preset.strength.yield_strength.map(num),
            hardness: preset.strength.hardness.map(num),
        })),
        friction: Some(FileFriction {
            coefficient: num(preset.friction.coefficient),
            adhesion: num(preset.friction.adhesion),
            shear_strength: preset
                .shear_strength
                .is_finite()
                .then(|| num(preset.shear_strength)),
        }),
        wear: Some(FileWear {
            coefficient: Some(num(preset.wear)),
            archard_coefficient: None,
            exponent: (preset.wear_exponent != 1.0).then(|| num(preset.wear_exponent)),
            reference_pressure: preset.reference_pressure.map(num),
        }),
        plane: Some(plain(FilePlane {
            model: preset.plane.model,
            radius: preset
                .plane
                .shape
                .is_none()
                .then(|| num(preset.plane.radius)),
            load: num(preset.plane.load),
            shape: preset.plane.shape.as_ref().map(|s| plain(shape_file(s))),
            sweep: Some(plain(FileLoadSweep {
                load_min: num(sw.min),
                load_max: num(sw.max),
                points: plain(sw.points as i64),
                scale: sw.spacing,
            })),
        })),
        spatial: Some(plain(spatial_file(&preset.spatial))),
        explore: preset.explore.as_ref().map(|e| plain(explore_file(e))),
        lesson: preset.lesson.as_ref().map(|l| plain(lesson::to_file(l))),
    };
    toml::to_string(&file).expect("a preset always serializes")
}

/// `plane.shape` as written by `to_toml`: the kind and its keys.
fn shape_file(shape: &Shape) -> FileShape {
    let mut out = FileShape {
        kind: plain(shape.kind().to_string()),
        radius: None,
        exponent: None,
        half_width: None,
        edge_radius: None,
        file: None,
    };
    match shape {
        Shape::Parabola { radius } => out.radius = Some(num(*radius)),
        Shape::Power { radius, exponent } => {
            out.radius = Some(num(*radius));
            out.exponent = Some(num(*exponent));
        }
        Shape::Flat {
            half_width,
            edge_radius,
        } => {
            out.half_width = Some(num(*half_width));
            out.edge_radius = Some(num(*edge_radius));
        }
        Shape::Table(t) => out.file = Some(plain(t.file.clone())),
    }
    out
}

/// The `[explore]` section as written by `to_toml`.
fn explore_file(e: &Explore) -> FileExplore {
    let axis = |a: &Axis| {
        plain(FileAxis {
            key: plain(a.key.to_string()),
            from: num(a.range.min),
            to: num(a.range.max),
            points: Some(plain(a.range.points as i64)),
            scale: Some(a.range.spacing),
        })
    };
    FileExplore {
        quantity: plain(e.quantity.to_string()),
        x: axis(&e.axes[0]),
        y: e.axes.get(1).map(axis),
        data: e.data.clone().map(plain),
    }
}

fn spatial_file(sp: &SpatialSection) -> FileSpatial {
    FileSpatial {
        mean_pressure: num(sp.mean_pressure),
        sliding_speed: num(sp.sliding_speed),
        time: num(sp.time),
        duration: Some(num(sp.duration)),
        // a height map is solved on its own grid: no spatial.grid beside it
        grid: sp.surface.is_none().then(|| plain(sp.grid as i64)),
        // written only when it is not the default, so that saved presets stay as they were
        time_tolerance: (sp.time_tolerance != default_spatial_section().time_tolerance)
            .then(|| num(sp.time_tolerance)),
        sweep: Some(plain(FilePressureSweep {
            pressure_min: num(sp.sweep.min),
            pressure_max: num(sp.sweep.max),
            points: plain(sp.sweep.points as i64),
            scale: sp.sweep.spacing,
        })),
        surface: sp
            .surface
            .as_ref()
            .map(|s| plain(surface_file::to_file(&s.source))),
        harmonics: sp
            .harmonics
            .iter()
            .map(|h| {
                plain(FileHarmonic {
                    amplitude: num(h.amplitude),
                    wavenumber_x: num(h.wavenumber_x),
                    wavenumber_y: num(h.wavenumber_y),
                    phase_x: num(h.phase_x),
                    phase_y: num(h.phase_y),
                })
            })
            .collect(),
    }
}

/// Saves a preset atomically, through a symbolic link to a file the user may replace.
pub fn save(preset: &Preset, path: &Path) -> std::io::Result<()> {
    save_with(preset, path, disk::Links::Follow).map(|_| ())
}

/// Saves a preset atomically, doing `links` with a symbolic link at `path`; Ok holds the file a
/// link led to that the save left as it was.
pub fn save_with(
    preset: &Preset,
    path: &Path,
    links: disk::Links,
) -> std::io::Result<Option<PathBuf>> {
    let text = to_toml(preset);
    disk::write_atomically(path, links, |f| f.write_all(text.as_bytes()))
}
