//! `wearlab solve PRESET --output KEY[,KEY...]`: the chosen quantities, equal to the full
//! report's; an unknown key is exit 2 naming the keys there are; a preset's warnings on stderr.

use crate::run::wearlab as run;

const PRESET: &str = "presets/polymer-coating.toml";

#[test]
fn output_lines_and_json_hold_the_report_s_values() {
    let (code, report, err) = run(&["solve", PRESET]);
    assert_eq!(code, 0, "{err}");
    let report: serde_json::Value = serde_json::from_str(&report).unwrap();
    let (code, json, err) = run(&[
        "solve",
        PRESET,
        "--output",
        "mu_star,a,validity.ok",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(json.starts_with("{\"mu_star\": "), "{json}");
    let chosen: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(chosen["mu_star"], report["mu_star"]);
    assert_eq!(chosen["a"], report["a"]);
    assert_eq!(chosen["validity.ok"], report["validity"]["ok"]);
    let (code, lines, err) = run(&["solve", PRESET, "--output", "mu_star,a,validity.ok"]);
    assert_eq!(code, 0, "{err}");
    let lines: Vec<&str> = lines.lines().collect();
    assert_eq!(lines.len(), 3, "{lines:?}");
    let mu_star: f64 = lines[0]
        .strip_prefix("mu_star = ")
        .unwrap()
        .parse()
        .unwrap();
    assert_eq!(Some(mu_star), report["mu_star"].as_f64());
    let a = lines[1].strip_prefix("a = ").unwrap();
    let a: f64 = a.strip_suffix(" m").unwrap().parse().unwrap();
    assert_eq!(Some(a), report["a"].as_f64());
    assert_eq!(
        lines[2],
        format!("validity.ok = {}", report["validity"]["ok"])
    );
    let (code, csv, _) = run(&["solve", PRESET, "--output", "mu_star", "--format", "csv"]);
    assert_eq!(code, 0);
    assert!(csv.starts_with("mu_star\n"), "{csv}");
}

#[test]
fn an_unknown_output_is_exit_2_naming_the_outputs() {
    let (code, out, err) = run(&["solve", PRESET, "--output", "mu_star,nonsense"]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert!(err.contains("'nonsense'"), "{err}");
    assert!(
        err.contains("mu_star") && err.contains("normal_force"),
        "{err}"
    );
}

#[test]
fn a_spatial_output_at_a_time() {
    let preset = "presets/jgh-egg-box.toml";
    let (code, report, err) = run(&["solve", preset, "--time", "10"]);
    assert_eq!(code, 0, "{err}");
    let report: serde_json::Value = serde_json::from_str(&report).unwrap();
    let (code, json, err) = run(&[
        "solve",
        preset,
        "--time",
        "10",
        "--output",
        "contact.min_pressure,harmonics.0.decay_rate",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let chosen: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(
        chosen["contact.min_pressure"],
        report["contact"]["min_pressure"]
    );
    assert_eq!(
        chosen["harmonics.0.decay_rate"],
        report["harmonics"][0]["decay_rate"]
    );
}

#[test]
fn a_preset_s_warnings_go_to_stderr_and_the_exit_code_stays_0() {
    // the egg box's harmonic with wavenumber_y = 0 and phase_y = 0 is zero everywhere
    let text = std::fs::read_to_string("presets/jgh-egg-box.toml")
        .unwrap()
        .replace("wavenumber_y = 6283.185307179586", "wavenumber_y = 0.0")
        .replace("phase_y = 1.5707963267948966", "phase_y = 0.0");
    let line = 1 + text.lines().position(|l| l == "phase_y = 0.0").unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("lab.toml");
    std::fs::write(&path, text).unwrap();
    let (code, out, err) = run(&["solve", path.to_str().unwrap(), "--output", "mu_star"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out, "mu_star = 0\n");
    assert!(
        err.starts_with(&format!(
            "warning: {}:{line}: wavenumber_y = 0 with phase_y = 0 (a multiple of pi)",
            path.display()
        )),
        "{err}"
    );
}
