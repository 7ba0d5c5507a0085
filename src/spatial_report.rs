//! The spatial report of `wearlab solve`: the preset's problem solved by the library's pipeline
//! (`physics::spatial::pipeline`), whose result serialises to the JSON keys of the command-line
//! contract (`docs/cli.md`), and its fields over the cell as CSV. All values SI.

use crate::physics::SolveError;
use crate::physics::spatial::pipeline;
use crate::physics::spatial::result::SpatialResult;
use crate::preset::Preset;

/// Solves a spatial preset at time `time` (the preset's own when None) with probes at `probes`,
/// mu* against pbar over the preset's sweep.
pub fn spatial_report(
    preset: &Preset,
    time: Option<f64>,
    probes: &[[f64; 2]],
) -> Result<SpatialResult, SolveError> {
    let mut at = preset.spatial_state_at();
    if let Some(t) = time {
        at.time = t;
    }
    pipeline::solve(&preset.spatial_inputs(), &at, probes, true)
}

/// The spatial field over the cell as CSV: x,y,pressure,shear,shape,wear.
pub fn field_csv(result: &SpatialResult) -> String {
    let f = &result.field;
    let mut out = String::from("x,y,pressure,shear,shape,wear\n");
    for (j, y) in f.y.iter().enumerate() {
        for (i, x) in f.x.iter().enumerate() {
            let k = j * f.x.len() + i;
            out.push_str(&format!(
                "{x:e},{y:e},{:e},{:e},{:e},{:e}\n",
                f.pressure[k], f.shear[k], f.shape[k], f.wear[k]
            ));
        }
    }
    out
}

/// The punch surface at t of a height-map punch as a height-map CSV (docs/presets.md, "Rough
/// surfaces"): `#` lines with the time and the cell, then one row per y grid line of heights [m]
/// at 17 significant digits (each reads back to the same number). None for harmonics.
pub fn surface_csv(result: &SpatialResult) -> Option<String> {
    let surface = result.surface.as_ref()?;
    let f = &result.field;
    let [lx, ly] = surface.cell;
    let mut out = format!(
        "# wearlab: the punch surface U at t = {:e} s, heights [m] from the punch toward the layer\n\
         # length_x = {lx:e} m, length_y = {ly:e} m; {} x {} nodes, rms height {:e} m, rms slope {:e}\n",
        result.time,
        f.x.len(),
        f.y.len(),
        surface.rms_height,
        surface.rms_slope
    );
    for row in f.shape.chunks(f.x.len().max(1)) {
        let cells: Vec<String> = row.iter().map(|h| format!("{h:.16e}")).collect();
        out.push_str(&cells.join(","));
        out.push('\n');
    }
    Some(out)
}
