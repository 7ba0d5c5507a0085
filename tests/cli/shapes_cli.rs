//! Punch shapes and laws beyond the paper's worked example as a script meets them: a measured
//! profile read relative to its preset, the JSON's `shape` and `profile.shape`, and the refusals
//! (exit 2) that say what is wrong and where.

use std::time::Duration;

use assert_cmd::Command;
use serde_json::Value;

const PRESET: &str = "schema = 1
problem = \"plane\"
[material]
youngs_modulus = 2.0e9
poisson_ratio = 0.4
thickness = 2.0e-5
[friction]
coefficient = 0.2
[wear]
coefficient = 1.0e-11
[plane]
model = \"narrow\"
load = 1.0e4
shape = { kind = \"table\", file = \"worn.csv\" }
";

/// `wearlab solve` on the preset with the profile `csv` beside it: (exit code, stdout, stderr).
fn solve(preset: &str, csv: &str, args: &[&str]) -> (Option<i32>, String, String) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("p.toml"), preset).unwrap();
    std::fs::write(dir.path().join("worn.csv"), csv).unwrap();
    let out = Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .timeout(Duration::from_secs(60))
        .arg("solve")
        .arg(dir.path().join("p.toml"))
        .args(args)
        .output()
        .unwrap();
    let text = |b: &[u8]| String::from_utf8_lossy(b).to_string();
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

/// The profile of a parabola of radius 50 mm over |x| <= 2 mm, 201 rows.
fn parabola_csv() -> String {
    let mut out = String::from("# a parabola of radius 50 mm\nx [m],g [m]\n");
    for i in 0..=200 {
        let x = -2e-3 + 2e-5 * i as f64;
        out += &format!("{x:e},{:e}\n", x * x / 0.1);
    }
    out
}

