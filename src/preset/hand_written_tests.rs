//! Presets as people write them by hand: values with units, the refusals and the warnings.

use std::path::Path;

use crate::preset::written::key_in_section;
use crate::preset::{BUNDLED, parse, parse_with_warnings, to_toml};
use crate::units::{prefix, prefixable};

/// `v` written as a decimal of `digits` (".", sign and digits of `{:e}`) times 10^shift, with
/// no exponent: ("6.283185307179586", 2) -> "628.3185307179586".
fn shift_point(mantissa: &str, shift: i32) -> String {
    let (sign, m) = match mantissa.strip_prefix('-') {
        Some(m) => ("-", m),
        None => ("", mantissa),
    };
    let digits: String = m.chars().filter(|c| *c != '.').collect();
    let point = 1 + shift as usize;
    let padded = format!("{digits:0<point$}");
    let (whole, fraction) = padded.split_at(point);
    if fraction.is_empty() {
        format!("{sign}{whole}")
    } else {
        format!("{sign}{whole}.{fraction}")
    }
}

/// The value of `literal` (SI) as a text with units: with an SI prefix where the unit takes
/// one ("6.283185307179586 km"), a wear coefficient in mm3/Nm, else the unit after the number.
fn with_units(literal: &str, unit: &str) -> String {
    let v: f64 = literal.parse().unwrap();
    let sci = format!("{v:e}");
    let (mantissa, exp) = sci.split_once('e').unwrap();
    let exp: i32 = exp.parse().unwrap();
    if v == 0.0 || unit.is_empty() {
        return format!("\"{literal}\"");
    }
    if unit == "1/Pa" {
        return format!("\"{mantissa}e{} mm3/Nm\"", exp + 9);
    }
    if !prefixable(unit) {
        return format!("\"{literal} {unit}\"");
    }
    let k = (3 * exp.div_euclid(3)).clamp(-15, 12);
    format!(
        "\"{} {}{unit}\"",
        shift_point(mantissa, exp - k),
        prefix(k).unwrap()
    )
}

/// The preset's text with every number of a parameter that has a unit rewritten with units
/// (the description and counts untouched).
fn rewritten(text: &str) -> String {
    let mut out = String::new();
    let mut before = String::new();
    let mut in_header = true;
    for line in text.lines() {
        if line.starts_with('[') {
            in_header = false;
        }
        let mut written = line.to_string();
        if !in_header {
            for part in line.split([',', '{', '}']) {
                let Some((key, value)) = part.split_once('=') else {
                    continue;
                };
                let (key, value) = (key.trim(), value.trim());
                let Some(p) = key_in_section(&before, key) else {
                    continue;
                };
                if p.is_whole()
                    || p.limit().is_none()
                    || !value.parse::<f64>().is_ok_and(f64::is_finite)
                {
                    continue;
                }
                let from = format!("{key} = {value}");
                let to = format!("{key} = {}", with_units(value, p.unit));
                written = written.replacen(&from, &to, 1);
            }
        }
        out += &written;
        out.push('\n');
        before += line;
        before.push('\n');
    }
    out
}

#[test]
fn every_bundled_preset_with_units_loads_bit_identically() {
    let mut rewritten_values = 0;
    for b in BUNDLED {
        let with_units = rewritten(b.text);
        rewritten_values += with_units.matches("= \"").count() - b.text.matches("= \"").count();
        // named as `Bundled::load` names it, so that a bundled data file is found
        let path = Path::new("presets").join(b.file);
        let si = parse(b.text, &path).unwrap();
        let units = parse(&with_units, &path).unwrap_or_else(|e| panic!("{e}\n{with_units}"));
        // the shortest round-trip text of every value is the same: the same bits
        assert_eq!(to_toml(&units), to_toml(&si), "{}:\n{with_units}", b.file);
        assert_eq!(units, si, "{}", b.file);
    }
    // the finite numbers of parameters in the bundled files: a new bundled preset changes it
    assert_eq!(rewritten_values, 269);
    let sample = rewritten(egg_box());
    for line in [
        "youngs_modulus = \"200 GPa\"",
        "coefficient = \"1e-7 mm3/Nm\"",
        "amplitude = \"100 nm\"",
        "mean_pressure = \"200 MPa\"",
        "wavenumber_x = \"6283.185307179586 rad/m\"",
    ] {
        assert!(sample.contains(line), "{line}\n{sample}");
    }
}

/// The text of the bundled spatial preset `jgh-egg-box.toml`.
fn egg_box() -> &'static str {
    BUNDLED
        .iter()
        .find(|b| b.file == "jgh-egg-box.toml")
        .unwrap()
        .text
}

