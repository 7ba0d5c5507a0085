//! The checks of a preset's `[explore]` section against the rest of the preset: the quantity,
//! the swept parameters and their ranges, a data file named; each refusal is `path:line: reason`.

use toml::Spanned;

use crate::physics::Spacing;
use crate::physics::limits;
use crate::preset::check::Checker;
use crate::preset::explore_section::Explore;
use crate::preset::file::{FileAxis, FileExplore};
use crate::preset::written::Written;
use crate::preset::{Preset, PresetError};
use crate::sweeps::axis::{Axis, CURVE_POINTS, GRID_POINTS};
use crate::sweeps::quantity::QuantityKey;

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
        // the ends in the unit of the key they vary
        let at = key.to_string();
        let end = |v: &Spanned<Written>| {
            v.get_ref()
                .si(&at)
                .map_err(|why| self.error(Some(v.span()), why))
        };
        let ends = [end(&a.from)?, end(&a.to)?];
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
        let data = match &e.data {
            Some(d) if d.get_ref().trim().is_empty() => {
                return Err(self.error(
                    Some(d.span()),
                    "data names no file: a data file's name, e.g. data = \"friction.csv\"",
                ));
            }
            d => d.as_ref().map(|d| d.get_ref().trim().to_string()),
        };
        Ok(Explore {
            quantity,
            axes,
            data,
        })
    }
}
