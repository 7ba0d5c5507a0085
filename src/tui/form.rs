//! The parameter form as a table: each parameter is one entry (label, unit, limits, step, getter,
//! setter), so a new parameter touches one place. Choice rows (model, scale) are their own kind.
//! Setting a value checks it against `physics::limits` and the rules between fields, and says
//! what is allowed when it refuses.

use wearlab::physics::limits::{self, Limit};
use wearlab::physics::plane::Model;
use wearlab::physics::spatial::harmonic::Harmonic;
use wearlab::physics::spatial::validate_harmonics;
use wearlab::physics::{Spacing, SweepRange};
use wearlab::preset::{Preset, Problem};
use wearlab::units::{format_si, parse_si};

/// How Left/Right change a number.
#[derive(Clone, Copy, Debug)]
pub enum Step {
    /// Multiply by 1.1 (large: 2); from 0, start at `seed`.
    Log { seed: f64 },
    /// Add `step` (large: ten steps), landing on whole steps.
    Linear { step: f64 },
    /// A hundredth of the duration (the time slider).
    Time,
}

/// Where a number lives.
#[derive(Clone, Copy, Debug)]
pub enum Access {
    /// A field of the preset.
    Preset(fn(&Preset) -> f64, fn(&mut Preset, f64)),
    /// A field of one harmonic (the row says which).
    Harmonic(fn(&Harmonic) -> f64, fn(&mut Harmonic, f64)),
    /// A named choice: its index, setting it, the names.
    Choice(
        fn(&Preset) -> usize,
        fn(&mut Preset, usize),
        fn() -> Vec<&'static str>,
    ),
}

/// One parameter of the form.
#[derive(Clone, Copy, Debug)]
pub struct Param {
    /// The heading it stands under.
    pub group: &'static str,
    /// Short label (the symbol).
    pub label: &'static str,
    /// SI unit ("" for none).
    pub unit: &'static str,
    /// Allowed values (unused for choices).
    pub limit: Limit,
    /// Nudge behaviour (unused for choices).
    pub step: Step,
    /// Shown and typed as a whole number.
    pub integer: bool,
    /// Getter and setter.
    pub access: Access,
}

const fn number(
    group: &'static str,
    label: &'static str,
    unit: &'static str,
    limit: Limit,
    step: Step,
    get: fn(&Preset) -> f64,
    set: fn(&mut Preset, f64),
) -> Param {
    Param {
        group,
        label,
        unit,
        limit,
        step,
        integer: false,
        access: Access::Preset(get, set),
    }
}

const fn whole(p: Param) -> Param {
    Param { integer: true, ..p }
}

const fn choice(
    group: &'static str,
    label: &'static str,
    get: fn(&Preset) -> usize,
    set: fn(&mut Preset, usize),
    names: fn() -> Vec<&'static str>,
) -> Param {
    Param {
        group,
        label,
        unit: "",
        limit: limits::SWEEP_POINTS,
        step: Step::Linear { step: 1.0 },
        integer: true,
        access: Access::Choice(get, set, names),
    }
}

const fn wave(
    label: &'static str,
    unit: &'static str,
    limit: Limit,
    step: Step,
    get: fn(&Harmonic) -> f64,
    set: fn(&mut Harmonic, f64),
) -> Param {
    Param {
        group: "harmonic",
        label,
        unit,
        limit,
        step,
        integer: false,
        access: Access::Harmonic(get, set),
    }
}

const SPACINGS: [(Spacing, &str); 2] = [(Spacing::Log, "log"), (Spacing::Linear, "linear")];

fn spacing_names() -> Vec<&'static str> {
    SPACINGS.iter().map(|(_, n)| *n).collect()
}

fn spacing_index(s: Spacing) -> usize {
    SPACINGS.iter().position(|(x, _)| *x == s).unwrap_or(0)
}

fn model_names() -> Vec<&'static str> {
    Model::ALL.iter().map(|m| m.name()).collect()
}

/// The parameters of both problems.
#[rustfmt::skip]
const COMMON: [Param; 6] = [
    number("material", "E", "Pa", limits::YOUNGS_MODULUS, Step::Log { seed: 1e9 }, |p| p.material.youngs_modulus, |p, v| p.material.youngs_modulus = v),
    number("material", "nu", "", limits::POISSON_RATIO, Step::Linear { step: 0.01 }, |p| p.material.poisson_ratio, |p, v| p.material.poisson_ratio = v),
    number("material", "h", "m", limits::THICKNESS, Step::Log { seed: 1e-3 }, |p| p.material.thickness, |p, v| p.material.thickness = v),
    number("friction", "mu", "", limits::FRICTION, Step::Linear { step: 0.01 }, |p| p.friction.coefficient, |p, v| p.friction.coefficient = v),
    number("friction", "tau0", "Pa", limits::ADHESION, Step::Log { seed: 1e4 }, |p| p.friction.adhesion, |p, v| p.friction.adhesion = v),
    number("wear", "k", "1/Pa", limits::WEAR, Step::Log { seed: 1e-15 }, |p| p.wear, |p, v| p.wear = v),
];

