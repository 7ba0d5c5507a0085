//! `wearlab solve`: the JSON contract of design.md and the exit codes.

use assert_cmd::Command;
use serde_json::Value;

fn wearlab() -> Command {
    Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
}

#[test]
fn plane_json_has_every_key_of_the_contract() {
    let out = wearlab()
        .args(["solve", "presets/wear-dominated.toml"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    for key in [
        "problem",
        "model",
        "load",
        "normal_force",
        "tangential_force",
        "a",
        "b",
        "theta",
        "gamma",
        "psi",
        "delta_g",
        "mu_star",
        "energy",
        "validity",
        "profile",
        "sweep",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    assert_eq!(v["problem"], "plane");
    assert_eq!(v["model"], "wide");
    for key in ["I", "J", "residual"] {
        assert!(v["energy"][key].is_number(), "energy.{key}");
    }
    for key in ["ok", "contact_width_over_thickness", "warnings"] {
        assert!(v["validity"].get(key).is_some(), "validity.{key}");
    }
    for key in ["x", "pressure", "shear", "wear_rate", "wear"] {
        assert_eq!(
            v["profile"][key].as_array().unwrap().len(),
            201,
            "profile.{key}"
        );
    }
    for key in ["load", "mu_star", "a", "b", "normal_force"] {
        assert_eq!(v["sweep"][key].as_array().unwrap().len(), 60, "sweep.{key}");
    }
    // wear dominates: theta < 0 and mu* > mu = 0.2
    assert!(v["theta"].as_f64().unwrap() < 0.0);
    assert!(v["mu_star"].as_f64().unwrap() > 0.2);
}

#[test]
fn narrow_model_has_null_theta_and_gamma() {
    let out = wearlab()
        .args(["solve", "presets/thin-strip-winkler.toml", "--points", "5"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(v["theta"].is_null() && v["gamma"].is_null());
    assert_eq!(v["model"], "narrow");
    assert_eq!(v["profile"]["x"].as_array().unwrap().len(), 5);
}

#[test]
fn csv_is_the_profile_table() {
    let out = wearlab()
        .args([
            "solve",
            "presets/hertz-check.toml",
            "--format",
            "csv",
            "--points",
            "11",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "x,pressure,shear,wear_rate,wear");
    assert_eq!(lines.len(), 12);
    let mid: Vec<f64> = lines[6].split(',').map(|c| c.parse().unwrap()).collect();
    assert_eq!(mid[0], 0.0);
    assert!(mid[1] > 0.0);
}

#[test]
fn invalid_input_exits_with_2_and_names_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.toml");
    let text = std::fs::read_to_string("presets/hertz-check.toml")
        .unwrap()
        .replace("poisson_ratio = 0.3", "poisson_ratio = 0.7");
    std::fs::write(&path, text).unwrap();
    let out = wearlab().arg("solve").arg(&path).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("bad.toml:13: poisson_ratio = 0.7 is out of range: allowed 0 <= nu < 0.5"),
        "{err}"
    );
    assert!(out.stdout.is_empty());
    // a missing file and a bad flag are invalid input too
    assert_eq!(
        wearlab()
            .args(["solve", "nope.toml"])
            .output()
            .unwrap()
            .status
            .code(),
        Some(2)
    );
    assert_eq!(
        wearlab()
            .args(["solve", "presets/hertz-check.toml", "--points", "1"])
            .output()
            .unwrap()
            .status
            .code(),
        Some(2)
    );
}

#[test]
fn unsolvable_input_exits_with_3_and_says_why() {
    // Wear dominates (theta < 0) and friction is large: P(L) of the wide model peaks and falls,
    // so a large enough load has no wide-model contact.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("overload.toml");
    let text = std::fs::read_to_string("presets/wear-dominated.toml")
        .unwrap()
        .replace("coefficient = 0.2", "coefficient = 5.0")
        .replace("coefficient = 3.7e-10", "coefficient = 1.0e-8")
        .replace("load = 1.0e3", "load = 1.0e9");
    std::fs::write(&path, text).unwrap();
    let out = wearlab().arg("solve").arg(&path).output().unwrap();
    assert_eq!(out.status.code(), Some(3));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("the wide-strip model has no contact at P = 1.0000e9 N/m: it carries at most"),
        "{err}"
    );
}

#[test]
fn spatial_json_has_every_key_of_the_contract() {
    let out = wearlab()
        .args([
            "solve",
            "presets/dispersion.toml",
            "--time",
            "100",
            "--probe",
            "0,0",
            "--probe",
            "1e-3,2e-4",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    for key in [
        "problem",
        "time",
        "mean_pressure",
        "load",
        "mu_star",
        "psi",
        "harmonics",
        "contact",
        "probes",
        "sweep",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    assert_eq!(
        (v["problem"].as_str(), v["time"].as_f64()),
        (Some("spatial"), Some(100.0))
    );
    let harmonics = v["harmonics"].as_array().unwrap();
    assert_eq!(harmonics.len(), 4);
    for key in [
        "k",
        "decay_rate",
        "drift_velocity",
        "phase_rate",
        "phase_lead",
        "pressure_per_amplitude",
        "amplitude",
        "phase_x",
        "phase_y",
    ] {
        assert!(harmonics[0][key].is_number(), "harmonics[].{key}");
    }
    for key in ["min_pressure", "at", "lower_bound", "complete", "exact"] {
        assert!(v["contact"].get(key).is_some(), "contact.{key}");
    }
    assert_eq!(v["contact"]["exact"], true);
    let probes = v["probes"].as_array().unwrap();
    assert_eq!(probes.len(), 2);
    assert_eq!(
        (probes[1]["x"].as_f64(), probes[1]["y"].as_f64()),
        (Some(1e-3), Some(2e-4))
    );
    for key in ["pressure", "shear", "shape"] {
        assert!(probes[0][key].is_number(), "probes[].{key}");
    }
    for key in ["mean_pressure", "load", "mu_star"] {
        assert_eq!(v["sweep"][key].as_array().unwrap().len(), 60, "sweep.{key}");
    }
}

#[test]
fn lost_contact_exits_with_3_and_says_where() {
    let out = wearlab()
        .args(["solve", "presets/contact-lost.toml"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(3));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(
        err.trim(),
        "error: complete contact lost: p_min = -5.32 MPa at x = 736 um, y = 0 m; it holds after t = 35.2 s"
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["contact"]["complete"], false);
    // after the wear has run long enough, contact is complete
    let later = wearlab()
        .args(["solve", "presets/contact-lost.toml", "--time", "40"])
        .output()
        .unwrap();
    assert!(later.status.success());
    assert_eq!(
        wearlab()
            .args(["solve", "presets/contact-lost.toml", "--time", "-1"])
            .output()
            .unwrap()
            .status
            .code(),
        Some(2)
    );
    assert_eq!(
        wearlab()
            .args(["solve", "presets/dispersion.toml", "--probe", "1;2"])
            .output()
            .unwrap()
            .status
            .code(),
        Some(2)
    );
}

#[test]
fn spatial_csv_is_the_field_over_the_cell() {
    let out = wearlab()
        .args(["solve", "presets/jgh-egg-box.toml", "--format", "csv"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(text.lines().next(), Some("x,y,pressure,shear,shape,wear"));
    assert_eq!(text.lines().count(), 1 + 64 * 64);
}

#[test]
fn strip_model_through_the_command_line() {
    let out = wearlab()
        .args(["solve", "presets/hard-coating-strip.toml", "--points", "11"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["model"], "strip");
    assert!(v["theta"].is_number() && v["validity"]["ok"] == true);
    // docs/physics/plane.md section 6 reference table, h = 1e-5, P = 1e3
    assert!((v["mu_star"].as_f64().unwrap() - 0.30048261).abs() < 6e-9);
    assert!(v["energy"]["residual"].as_f64().unwrap() < 1e-6);
    assert_eq!(v["sweep"]["mu_star"].as_array().unwrap().len(), 40);
}
