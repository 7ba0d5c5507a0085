//! Preset files (schema 1, TOML, SI units; `design.md`): load with `path:line: reason` errors,
//! validation against `physics::limits`, atomic save.

use std::fmt;
use std::io::Write;
use std::ops::Range;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};
use toml::Spanned;

use crate::physics::limits::{self, Limit};
use crate::physics::plane::sweep::LoadSweep;
use crate::physics::plane::{Model, PlaneInputs};
use crate::physics::{Friction, Material, Spacing};

/// The schema version this build reads and writes.
pub const SCHEMA: i64 = 1;

/// Which problem a preset opens on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Problem {
    /// The plane problem (parabolic punch on a strip).
    Plane,
}

/// The `[plane]` section.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlaneSection {
    /// Which model solves it.
    pub model: Model,
    /// Punch radius R [m].
    pub radius: f64,
    /// Load per unit length P [N/m].
    pub load: f64,
    /// The loads of the mu*(P) sweep.
    pub sweep: LoadSweep,
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
    /// The plane problem.
    pub plane: PlaneSection,
}

impl Preset {
    /// The plane solver's inputs at the preset's load.
    pub fn plane_inputs(&self) -> PlaneInputs {
        PlaneInputs {
            material: self.material,
            friction: self.friction,
            wear: self.wear,
            radius: self.plane.radius,
            load: self.plane.load,
        }
    }
}

