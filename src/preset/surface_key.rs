//! The preset key `spatial.surface` (docs/presets.md): the punch as a height-map file (the CSV
//! grid, or `x y z` columns when the name ends in `.xyz`, relative to the preset's folder) or a
//! generated self-affine surface, in place of `[[spatial.harmonics]]`: its checks (each refusal
//! `path:line: reason`; the layout and the writing are in `surface_file`).

use std::path::Path;
use std::sync::Arc;

use toml::Spanned;

use crate::physics::spatial::surface::{
    Amplitude, SelfAffine, Surface, SurfaceShape, SurfaceSource, generate, parse_csv, periodicity,
    read_csv, read_xyz,
};
use crate::preset::PresetError;
use crate::preset::bundled::bundled_data;
use crate::preset::check::Checker;
use crate::preset::surface_file::{FileSurface, SELF_AFFINE};
use crate::preset::written::Written;
use crate::units::parse_si;

/// The keys of a height-map file.
const FILE_KEYS: &[&str] = &["file", "length_x", "length_y"];
/// The keys of a generated surface.
const SELF_AFFINE_KEYS: &[&str] = &[
    "kind",
    "hurst",
    "rms_height",
    "rms_slope",
    "rolloff_wavelength",
    "cutoff_wavelength",
    "length_x",
    "length_y",
    "grid",
    "seed",
];
/// An edge step more than this many times the interior neighbour steps is reported: the cell's
/// edge is then a ridge the periodic cell repeats.
const EDGE_STEP_WARNING: f64 = 3.0;