/// The plane problem's parameters.
#[rustfmt::skip]
const PLANE: [Param; 7] = [
    choice("punch and load", "model", |p| Model::ALL.iter().position(|m| *m == p.plane.model).unwrap_or(0), |p, i| p.plane.model = Model::ALL[i % Model::ALL.len()], model_names),
    number("punch and load", "R", "m", limits::RADIUS, Step::Log { seed: 0.01 }, |p| p.plane.radius, |p, v| p.plane.radius = v),
    number("punch and load", "P", "N/m", limits::LINE_LOAD, Step::Log { seed: 1e3 }, |p| p.plane.load, |p, v| p.plane.load = v),
    number("punch and load", "P min", "N/m", limits::LINE_LOAD, Step::Log { seed: 1e2 }, |p| p.plane.sweep.min, |p, v| p.plane.sweep.min = v),
    number("punch and load", "P max", "N/m", limits::LINE_LOAD, Step::Log { seed: 1e5 }, |p| p.plane.sweep.max, |p, v| p.plane.sweep.max = v),
    whole(number("punch and load", "points", "", limits::SWEEP_POINTS, Step::Linear { step: 10.0 }, |p| p.plane.sweep.points as f64, |p, v| p.plane.sweep.points = v as usize)),
    choice("punch and load", "scale", |p| spacing_index(p.plane.sweep.spacing), |p, i| p.plane.sweep.spacing = SPACINGS[i % 2].0, spacing_names),
];

/// The spatial problem's parameters (the harmonics follow, one group each).
#[rustfmt::skip]
const SPATIAL: [Param; 9] = [
    number("load and time", "pbar", "Pa", limits::MEAN_PRESSURE, Step::Log { seed: 1e6 }, |p| p.spatial.mean_pressure, |p, v| p.spatial.mean_pressure = v),
    number("load and time", "V", "m/s", limits::SPEED, Step::Log { seed: 0.1 }, |p| p.spatial.sliding_speed, |p, v| p.spatial.sliding_speed = v),
    number("load and time", "t", "s", limits::TIME, Step::Time, |p| p.spatial.time, |p, v| p.spatial.time = v),
    number("load and time", "duration", "s", limits::DURATION, Step::Log { seed: 10.0 }, |p| p.spatial.duration, |p, v| p.spatial.duration = v),
    whole(number("load and time", "grid", "", limits::GRID, Step::Linear { step: 8.0 }, |p| p.spatial.grid as f64, |p, v| p.spatial.grid = v as usize)),
    number("load and time", "pbar min", "Pa", limits::MEAN_PRESSURE, Step::Log { seed: 1e5 }, |p| p.spatial.sweep.min, |p, v| p.spatial.sweep.min = v),
    number("load and time", "pbar max", "Pa", limits::MEAN_PRESSURE, Step::Log { seed: 1e8 }, |p| p.spatial.sweep.max, |p, v| p.spatial.sweep.max = v),
    whole(number("load and time", "points", "", limits::SWEEP_POINTS, Step::Linear { step: 10.0 }, |p| p.spatial.sweep.points as f64, |p, v| p.spatial.sweep.points = v as usize)),
    choice("load and time", "scale", |p| spacing_index(p.spatial.sweep.spacing), |p, i| p.spatial.sweep.spacing = SPACINGS[i % 2].0, spacing_names),
];

/// The parameters of each harmonic.
#[rustfmt::skip]
const HARMONIC: [Param; 5] = [
    wave("A", "m", limits::AMPLITUDE, Step::Log { seed: 1e-7 }, |h| h.amplitude, |h, v| h.amplitude = v),
    wave("wx", "rad/m", limits::WAVENUMBER, Step::Log { seed: 1e3 }, |h| h.wavenumber_x, |h, v| h.wavenumber_x = v),
    wave("wy", "rad/m", limits::WAVENUMBER, Step::Log { seed: 1e3 }, |h| h.wavenumber_y, |h, v| h.wavenumber_y = v),
    wave("rho_x", "rad", limits::PHASE, Step::Linear { step: 0.05 }, |h| h.phase_x, |h, v| h.phase_x = v),
    wave("rho_y", "rad", limits::PHASE, Step::Linear { step: 0.05 }, |h| h.phase_y, |h, v| h.phase_y = v),
];

/// One row of the form: a parameter, and for a harmonic's parameter, which harmonic.
#[derive(Clone, Copy, Debug)]
pub struct Row {
    /// The parameter.
    pub param: &'static Param,
    /// The harmonic (0-based) of a harmonic's row.
    pub harmonic: Option<usize>,
}