const PLANE: &str = "schema = 1\nproblem = \"plane\"\n\n[material]\nyoungs_modulus = 3.0e9\n\
    poisson_ratio = 0.3\nthickness = 1.0e-3\n\n[friction]\ncoefficient = 0.3\n\n[wear]\n\
    coefficient = 2.0e-11\n\n[plane]\nmodel = \"wide\"\nradius = 0.05\nload = 1.0e4\n";

fn error_of(text: &str) -> String {
    parse(text, Path::new("lab.toml")).unwrap_err().to_string()
}

#[test]
fn values_with_units_are_read_as_the_form_reads_them() {
    let text = PLANE
        .replace("thickness = 1.0e-3", "thickness = \"2 mm\"")
        .replace("youngs_modulus = 3.0e9", "youngs_modulus = \"0.5 GPa\"")
        .replace("coefficient = 2.0e-11", "coefficient = \"3e-5 mm3/Nm\"");
    let p = parse(&text, Path::new("lab.toml")).unwrap();
    assert_eq!(
        (p.material.thickness, p.material.youngs_modulus, p.wear),
        (2e-3, 5e8, 3e-14)
    );
}

#[test]
fn refusals_name_the_line_and_give_an_example_of_the_key_s_kind() {
    assert_eq!(
        error_of(&PLANE.replace("thickness = 1.0e-3", "thickness = 2 mm")),
        "lab.toml:7: thickness = 2 mm: a value with units is written in quotes: write \
         thickness = \"2 mm\" or 2e-3"
    );
    assert_eq!(
        error_of(&PLANE.replace("thickness = 1.0e-3", "thickness = \"2 GPa\"")),
        "lab.toml:7: thickness = \"2 GPa\": '2 GPa': unknown unit; write a plain number or a \
         prefixed m (e.g. km, Mm); e.g. thickness = \"1 mm\" or 1e-3"
    );
    assert_eq!(
        error_of(&PLANE.replace("youngs_modulus = 3.0e9", "youngs_modulus = true")),
        "lab.toml:5: youngs_modulus: expected a number in SI units or a text with units (e.g. \
         youngs_modulus = \"1 GPa\" or 1e9), found the value true"
    );
    assert_eq!(
        error_of(&PLANE.replace("load = 1.0e4", "load = \"-3 kN/m\"")),
        format!(
            "lab.toml:18: {}",
            crate::physics::limits::LINE_LOAD
                .check("load", -3000.0)
                .unwrap_err()
        )
    );
}

#[test]
fn a_grid_out_of_range_is_refused_at_its_line() {
    let spatial = egg_box();
    let line = 1 + spatial.lines().position(|l| l == "grid = 64").unwrap();
    for grid in ["4", "99999", "64.5", "\"12 m\""] {
        let err = error_of(&spatial.replace("grid = 64", &format!("grid = {grid}")));
        assert!(
            err.starts_with(&format!("lab.toml:{line}: ")),
            "{grid}: {err}"
        );
    }
}

#[test]
fn a_grid_too_coarse_for_partial_contact_is_refused_when_read_and_when_set() {
    // the partial-contact solver's 16 nodes per wavelength: no harmonic is solved on fewer
    let spatial = egg_box();
    let line = 1 + spatial.lines().position(|l| l == "grid = 64").unwrap();
    let why = "grid = 12 is too coarse for partial contact: every harmonic needs at least 16 \
               nodes per wavelength, so grid >= 16";
    assert_eq!(
        error_of(&spatial.replace("grid = 64", "grid = 12")),
        format!("lab.toml:{line}: {why}")
    );
    let preset = parse(spatial, Path::new("lab.toml")).unwrap();
    assert_eq!(
        preset.with_settings(&["spatial.grid=12"]).unwrap_err(),
        format!("the values set break a rule: {why}")
    );
    assert!(preset.with_settings(&["spatial.grid=16"]).is_ok());
}

fn warnings_of(text: &str) -> Vec<String> {
    let (_, warnings) = parse_with_warnings(text, Path::new("lab.toml")).unwrap();
    warnings.iter().map(|w| w.to_string()).collect()
}

#[test]
fn no_bundled_preset_warns() {
    for b in BUNDLED {
        let path = Path::new("presets").join(b.file);
        let (_, warnings) = parse_with_warnings(b.text, &path).unwrap();
        assert!(warnings.is_empty(), "{}: {warnings:?}", b.file);
    }
}