impl Checker<'_> {
    /// `spatial.surface`: the height map read or generated.
    pub(super) fn surface(
        &self,
        surface: &Spanned<FileSurface>,
    ) -> Result<Arc<SurfaceShape>, PresetError> {
        let s = surface.get_ref();
        let refuse = |why: String| self.error(Some(surface.span()), why);
        let shape = match (&s.file, &s.kind) {
            (Some(file), None) => self.surface_file(surface, file)?,
            (None, Some(kind)) if kind.get_ref() == SELF_AFFINE => {
                self.only_surface_keys(surface, SELF_AFFINE_KEYS, "a self-affine surface")?;
                let p = self.self_affine(surface)?;
                let generated = generate(&p).map_err(&refuse)?;
                SurfaceShape {
                    source: SurfaceSource::SelfAffine(p),
                    surface: generated,
                }
            }
            (None, Some(kind)) => {
                return Err(self.error(
                    Some(kind.span()),
                    format!(
                        "kind = \"{}\" is not a surface: the generated kind is \"{SELF_AFFINE}\" \
                         (a height map is file = \"...\" without kind)",
                        kind.get_ref()
                    ),
                ));
            }
            (Some(_), Some(_)) => {
                return Err(refuse(
                    "give file (a height map) or kind = \"self-affine\" (a generated surface), \
                     not both"
                        .into(),
                ));
            }
            (None, None) => {
                return Err(refuse(format!(
                    "spatial.surface needs file = \"map.csv\" (with length_x, length_y) or \
                     kind = \"{SELF_AFFINE}\" (with {})",
                    SELF_AFFINE_KEYS[1..].join(", ")
                )));
            }
        };
        let report = periodicity(&shape.surface);
        let edge = |step: f64, interior: f64| step > EDGE_STEP_WARNING * interior;
        if edge(report.edge_step_x, report.interior_step_x)
            || edge(report.edge_step_y, report.interior_step_y)
        {
            self.warn(
                Some(surface.span()),
                format!("the height map is not periodic: {}", report.message()),
            );
        }
        Ok(Arc::new(shape))
    }

    /// A height-map file relative to the preset's folder.
    fn surface_file(
        &self,
        surface: &Spanned<FileSurface>,
        file: &Spanned<String>,
    ) -> Result<SurfaceShape, PresetError> {
        let s = surface.get_ref();
        let folder = self.path.parent().unwrap_or(Path::new(""));
        let path = folder.join(file.get_ref());
        let xyz = file.get_ref().ends_with(".xyz");
        let read = if xyz {
            self.only_surface_keys(surface, &["file"], "an x y z file (its cell is its grid's)")?;
            read_xyz(&path)
        } else {
            self.only_surface_keys(surface, FILE_KEYS, "a height-map file")?;
            let length_x = self.surface_number(surface, &s.length_x, "length_x", "m")?;
            let length_y = match &s.length_y {
                Some(v) => self.number(v, "length_y", "m")?,
                None => 0.0,
            };
            match bundled_data(self.path, file.get_ref()) {
                Some(text) => parse_csv(text, &path, length_x, length_y),
                None => read_csv(&path, length_x, length_y),
            }
        };
        let map: Surface = read.map_err(|e| PresetError {
            path: e.path.into(),
            line: (e.line > 0).then_some(e.line),
            reason: e.reason,
        })?;
        Ok(SurfaceShape {
            source: SurfaceSource::File {
                file: file.get_ref().clone(),
                length_x: map.lx,
                length_y: map.ly,
            },
            surface: map,
        })
    }

    /// The generator's parameters.
    fn self_affine(&self, surface: &Spanned<FileSurface>) -> Result<SelfAffine, PresetError> {
        let s = surface.get_ref();
        let amplitude = match (&s.rms_height, &s.rms_slope) {
            (Some(h), None) => Amplitude::RmsHeight(self.number(h, "rms_height", "m")?),
            (None, Some(g)) => Amplitude::RmsSlope(self.number(g, "rms_slope", "")?),
            _ => {
                return Err(self.error(
                    Some(surface.span()),
                    "a self-affine surface needs rms_height or rms_slope (one of them)",
                ));
            }
        };
        let whole = |v: &Option<Spanned<i64>>, name: &str, min: i64| match v {
            Some(n) if *n.get_ref() >= min => Ok(*n.get_ref()),
            Some(n) => Err(self.error(
                Some(n.span()),
                format!("{name} = {}: must be a whole number >= {min}", n.get_ref()),
            )),
            None => Err(self.error(
                Some(surface.span()),
                format!("a self-affine surface needs {name}"),
            )),
        };
        Ok(SelfAffine {
            hurst: self.surface_number(surface, &s.hurst, "hurst", "")?,
            amplitude,
            rolloff_wavelength: self.surface_number(
                surface,
                &s.rolloff_wavelength,
                "rolloff_wavelength",
                "m",
            )?,
            cutoff_wavelength: self.surface_number(
                surface,
                &s.cutoff_wavelength,
                "cutoff_wavelength",
                "m",
            )?,
            length_x: self.surface_number(surface, &s.length_x, "length_x", "m")?,
            length_y: self.surface_number(surface, &s.length_y, "length_y", "m")?,
            grid: whole(&s.grid, "grid", 2)? as usize,
            seed: whole(&s.seed, "seed", 0)? as u64,
        })
    }

    /// A key of the table that must be there.
    fn surface_number(
        &self,
        surface: &Spanned<FileSurface>,
        v: &Option<Spanned<Written>>,
        name: &str,
        unit: &str,
    ) -> Result<f64, PresetError> {
        match v {
            Some(v) => self.number(v, name, unit),
            None => Err(self.error(
                Some(surface.span()),
                format!("spatial.surface needs {name}"),
            )),
        }
    }

    /// A finite number in SI units or a text with `unit` (the range is the reader's or the
    /// generator's to check).
    fn number(&self, v: &Spanned<Written>, name: &str, unit: &str) -> Result<f64, PresetError> {
        let value = match v.get_ref() {
            Written::Number(x) => *x,
            Written::Text(t) => parse_si(t, unit)
                .map_err(|why| self.error(Some(v.span()), format!("{name} = \"{t}\": {why}")))?,
        };
        if value.is_finite() {
            Ok(value)
        } else {
            Err(self.error(
                Some(v.span()),
                format!("{name} = {value}: not a finite number"),
            ))
        }
    }

    /// Refuses a key that this kind of surface does not take.
    fn only_surface_keys(
        &self,
        surface: &Spanned<FileSurface>,
        keys: &[&str],
        what: &str,
    ) -> Result<(), PresetError> {
        let s = surface.get_ref();
        let given = [
            ("file", s.file.is_some()),
            ("kind", s.kind.is_some()),
            ("hurst", s.hurst.is_some()),
            ("rms_height", s.rms_height.is_some()),
            ("rms_slope", s.rms_slope.is_some()),
            ("rolloff_wavelength", s.rolloff_wavelength.is_some()),
            ("cutoff_wavelength", s.cutoff_wavelength.is_some()),
            ("length_x", s.length_x.is_some()),
            ("length_y", s.length_y.is_some()),
            ("grid", s.grid.is_some()),
            ("seed", s.seed.is_some()),
        ];
        match given.iter().find(|(k, on)| *on && !keys.contains(k)) {
            Some((k, _)) => Err(self.error(
                Some(surface.span()),
                format!(
                    "{what} takes {}; {k} belongs to another kind",
                    keys.join(", ")
                ),
            )),
            None => Ok(()),
        }
    }
}
