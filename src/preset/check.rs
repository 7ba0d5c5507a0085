//! The checks of a preset file: every value against `physics::limits`, the sections a problem
//! needs, the sweep's order, the `[explore]` (`explore_check`) and `[lesson]` sections; each
//! refusal is `path:line: reason`.

use std::cell::RefCell;
use std::ops::Range;
use std::path::Path;

use toml::Spanned;

use crate::physics::limits::{self, Limit};
use crate::physics::plane::Shape;
use crate::physics::{Friction, Material, Spacing, SweepRange};
use crate::preset::file::{FilePlane, FilePreset};
use crate::preset::written::{self, Written};
use crate::preset::{
    PlaneSection, Preset, PresetError, Problem, SCHEMA, default_load_sweep, default_plane_section,
    default_spatial_section,
};
use crate::preset::{disk, law_rules, lesson, plausible, wording};

fn line_of(text: &str, offset: usize) -> usize {
    1 + text.as_bytes()[..offset.min(text.len())]
        .iter()
        .filter(|&&c| c == b'\n')
        .count()
}

pub(super) struct Checker<'a> {
    pub(super) path: &'a Path,
    text: &'a str,
    /// The values that look like a unit mistake, and the harmonics that vanish.
    warnings: RefCell<Vec<PresetError>>,
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

    /// A number of the file, in SI units or a text with units, within `limit`; `key` is its
    /// preset key (`material.thickness`), which gives the unit and the examples.
    pub(super) fn value(
        &self,
        v: &Spanned<Written>,
        key: &str,
        limit: &Limit,
    ) -> Result<f64, PresetError> {
        let value = v
            .get_ref()
            .si(key)
            .map_err(|why| self.error(Some(v.span()), why))?;
        let name = key.rsplit('.').next().unwrap_or(key);
        limit
            .check(name, value)
            .map_err(|why| self.error(Some(v.span()), why))?;
        if let Some(why) = plausible::suspicious(key, value) {
            self.warn(Some(v.span()), format!("{name} = {value:e}: {why}"));
        }
        Ok(value)
    }

    pub(super) fn warn(&self, span: Option<Range<usize>>, reason: String) {
        self.warnings.borrow_mut().push(self.error(span, reason));
    }
}

/// Reads and validates a preset file (a regular UTF-8 file of at most
/// `disk::MAX_PRESET_BYTES`).
pub fn load(path: &Path) -> Result<Preset, PresetError> {
    parse(&disk::read_text(path)?, path)
}

/// Parses and validates preset text; `path` is only used in messages.
pub fn parse(text: &str, path: &Path) -> Result<Preset, PresetError> {
    parse_with_warnings(text, path).map(|(preset, _)| preset)
}

/// Reads and validates a preset file as `load` does, with the warnings of its valid values that
/// look like a unit mistake or a harmonic that vanishes (`plausible`), each `path:line: reason`.
pub fn load_with_warnings(path: &Path) -> Result<(Preset, Vec<PresetError>), PresetError> {
    parse_with_warnings(&disk::read_text(path)?, path)
}

/// Parses and validates preset text as `parse` does, with the warnings of `load_with_warnings`.
pub fn parse_with_warnings(
    text: &str,
    path: &Path,
) -> Result<(Preset, Vec<PresetError>), PresetError> {
    let ck = Checker {
        path,
        text,
        warnings: RefCell::new(Vec::new()),
    };
    let file: FilePreset = toml::from_str(text).map_err(|e| {
        let before = wording::text_before(text, e.span().map_or(0, |s| s.start));
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let line = text[line_start..].lines().next().unwrap_or("");
        let why = if e.message().contains("must be quoted") {
            written::unquoted(line, &before[..line_start])
        } else {
            None
        };
        ck.error(
            e.span(),
            why.unwrap_or_else(|| wording::reason(e.message(), before)),
        )
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
    let (material, strength) = ck.material(&material)?;
    let friction = match &file.friction {
        Some(f) => Friction {
            coefficient: ck.value(&f.coefficient, "friction.coefficient", &limits::FRICTION)?,
            adhesion: ck.value(&f.adhesion, "friction.adhesion", &limits::ADHESION)?,
        },
        None => Friction {
            coefficient: 0.0,
            adhesion: 0.0,
        },
    };
    let wear = ck.wear_coefficient(file.wear.as_ref(), strength)?;
    let laws = ck.laws(file.wear.as_ref(), file.friction.as_ref())?;
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
        wear_exponent: laws.wear_exponent,
        reference_pressure: laws.reference_pressure,
        shear_strength: laws.shear_strength,
        strength,
        plane,
        spatial,
        explore: None,
        lesson: None,
    };
    law_rules::check(&preset).map_err(|why| ck.error(None, why))?;
    if !duration_given {
        preset.spatial.duration = preset.auto_duration();
    }
    // the section that names keys and outputs is checked against the preset it belongs to
    if let Some(e) = &file.explore {
        preset.explore = Some(ck.explore(e, &preset)?);
    }
    if let Some(l) = &file.lesson {
        preset.lesson = Some(lesson::read(l, &preset, &|span, why| ck.error(span, why))?);
    }
    Ok((preset, ck.warnings.into_inner()))
}

impl Checker<'_> {
    pub(super) fn count(
        &self,
        v: &Spanned<i64>,
        name: &str,
        limit: &Limit,
    ) -> Result<usize, PresetError> {
        let n = *v.get_ref();
        limit
            .check(name, n as f64)
            .map_err(|why| self.error(Some(v.span()), why))?;
        Ok(n as usize)
    }

    /// A sweep: both ends within `limit`, min < max (`SweepRange::check_order`), the points.
    pub(super) fn sweep(
        &self,
        ends: [&Spanned<Written>; 2],
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
        let short = names.map(|n| n.rsplit('.').next().unwrap_or(n));
        range
            .check_order(short, |v| v.to_string())
            .map_err(|why| self.error(Some(ends[1].span()), why))?;
        Ok(range)
    }

    fn plane(
        &self,
        plane: &Spanned<FilePlane>,
        material: &Material,
    ) -> Result<PlaneSection, PresetError> {
        let pl = plane.get_ref();
        let (radius, shape) = self.plane_shape(plane, default_plane_section().radius)?;
        let load = self.value(&pl.load, "plane.load", &limits::LINE_LOAD)?;
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
                    ["plane.sweep.load_min", "plane.sweep.load_max"],
                    &limits::LINE_LOAD,
                    &s.points,
                    s.scale,
                )?
            }
            None => default_load_sweep(load),
        };
        let measured = match &shape {
            Some(Shape::Table(t)) => Some(std::sync::Arc::clone(t)),
            _ => None,
        };
        Ok(PlaneSection {
            model: pl.model,
            radius,
            shape,
            measured,
            load,
            sweep,
        })
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