#[test]
fn each_value_that_looks_like_a_unit_mistake_warns_at_its_line() {
    // (the line as written in PLANE or a spatial preset, the suspicious line, a word of the why)
    let plane = [
        ("coefficient = 2.0e-11", "coefficient = 3.0e-5", "mm3/Nm"),
        ("youngs_modulus = 3.0e9", "youngs_modulus = 500", "1 kPa"),
        (
            "youngs_modulus = 3.0e9",
            "youngs_modulus = 3.0e12",
            "diamond",
        ),
        ("thickness = 1.0e-3", "thickness = 2", "thickness in mm"),
        ("radius = 0.05", "radius = 50", "punch radius"),
        (
            "coefficient = 0.3",
            "coefficient = 3",
            "friction coefficient",
        ),
        (
            "coefficient = 0.3",
            "coefficient = 0.3\nadhesion = 2.0e9",
            "shear strength",
        ),
    ];
    for (from, to, why) in plane {
        let text = PLANE.replacen(from, to, 1);
        let line = 1 + text
            .lines()
            .position(|l| to.ends_with(l) && !l.is_empty())
            .unwrap();
        let warnings = warnings_of(&text);
        assert_eq!(warnings.len(), 1, "{to}: {warnings:?}");
        assert!(
            warnings[0].starts_with(&format!("lab.toml:{line}: ")) && warnings[0].contains(why),
            "{to}: {warnings:?}"
        );
    }
    let spatial = egg_box();
    for (from, to, why) in [
        (
            "mean_pressure = 2.0e8",
            "mean_pressure = 2.0e11",
            "hardness",
        ),
        ("sliding_speed = 1.0", "sliding_speed = 500.0", "mm/s"),
        (
            "amplitude = 1.0e-7",
            "amplitude = 0.1",
            "amplitude over 1 mm",
        ),
    ] {
        let text = spatial.replacen(from, to, 1);
        let line = 1 + text.lines().position(|l| l == to).unwrap();
        let warnings = warnings_of(&text);
        assert_eq!(warnings.len(), 1, "{to}: {warnings:?}");
        assert!(
            warnings[0].starts_with(&format!("lab.toml:{line}: ")) && warnings[0].contains(why),
            "{to}: {warnings:?}"
        );
    }
}

#[test]
fn a_harmonic_that_vanishes_warns_at_its_phase() {
    let spatial = egg_box();
    let cases = [
        (
            "wavenumber_y = 6283.185307179586",
            "wavenumber_y = 0.0",
            "phase_y",
            "0.0",
        ),
        (
            "wavenumber_x = 6283.185307179586",
            "wavenumber_x = 0.0",
            "phase_x",
            "3.141592653589793",
        ),
    ];
    for (from, to, phase, value) in cases {
        let text = spatial.replacen(from, to, 1).replacen(
            &format!("{phase} = 1.5707963267948966"),
            &format!("{phase} = {value}"),
            1,
        );
        let line = 1 + text
            .lines()
            .position(|l| l.starts_with(&format!("{phase} =")))
            .unwrap();
        let warnings = warnings_of(&text);
        assert_eq!(warnings.len(), 1, "{warnings:?}");
        assert!(
            warnings[0].starts_with(&format!("lab.toml:{line}: wavenumber_")),
            "{warnings:?}"
        );
        assert!(warnings[0].contains("zero everywhere"), "{warnings:?}");
        // at pi/2 the same harmonic is a 1-D wave: no warning
        assert!(warnings_of(&spatial.replacen(from, to, 1)).is_empty());
    }
}

#[test]
fn none_clears_an_optional_key_and_only_one() {
    let preset = crate::preset::bundled("polymer-coating.toml")
        .unwrap()
        .unwrap();
    let given = preset
        .with_settings(&["material.hardness=15MPa", "material.yield_strength=20MPa"])
        .unwrap();
    assert_eq!(given.strength.hardness, Some(15e6));
    let cleared = given
        .with_settings(&["material.hardness=none", "material.yield_strength= none"])
        .unwrap();
    assert_eq!(cleared.strength, preset.strength);
    assert_eq!(cleared.strength.yield_strength, None);
    // p0 is optional for the linear law; a nonlinear law needs it, and says so
    let squared = preset
        .with_settings(&["wear.exponent=2", "wear.reference_pressure=1MPa"])
        .unwrap();
    let why = squared
        .with_settings(&["wear.reference_pressure=none"])
        .unwrap_err();
    assert!(why.contains("needs wear.reference_pressure"), "{why}");
    // a key that is not optional has no none
    let why = preset
        .with_settings(&["material.thickness=none"])
        .unwrap_err();
    assert!(why.starts_with("material.thickness=none: "), "{why}");
    assert!(!why.contains("or none"), "{why}");
    let why = preset
        .with_settings(&["material.hardness=soft"])
        .unwrap_err();
    assert!(why.contains("or none to clear it"), "{why}");
}
