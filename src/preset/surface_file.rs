//! The layout of the preset key `spatial.surface` in the file (docs/presets.md, "Rough
//! surfaces") and how a save writes it back: the file's name and cell, or the generator's keys.

use serde::{Deserialize, Serialize};
use toml::Spanned;

use crate::physics::spatial::surface::{Amplitude, SurfaceSource};
use crate::preset::written::Written;

/// The kind of a generated surface.
pub(super) const SELF_AFFINE: &str = "self-affine";

fn plain<T>(value: T) -> Spanned<T> {
    Spanned::new(0..0, value)
}

fn num(value: f64) -> Spanned<Written> {
    plain(Written::Number(value))
}

/// `spatial.surface`: a height-map file, or `kind = "self-affine"` and the generator's keys (the
/// checks say which belong to which).
#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileSurface {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) file: Option<Spanned<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) kind: Option<Spanned<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) hurst: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) rms_height: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) rms_slope: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) rolloff_wavelength: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) cutoff_wavelength: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) length_x: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) length_y: Option<Spanned<Written>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) grid: Option<Spanned<i64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(super) seed: Option<Spanned<i64>>,
}

/// `spatial.surface` as written by `to_toml`: the file and its cell, or the generator's keys.
pub(super) fn to_file(source: &SurfaceSource) -> FileSurface {
    let mut out = FileSurface {
        file: None,
        kind: None,
        hurst: None,
        rms_height: None,
        rms_slope: None,
        rolloff_wavelength: None,
        cutoff_wavelength: None,
        length_x: None,
        length_y: None,
        grid: None,
        seed: None,
    };
    match source {
        SurfaceSource::File {
            file,
            length_x,
            length_y,
        } => {
            out.file = Some(plain(file.clone()));
            if !file.ends_with(".xyz") {
                out.length_x = Some(num(*length_x));
                out.length_y = Some(num(*length_y));
            }
        }
        SurfaceSource::SelfAffine(p) => {
            out.kind = Some(plain(SELF_AFFINE.to_string()));
            out.hurst = Some(num(p.hurst));
            match p.amplitude {
                Amplitude::RmsHeight(h) => out.rms_height = Some(num(h)),
                Amplitude::RmsSlope(s) => out.rms_slope = Some(num(s)),
            }
            out.rolloff_wavelength = Some(num(p.rolloff_wavelength));
            out.cutoff_wavelength = Some(num(p.cutoff_wavelength));
            out.length_x = Some(num(p.length_x));
            out.length_y = Some(num(p.length_y));
            out.grid = Some(plain(p.grid as i64));
            out.seed = Some(plain(p.seed as i64));
        }
    }
    out
}
