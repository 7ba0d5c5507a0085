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
use crate::physics::spatial::harmonic::Harmonic;
use crate::physics::spatial::history::PressureSweep;
use crate::physics::spatial::{SpatialInputs, validate_harmonics};
use crate::physics::{Friction, Material, Spacing};

/// The schema version this build reads and writes.
pub const SCHEMA: i64 = 1;

/// Which problem a preset opens on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Problem {
    /// The plane problem (parabolic punch on a strip).
    Plane,
    /// The spatial problem (wavy punch on a layer).
    Spatial,
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

/// The `[spatial]` section.
#[derive(Clone, Debug, PartialEq)]
pub struct SpatialSection {
    /// Mean pressure pbar [Pa].
    pub mean_pressure: f64,
    /// Sliding speed V [m/s].
    pub sliding_speed: f64,
    /// The instant shown t [s].
    pub time: f64,
    /// Extent of the time charts [s].
    pub duration: f64,
    /// Points per side of the field grid.
    pub grid: usize,
    /// The mean pressures of the mu*(pbar) sweep.
    pub sweep: PressureSweep,
    /// The punch harmonics at t = 0.
    pub harmonics: Vec<Harmonic>,
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
    /// The plane problem (defaults when the file has no `[plane]`).
    pub plane: PlaneSection,
    /// The spatial problem (defaults when the file has no `[spatial]`).
    pub spatial: SpatialSection,
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

impl Preset {
    /// The spatial solver's inputs.
    pub fn spatial_inputs(&self) -> SpatialInputs {
        SpatialInputs {
            material: self.material,
            friction: self.friction,
            wear: self.wear,
            sliding_speed: self.spatial.sliding_speed,
            mean_pressure: self.spatial.mean_pressure,
            harmonics: self.spatial.harmonics.clone(),
        }
    }
}

/// The `[plane]` section a preset without one gets: a wide strip, R = 50 mm, P = 1e4 N/m.
pub fn default_plane_section() -> PlaneSection {
    PlaneSection {
        model: Model::Wide,
        radius: 0.05,
        load: 1e4,
        sweep: default_load_sweep(1e4),
    }
}

/// The `[spatial]` section a preset without one gets: pbar = 50 MPa, V = 1 m/s, one 1-D wave of
/// 1 mm wavelength and 40 nm amplitude, t = 0, duration 200 s, a 64-point grid.
pub fn default_spatial_section() -> SpatialSection {
    SpatialSection {
        mean_pressure: 5e7,
        sliding_speed: 1.0,
        time: 0.0,
        duration: 200.0,
        grid: 64,
        sweep: default_pressure_sweep(5e7),
        harmonics: vec![Harmonic {
            amplitude: 4e-8,
            wavenumber_x: 2.0 * std::f64::consts::PI / 1e-3,
            wavenumber_y: 0.0,
            phase_x: 0.0,
            phase_y: std::f64::consts::FRAC_PI_2,
        }],
    }
}

/// The default mean-pressure sweep: pbar/10 to 10 pbar, 60 points, log.
pub fn default_pressure_sweep(mean_pressure: f64) -> PressureSweep {
    PressureSweep {
        min: mean_pressure / 10.0,
        max: mean_pressure * 10.0,
        points: 60,
        spacing: Spacing::Log,
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
struct FilePressureSweep {
    pressure_min: Spanned<f64>,
    pressure_max: Spanned<f64>,
    points: Spanned<i64>,
    scale: Spacing,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct FileHarmonic {
    amplitude: Spanned<f64>,
    wavenumber_x: Spanned<f64>,
    wavenumber_y: Spanned<f64>,
    phase_x: Spanned<f64>,
    phase_y: Spanned<f64>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct FileSpatial {
    mean_pressure: Spanned<f64>,
    sliding_speed: Spanned<f64>,
    #[serde(default = "zero")]
    time: Spanned<f64>,
    #[serde(default = "default_duration")]
    duration: Spanned<f64>,
    #[serde(default = "default_grid")]
    grid: Spanned<i64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    sweep: Option<Spanned<FilePressureSweep>>,
    #[serde(default)]
    harmonics: Vec<Spanned<FileHarmonic>>,
}

fn default_duration() -> Spanned<f64> {
    plain(default_spatial_section().duration)
}

fn default_grid() -> Spanned<i64> {
    plain(default_spatial_section().grid as i64)
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
    spatial: Option<Spanned<FileSpatial>>,
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
    let problem = *file.problem.get_ref();
    let missing = |section: &str, keys: &str| {
        ck.error(
            Some(file.problem.span()),
            format!("problem = \"{section}\" needs a [{section}] section ({keys})"),
        )
    };
    let plane = match &file.plane {
        Some(pl) => ck.plane(pl, &material)?,
        None if problem == Problem::Plane => return Err(missing("plane", "model, radius, load")),
        None => default_plane_section(),
    };
    let spatial = match &file.spatial {
        Some(sp) => ck.spatial(sp)?,
        None if problem == Problem::Spatial => {
            return Err(missing(
                "spatial",
                "mean_pressure, sliding_speed, [[spatial.harmonics]]",
            ));
        }
        None => default_spatial_section(),
    };
    Ok(Preset {
        name: file.name,
        description: file.description,
        problem,
        material,
        friction,
        wear,
        plane,
        spatial,
    })
}

impl Checker<'_> {
    fn count(&self, v: &Spanned<i64>, name: &str, limit: &Limit) -> Result<usize, PresetError> {
        let n = *v.get_ref();
        limit
            .check(name, n as f64)
            .map_err(|why| self.error(Some(v.span()), why))?;
        Ok(n as usize)
    }

    fn range(
        &self,
        lo: &Spanned<f64>,
        hi: &Spanned<f64>,
        names: [&str; 2],
        limit: &Limit,
    ) -> Result<(f64, f64), PresetError> {
        let min = self.value(lo, names[0], limit)?;
        let max = self.value(hi, names[1], limit)?;
        if max <= min {
            return Err(self.error(
                Some(hi.span()),
                format!(
                    "{} = {max} must be larger than {} = {min}",
                    names[1], names[0]
                ),
            ));
        }
        Ok((min, max))
    }

    fn plane(
        &self,
        plane: &Spanned<FilePlane>,
        material: &Material,
    ) -> Result<PlaneSection, PresetError> {
        let pl = plane.get_ref();
        let radius = self.value(&pl.radius, "radius", &limits::RADIUS)?;
        let load = self.value(&pl.load, "load", &limits::LINE_LOAD)?;
        if pl.model != Model::Wide && material.thickness.is_infinite() {
            return Err(self.error(
                Some(plane.span()),
                format!(
                    "model = \"{}\" needs a finite thickness: set [material] thickness or use model = \"wide\"",
                    pl.model.name()
                ),
            ));
        }
        let sweep = match &pl.sweep {
            Some(sw) => {
                let s = sw.get_ref();
                let (min, max) = self.range(
                    &s.load_min,
                    &s.load_max,
                    ["load_min", "load_max"],
                    &limits::LINE_LOAD,
                )?;
                let points = self.count(&s.points, "points", &limits::SWEEP_POINTS)?;
                LoadSweep {
                    min,
                    max,
                    points,
                    spacing: s.scale,
                }
            }
            None => default_load_sweep(load),
        };
        Ok(PlaneSection {
            model: pl.model,
            radius,
            load,
            sweep,
        })
    }

    fn spatial(&self, spatial: &Spanned<FileSpatial>) -> Result<SpatialSection, PresetError> {
        let sp = spatial.get_ref();
        let mean_pressure =
            self.value(&sp.mean_pressure, "mean_pressure", &limits::MEAN_PRESSURE)?;
        let mut harmonics = Vec::new();
        for fh in &sp.harmonics {
            let h = fh.get_ref();
            let harmonic = Harmonic {
                amplitude: self.value(&h.amplitude, "amplitude", &limits::AMPLITUDE)?,
                wavenumber_x: self.value(&h.wavenumber_x, "wavenumber_x", &limits::WAVENUMBER)?,
                wavenumber_y: self.value(&h.wavenumber_y, "wavenumber_y", &limits::WAVENUMBER)?,
                phase_x: self.value(&h.phase_x, "phase_x", &limits::PHASE)?,
                phase_y: self.value(&h.phase_y, "phase_y", &limits::PHASE)?,
            };
            harmonics.push(harmonic);
            // the wave-vector rules (nonzero, not repeated) are the solver's
            if let Err(e) = validate_harmonics(&harmonics) {
                let why = e.to_string();
                return Err(self.error(Some(fh.span()), why.trim_start_matches("invalid input: ")));
            }
        }
        if harmonics.is_empty() {
            return Err(self.error(
                Some(spatial.span()),
                "[spatial] has no [[spatial.harmonics]]: the punch needs at least one harmonic",
            ));
        }
        let sweep = match &sp.sweep {
            Some(sw) => {
                let s = sw.get_ref();
                let (min, max) = self.range(
                    &s.pressure_min,
                    &s.pressure_max,
                    ["pressure_min", "pressure_max"],
                    &limits::MEAN_PRESSURE,
                )?;
                let points = self.count(&s.points, "points", &limits::SWEEP_POINTS)?;
                PressureSweep {
                    min,
                    max,
                    points,
                    spacing: s.scale,
                }
            }
            None => default_pressure_sweep(mean_pressure),
        };
        Ok(SpatialSection {
            mean_pressure,
            sliding_speed: self.value(&sp.sliding_speed, "sliding_speed", &limits::SPEED)?,
            time: self.value(&sp.time, "time", &limits::TIME)?,
            duration: self.value(&sp.duration, "duration", &limits::DURATION)?,
            grid: self.count(&sp.grid, "grid", &limits::GRID)?,
            sweep,
            harmonics,
        })
    }
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
    Bundled {
        file: "hard-coating-strip.toml",
        text: include_str!("../presets/hard-coating-strip.toml"),
    },
    Bundled {
        file: "jgh-egg-box.toml",
        text: include_str!("../presets/jgh-egg-box.toml"),
    },
    Bundled {
        file: "wave-thick-layer.toml",
        text: include_str!("../presets/wave-thick-layer.toml"),
    },
    Bundled {
        file: "rubber-backward-drift.toml",
        text: include_str!("../presets/rubber-backward-drift.toml"),
    },
    Bundled {
        file: "dispersion.toml",
        text: include_str!("../presets/dispersion.toml"),
    },
    Bundled {
        file: "contact-lost.toml",
        text: include_str!("../presets/contact-lost.toml"),
    },
];

impl Bundled {
    /// Parses the bundled text (its path in messages is `presets/<file>`).
    pub fn load(&self) -> Result<Preset, PresetError> {
        parse(self.text, &Path::new("presets").join(self.file))
    }
}

/// The bundled preset of that file name, parsed (None for an unknown name).
pub fn bundled(file: &str) -> Option<Result<Preset, PresetError>> {
    BUNDLED.iter().find(|b| b.file == file).map(Bundled::load)
}

/// The built-in default preset (the first bundled one).
pub fn default_preset() -> Preset {
    BUNDLED[0]
        .load()
        .expect("the bundled default preset is valid (tested)")
}
