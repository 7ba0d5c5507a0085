//! Values a preset allows but that look like a unit mistake (a millimetre written as a metre, a
//! specific wear rate in mm^3/(N m) written as 1/Pa), and harmonics that vanish: warnings, not
//! refusals. The thresholds sit far outside what tribometer tests and the literature report, so
//! a warning is rare for a value that was meant.

use crate::physics::spatial::harmonic::Harmonic;
use crate::preset::{Key, Preset, Problem};
use crate::units::format_si;

/// One plausibility rule: the parameter's preset key, when its value (SI) is suspicious, and why.
struct Rule {
    key: &'static str,
    suspicious: fn(f64) -> bool,
    why: &'static str,
}

/// Sliding of 1 m at 1 MPa wears k * 1e6 Pa * 1 m of height (Archard: h = k p s); over 1 mm is
/// wear no test runs for long, and it is what a specific wear rate in mm^3/(N m) (1 mm^3/(N m) =
/// 1e-9 1/Pa) gives when written as 1/Pa.
const RULES: &[Rule] = &[
    Rule {
        key: "wear.coefficient",
        suspicious: |k| k * 1e6 * 1.0 > 1e-3,
        why: "more than 1 mm of wear per metre of sliding at 1 MPa: was a specific wear rate in \
              mm3/Nm written as 1/Pa? (write \"... mm3/Nm\"; 1 mm3/Nm = 1e-9 1/Pa)",
    },
    Rule {
        key: "material.youngs_modulus",
        suspicious: |e| e < 1e3,
        why: "a modulus under 1 kPa is softer than any gel: was MPa or GPa meant? (write \"3 GPa\")",
    },
    Rule {
        key: "material.youngs_modulus",
        suspicious: |e| e > 1.2e12,
        why: "a modulus above 1.2 TPa is stiffer than diamond (1.05 TPa): was kPa or MPa written \
              as Pa?",
    },
    Rule {
        key: "material.thickness",
        suspicious: |h| h > 1.0 && h.is_finite(),
        why: "a layer over 1 m thick: was a thickness in mm written in m? (write \"2 mm\"; inf is \
              the half-space)",
    },
    Rule {
        key: "plane.radius",
        suspicious: |r| r > 10.0,
        why: "a punch radius over 10 m: was mm written as m? (write \"50 mm\")",
    },
    Rule {
        key: "friction.coefficient",
        suspicious: |mu| mu > 2.0,
        why: "a friction coefficient above 2: measured values stay below about 1.5 outside clean \
              metals in vacuum",
    },
    Rule {
        key: "friction.adhesion",
        suspicious: |t| t > 1e9,
        why: "an adhesive shear stress above 1 GPa exceeds the shear strength of nearly every \
              solid: was kPa or MPa meant?",
    },
    Rule {
        key: "spatial.mean_pressure",
        suspicious: |p| p > 1e10,
        why: "a mean pressure above 10 GPa exceeds the hardness of nearly every solid: was kPa or \
              MPa meant?",
    },
    Rule {
        key: "spatial.sliding_speed",
        suspicious: |v| v > 100.0,
        why: "sliding faster than 100 m/s: was mm/s written as m/s?",
    },
    Rule {
        key: "spatial.harmonics.N.amplitude",
        suspicious: |a| a > 1e-3,
        why: "a waviness amplitude over 1 mm: was um written as m? (write \"40 nm\", \"2 um\")",
    },
];

/// Why `value` of the parameter `key` (a harmonic's with `N`) looks like a unit mistake, if it
/// does.
pub(super) fn suspicious(key: &str, value: f64) -> Option<&'static str> {
    RULES
        .iter()
        .find(|r| r.key == key && (r.suspicious)(value))
        .map(|r| r.why)
}

/// The warnings of `settings` (`KEY=VALUE`, as `Preset::with_settings` applies them to `preset`)
/// whose values look like a unit mistake, as a preset file's would be warned of: "--set
/// wear.coefficient=1e-7: k = 1e-7: ... was a specific wear rate ...".
pub fn settings_warnings<S: AsRef<str>>(preset: &Preset, settings: &[S]) -> Vec<String> {
    (settings.iter().map(AsRef::as_ref))
        .filter_map(|setting| {
            let (text, _) = setting.split_once('=')?;
            let key = preset.key(text).ok()?;
            let value = preset.get(key).ok()?;
            let why = suspicious(text.trim(), value)?;
            Some(format!(
                "--set {setting}: {} = {value:e}: {why}",
                key.symbol()
            ))
        })
        .collect()
}

/// A phase within this of a multiple of pi leaves sin(phase) under 1e-9: the harmonic is zero
/// to round-off.
const PHASE_TOLERANCE: f64 = 1e-9;

/// Why a harmonic A sin(wx x + rho_x) sin(wy y + rho_y) is zero everywhere, if it is: a zero
/// wavenumber leaves a constant factor sin(rho), which vanishes when rho is a multiple of pi.
/// The key named is the phase that makes it vanish.
pub(super) fn vanishes(h: &Harmonic) -> Option<(&'static str, String)> {
    let zero = |w: f64, phase: f64| w == 0.0 && phase.sin().abs() < PHASE_TOLERANCE;
    let why = |axis: &str, phase: f64| {
        format!(
            "wavenumber_{axis} = 0 with phase_{axis} = {phase} (a multiple of pi) makes this \
             harmonic zero everywhere (sin(phase_{axis}) = 0): it adds nothing to the punch; \
             use phase_{axis} = 1.5707963267948966 (pi/2) for a wave along the other axis"
        )
    };
    if zero(h.wavenumber_y, h.phase_y) {
        Some(("phase_y", why("y", h.phase_y)))
    } else if zero(h.wavenumber_x, h.phase_x) {
        Some(("phase_x", why("x", h.phase_x)))
    } else {
        None
    }
}

/// The warnings of a preset's values, as the explorer shows them (the file's own, with their
/// lines, are `load_with_warnings`'): each value of its problem that looks like a unit mistake,
/// named by its symbol (`k = 1.000e-07 1/Pa: more than 1 mm of wear ...`), and each harmonic that
/// vanishes.
pub fn warnings(preset: &Preset) -> Vec<String> {
    let mut out = Vec::new();
    for key in Key::all(preset) {
        let param = key.param();
        let Ok(value) = preset.get(key) else {
            continue;
        };
        if let Some(why) = suspicious(param.key, value) {
            let shown = format_si(value, param.unit);
            out.push(format!("{} = {shown}: {why}", key.symbol()));
        }
    }
    if preset.problem == Problem::Spatial {
        for (n, h) in preset.spatial.harmonics.iter().enumerate() {
            if let Some((_, why)) = vanishes(h) {
                out.push(format!("harmonic {}: {why}", n + 1));
            }
        }
    }
    out
}
