//! Sweeps and regime maps over any parameter: every numeric input of a preset (`preset::Key`)
//! over a range (`axis`), the quantities a sweep can show (`quantity`, one registry for the
//! command line and the explorer, the dimensionless groups among them), one solved point
//! (`point`), sweeps in parallel for `wearlab sweep` (`sweep`) and their CSV and JSON (`output`),
//! and for the explorer a curve with overlays and validity changes (`curve`) and a regime map
//! with its lines, coarse first (`map`), both located by `locate`.

pub mod axis;
pub mod curve;
pub mod groups;
pub mod locate;
pub mod map;
pub mod map_yield;
pub mod output;
pub mod point;
pub mod quantity;
mod quantity_table;
pub mod sweep;

pub use axis::Axis;
pub use quantity::{Quantity, QuantityKey};

use crate::physics::plane::Model;
use crate::preset::Preset;
use crate::sweeps::curve::CurveSpec;
use crate::sweeps::map::MapSpec;

/// What a preset's `[explore]` section opens on.
#[derive(Clone, Debug, PartialEq)]
pub enum Opening {
    /// A sweep: the curve of the section's quantity, the preset's model first, then the other
    /// plane models that apply (narrow and strip need a finite thickness).
    Curve(CurveSpec),
    /// A map over the section's two parameters.
    Map(MapSpec),
}

/// The sweep or map of the preset's `[explore]` section, checked against the preset as it is now
/// (None without the section; Err when an edit since broke it, e.g. the model changed to one
/// without the quantity).
pub fn opening(preset: &Preset) -> Option<Result<Opening, String>> {
    let e = preset.explore.as_ref()?;
    Some(e.check(preset).map(|()| match e.axes.as_slice() {
        [x, y] => Opening::Map(MapSpec {
            x: *x,
            y: *y,
            quantity: e.quantity,
        }),
        _ => Opening::Curve(CurveSpec {
            axis: e.axes[0],
            quantity: e.quantity,
            models: models(preset, &e.axes[0]),
        }),
    }))
}

/// The preset's plane model, then the others that apply along `axis`: those needing a finite
/// thickness (all but the wide one) only when the thickness is finite or is what varies.
pub fn models(preset: &Preset, axis: &Axis) -> Vec<Model> {
    let own = preset.plane.model;
    let finite = !preset.material.is_half_space() || axis.key.param().key == "material.thickness";
    std::iter::once(own)
        .chain(
            Model::ALL
                .iter()
                .copied()
                .filter(|m| *m != own && (finite || !m.needs_finite_thickness())),
        )
        .collect()
}