impl Row {
    /// The heading the row stands under ("harmonic 2" for a harmonic's rows).
    pub fn heading(&self) -> String {
        match self.harmonic {
            Some(n) => format!("harmonic {}", n + 1),
            None => self.param.group.to_string(),
        }
    }

    /// The label, with the harmonic's number for messages ("A2").
    pub fn name(&self) -> String {
        match self.harmonic {
            Some(n) => format!("{}{}", self.param.label, n + 1),
            None => self.param.label.to_string(),
        }
    }

    /// The choices of a choice row.
    pub fn choices(&self) -> Option<Vec<&'static str>> {
        match self.param.access {
            Access::Choice(_, _, names) => Some(names()),
            _ => None,
        }
    }
}

/// The rows of the preset's current problem.
pub fn rows(preset: &Preset) -> Vec<Row> {
    let plain = |param| Row {
        param,
        harmonic: None,
    };
    let mut out: Vec<Row> = COMMON.iter().map(plain).collect();
    match preset.problem {
        Problem::Plane => out.extend(PLANE.iter().map(plain)),
        Problem::Spatial => {
            out.extend(SPATIAL.iter().map(plain));
            for n in 0..preset.spatial.harmonics.len() {
                out.extend(HARMONIC.iter().map(|param| Row {
                    param,
                    harmonic: Some(n),
                }));
            }
        }
    }
    out
}

/// The row's value as a number (a choice as its index).
pub fn get(preset: &Preset, row: &Row) -> f64 {
    match row.param.access {
        Access::Preset(get, _) => get(preset),
        Access::Harmonic(get, _) => get(&preset.spatial.harmonics[row.harmonic.unwrap_or(0)]),
        Access::Choice(get, _, _) => get(preset) as f64,
    }
}

/// The row's value as the form shows it: SI prefixes, engineering notation past them.
pub fn show(preset: &Preset, row: &Row) -> String {
    let v = get(preset, row);
    match row.choices() {
        Some(names) => names[v as usize % names.len()].to_string(),
        None if row.param.integer => format!("{v}"),
        None => format_si(v, row.param.unit),
    }
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

/// Sets a row's value on a copy of the preset and checks the result; Err says what is allowed.
pub fn set(preset: &Preset, row: &Row, value: f64) -> Result<(Preset, Change), String> {
    let name = row.name();
    let mut p = preset.clone();
    match row.param.access {
        Access::Choice(_, set, names) => set(&mut p, value as usize % names().len()),
        Access::Preset(_, set) => {
            row.param.limit.check(&name, value)?;
            set(&mut p, value);
        }
        Access::Harmonic(_, set) => {
            row.param.limit.check(&name, value)?;
            set(&mut p.spatial.harmonics[row.harmonic.unwrap_or(0)], value);
        }
    }
    consistent(&p)?;
    let change = Change {
        from: show(preset, row),
        to: show(&p, row),
        name,
    };
    Ok((p, change))
}

/// Parses typed text for a row (a choice by its name) and sets it.
pub fn set_text(preset: &Preset, row: &Row, text: &str) -> Result<(Preset, Change), String> {
    let value = match row.choices() {
        Some(names) => names
            .iter()
            .position(|n| *n == text.trim())
            .map(|i| i as f64)
            .ok_or_else(|| format!("type one of: {}", names.join(", ")))?,
        None => parse_si(text, row.param.unit)?,
    };
    set(preset, row, value)
}

/// The rules between fields, the same as the preset file's: a model other than wide needs a
/// finite thickness; each sweep's min < max; the harmonics' wave vectors are nonzero and distinct.
pub fn consistent(p: &Preset) -> Result<(), String> {
    let model = p.plane.model;
    if model.needs_finite_thickness() && p.material.is_half_space() {
        return Err(format!(
            "the {} model needs a finite thickness h (h = inf is a half-plane): set h, or switch the model with m",
            model.name()
        ));
    }
    let order = |s: &SweepRange, names, unit| s.check_order(names, |v| format_si(v, unit));
    order(&p.plane.sweep, ["P min", "P max"], "N/m")?;
    order(&p.spatial.sweep, ["pbar min", "pbar max"], "Pa")?;
    validate_harmonics(&p.spatial.harmonics)
        .map_err(|e| e.to_string().trim_start_matches("invalid input: ").into())
}

/// The nudged value (`up` or down, `large` for Shift).
pub fn nudged(preset: &Preset, row: &Row, up: bool, large: bool) -> f64 {
    let v = get(preset, row);
    let dir = if up { 1.0 } else { -1.0 };
    if let Some(names) = row.choices() {
        let n = names.len() as f64;
        return (v + if up { 1.0 } else { n - 1.0 }) % n;
    }
    let linear = |step: f64| {
        let s = if large { 10.0 * step } else { step };
        // land on whole steps so repeated nudges read cleanly
        ((v + dir * s) / step).round() * step
    };
    match row.param.step {
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
    }
}
