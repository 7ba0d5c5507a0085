//! The parameter form: every preset parameter as a row with a label, a unit, a getter and a
//! setter that refuses what the limits refuse (and says why).

use wearlab::physics::Spacing;
use wearlab::physics::limits::{self, Limit};
use wearlab::physics::plane::Model;
use wearlab::physics::spatial::harmonic::Harmonic;
use wearlab::preset::{Preset, Problem};
use wearlab::units::format_si;

/// How Left/Right change a value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Nudge {
    /// Multiply by 1.1 (Shift: 2); from 0, start at `seed`.
    Log { seed: f64 },
    /// Add `step` (Shift: 10 steps).
    Linear { step: f64 },
    /// Cycle through these named choices (the row's value is the index).
    Choice(&'static [&'static str]),
}

/// The plane models by name, in the order of `Model::ALL`.
pub const MODELS: &[&str] = &["wide", "narrow", "strip"];
/// Sweep spacings by name.
pub const SCALES: &[&str] = &["log", "linear"];

fn spacing(index: f64) -> Spacing {
    if index == 0.0 {
        Spacing::Log
    } else {
        Spacing::Linear
    }
}

fn spacing_index(s: Spacing) -> f64 {
    match s {
        Spacing::Log => 0.0,
        Spacing::Linear => 1.0,
    }
}

/// Which number a row edits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Key {
    YoungsModulus,
    PoissonRatio,
    Thickness,
    Friction,
    Adhesion,
    Wear,
    Model,
    Radius,
    Load,
    LoadMin,
    LoadMax,
    LoadPoints,
    LoadScale,
    MeanPressure,
    Speed,
    Time,
    Duration,
    Grid,
    PressureMin,
    PressureMax,
    PressurePoints,
    PressureScale,
    Amplitude(usize),
    WavenumberX(usize),
    WavenumberY(usize),
    PhaseX(usize),
    PhaseY(usize),
}

/// One row of the form.
#[derive(Clone, Copy, Debug)]
pub struct Row {
    /// What it edits.
    pub key: Key,
    /// Group heading it belongs to.
    pub group: &'static str,
    /// Short label (symbol).
    pub label: &'static str,
    /// SI unit ("" for none).
    pub unit: &'static str,
    /// Allowed range.
    pub limit: Limit,
    /// Nudge behaviour.
    pub nudge: Nudge,
}

const fn row(
    key: Key,
    group: &'static str,
    label: &'static str,
    unit: &'static str,
    limit: Limit,
    nudge: Nudge,
) -> Row {
    Row {
        key,
        group,
        label,
        unit,
        limit,
        nudge,
    }
}