/// The default sweep when a preset gives none: P/100 to 100 P, 60 points, log.
pub fn default_load_sweep(load: f64) -> LoadSweep {
    LoadSweep {
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

// ---- the file layout (spans kept for error messages) ----

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct FileMaterial {
    youngs_modulus: Spanned<f64>,
    poisson_ratio: Spanned<f64>,
    thickness: Spanned<f64>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct FileFriction {
    #[serde(default = "zero")]
    coefficient: Spanned<f64>,
    #[serde(default = "zero")]
    adhesion: Spanned<f64>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct FileWear {
    #[serde(default = "zero")]
    coefficient: Spanned<f64>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct FileLoadSweep {
    load_min: Spanned<f64>,
    load_max: Spanned<f64>,
    points: Spanned<i64>,
    scale: Spacing,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct FilePlane {
    model: Model,
    radius: Spanned<f64>,
    load: Spanned<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    sweep: Option<Spanned<FileLoadSweep>>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct FilePreset {
    schema: Spanned<i64>,
    #[serde(default)]
    name: String,
    #[serde(default)]
    description: String,
    problem: Spanned<Problem>,
    material: Option<Spanned<FileMaterial>>,
    friction: Option<FileFriction>,
    wear: Option<FileWear>,
    plane: Option<Spanned<FilePlane>>,
}

fn zero() -> Spanned<f64> {
    Spanned::new(0..0, 0.0)
}

fn plain<T>(value: T) -> Spanned<T> {
    Spanned::new(0..0, value)
}

fn line_of(text: &str, offset: usize) -> usize {
    1 + text.as_bytes()[..offset.min(text.len())]
        .iter()
        .filter(|&&c| c == b'\n')
        .count()
}

struct Checker<'a> {
    path: &'a Path,
    text: &'a str,
}

impl Checker<'_> {
    fn error(&self, span: Option<Range<usize>>, reason: impl Into<String>) -> PresetError {
        PresetError {
            path: self.path.to_path_buf(),
            line: span.map(|s| line_of(self.text, s.start)),
            reason: reason.into(),
        }
    }

    fn value(&self, v: &Spanned<f64>, name: &str, limit: &Limit) -> Result<f64, PresetError> {
        limit
            .check(name, *v.get_ref())
            .map_err(|why| self.error(Some(v.span()), why))?;
        Ok(*v.get_ref())
    }
}

/// Parses and validates preset text; `path` is only used in messages.
pub fn parse(text: &str, path: &Path) -> Result<Preset, PresetError> {
    let ck = Checker { path, text };
    let file: FilePreset = toml::from_str(text).map_err(|e| {
        let reason = e.message().trim().replace('\n', " ");
        ck.error(e.span(), reason)
    })?;
    if *file.schema.get_ref() != SCHEMA {
        return Err(ck.error(
            Some(file.schema.span()),
            format!(
                "schema = {} is not supported: this wearlab reads schema = {SCHEMA}",
                file.schema.get_ref()
            ),
        ));
    }
    let material = file
        .material
        .ok_or_else(|| ck.error(None, "missing section [material] (every preset needs it)"))?;
    let mat = material.get_ref();
    let material = Material {
        youngs_modulus: ck.value(
            &mat.youngs_modulus,
            "youngs_modulus",
            &limits::YOUNGS_MODULUS,
        )?,
        poisson_ratio: ck.value(&mat.poisson_ratio, "poisson_ratio", &limits::POISSON_RATIO)?,
        thickness: ck.value(&mat.thickness, "thickness", &limits::THICKNESS)?,
    };
    let friction = match &file.friction {
        Some(f) => Friction {
            coefficient: ck.value(&f.coefficient, "coefficient", &limits::FRICTION)?,
            adhesion: ck.value(&f.adhesion, "adhesion", &limits::ADHESION)?,
        },
        None => Friction {
            coefficient: 0.0,
            adhesion: 0.0,
        },
    };
    let wear = match &file.wear {
        Some(w) => ck.value(&w.coefficient, "coefficient", &limits::WEAR)?,
        None => 0.0,
    };
    let plane = file.plane.as_ref().ok_or_else(|| {
        ck.error(
            Some(file.problem.span()),
            "problem = \"plane\" needs a [plane] section (model, radius, load)",
        )
    })?;
    let pl = plane.get_ref();
    let radius = ck.value(&pl.radius, "radius", &limits::RADIUS)?;
    let load = ck.value(&pl.load, "load", &limits::LINE_LOAD)?;
    if pl.model == Model::Narrow && material.thickness.is_infinite() {
        return Err(ck.error(
            Some(plane.span()),
            "model = \"narrow\" (Winkler) needs a finite thickness: set [material] thickness or use model = \"wide\"",
        ));
    }
    let sweep = match &pl.sweep {
        Some(sw) => {
            let s = sw.get_ref();
            let min = ck.value(&s.load_min, "load_min", &limits::LINE_LOAD)?;
            let max = ck.value(&s.load_max, "load_max", &limits::LINE_LOAD)?;
            if max <= min {
                return Err(ck.error(
                    Some(s.load_max.span()),
                    format!("load_max = {max} must be larger than load_min = {min}"),
                ));
            }
            let points = *s.points.get_ref();
            limits::SWEEP_POINTS
                .check("points", points as f64)
                .map_err(|why| ck.error(Some(s.points.span()), why))?;
            LoadSweep {
                min,
                max,
                points: points as usize,
                spacing: s.scale,
            }
        }
        None => default_load_sweep(load),
    };
    Ok(Preset {
        name: file.name,
        description: file.description,
        problem: *file.problem.get_ref(),
        material,
        friction,
        wear,
        plane: PlaneSection {
            model: pl.model,
            radius,
            load,
            sweep,
        },
    })
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
    };
    toml::to_string(&file).expect("a preset always serializes")
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

/// A preset that ships inside the binary (the files of `presets/`).
#[derive(Clone, Copy, Debug)]
pub struct Bundled {
    /// File name, e.g. "hertz-check.toml".
    pub file: &'static str,
    /// The file's text.
    pub text: &'static str,
}

/// The bundled presets, the default first.
pub const BUNDLED: &[Bundled] = &[
    Bundled {
        file: "polymer-coating.toml",
        text: include_str!("../presets/polymer-coating.toml"),
    },
    Bundled {
        file: "hertz-check.toml",
        text: include_str!("../presets/hertz-check.toml"),
    },
    Bundled {
        file: "friction-half-plane.toml",
        text: include_str!("../presets/friction-half-plane.toml"),
    },
    Bundled {
        file: "wear-dominated.toml",
        text: include_str!("../presets/wear-dominated.toml"),
    },
    Bundled {
        file: "thin-strip-winkler.toml",
        text: include_str!("../presets/thin-strip-winkler.toml"),
    },
];

impl Bundled {
    /// Parses the bundled text (its path in messages is `presets/<file>`).
    pub fn load(&self) -> Result<Preset, PresetError> {
        parse(self.text, &Path::new("presets").join(self.file))
    }
}

/// The built-in default preset (the first bundled one).
pub fn default_preset() -> Preset {
    BUNDLED[0]
        .load()
        .expect("the bundled default preset is valid (tested)")
}
