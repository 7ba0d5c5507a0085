//! The checks of a preset file: every value against `physics::limits`, the sections a problem
//! needs, the sweep's order, the `[explore]` section; each refusal is `path:line: reason`.

use std::ops::Range;
use std::path::Path;

use toml::Spanned;

use crate::physics::limits::{self, Limit};
use crate::physics::spatial::harmonic::Harmonic;
use crate::physics::spatial::{validate_grid, validate_harmonics};
use crate::physics::{Friction, Material, Spacing, SweepRange};
use crate::preset::explore_section::Explore;
use crate::preset::file::{FileAxis, FileExplore, FilePlane, FilePreset, FileSpatial};
use crate::preset::{
    PlaneSection, Preset, PresetError, Problem, SCHEMA, SpatialSection, default_load_sweep,
    default_plane_section, default_pressure_sweep, default_spatial_section,
};
use crate::preset::{disk, wording};
use crate::sweeps::axis::{Axis, CURVE_POINTS, GRID_POINTS};
use crate::sweeps::quantity::QuantityKey;

fn line_of(text: &str, offset: usize) -> usize {
    1 + text.as_bytes()[..offset.min(text.len())]
        .iter()
        .filter(|&&c| c == b'\n')
        .count()
}

pub(super) struct Checker<'a> {
    path: &'a Path,
    text: &'a str,
}

