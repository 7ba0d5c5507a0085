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
