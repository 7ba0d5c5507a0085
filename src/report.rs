//! The reports of `wearlab solve`: JSON and CSV, with the keys of the command-line contract
//! (`docs/cli.md`). All values SI. The spatial report is in `spatial_report`.

use std::io::{self, Write};

use serde::Serialize;

use crate::finite::{self, NonFinite};
use crate::physics::SolveError;
use crate::physics::plane::energy::{Energy, Undefined, serialize_balance};
use crate::physics::plane::operating_point;
use crate::physics::plane::profile::Profile;
use crate::physics::plane::sweep::{Sweep, sweep};
use crate::physics::plane::validity::Validity;
use crate::physics::plane::yield_onset::{YieldCheck, judge};
use crate::physics::plane::{PlaneSolution, Shape};
use crate::preset::Preset;

/// The full plane report.
#[derive(Clone, Debug, Serialize)]
pub struct PlaneReport {
    /// Always "plane".
    pub problem: &'static str,
    /// The solution at the preset's load (its keys at the top level of the JSON).
    #[serde(flatten)]
    pub solution: PlaneSolution,
    /// The punch's shape as the preset gives it.
    pub shape: Shape,
    /// I, J of (2.9) and the losses; null with a note where they have no number.
    #[serde(serialize_with = "serialize_balance")]
    pub energy: Result<Energy, Undefined>,
    /// Validity flags.
    pub validity: Validity,
    /// The yield check, when the preset gives a yield strength or hardness.
    #[serde(rename = "yield", skip_serializing_if = "Option::is_none")]
    pub yield_check: Option<YieldCheck>,
    /// Profiles on [-a, b].
    pub profile: Profile,
    /// mu*(P) over the preset's sweep.
    pub sweep: Sweep,
}

/// Solves a plane preset and gathers everything `wearlab solve` prints.
pub fn plane_report(preset: &Preset, points: usize) -> Result<PlaneReport, SolveError> {
    let inputs = preset.plane_inputs();
    let model = preset.plane.model;
    let point = operating_point(&inputs, model, points)?;
    let yield_check = judge(&point.solution, preset.strength);
    Ok(PlaneReport {
        problem: "plane",
        shape: inputs.shape.clone(),
        solution: point.solution,
        energy: point.energy,
        validity: point.validity,
        yield_check,
        profile: point.profile,
        sweep: sweep(&inputs, model, &preset.plane.sweep),
    })
}

/// Pretty JSON of any report.
pub fn to_json(report: &impl Serialize) -> String {
    serde_json::to_string_pretty(report).expect("reports hold only numbers and strings")
}

/// Writes [`to_json`] to `out` as it is serialised.
pub fn write_json(out: &mut dyn Write, report: &impl Serialize) -> io::Result<()> {
    serde_json::to_writer_pretty(out, report).map_err(io::Error::from)
}

/// The columns of the profile's CSV.
const PROFILE_COLUMNS: [&str; 5] = ["x", "pressure", "shear", "wear_rate", "wear"];

/// The profile's row i, in the order of `PROFILE_COLUMNS`.
fn profile_row(p: &Profile, i: usize) -> [f64; 5] {
    [p.x[i], p.pressure[i], p.shear[i], p.wear_rate[i], p.wear[i]]
}

/// The profile as CSV: a header line, then one row per point.
pub fn profile_csv(p: &Profile) -> String {
    let mut out = Vec::new();
    write_profile_csv(&mut out, p).expect("a vector takes every byte");
    String::from_utf8(out).expect("numbers and names are ASCII")
}

/// Writes [`profile_csv`] row by row to `out`.
pub fn write_profile_csv(out: &mut dyn Write, p: &Profile) -> io::Result<()> {
    writeln!(out, "{}", PROFILE_COLUMNS.join(","))?;
    for i in 0..p.x.len() {
        let [x, pressure, shear, wear_rate, wear] = profile_row(p, i);
        writeln!(out, "{x:e},{pressure:e},{shear:e},{wear_rate:e},{wear:e}")?;
    }
    Ok(())
}

/// The check of `finite::check_csv` on [`profile_csv`], without its text.
pub fn check_profile_csv(p: &Profile) -> Result<(), NonFinite> {
    finite::check_table(&PROFILE_COLUMNS, p.x.len(), |i, c| profile_row(p, i)[c])
}
