//! The parameter form: the library's parameter registry (`preset::PARAMS`: symbol, unit,
//! limits, getter and setter, the rules between fields) shown as rows under headings, with what
//! only the explorer needs: how Left/Right nudge each parameter. A new parameter is one entry of
//! the registry and one of `STEPS`.

use crate::preset::{Key, Preset, Problem, surface_from_file};
use crate::units::{clean, format_si};

/// How Left/Right change a number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Step {
    /// Multiply by 1.1 (large: 2); from 0, start at `seed`.
    Log { seed: f64 },
    /// Add `step` (large: ten steps), landing on whole steps.
    Linear { step: f64 },
    /// A hundredth of the duration (the time slider).
    Time,
    /// The next or previous choice.
    Choice,
    /// None: the value is read from the preset file.
    Fixed,
}

/// The nudge of each parameter, by preset key (`N` for the harmonic's index).
#[rustfmt::skip]
pub const STEPS: [(&str, Step); 51] = [
    ("material.name", Step::Choice),
    ("material.youngs_modulus", Step::Log { seed: 1e9 }),
    ("material.poisson_ratio", Step::Linear { step: 0.01 }),
    ("material.thickness", Step::Log { seed: 1e-3 }),
    ("material.yield_strength", Step::Log { seed: 1e8 }),
    ("material.hardness", Step::Log { seed: 3e8 }),
    ("friction.coefficient", Step::Linear { step: 0.01 }),
    ("friction.adhesion", Step::Log { seed: 1e4 }),
    ("friction.shear_strength", Step::Log { seed: 1e7 }),
    ("wear.coefficient", Step::Log { seed: 1e-15 }),
    ("wear.archard_coefficient", Step::Log { seed: 1e-4 }),
    ("wear.exponent", Step::Linear { step: 0.1 }),
    ("wear.reference_pressure", Step::Log { seed: 1e6 }),
    ("plane.model", Step::Choice),
    ("plane.shape.kind", Step::Choice),
    ("plane.radius", Step::Log { seed: 0.01 }),
    ("plane.shape.radius", Step::Log { seed: 0.01 }),
    ("plane.shape.exponent", Step::Linear { step: 0.1 }),
    ("plane.shape.half_width", Step::Log { seed: 1e-3 }),
    ("plane.shape.edge_radius", Step::Log { seed: 1e-4 }),
    ("plane.shape.file", Step::Fixed),
    ("plane.shape.range", Step::Fixed),
    ("plane.load", Step::Log { seed: 1e3 }),
    ("plane.sweep.load_min", Step::Log { seed: 1e2 }),
    ("plane.sweep.load_max", Step::Log { seed: 1e5 }),
    ("plane.sweep.points", Step::Linear { step: 10.0 }),
    ("plane.sweep.scale", Step::Choice),
    ("spatial.mean_pressure", Step::Log { seed: 1e6 }),
    ("spatial.sliding_speed", Step::Log { seed: 0.1 }),
    ("spatial.time", Step::Time),
    ("spatial.duration", Step::Log { seed: 10.0 }),
    ("spatial.grid", Step::Linear { step: 8.0 }),
    ("spatial.sweep.pressure_min", Step::Log { seed: 1e5 }),
    ("spatial.sweep.pressure_max", Step::Log { seed: 1e8 }),
    ("spatial.sweep.points", Step::Linear { step: 10.0 }),
    ("spatial.sweep.scale", Step::Choice),
    ("spatial.surface.file", Step::Fixed),
    ("spatial.surface.hurst", Step::Linear { step: 0.05 }),
    ("spatial.surface.rms_height", Step::Log { seed: 1e-6 }),
    ("spatial.surface.rms_slope", Step::Log { seed: 0.1 }),
    ("spatial.surface.rolloff_wavelength", Step::Log { seed: 1e-4 }),
    ("spatial.surface.cutoff_wavelength", Step::Log { seed: 1e-5 }),
    ("spatial.surface.length_x", Step::Log { seed: 1e-3 }),
    ("spatial.surface.length_y", Step::Log { seed: 1e-3 }),
    ("spatial.surface.grid", Step::Linear { step: 8.0 }),
    ("spatial.surface.seed", Step::Linear { step: 1.0 }),
    ("spatial.harmonics.N.amplitude", Step::Log { seed: 1e-7 }),
    ("spatial.harmonics.N.wavenumber_x", Step::Log { seed: 1e3 }),
    ("spatial.harmonics.N.wavenumber_y", Step::Log { seed: 1e3 }),
    ("spatial.harmonics.N.phase_x", Step::Linear { step: 0.05 }),
    ("spatial.harmonics.N.phase_y", Step::Linear { step: 0.05 }),
];

