//! The spatial report of `wearlab solve`: the preset's problem solved by the library's pipeline
//! (`physics::spatial::pipeline`), whose result serialises to the JSON keys of the command-line
//! contract (`docs/cli.md`), and its fields over the cell as CSV. All values SI.

use std::io::{self, Write};

use crate::finite::{self, NonFinite};
use crate::physics::SolveError;
use crate::physics::spatial::partial::running_in::Stopped;
use crate::physics::spatial::pipeline;
use crate::physics::spatial::result::{FieldTable, SpatialResult};
use crate::physics::stop::Stop;
use crate::preset::Preset;

/// Solves a spatial preset at time `time` (the preset's own when None) with probes at `probes`,
/// and when `sweep`, mu* against pbar over the preset's sweep (on the period cell each of its
/// points is a contact solve: several times the cost of the solve itself).
pub fn spatial_report(
    preset: &Preset,
    time: Option<f64>,
    probes: &[[f64; 2]],
    sweep: bool,
) -> Result<SpatialResult, SolveError> {
    spatial_report_until(preset, time, probes, sweep, Stop::Never).map_err(SolveError::from)
}

/// As [`spatial_report`], told to stop by `stop` (`pipeline::solve_until`).
pub fn spatial_report_until(
    preset: &Preset,
    time: Option<f64>,
    probes: &[[f64; 2]],
    sweep: bool,
    stop: Stop,
) -> Result<SpatialResult, Stopped> {
    let mut at = preset.spatial_state_at();
    if let Some(t) = time {
        at.time = t;
    }
    pipeline::solve_until(&preset.spatial_inputs(), &at, probes, sweep, stop)
}

/// The columns of the field's CSV.
const FIELD_COLUMNS: [&str; 6] = ["x", "y", "pressure", "shear", "shape", "wear"];

/// Row k = j nx + i of the field (x fastest), in the order of `FIELD_COLUMNS`.
fn field_row(f: &FieldTable, k: usize) -> [f64; 6] {
    let nx = f.x.len();
    [
        f.x[k % nx],
        f.y[k / nx],
        f.pressure[k],
        f.shear[k],
        f.shape[k],
        f.wear[k],
    ]
}

/// The spatial field over the cell as CSV: x,y,pressure,shear,shape,wear.
pub fn field_csv(result: &SpatialResult) -> String {
    let mut out = Vec::new();
    write_field_csv(&mut out, result).expect("a vector takes every byte");
    String::from_utf8(out).expect("numbers and names are ASCII")
}

/// Writes [`field_csv`] row by row to `out`.
pub fn write_field_csv(out: &mut dyn Write, result: &SpatialResult) -> io::Result<()> {
    let f = &result.field;
    writeln!(out, "{}", FIELD_COLUMNS.join(","))?;
    for k in 0..f.x.len() * f.y.len() {
        let [x, y, pressure, shear, shape, wear] = field_row(f, k);
        writeln!(out, "{x:e},{y:e},{pressure:e},{shear:e},{shape:e},{wear:e}")?;
    }
    Ok(())
}

/// The check of `finite::check_csv` on [`field_csv`], without its text.
pub fn check_field_csv(result: &SpatialResult) -> Result<(), NonFinite> {
    let f = &result.field;
    let rows = f.x.len() * f.y.len();
    finite::check_table(&FIELD_COLUMNS, rows, |k, c| field_row(f, k)[c])
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
