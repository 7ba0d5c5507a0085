//! Whether the contact yields at a point of a plane regime map: the preset's model solved there
//! and judged against the preset's strength there (`yield_onset::judge`, Johnson (1985) sections
//! 7.2 and 9.2: the largest von Mises stress against Y, or H/3). A judge costs 4-20 ms against
//! the map's 0.4 ms a point (`map` judges from its second pass on).

use rayon::prelude::*;

use crate::physics::plane::yield_onset::judge;
use crate::physics::stop::Stop;
use crate::preset::{Preset, Problem};
use crate::sweeps::axis::Axis;
use crate::sweeps::point::{Point, solve_until};
use crate::sweeps::sweep::preset_at;

/// Whether the map judges yield at all: a plane preset that gives a yield strength or hardness.
pub fn judged(preset: &Preset) -> bool {
    preset.problem == Problem::Plane && preset.strength.yield_stress().is_some()
}

/// Whether the contact yields with `axes` at `at`: the preset's model solved there and judged
/// against the strength there; None where it has no solution, where yield is not judged (the
/// narrow model), or where the preset gives no strength.
pub fn yields_at(base: &Preset, axes: [Axis; 2], at: [f64; 2], stop: Stop) -> Option<bool> {
    let preset = preset_at(base, &axes, &at).ok()?;
    let Ok(Point::Plane(p)) = solve_until(&preset, stop) else {
        return None;
    };
    judge(&p.solution, preset.strength)?.yields
}

/// `yields_at` at each of `points` (an index of the caller's and the point), in parallel; None
/// when `stop` said so before the last.
pub fn judge_all(
    base: &Preset,
    axes: [Axis; 2],
    points: Vec<(usize, [f64; 2])>,
    stop: Stop,
) -> Option<Vec<(usize, Option<bool>)>> {
    points
        .into_par_iter()
        .map(|(k, at)| (!stop.now()).then(|| (k, yields_at(base, axes, at, stop))))
        .collect()
}
