//! The optional `[explore]` section of a preset file: the sweep (one axis) or the map (two axes)
//! and the quantity the preset's lesson is about. `wearlab sweep PRESET` runs it when no `--vary`
//! is given, and the explorer opens its sweep chart or map on it.
//!
//! ```toml
//! [explore]
//! quantity = "mu_star_minus_mu"     # a name of `wearlab sweep --output`
//! x = { key = "material.thickness", from = 1.0e-6, to = 1.0e-2, points = 40, scale = "log" }
//! y = { key = "plane.load", from = 1.0e2, to = 1.0e4 }    # optional: a map over (x, y)
//! ```
//!
//! `points` defaults to 50 for a sweep and 20 per side for a map, `scale` to "linear". The keys
//! are preset keys of the preset's problem; each range is checked as `--vary` checks it.

use serde::{Deserialize, Serialize};
use toml::Spanned;

use crate::physics::{Spacing, limits};
use crate::preset::check::Checker;
use crate::preset::file::plain;
use crate::preset::{Preset, PresetError};
use crate::sweeps::axis::{Axis, CURVE_POINTS, GRID_POINTS};
use crate::sweeps::quantity::QuantityKey;

/// What a preset's lesson sweeps or maps.
#[derive(Clone, Debug, PartialEq)]
pub struct Explore {
    /// The quantity shown.
    pub quantity: QuantityKey,
    /// The varied parameters: one (a sweep) or two (a map, x then y).
    pub axes: Vec<Axis>,
}

impl Explore {
    /// Checks the section against a preset edited since it was read (`--set`, the explorer's
    /// form): the quantity must still exist for its model, the keys and ranges still hold.
    pub fn check(&self, preset: &Preset) -> Result<(), String> {
        QuantityKey::parse(&self.quantity.to_string(), preset)?;
        for a in &self.axes {
            let r = a.range;
            Axis::new(preset, a.key, [r.min, r.max], r.points, r.spacing)?;
        }
        Ok(())
    }
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileAxis {
    key: Spanned<String>,
    from: Spanned<f64>,
    to: Spanned<f64>,
    #[serde(default)]
    points: Option<Spanned<i64>>,
    #[serde(default)]
    scale: Option<Spacing>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileExplore {
    quantity: Spanned<String>,
    x: Spanned<FileAxis>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    y: Option<Spanned<FileAxis>>,
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

/// The section as written by `to_toml`.
pub(super) fn to_file(e: &Explore) -> FileExplore {
    let axis = |a: &Axis| {
        plain(FileAxis {
            key: plain(a.key.to_string()),
            from: plain(a.range.min),
            to: plain(a.range.max),
            points: Some(plain(a.range.points as i64)),
            scale: Some(a.range.spacing),
        })
    };
    FileExplore {
        quantity: plain(e.quantity.to_string()),
        x: axis(&e.axes[0]),
        y: e.axes.get(1).map(axis),
    }
}