/// The rows for the preset's current problem.
pub fn rows(preset: &Preset) -> Vec<Row> {
    let mut out = vec![
        row(
            Key::YoungsModulus,
            "material",
            "E",
            "Pa",
            limits::YOUNGS_MODULUS,
            Nudge::Log { seed: 1e9 },
        ),
        row(
            Key::PoissonRatio,
            "material",
            "nu",
            "",
            limits::POISSON_RATIO,
            Nudge::Linear { step: 0.01 },
        ),
        row(
            Key::Thickness,
            "material",
            "h",
            "m",
            limits::THICKNESS,
            Nudge::Log { seed: 1e-3 },
        ),
        row(
            Key::Friction,
            "friction",
            "mu",
            "",
            limits::FRICTION,
            Nudge::Linear { step: 0.01 },
        ),
        row(
            Key::Adhesion,
            "friction",
            "tau0",
            "Pa",
            limits::ADHESION,
            Nudge::Log { seed: 1e4 },
        ),
        row(
            Key::Wear,
            "wear",
            "k",
            "1/Pa",
            limits::WEAR,
            Nudge::Log { seed: 1e-15 },
        ),
    ];
    match preset.problem {
        Problem::Plane => out.extend([
            row(
                Key::Model,
                "punch and load",
                "model",
                "",
                limits::FRICTION,
                Nudge::Choice(MODELS),
            ),
            row(
                Key::Radius,
                "punch and load",
                "R",
                "m",
                limits::RADIUS,
                Nudge::Log { seed: 0.01 },
            ),
            row(
                Key::Load,
                "punch and load",
                "P",
                "N/m",
                limits::LINE_LOAD,
                Nudge::Log { seed: 1e3 },
            ),
            row(
                Key::LoadMin,
                "punch and load",
                "P min",
                "N/m",
                limits::LINE_LOAD,
                Nudge::Log { seed: 1e2 },
            ),
            row(
                Key::LoadMax,
                "punch and load",
                "P max",
                "N/m",
                limits::LINE_LOAD,
                Nudge::Log { seed: 1e5 },
            ),
            row(
                Key::LoadPoints,
                "punch and load",
                "points",
                "",
                limits::SWEEP_POINTS,
                Nudge::Linear { step: 10.0 },
            ),
            row(
                Key::LoadScale,
                "punch and load",
                "scale",
                "",
                limits::SWEEP_POINTS,
                Nudge::Choice(SCALES),
            ),
        ]),
        Problem::Spatial => {
            out.extend([
                row(
                    Key::MeanPressure,
                    "load and time",
                    "pbar",
                    "Pa",
                    limits::MEAN_PRESSURE,
                    Nudge::Log { seed: 1e6 },
                ),
                row(
                    Key::Speed,
                    "load and time",
                    "V",
                    "m/s",
                    limits::SPEED,
                    Nudge::Log { seed: 0.1 },
                ),
                row(
                    Key::Time,
                    "load and time",
                    "t",
                    "s",
                    limits::TIME,
                    Nudge::Linear {
                        step: preset.spatial.duration / 100.0,
                    },
                ),
                row(
                    Key::Duration,
                    "load and time",
                    "duration",
                    "s",
                    limits::DURATION,
                    Nudge::Log { seed: 10.0 },
                ),
                row(
                    Key::Grid,
                    "load and time",
                    "grid",
                    "",
                    limits::GRID,
                    Nudge::Linear { step: 8.0 },
                ),
                row(
                    Key::PressureMin,
                    "load and time",
                    "pbar min",
                    "Pa",
                    limits::MEAN_PRESSURE,
                    Nudge::Log { seed: 1e5 },
                ),
                row(
                    Key::PressureMax,
                    "load and time",
                    "pbar max",
                    "Pa",
                    limits::MEAN_PRESSURE,
                    Nudge::Log { seed: 1e8 },
                ),
                row(
                    Key::PressurePoints,
                    "load and time",
                    "points",
                    "",
                    limits::SWEEP_POINTS,
                    Nudge::Linear { step: 10.0 },
                ),
                row(
                    Key::PressureScale,
                    "load and time",
                    "scale",
                    "",
                    limits::SWEEP_POINTS,
                    Nudge::Choice(SCALES),
                ),
            ]);
            for n in 0..preset.spatial.harmonics.len() {
                out.extend([
                    row(
                        Key::Amplitude(n),
                        "harmonics",
                        "A",
                        "m",
                        limits::AMPLITUDE,
                        Nudge::Log { seed: 1e-7 },
                    ),
                    row(
                        Key::WavenumberX(n),
                        "harmonics",
                        "wx",
                        "rad/m",
                        limits::WAVENUMBER,
                        Nudge::Log { seed: 1e3 },
                    ),
                    row(
                        Key::WavenumberY(n),
                        "harmonics",
                        "wy",
                        "rad/m",
                        limits::WAVENUMBER,
                        Nudge::Log { seed: 1e3 },
                    ),
                    row(
                        Key::PhaseX(n),
                        "harmonics",
                        "rho_x",
                        "rad",
                        limits::PHASE,
                        Nudge::Linear { step: 0.05 },
                    ),
                    row(
                        Key::PhaseY(n),
                        "harmonics",
                        "rho_y",
                        "rad",
                        limits::PHASE,
                        Nudge::Linear { step: 0.05 },
                    ),
                ]);
            }
        }
    }
    out
}

/// The number a row shows (the model as its index).
pub fn get(preset: &Preset, key: Key) -> f64 {
    let h = |n: usize| -> &Harmonic { &preset.spatial.harmonics[n] };
    match key {
        Key::YoungsModulus => preset.material.youngs_modulus,
        Key::PoissonRatio => preset.material.poisson_ratio,
        Key::Thickness => preset.material.thickness,
        Key::Friction => preset.friction.coefficient,
        Key::Adhesion => preset.friction.adhesion,
        Key::Wear => preset.wear,
        Key::Model => Model::ALL
            .iter()
            .position(|m| *m == preset.plane.model)
            .unwrap_or(0) as f64,
        Key::Radius => preset.plane.radius,
        Key::Load => preset.plane.load,
        Key::LoadMin => preset.plane.sweep.min,
        Key::LoadMax => preset.plane.sweep.max,
        Key::LoadPoints => preset.plane.sweep.points as f64,
        Key::LoadScale => spacing_index(preset.plane.sweep.spacing),
        Key::PressureMin => preset.spatial.sweep.min,
        Key::PressureMax => preset.spatial.sweep.max,
        Key::PressurePoints => preset.spatial.sweep.points as f64,
        Key::PressureScale => spacing_index(preset.spatial.sweep.spacing),
        Key::MeanPressure => preset.spatial.mean_pressure,
        Key::Speed => preset.spatial.sliding_speed,
        Key::Time => preset.spatial.time,
        Key::Duration => preset.spatial.duration,
        Key::Grid => preset.spatial.grid as f64,
        Key::Amplitude(n) => h(n).amplitude,
        Key::WavenumberX(n) => h(n).wavenumber_x,
        Key::WavenumberY(n) => h(n).wavenumber_y,
        Key::PhaseX(n) => h(n).phase_x,
        Key::PhaseY(n) => h(n).phase_y,
    }
}

