//! The yield check in `wearlab solve`: `material.yield_strength` or `material.hardness` (from a
//! preset file or `--set`) add the `yield` block of docs/cli.md, a contact that yields adds a
//! warning on stderr and still exits 0, and a preset without either has no `yield` block. The
//! stresses themselves are verified in tests/plane/plane_yield.rs.

use crate::run::wearlab;
use serde_json::Value;

/// A wide half-plane contact with mu = 0.4 (presets/friction-half-plane.toml).
const PRESET: &str = "presets/friction-half-plane.toml";

fn report(settings: &[&str]) -> (Value, String) {
    let mut args = vec!["solve", PRESET];
    for s in settings {
        args.extend(["--set", s]);
    }
    let (code, out, err) = wearlab(&args);
    assert_eq!(code, 0, "{err}");
    (serde_json::from_str(&out).unwrap(), err)
}

#[test]
fn a_preset_without_strength_has_no_yield_block() {
    let (r, err) = report(&[]);
    assert!(r.get("yield").is_none(), "{r}");
    assert!(!err.contains("yield"), "{err}");
}

#[test]
fn a_strong_strip_reports_its_largest_stress_below_yield_without_a_warning() {
    let (r, err) = report(&["material.yield_strength=10GPa"]);
    let y = &r["yield"];
    assert_eq!(y["strength"], 1e10);
    assert_eq!(y["basis"], "yield_strength");
    assert_eq!(y["yields"], false);
    let (stress, ratio) = (
        y["von_mises_max"].as_f64().unwrap(),
        y["ratio"].as_f64().unwrap(),
    );
    assert!(stress > 0.0 && (ratio - stress / 1e10).abs() < 1e-15, "{y}");
    assert!(y["depth"].as_f64().unwrap() >= 0.0, "{y}");
    let (a, b, x) = (
        r["a"].as_f64().unwrap(),
        r["b"].as_f64().unwrap(),
        y["x"].as_f64().unwrap(),
    );
    assert!((-2.0 * a..=2.0 * b).contains(&x), "{x} outside [-2a, 2b]");
    assert!(!err.contains("yield"), "{err}");
}

#[test]
fn a_weak_strip_yields_with_a_warning_and_exit_0() {
    let (strong, _) = report(&["material.yield_strength=10GPa"]);
    let stress = strong["yield"]["von_mises_max"].as_f64().unwrap();
    // a yield strength just under the largest stress
    let y = format!("material.yield_strength={}", 0.9 * stress);
    let (r, err) = report(&[&y]);
    assert_eq!(r["yield"]["yields"], true);
    assert_eq!(
        r["yield"]["von_mises_max"],
        strong["yield"]["von_mises_max"]
    );
    assert!(
        err.contains("warning: the strip yields: von Mises stress"),
        "{err}"
    );
}

#[test]
fn a_hardness_alone_gives_a_third_of_it_as_the_yield_stress() {
    let (r, _) = report(&["material.hardness=3GPa"]);
    assert_eq!(r["yield"]["strength"], 1e9);
    assert_eq!(r["yield"]["basis"], "hardness / 3");
    // with both, the yield strength is the one judged against
    let (r, _) = report(&["material.hardness=3GPa", "material.yield_strength=2GPa"]);
    assert_eq!(r["yield"]["strength"], 2e9);
}

#[test]
fn a_strength_out_of_range_is_refused_with_what_is_allowed() {
    let (code, _, err) = wearlab(&["solve", PRESET, "--set", "material.yield_strength=-1"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("1e3 <= Y <= 1e11"), "{err}");
    let text = std::fs::read_to_string(PRESET).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("weak.toml");
    let written = text.replace("thickness = inf", "thickness = inf\nhardness = \"2 Pa\"");
    std::fs::write(&path, &written).unwrap();
    let line = written
        .lines()
        .position(|l| l.starts_with("hardness"))
        .unwrap()
        + 1;
    let (code, _, err) = wearlab(&["solve", path.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains(&format!("weak.toml:{line}:")), "{err}");
    assert!(err.contains("1e3 <= H <= 1e12"), "{err}");
}

#[test]
fn a_strength_written_with_units_in_the_file_is_read_and_saved_back() {
    let text = std::fs::read_to_string(PRESET).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("strong.toml");
    let written = text.replace(
        "thickness = inf",
        "thickness = inf\nyield_strength = \"60 MPa\"",
    );
    std::fs::write(&path, written).unwrap();
    let preset = wearlab::preset::load(&path).unwrap();
    assert_eq!(preset.strength.yield_strength, Some(6e7));
    assert_eq!(preset.strength.hardness, None);
    let again = wearlab::preset::parse(&wearlab::preset::to_toml(&preset), &path).unwrap();
    assert_eq!(again.strength, preset.strength);
}
