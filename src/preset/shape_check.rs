//! The checks of the keys beyond the paper's worked example (`docs/presets.md`): `plane.shape`
//! (an inline table whose keys follow its kind; a table's profile file read relative to the
//! preset's folder), `wear.exponent`, `wear.reference_pressure`, `friction.shear_strength`; each
//! refusal is `path:line: reason` (the rules between them are in `law_rules`).

use std::sync::Arc;

use toml::Spanned;

use crate::physics::limits::{self, Limit};
use crate::physics::plane::Shape;
use crate::physics::plane::shape::Table;
use crate::preset::check::Checker;
use crate::preset::file::{FileFriction, FilePlane, FileShape, FileWear};
use crate::preset::written::Written;
use crate::preset::{PresetError, bundled, profile_csv};
use crate::units::parse_si;

/// The keys each kind of shape takes.
const KINDS: &[(&str, &[&str])] = &[
    ("parabola", &["radius"]),
    ("power", &["radius", "exponent"]),
    ("flat", &["half_width", "edge_radius"]),
    ("table", &["file"]),
];

/// The wear law and the cap of a preset file: (n, p0, tau_max).
pub(super) struct Laws {
    pub(super) wear_exponent: f64,
    pub(super) reference_pressure: Option<f64>,
    pub(super) shear_strength: f64,
}

impl Checker<'_> {
    /// `plane.radius` or `plane.shape`: the parabola's radius (the default section's when a
    /// shape is given) and the shape other than a parabola.
    pub(super) fn plane_shape(
        &self,
        plane: &Spanned<FilePlane>,
        default_radius: f64,
    ) -> Result<(f64, Option<Shape>), PresetError> {
        let pl = plane.get_ref();
        let shape = match (&pl.radius, &pl.shape) {
            (Some(r), None) => return Ok((self.value(r, "plane.radius", &limits::RADIUS)?, None)),
            (None, Some(s)) => s,
            (Some(_), Some(s)) => {
                return Err(self.error(
                    Some(s.span()),
                    "give plane.radius or plane.shape, not both (a parabola is shape = { kind = \
                     \"parabola\", radius = ... } or radius alone)",
                ));
            }
            (None, None) => {
                return Err(self.error(
                    Some(plane.span()),
                    "[plane] needs radius (a parabolic punch) or shape, e.g. shape = { kind = \
                     \"flat\", half_width = \"1 mm\", edge_radius = \"0.2 mm\" }",
                ));
            }
        };
        let s = shape.get_ref();
        let kind = s.kind.get_ref().as_str();
        let Some((_, keys)) = KINDS.iter().find(|(k, _)| *k == kind) else {
            return Err(self.error(
                Some(s.kind.span()),
                format!(
                    "kind = \"{kind}\" is not a shape: allowed one of {}",
                    KINDS.iter().map(|(k, _)| *k).collect::<Vec<_>>().join(", ")
                ),
            ));
        };
        self.only_keys(shape, kind, keys)?;
        let need = |v: &Option<Spanned<Written>>, name: &str, unit: &str, limit: &Limit| match v {
            Some(v) => self.shape_value(v, name, unit, limit),
            None => Err(self.error(
                Some(shape.span()),
                format!(
                    "a {kind} shape needs {} (it takes {})",
                    name,
                    keys.join(", ")
                ),
            )),
        };
        let out = match kind {
            "parabola" => return Ok((need(&s.radius, "radius", "m", &limits::RADIUS)?, None)),
            "power" => Shape::Power {
                radius: need(&s.radius, "radius", "m", &limits::RADIUS)?,
                exponent: need(&s.exponent, "exponent", "", &limits::POWER_EXPONENT)?,
            },
            "flat" => Shape::Flat {
                half_width: need(&s.half_width, "half_width", "m", &limits::HALF_WIDTH)?,
                edge_radius: need(&s.edge_radius, "edge_radius", "m", &limits::EDGE_RADIUS)?,
            },
            _ => self.table(shape)?,
        };
        Ok((default_radius, Some(out)))
    }

    /// Refuses a key of the inline table that the kind does not take.
    fn only_keys(
        &self,
        shape: &Spanned<FileShape>,
        kind: &str,
        keys: &[&str],
    ) -> Result<(), PresetError> {
        let s = shape.get_ref();
        let given = [
            ("radius", s.radius.is_some()),
            ("exponent", s.exponent.is_some()),
            ("half_width", s.half_width.is_some()),
            ("edge_radius", s.edge_radius.is_some()),
            ("file", s.file.is_some()),
        ];
        match given.iter().find(|(k, on)| *on && !keys.contains(k)) {
            Some((k, _)) => Err(self.error(
                Some(shape.span()),
                format!(
                    "a {kind} shape takes {}; {k} belongs to another kind",
                    keys.join(", ")
                ),
            )),
            None => Ok(()),
        }
    }

    /// A table shape: its profile read from the file relative to the preset's folder.
    fn table(&self, shape: &Spanned<FileShape>) -> Result<Shape, PresetError> {
        let Some(file) = &shape.get_ref().file else {
            return Err(self.error(
                Some(shape.span()),
                "a table shape needs file, e.g. file = \"profile.csv\" (columns x [m],g [m], \
                 relative to this preset's folder)",
            ));
        };
        let folder = self.path.parent().unwrap_or(std::path::Path::new(""));
        let path = folder.join(file.get_ref());
        let spline = match bundled::bundled_data(self.path, file.get_ref()) {
            Some(text) => profile_csv::parse(text, &path)?,
            None => profile_csv::read(&path)?,
        };
        Ok(Shape::Table(Arc::new(Table {
            file: file.get_ref().clone(),
            spline,
        })))
    }

    /// A number of the shape's table, in SI units or a text with `unit`, within `limit`.
    fn shape_value(
        &self,
        v: &Spanned<Written>,
        name: &str,
        unit: &str,
        limit: &Limit,
    ) -> Result<f64, PresetError> {
        let value = match v.get_ref() {
            Written::Number(x) => *x,
            Written::Text(t) => parse_si(t, unit)
                .map_err(|why| self.error(Some(v.span()), format!("{name} = \"{t}\": {why}")))?,
        };
        limit
            .check(name, value)
            .map_err(|why| self.error(Some(v.span()), why))?;
        Ok(value)
    }

    /// `wear.exponent`, `wear.reference_pressure` and `friction.shear_strength`, each within its
    /// limits (defaults: 1, none, inf).
    pub(super) fn laws(
        &self,
        wear: Option<&FileWear>,
        friction: Option<&FileFriction>,
    ) -> Result<Laws, PresetError> {
        let opt = |v: Option<&Spanned<Written>>, key: &str, limit: &Limit| {
            v.map(|v| self.value(v, key, limit)).transpose()
        };
        Ok(Laws {
            wear_exponent: opt(
                wear.and_then(|w| w.exponent.as_ref()),
                "wear.exponent",
                &limits::WEAR_EXPONENT,
            )?
            .unwrap_or(1.0),
            reference_pressure: opt(
                wear.and_then(|w| w.reference_pressure.as_ref()),
                "wear.reference_pressure",
                &limits::REFERENCE_PRESSURE,
            )?,
            shear_strength: opt(
                friction.and_then(|f| f.shear_strength.as_ref()),
                "friction.shear_strength",
                &limits::SHEAR_STRENGTH,
            )?
            .unwrap_or(f64::INFINITY),
        })
    }
}