#[test]
fn a_measured_profile_is_read_beside_its_preset_and_reported() {
    let (code, out, err) = solve(PRESET, &parabola_csv(), &["--points", "5"]);
    assert_eq!(code, Some(0), "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["shape"]["kind"], "table");
    assert_eq!(v["shape"]["file"], "worn.csv");
    assert_eq!(v["shape"]["range"][1].as_f64(), Some(2e-3));
    // the same punch as a parabola: the spline through 201 points answers within 1e-6
    let (_, parabola, _) = solve(
        &PRESET.replace(
            "shape = { kind = \"table\", file = \"worn.csv\" }",
            "radius = 0.05",
        ),
        "",
        &["--points", "5"],
    );
    let p: Value = serde_json::from_str(&parabola).unwrap();
    let (a, b) = (v["a"].as_f64().unwrap(), p["a"].as_f64().unwrap());
    assert!((a / b - 1.0).abs() < 1e-6, "{a} vs {b}");
    let x = v["profile"]["x"][4].as_f64().unwrap();
    let g = v["profile"]["shape"][4].as_f64().unwrap();
    assert!((g - x * x / 0.1).abs() < 1e-6 * g, "{g} at {x}");
}

#[test]
fn hostile_profiles_and_laws_are_refused_in_words() {
    for (csv, message) in [
        (
            "x [m],g [m]\n0,0\n",
            "worn.csv:2: the profile has 1 row(s): at least 3",
        ),
        (
            "x [m],g [m]\n0,0\n2e-3,1e-6\n1e-3,1e-6\n",
            "worn.csv:4: x = 0.001 m does not exceed",
        ),
        (
            "x [m],g [m]\n0,0\n1e-3,NaN\n2e-3,0\n",
            "worn.csv:3: '1e-3,NaN' is not two finite numbers",
        ),
        ("x,g\n0,0\n", "worn.csv:1: the first row is 'x,g'"),
    ] {
        let (code, _, err) = solve(PRESET, csv, &[]);
        assert_eq!(code, Some(2), "{err}");
        assert!(err.contains(message), "{err}");
    }
    // the contact runs off a profile 0.2 mm long
    let short = "x [m],g [m]\n-1e-4,1e-7\n0,0\n1e-4,1e-7\n";
    let (code, _, err) = solve(PRESET, short, &[]);
    assert_eq!(code, Some(3), "{err}");
    assert!(err.contains("runs off the measured profile"), "{err}");
    // the wide model answers a table by the general solver; this contact, many thicknesses wide,
    // leaves the punch tip there: exit 3 in words
    let (code, _, err) = solve(PRESET, &parabola_csv(), &["--set", "plane.model=wide"]);
    assert!(
        code == Some(0) || (code == Some(3) && err.contains("fails a check")),
        "{err}"
    );
    for (set, message) in [
        ("friction.shear_strength=0", "out of range"),
        ("wear.exponent=2", "needs wear.reference_pressure"),
    ] {
        let (code, _, err) = solve(PRESET, &parabola_csv(), &["--set", set]);
        assert_eq!(code, Some(2), "{set}: {err}");
        assert!(err.contains(message), "{set}: {err}");
    }
    let sharp = PRESET
        .replace(
            "shape = { kind = \"table\", file = \"worn.csv\" }",
            "shape = { kind = \"flat\", half_width = 1e-3, edge_radius = 0.0 }",
        )
        .replace(
            "coefficient = 1.0e-11",
            "coefficient = 1.0e-11\nexponent = 2.0\nreference_pressure = 1.0e6",
        );
    let (code, _, err) = solve(&sharp, "", &[]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("no steady solution"), "{err}");
}

#[test]
fn the_parabolas_radius_is_no_input_of_another_shape() {
    // setting it would change nothing: refused with the reason, not ignored
    let (code, _, err) = solve(PRESET, &parabola_csv(), &["--set", "plane.radius=0.1"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("plane.radius is the parabola's radius; this preset's punch is a table shape"),
        "{err}"
    );
    // and the explorer's form has no R row for it
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("worn.csv"), parabola_csv()).unwrap();
    let path = dir.path().join("p.toml");
    std::fs::write(&path, PRESET).unwrap();
    let preset = wearlab::preset::load(&path).unwrap();
    let keys = wearlab::preset::Key::all(&preset);
    assert!(keys.iter().all(|k| k.param().key != "plane.radius"));
}

#[test]
fn sharp_corners_are_answered_with_null_energies_and_the_reason() {
    let sharp = PRESET.replace(
        "shape = { kind = \"table\", file = \"worn.csv\" }",
        "shape = { kind = \"flat\", half_width = 1e-3, edge_radius = 0.0 }",
    );
    for (model, thickness) in [("wide", "inf"), ("narrow", "2.0e-5"), ("strip", "2.0e-5")] {
        let preset = sharp
            .replace("model = \"narrow\"", &format!("model = \"{model}\""))
            .replace("thickness = 2.0e-5", &format!("thickness = {thickness}"));
        let (code, out, err) = solve(&preset, "", &["--points", "5"]);
        assert_eq!(code, Some(0), "{model}: {err}");
        let v: Value = serde_json::from_str(&out).unwrap();
        let energy = &v["energy"];
        assert!(energy["I"].is_null() && energy["J"].is_null(), "{energy}");
        assert!(energy["friction_loss"].is_null(), "{energy}");
        assert!(
            energy["note"].as_str().unwrap().contains("sharp corners"),
            "{energy}"
        );
        // mu* = mu and psi = 0 on a flat face; T = Q1 = mu P + 2 c tau0 (tau0 = 0 here)
        assert_eq!(v["mu_star"].as_f64(), Some(0.2));
        assert_eq!(v["psi"].as_f64(), Some(0.0));
        assert_eq!(energy["external"].as_f64(), Some(0.2 * 1e4));
        // the Winkler strip's pressure is bounded: its wear loss k int q2^2 has a number
        assert_eq!(energy["wear_loss"].is_null(), model != "narrow", "{energy}");
    }
}

#[test]
fn a_repeated_x_in_a_profile_is_refused_at_its_row() {
    let csv = "x [m],g [m]\n-1e-3,1e-6\n0,0\n0,1e-7\n1e-3,1e-6\n";
    let (code, _, err) = solve(PRESET, csv, &[]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("worn.csv:4: x = 0 m does not exceed the previous row's x = 0 m"),
        "{err}"
    );
}

#[test]
fn a_tenth_power_punch_of_a_tiny_radius_is_answered_in_words_in_bounded_time() {
    // g = (R/n)(|x|/R)^n with n = 10 and R = 1 nm: the slope (|x|/R)^9 passes 1 within 1 nm of
    // the tip, so no contact that carries 1e4 N/m keeps linear elasticity's small slopes; every
    // model must end in words (exit 2 or 3), never a panic, a NaN or a hang (each run is killed
    // after `solve`'s 60 s)
    let power = PRESET.replace(
        "shape = { kind = \"table\", file = \"worn.csv\" }",
        "shape = { kind = \"power\", radius = 1.0e-9, exponent = 10.0 }",
    );
    for model in ["wide", "narrow", "strip"] {
        let preset = power.replace("model = \"narrow\"", &format!("model = \"{model}\""));
        let start = std::time::Instant::now();
        let (code, out, err) = solve(&preset, "", &[]);
        let took = start.elapsed();
        assert!(matches!(code, Some(2 | 3)), "{model}: {code:?} {out} {err}");
        assert!(
            !err.contains("panicked") && !err.contains("NaN"),
            "{model}: {err}"
        );
        assert!(err.trim().len() > 20, "{model}: {err}");
        assert!(took < Duration::from_secs(30), "{model}: {took:?}");
    }
}
