//! The optional `[explore]` section of a preset file: the sweep (one axis) or the map (two axes)
//! and the quantity the preset's lesson is about. `wearlab sweep PRESET` runs it when no `--vary`
//! is given, and the explorer opens its sweep chart or map on it.
//!
//! ```toml
//! [explore]
//! quantity = "mu_star_minus_mu"     # a name of `wearlab sweep --output`
//! x = { key = "material.thickness", from = 1.0e-6, to = 1.0e-2, points = 40, scale = "log" }
//! y = { key = "plane.load", from = 1.0e2, to = 1.0e4 }    # optional: a map over (x, y)
//! data = "lab-friction.csv"         # optional: a data file the explorer draws (`d`)
//! ```
//!
//! `points` defaults to 50 for a sweep and 20 per side for a map, `scale` to "linear". The keys
//! are preset keys of the preset's problem; each range is checked as `--vary` checks it. The
//! file's layout is in `file`, its checks in `check`.

use crate::preset::Preset;
use crate::sweeps::axis::Axis;
use crate::sweeps::quantity::QuantityKey;

/// What a preset's lesson sweeps or maps.
#[derive(Clone, Debug, PartialEq)]
pub struct Explore {
    /// The quantity shown.
    pub quantity: QuantityKey,
    /// The varied parameters: one (a sweep) or two (a map, x then y).
    pub axes: Vec<Axis>,
    /// A data file drawn over the charts whose axes it matches, as written (relative to the
    /// preset's folder); the explorer reads it when it opens the preset.
    pub data: Option<String>,
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