/// One row of the form: a parameter of the preset.
pub type Row = Key;

/// The heading a row stands under ("harmonic 2" for a harmonic's rows; a height map's rows say
/// where the surface comes from, and that a file's are not set here).
pub fn heading(preset: &Preset, row: &Row) -> String {
    if let Some(n) = row.harmonic_index() {
        return format!("harmonic {}", n + 1);
    }
    if row.param().surface_name().is_some() {
        return if surface_from_file(preset) {
            "measured surface (from the file)".into()
        } else {
            "generated rough surface".into()
        };
    }
    match row.param().key.split('.').next().unwrap_or("") {
        "plane" => "punch and load".into(),
        "spatial" => "load and time".into(),
        section => section.into(),
    }
}

/// The nudge of a row.
pub fn step(row: &Row) -> Step {
    STEPS
        .iter()
        .find(|(k, _)| *k == row.param().key)
        .map_or(Step::Choice, |(_, s)| *s)
}

/// The rows of the preset's current problem.
pub fn rows(preset: &Preset) -> Vec<Row> {
    Key::all(preset)
}

/// The row's value as a number (a choice as its index).
pub fn get(preset: &Preset, row: &Row) -> f64 {
    preset.get(*row).expect("the rows are the preset's own")
}

/// The row's value as the form shows it: SI prefixes, engineering notation past them.
pub fn show(preset: &Preset, row: &Row) -> String {
    let param = row.param();
    if let Some(text) = preset.fixed_text(*row) {
        return text;
    }
    if not_given(preset, param.key) {
        return "none".into();
    }
    let v = get(preset, row);
    match param.choices() {
        Some(names) => names[v as usize % names.len()].to_string(),
        None if param.is_whole() => format!("{v}"),
        None => format_si(v, param.unit),
    }
}

/// True for a yield strength or hardness the preset does not give (no yield check).
fn not_given(preset: &Preset, key: &str) -> bool {
    match key {
        "material.yield_strength" => preset.strength.yield_strength.is_none(),
        "material.hardness" => preset.strength.hardness.is_none(),
        _ => false,
    }
}

/// What differs from `from` to `to`, as the form shows it ("mu 0.1 -> 0.3"), the time apart
/// (where one looks, not an input); a harmonic added or removed is counted.
pub fn differences(from: &Preset, to: &Preset) -> Vec<String> {
    let (was, now) = (&from.spatial.harmonics, &to.spatial.harmonics);
    let before = rows(from);
    let mut out: Vec<String> = rows(to)
        .iter()
        .filter(|r| r.param().key != "spatial.time")
        // a number of another kind of punch or surface than before: the kind's row, or the
        // preset's name, says what changed
        .filter(|r| {
            !(r.param().key.starts_with("plane.shape.") || r.param().surface_name().is_some())
                || before.contains(r)
        })
        .filter(|r| r.param().key != "plane.radius" || before.contains(r))
        .filter(|r| r.harmonic_index().is_none_or(|n| n < was.len()))
        .filter(|r| show(from, r) != show(to, r))
        .map(|r| format!("{} {} -> {}", r.symbol(), show(from, r), show(to, r)))
        .collect();
    if from.problem != to.problem {
        out.insert(
            0,
            format!("problem {} -> {}", from.problem.name(), to.problem.name()),
        );
    }
    if to.problem == Problem::Spatial && was.len() != now.len() {
        out.push(format!("harmonics {} -> {}", was.len(), now.len()));
    }
    out
}

