//! `--set spatial.surface.NAME=VALUE` and the explorer's form: one scalar key of a generated
//! surface (`kind = "self-affine"`) changed, read and checked as the preset file's key is (a number
//! with an optional unit, whole numbers for `grid` and `seed`, then the generator's own checks),
//! and why `spatial.grid` is refused beside any height map (the file's key and `--set`).

use std::sync::Arc;

use crate::physics::spatial::surface::{
    Amplitude, SelfAffine, Surface, SurfaceShape, SurfaceSource, generate,
};
use crate::preset::Preset;
use crate::units::parse_si;

/// The prefix of a generated surface's keys on the command line.
pub const SURFACE_PREFIX: &str = "spatial.surface.";

/// The keys `--set` changes, with the unit their texts take.
const KEYS: &[(&str, &str)] = &[
    ("hurst", ""),
    ("rms_height", "m"),
    ("rms_slope", ""),
    ("rolloff_wavelength", "m"),
    ("cutoff_wavelength", "m"),
    ("length_x", "m"),
    ("length_y", "m"),
    ("grid", ""),
    ("seed", ""),
];

fn names() -> String {
    KEYS.iter()
        .map(|(k, _)| format!("{SURFACE_PREFIX}{k}"))
        .collect::<Vec<_>>()
        .join(", ")
}

impl Preset {
    /// Sets the generated surface's key `name` (after `spatial.surface.`) from `text` and
    /// generates the surface again; on Err the preset is unchanged and the text says why.
    pub fn set_surface_key(&mut self, name: &str, text: &str) -> Result<(), String> {
        let (key, unit, mut p) = self.generator(name)?;
        match name {
            "grid" => p.grid = whole(&key, text, 2)? as usize,
            "seed" => p.seed = whole(&key, text, 0)?,
            _ => {
                let value = parse_si(text, unit).map_err(|why| format!("{key} = {why}"))?;
                if !value.is_finite() {
                    return Err(format!("{key} = {value}: not a finite number"));
                }
                set_number(&mut p, name, value);
            }
        }
        self.regenerate(p)
    }

    /// Sets the generated surface's key `name` to a number (the explorer's form: `grid` and
    /// `seed` whole) with the checks of `set_surface_key`.
    pub fn set_surface_value(&mut self, name: &str, value: f64) -> Result<(), String> {
        let (key, _, mut p) = self.generator(name)?;
        let whole = |min: f64| {
            if value >= min && value.fract() == 0.0 && value < 2f64.powi(53) {
                Ok(value)
            } else {
                Err(format!("{key} = {value}: must be a whole number >= {min}"))
            }
        };
        match name {
            "grid" => p.grid = whole(2.0)? as usize,
            "seed" => p.seed = whole(0.0)? as u64,
            _ if !value.is_finite() => {
                return Err(format!("{key} = {value}: not a finite number"));
            }
            _ => set_number(&mut p, name, value),
        }
        self.regenerate(p)
    }

    /// The key, its unit and the generator's parameters to change; Err for an unknown key or a
    /// surface that is not generated.
    fn generator(&self, name: &str) -> Result<(String, &'static str, SelfAffine), String> {
        let key = format!("{SURFACE_PREFIX}{name}");
        let Some(&(_, unit)) = KEYS.iter().find(|(k, _)| *k == name) else {
            return Err(format!(
                "unknown key '{key}': a generated surface's keys are {}",
                names()
            ));
        };
        let shape = self.spatial.surface.as_ref().ok_or_else(|| {
            format!("{key}: this preset's punch has no spatial.surface (it is given by harmonics)")
        })?;
        match &shape.source {
            SurfaceSource::SelfAffine(p) => Ok((key, unit, *p)),
            SurfaceSource::File { file, .. } => Err(format!(
                "{key}: this preset's surface is a height-map file ({file}), whose heights, grid \
                 and lengths are the file's; --set and the form change a generated surface \
                 (kind = \"self-affine\"): {}",
                names()
            )),
        }
    }

    /// Generates the surface of `p` in place of the preset's.
    fn regenerate(&mut self, p: SelfAffine) -> Result<(), String> {
        // the generator's refusals name the file's key and value
        let surface = generate(&p)?;
        self.spatial.surface = Some(Arc::new(SurfaceShape {
            source: SurfaceSource::SelfAffine(p),
            surface,
        }));
        Ok(())
    }
}

/// A whole number >= `min`, as the file's `grid` and `seed`.
fn whole(key: &str, text: &str, min: u64) -> Result<u64, String> {
    match text.trim().parse::<u64>() {
        Ok(n) if n >= min => Ok(n),
        _ => Err(format!(
            "{key} = {}: must be a whole number >= {min}",
            text.trim()
        )),
    }
}

/// Writes a number key; `rms_height` and `rms_slope` each replace the other (a surface is scaled
/// to one of them).
fn set_number(p: &mut SelfAffine, name: &str, value: f64) {
    match name {
        "hurst" => p.hurst = value,
        "rms_height" => p.amplitude = Amplitude::RmsHeight(value),
        "rms_slope" => p.amplitude = Amplitude::RmsSlope(value),
        "rolloff_wavelength" => p.rolloff_wavelength = value,
        "cutoff_wavelength" => p.cutoff_wavelength = value,
        "length_x" => p.length_x = value,
        _ => p.length_y = value,
    }
}

/// Why `spatial.grid` is refused beside a height map: the map is solved on its own grid.
pub(super) fn grid_beside_map(map: &Surface) -> String {
    format!(
        "spatial.grid does not apply to a height map (spatial.surface): the map is solved on its \
         own grid of {} x {} nodes; remove spatial.grid (for another grid, resample the map's \
         file, or set the generator's grid)",
        map.nx, map.ny
    )
}
