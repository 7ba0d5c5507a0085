//! The preset file format (schema 1, TOML, SI units; `design.md`): the file's layout with the
//! spans kept for error messages, reading, writing as TOML, and the atomic save.

use std::io::Write;
use std::path::Path;

use serde::{Deserialize, Serialize};
use toml::Spanned;

use crate::physics::Spacing;
use crate::physics::plane::Model;
use crate::preset::{
    Preset, PresetError, Problem, SCHEMA, SpatialSection, default_spatial_section, parse,
};

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileMaterial {
    pub(super) youngs_modulus: Spanned<f64>,
    pub(super) poisson_ratio: Spanned<f64>,
    pub(super) thickness: Spanned<f64>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileFriction {
    #[serde(default = "zero")]
    pub(super) coefficient: Spanned<f64>,
    #[serde(default = "zero")]
    pub(super) adhesion: Spanned<f64>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileWear {
    #[serde(default = "zero")]
    pub(super) coefficient: Spanned<f64>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileLoadSweep {
    pub(super) load_min: Spanned<f64>,
    pub(super) load_max: Spanned<f64>,
    pub(super) points: Spanned<i64>,
    pub(super) scale: Spacing,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FilePlane {
    pub(super) model: Model,
    pub(super) radius: Spanned<f64>,
    pub(super) load: Spanned<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) sweep: Option<Spanned<FileLoadSweep>>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FilePressureSweep {
    pub(super) pressure_min: Spanned<f64>,
    pub(super) pressure_max: Spanned<f64>,
    pub(super) points: Spanned<i64>,
    pub(super) scale: Spacing,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileHarmonic {
    pub(super) amplitude: Spanned<f64>,
    pub(super) wavenumber_x: Spanned<f64>,
    pub(super) wavenumber_y: Spanned<f64>,
    pub(super) phase_x: Spanned<f64>,
    pub(super) phase_y: Spanned<f64>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileSpatial {
    pub(super) mean_pressure: Spanned<f64>,
    pub(super) sliding_speed: Spanned<f64>,
    #[serde(default = "zero")]
    pub(super) time: Spanned<f64>,
    #[serde(default = "default_duration")]
    pub(super) duration: Spanned<f64>,
    #[serde(default = "default_grid")]
    pub(super) grid: Spanned<i64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) sweep: Option<Spanned<FilePressureSweep>>,
    #[serde(default)]
    pub(super) harmonics: Vec<Spanned<FileHarmonic>>,
}

fn default_duration() -> Spanned<f64> {
    plain(default_spatial_section().duration)
}

fn default_grid() -> Spanned<i64> {
    plain(default_spatial_section().grid as i64)
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
}

pub(super) fn zero() -> Spanned<f64> {
    Spanned::new(0..0, 0.0)
}

pub(super) fn plain<T>(value: T) -> Spanned<T> {
    Spanned::new(0..0, value)
}

/// Reads and validates a preset file.
pub fn load(path: &Path) -> Result<Preset, PresetError> {
    let text = std::fs::read_to_string(path).map_err(|e| PresetError {
        path: path.to_path_buf(),
        line: None,
        reason: format!("cannot read the file: {e}"),
    })?;
    parse(&text, path)
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
            youngs_modulus: plain(preset.material.youngs_modulus),
            poisson_ratio: plain(preset.material.poisson_ratio),
            thickness: plain(preset.material.thickness),
        })),
        friction: Some(FileFriction {
            coefficient: plain(preset.friction.coefficient),
            adhesion: plain(preset.friction.adhesion),
        }),
        wear: Some(FileWear {
            coefficient: plain(preset.wear),
        }),
        plane: Some(plain(FilePlane {
            model: preset.plane.model,
            radius: plain(preset.plane.radius),
            load: plain(preset.plane.load),
            sweep: Some(plain(FileLoadSweep {
                load_min: plain(sw.min),
                load_max: plain(sw.max),
                points: plain(sw.points as i64),
                scale: sw.spacing,
            })),
        })),
        spatial: Some(plain(spatial_file(&preset.spatial))),
    };
    toml::to_string(&file).expect("a preset always serializes")
}

fn spatial_file(sp: &SpatialSection) -> FileSpatial {
    FileSpatial {
        mean_pressure: plain(sp.mean_pressure),
        sliding_speed: plain(sp.sliding_speed),
        time: plain(sp.time),
        duration: plain(sp.duration),
        grid: plain(sp.grid as i64),
        sweep: Some(plain(FilePressureSweep {
            pressure_min: plain(sp.sweep.min),
            pressure_max: plain(sp.sweep.max),
            points: plain(sp.sweep.points as i64),
            scale: sp.sweep.spacing,
        })),
        harmonics: sp
            .harmonics
            .iter()
            .map(|h| {
                plain(FileHarmonic {
                    amplitude: plain(h.amplitude),
                    wavenumber_x: plain(h.wavenumber_x),
                    wavenumber_y: plain(h.wavenumber_y),
                    phase_x: plain(h.phase_x),
                    phase_y: plain(h.phase_y),
                })
            })
            .collect(),
    }
}

/// Writes `path` atomically: the bytes go to a temporary file in the same folder, which is
/// synced and then renamed over `path`. If `write` fails, the old file is untouched and the
/// temporary file is removed.
pub fn write_atomically(
    path: &Path,
    write: impl FnOnce(&mut std::fs::File) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut tmp = tempfile::Builder::new()
        .prefix(".wearlab-save-")
        .tempfile_in(dir)?;
    write(tmp.as_file_mut())?;
    tmp.as_file_mut().flush()?;
    tmp.as_file().sync_all()?;
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}

/// Saves a preset atomically.
pub fn save(preset: &Preset, path: &Path) -> std::io::Result<()> {
    let text = to_toml(preset);
    write_atomically(path, |f| f.write_all(text.as_bytes()))
}