/// A change the form made, for the undo message: "E 3.00 GPa -> 3.30 GPa".
#[derive(Clone, Debug, PartialEq)]
pub struct Change {
    /// What changed.
    pub name: String,
    /// Its value before, as text.
    pub from: String,
    /// Its value after.
    pub to: String,
}

fn changed(preset: &Preset, next: Preset, row: &Row) -> (Preset, Change) {
    let change = Change {
        name: row.symbol(),
        from: show(preset, row),
        to: show(&next, row),
    };
    (next, change)
}

/// Sets a row's value on a copy of the preset (its limit, then the rules between fields); Err
/// says what is allowed, and the caller's preset keeps the last valid value.
pub fn set(preset: &Preset, row: &Row, value: f64) -> Result<(Preset, Change), String> {
    let mut next = preset.clone();
    reference_for(&mut next, row, value);
    next.set(*row, value)?;
    Ok(changed(preset, next, row))
}

/// A wear law made nonlinear in the form needs its reference pressure p0: where the preset has
/// none, the mean pressure of the punch's contact on a half-plane at the preset's load (Hertz,
/// half-width sqrt(2 P R/m); the flat's face added), so that at the pressures of the contact the
/// law wears at about the linear law's rate.
fn reference_for(preset: &mut Preset, row: &Row, value: f64) {
    if row.param().key != "wear.exponent" || value == 1.0 || preset.reference_pressure.is_some() {
        return;
    }
    let inputs = preset.plane_inputs();
    let load = inputs.load;
    let hertz = (2.0 * load * inputs.shape.radius() / inputs.material.plane_modulus()).sqrt();
    let face = match inputs.shape {
        crate::physics::plane::Shape::Flat { half_width, .. } => half_width,
        _ => 0.0,
    };
    preset.reference_pressure = Some(clean(load / (2.0 * (hertz + face))));
}

/// Parses typed text for a row (a choice by its name, a number with SI prefix and unit) and
/// sets it as `set` does.
pub fn set_text(preset: &Preset, row: &Row, text: &str) -> Result<(Preset, Change), String> {
    let mut next = preset.clone();
    if let Ok(value) = crate::units::parse_si(text, row.param().unit) {
        reference_for(&mut next, row, value);
    }
    next.assign_text(*row, text)?;
    next.check_rules()?;
    Ok(changed(preset, next, row))
}

/// The nudged value (`up` or down, `large` for Shift), rounded to `units::clean`'s significant
/// digits so that a saved preset and the form read "3.3 GPa", not 3300000000.0000005.
pub fn nudged(preset: &Preset, row: &Row, up: bool, large: bool) -> f64 {
    clean(nudged_raw(preset, row, up, large))
}

fn nudged_raw(preset: &Preset, row: &Row, up: bool, large: bool) -> f64 {
    if step(row) == Step::Fixed || preset.fixed_text(*row).is_some() {
        // nothing to nudge: setting it says why
        return 0.0;
    }
    let v = get(preset, row);
    let dir = if up { 1.0 } else { -1.0 };
    let linear = |step: f64| {
        let s = if large { 10.0 * step } else { step };
        // land on whole steps so repeated nudges read cleanly
        ((v + dir * s) / step).round() * step
    };
    match step(row) {
        Step::Choice => {
            let n = row.param().choices().map_or(1, <[_]>::len) as f64;
            (v + if up { 1.0 } else { n - 1.0 }) % n
        }
        Step::Log { seed } if v == 0.0 => {
            if up {
                seed
            } else {
                0.0
            }
        }
        Step::Log { .. } if v.is_infinite() => v,
        Step::Log { .. } => v * if large { 2f64 } else { 1.1 }.powf(dir),
        Step::Linear { step } => linear(step),
        Step::Time => linear(preset.spatial.duration / 100.0),
        Step::Fixed => 0.0,
    }
}