/// The row's value as text, with SI prefixes.
pub fn show(preset: &Preset, r: &Row) -> String {
    match (r.key, r.nudge) {
        (_, Nudge::Choice(names)) => names[get(preset, r.key) as usize].to_string(),
        (Key::Grid | Key::LoadPoints | Key::PressurePoints, _) => format!("{}", get(preset, r.key)),
        _ => format_si(get(preset, r.key), r.unit),
    }
}

/// Sets a row's value on a copy of the preset; Err says what is allowed. The last valid value
/// stays in force on error (the caller keeps its preset).
pub fn set(preset: &Preset, r: &Row, value: f64) -> Result<Preset, String> {
    if !matches!(r.nudge, Nudge::Choice(_)) {
        r.limit.check(r.label, value)?;
    }
    let mut p = preset.clone();
    match r.key {
        Key::YoungsModulus => p.material.youngs_modulus = value,
        Key::PoissonRatio => p.material.poisson_ratio = value,
        Key::Thickness => {
            if value.is_infinite() && p.problem == Problem::Plane && p.plane.model != Model::Wide {
                return Err(format!(
                    "h = inf is a half-plane, which the {} model cannot take: switch the model with m first",
                    p.plane.model.name()
                ));
            }
            p.material.thickness = value
        }
        Key::Friction => p.friction.coefficient = value,
        Key::Adhesion => p.friction.adhesion = value,
        Key::Wear => p.wear = value,
        Key::Model => {
            let model = Model::ALL[(value as usize) % Model::ALL.len()];
            if model != Model::Wide && p.material.is_half_space() {
                return Err(format!(
                    "the {} model needs a finite thickness h: set h first",
                    model.name()
                ));
            }
            p.plane.model = model;
        }
        Key::Radius => p.plane.radius = value,
        Key::Load => p.plane.load = value,
        Key::LoadMin => p.plane.sweep.min = value,
        Key::LoadMax => p.plane.sweep.max = value,
        Key::LoadPoints => p.plane.sweep.points = value as usize,
        Key::LoadScale => p.plane.sweep.spacing = spacing(value),
        Key::PressureMin => p.spatial.sweep.min = value,
        Key::PressureMax => p.spatial.sweep.max = value,
        Key::PressurePoints => p.spatial.sweep.points = value as usize,
        Key::PressureScale => p.spatial.sweep.spacing = spacing(value),
        Key::MeanPressure => p.spatial.mean_pressure = value,
        Key::Speed => p.spatial.sliding_speed = value,
        Key::Time => p.spatial.time = value,
        Key::Duration => p.spatial.duration = value,
        Key::Grid => p.spatial.grid = value as usize,
        Key::Amplitude(n) => with_harmonic(&mut p, n, |h| h.amplitude = value),
        Key::WavenumberX(n) => with_harmonic(&mut p, n, |h| h.wavenumber_x = value),
        Key::WavenumberY(n) => with_harmonic(&mut p, n, |h| h.wavenumber_y = value),
        Key::PhaseX(n) => with_harmonic(&mut p, n, |h| h.phase_x = value),
        Key::PhaseY(n) => with_harmonic(&mut p, n, |h| h.phase_y = value),
    }
    p.plane
        .sweep
        .check_order(["P min", "P max"], |v| format_si(v, "N/m"))?;
    p.spatial
        .sweep
        .check_order(["pbar min", "pbar max"], |v| format_si(v, "Pa"))?;
    if p.problem == Problem::Spatial {
        wearlab::physics::spatial::validate_harmonics(&p.spatial.harmonics).map_err(|e| {
            e.to_string()
                .trim_start_matches("invalid input: ")
                .to_string()
        })?;
    }
    Ok(p)
}

fn with_harmonic(p: &mut Preset, n: usize, f: impl FnOnce(&mut Harmonic)) {
    f(&mut p.spatial.harmonics[n]);
}

/// The nudged value (`dir` = +1 or -1, `large` for Shift).
pub fn nudged(preset: &Preset, r: &Row, dir: f64, large: bool) -> f64 {
    let v = get(preset, r.key);
    match r.nudge {
        Nudge::Log { seed } => {
            if v == 0.0 {
                if dir > 0.0 { seed } else { 0.0 }
            } else if v.is_infinite() {
                v
            } else {
                let factor: f64 = if large { 2.0 } else { 1.1 };
                v * factor.powf(dir)
            }
        }
        Nudge::Linear { step } => {
            let s = if large { 10.0 * step } else { step };
            let next = v + dir * s;
            // land on whole steps so repeated nudges read cleanly
            (next / step).round() * step
        }
        Nudge::Choice(names) => {
            let n = names.len() as f64;
            (v + if dir > 0.0 { 1.0 } else { n - 1.0 }) % n
        }
    }
}
