//! The punch's height map (`spatial.surface`) as parameters of the registry (`params::PARAMS`,
//! keys `spatial.surface.NAME`): a generated surface's keys read and set through the checks of
//! `--set` (`surface_set`), a height-map file's name, grid and lengths shown and refused with the
//! reason (they are the file's). Which rows a surface has is `applies`.

use crate::physics::spatial::surface::{Amplitude, SelfAffine, SurfaceShape, SurfaceSource};
use crate::preset::Preset;
use crate::units::format_si;

/// The registry's prefix of a surface's keys.
pub(super) const PREFIX: &str = "spatial.surface.";

/// The rows of a height-map file, by the key's last part.
const FILE_ROWS: &[&str] = &["file", "grid", "length_x", "length_y"];

fn shape(p: &Preset) -> Option<&SurfaceShape> {
    p.spatial.surface.as_deref()
}

fn generated(p: &Preset) -> Option<&SelfAffine> {
    match &shape(p)?.source {
        SurfaceSource::SelfAffine(g) => Some(g),
        SurfaceSource::File { .. } => None,
    }
}

/// Whether the preset's punch has the surface key `name` (after `spatial.surface.`): a file's
/// name, grid and lengths; a generated surface's keys, with the rms height or the rms slope,
/// whichever it is scaled to. Err says why not.
pub(super) fn applies(p: &Preset, name: &str) -> Result<(), String> {
    let key = format!("{PREFIX}{name}");
    let Some(s) = shape(p) else {
        return Err(format!(
            "{key}: this preset's punch has no spatial.surface (it is given by harmonics)"
        ));
    };
    let has = match &s.source {
        SurfaceSource::File { .. } => FILE_ROWS.contains(&name),
        SurfaceSource::SelfAffine(g) => !matches!(
            (name, g.amplitude),
            ("file", _)
                | ("rms_height", Amplitude::RmsSlope(_))
                | ("rms_slope", Amplitude::RmsHeight(_))
        ),
    };
    if has {
        return Ok(());
    }
    Err(match &s.source {
        SurfaceSource::File { file, .. } => format!(
            "{key}: this preset's surface is the height-map file {file}, which has a file, a \
             grid and lengths"
        ),
        SurfaceSource::SelfAffine(_) => {
            format!("{key}: this preset's surface is generated (kind = \"self-affine\")")
        }
    })
}

/// True for a surface whose rows are shown and not set: a height-map file's.
pub fn from_file(p: &Preset) -> bool {
    shape(p).is_some_and(|s| matches!(s.source, SurfaceSource::File { .. }))
}

/// The value of a generated surface's key (`grid`, `seed` as whole numbers); Err for a file's,
/// saying why it is not set here.
pub(super) fn value(p: &Preset, name: &str) -> Result<f64, String> {
    let Some(g) = generated(p) else {
        return Err(refusal(p, name));
    };
    Ok(match (name, g.amplitude) {
        ("hurst", _) => g.hurst,
        ("rms_height", Amplitude::RmsHeight(v)) | ("rms_slope", Amplitude::RmsSlope(v)) => v,
        ("rolloff_wavelength", _) => g.rolloff_wavelength,
        ("cutoff_wavelength", _) => g.cutoff_wavelength,
        ("length_x", _) => g.length_x,
        ("length_y", _) => g.length_y,
        ("grid", _) => g.grid as f64,
        ("seed", _) => g.seed as f64,
        _ => return Err(applies(p, name).err().unwrap_or_default()),
    })
}

/// Sets a generated surface's key and generates the surface again (the checks of `--set`);
/// Err for a file's.
pub(super) fn set(p: &mut Preset, name: &str, value: f64) -> Result<(), String> {
    if generated(p).is_none() {
        return Err(refusal(p, name));
    }
    p.set_surface_value(name, value)
}

/// A height-map file's row as the form shows it (None for a generated surface's): the file's
/// name, its grid ("256 x 256", "4096 x 1" for a profile) and its lengths.
pub(super) fn text(p: &Preset, name: &str) -> Option<String> {
    let s = shape(p)?;
    let SurfaceSource::File { file, .. } = &s.source else {
        return None;
    };
    let map = &s.surface;
    Some(match name {
        "file" => file.clone(),
        "grid" => format!("{} x {}", map.nx, map.ny),
        "length_x" => format_si(map.lx, "m"),
        _ => format_si(map.ly, "m"),
    })
}

/// Why a height-map file's row is not set here.
fn refusal(p: &Preset, name: &str) -> String {
    let file = match shape(p).map(|s| &s.source) {
        Some(SurfaceSource::File { file, .. }) => file.as_str(),
        _ => "",
    };
    format!(
        "{PREFIX}{name} is from the file {file}: a measured surface's heights, grid and lengths \
         are the file's (edit or resample the file; a generated surface's keys are set here)"
    )
}
