//! Exploring any parameter (issue 12): sweeps of every numeric input of a preset (`preset::Key`)
//! over a range (`axis`), the quantities a sweep can show (`quantity`, one registry for the
//! command line and the explorer, the dimensionless groups among them), one solved point
//! (`point`), sweeps in parallel for `wearlab sweep` (`sweep`) and their CSV and JSON (`output`),
//! and for the explorer a curve with overlays and validity changes (`curve`) and a regime map
//! with its lines, coarse first (`map`), both located by `locate`.

pub mod axis;
pub mod curve;
pub mod locate;
pub mod map;
pub mod output;
pub mod point;
mod quantities;
pub mod quantity;
pub mod sweep;

pub use axis::Axis;
pub use quantity::{Quantity, QuantityKey};