impl Checker<'_> {
    pub(super) fn error(
        &self,
        span: Option<Range<usize>>,
        reason: impl Into<String>,
    ) -> PresetError {
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

/// Reads and validates a preset file (a regular UTF-8 file of at most
/// `disk::MAX_PRESET_BYTES`).
pub fn load(path: &Path) -> Result<Preset, PresetError> {
    parse(&disk::read_text(path)?, path)
}

/// Parses and validates preset text; `path` is only used in messages.
pub fn parse(text: &str, path: &Path) -> Result<Preset, PresetError> {
    let ck = Checker { path, text };
    let file: FilePreset = toml::from_str(text).map_err(|e| {
        let before = wording::text_before(text, e.span().map_or(0, |s| s.start));
        ck.error(e.span(), wording::reason(e.message(), before))
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
    let (spatial, duration_given) = match &file.spatial {
        Some(sp) => ck.spatial(sp)?,
        None if problem == Problem::Spatial => {
            return Err(missing(
                "spatial",
                "mean_pressure, sliding_speed, [[spatial.harmonics]]",
            ));
        }
        None => (default_spatial_section(), false),
    };
    let mut preset = Preset {
        name: file.name,
        description: file.description,
        problem,
        material,
        friction,
        wear,
        plane,
        spatial,
        explore: None,
    };
    if !duration_given {
        preset.spatial.duration = preset.auto_duration();
    }
    // the section that names keys and outputs is checked against the preset it belongs to
    if let Some(e) = &file.explore {
        preset.explore = Some(ck.explore(e, &preset)?);
    }
    Ok(preset)
}

impl Checker<'_> {
    fn count(&self, v: &Spanned<i64>, name: &str, limit: &Limit) -> Result<usize, PresetError> {
        let n = *v.get_ref();
        limit
            .check(name, n as f64)
            .map_err(|why| self.error(Some(v.span()), why))?;
        Ok(n as usize)
    }

    /// A sweep: both ends within `limit`, min < max (`SweepRange::check_order`), the points.
    fn sweep(
        &self,
        ends: [&Spanned<f64>; 2],
        names: [&str; 2],
        limit: &Limit,
        points: &Spanned<i64>,
        spacing: Spacing,
    ) -> Result<SweepRange, PresetError> {
        let range = SweepRange {
            min: self.value(ends[0], names[0], limit)?,
            max: self.value(ends[1], names[1], limit)?,
            points: self.count(points, "points", &limits::SWEEP_POINTS)?,
            spacing,
        };
        range
            .check_order(names, |v| v.to_string())
            .map_err(|why| self.error(Some(ends[1].span()), why))?;
        Ok(range)
    }

    fn plane(
        &self,
        plane: &Spanned<FilePlane>,
        material: &Material,
    ) -> Result<PlaneSection, PresetError> {
        let pl = plane.get_ref();
        let radius = self.value(&pl.radius, "radius", &limits::RADIUS)?;
        let load = self.value(&pl.load, "load", &limits::LINE_LOAD)?;
        if pl.model.needs_finite_thickness() && material.is_half_space() {
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
                self.sweep(
                    [&s.load_min, &s.load_max],
                    ["load_min", "load_max"],
                    &limits::LINE_LOAD,
                    &s.points,
                    s.scale,
                )?
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

    /// The `[spatial]` section, and whether it gives a duration.
    fn spatial(
        &self,
        spatial: &Spanned<FileSpatial>,
    ) -> Result<(SpatialSection, bool), PresetError> {
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
                self.sweep(
                    [&s.pressure_min, &s.pressure_max],
                    ["pressure_min", "pressure_max"],
                    &limits::MEAN_PRESSURE,
                    &s.points,
                    s.scale,
                )?
            }
            None => default_pressure_sweep(mean_pressure),
        };
        let grid = self.count(&sp.grid, "grid", &limits::GRID)?;
        validate_grid(&harmonics, grid).map_err(|e| {
            let why = e.to_string();
            self.error(
                Some(sp.grid.span()),
                why.trim_start_matches("invalid input: "),
            )
        })?;
        let section = SpatialSection {
            mean_pressure,
            sliding_speed: self.value(&sp.sliding_speed, "sliding_speed", &limits::SPEED)?,
            time: self.value(&sp.time, "time", &limits::TIME)?,
            duration: match &sp.duration {
                Some(d) => self.value(d, "duration", &limits::DURATION)?,
                None => default_spatial_section().duration,
            },
            grid,
            time_tolerance: match &sp.time_tolerance {
                Some(t) => self.value(t, "time_tolerance", &limits::TIME_TOLERANCE)?,
                None => default_spatial_section().time_tolerance,
            },
            sweep,
            harmonics,
        };
        Ok((section, sp.duration.is_some()))
    }
}

impl Checker<'_> {
    fn axis(
        &self,
        preset: &Preset,
        axis: &Spanned<FileAxis>,
        default_points: usize,
    ) -> Result<Axis, PresetError> {
        let a = axis.get_ref();
        let key = preset
            .key(a.key.get_ref())
            .map_err(|why| self.error(Some(a.key.span()), why))?;
        let points = match &a.points {
            Some(n) => {
                limits::SWEEP_POINTS
                    .check("points", *n.get_ref() as f64)
                    .map_err(|why| self.error(Some(n.span()), why))?;
                *n.get_ref() as usize
            }
            None => default_points,
        };
        let ends = [*a.from.get_ref(), *a.to.get_ref()];
        let spacing = a.scale.unwrap_or(Spacing::Linear);
        Axis::new(preset, key, ends, points, spacing).map_err(|why| {
            // the fault is at the end it names, else at the axis
            let span = if why.contains("bad range") || why.contains(": TO") {
                a.to.span()
            } else if why.contains(": FROM") {
                a.from.span()
            } else {
                axis.span()
            };
            self.error(Some(span), why)
        })
    }

    /// The `[explore]` section, checked against the rest of the preset.
    pub(super) fn explore(
        &self,
        file: &Spanned<FileExplore>,
        preset: &Preset,
    ) -> Result<Explore, PresetError> {
        let e = file.get_ref();
        let quantity = QuantityKey::parse(e.quantity.get_ref(), preset)
            .map_err(|why| self.error(Some(e.quantity.span()), why))?;
        let points = if e.y.is_some() {
            GRID_POINTS
        } else {
            CURVE_POINTS
        };
        let mut axes = vec![self.axis(preset, &e.x, points)?];
        if let Some(y) = &e.y {
            let axis = self.axis(preset, y, points)?;
            if axis.key == axes[0].key {
                return Err(self.error(
                    Some(y.span()),
                    format!(
                        "x and y both vary {}: vary two different parameters",
                        axis.key
                    ),
                ));
            }
            axes.push(axis);
        }
        Ok(Explore { quantity, axes })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sweep_whose_ends_are_in_the_wrong_order_names_the_line_and_both_ends() {
        let text = crate::preset::BUNDLED[0].text.replace(
            "load_min = 1.0e2, load_max = 1.0e5",
            "load_min = 1.0e3, load_max = 1.0e2",
        );
        let line = 1 + text.lines().position(|l| l.starts_with("sweep")).unwrap();
        let err = parse(&text, Path::new("x.toml")).unwrap_err().to_string();
        assert_eq!(
            err,
            format!("x.toml:{line}: load_max = 100 must be larger than load_min = 1000")
        );
    }
}
