//! A height-map punch (`spatial.surface`) as a script meets it: the file read beside its preset,
//! the JSON's `surface` keys, `--write-surface` reading back, and the refusals in words.

use crate::run::SURFACE_PRESET as PRESET;
use std::path::Path;
use std::time::Duration;

use assert_cmd::Command;
use serde_json::Value;

/// `wearlab solve` of `dir/p.toml` with `args`: (exit code, stdout, stderr).
fn solve(dir: &Path, args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .timeout(Duration::from_secs(60))
        .current_dir(dir)
        .arg("solve")
        .arg("p.toml")
        .args(args)
        .output()
        .unwrap();
    let text = |b: &[u8]| String::from_utf8_lossy(b).to_string();
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

/// A cosine of 0.1 um over 1 mm on 64 nodes, one row.
fn cosine_row() -> String {
    let row: Vec<String> = (0..64)
        .map(|i| {
            format!(
                "{:e}",
                1e-7 * (2.0 * std::f64::consts::PI * i as f64 / 64.0).cos()
            )
        })
        .collect();
    format!("# a cosine\n{}\n", row.join(","))
}

fn with_surface(dir: &Path, surface: &str) {
    std::fs::write(dir.join("p.toml"), format!("{PRESET}surface = {surface}\n")).unwrap();
}

#[test]
fn a_profile_file_beside_its_preset_gives_the_surface_keys() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("wave.csv"), cosine_row()).unwrap();
    with_surface(dir.path(), "{ file = \"wave.csv\", length_x = \"1 mm\" }");
    let (code, out, err) = solve(dir.path(), &["--time", "0"]);
    assert_eq!(code, Some(0), "{err}");
    let json: Value = serde_json::from_str(&out).unwrap();
    // the rms of a cosine of amplitude A is A/sqrt(2); its rms slope 2 pi A/(l sqrt(2))
    let rms = json["surface"]["rms_height"].as_f64().unwrap();
    let slope = json["surface"]["rms_slope"].as_f64().unwrap();
    assert!((rms - 1e-7 / 2f64.sqrt()).abs() < 1e-20, "{rms}");
    let exact = 2.0 * std::f64::consts::PI * 1e-7 / (1e-3 * 2f64.sqrt());
    assert!((slope - exact).abs() < 1e-12 * exact, "{slope}");
    assert_eq!(json["harmonics"].as_array().unwrap().len(), 0);
    assert_eq!(json["contact"]["complete"], Value::Bool(true));
}

#[test]
fn write_surface_writes_the_worn_map_that_reads_back() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("wave.csv"), cosine_row()).unwrap();
    with_surface(dir.path(), "{ file = \"wave.csv\", length_x = \"1 mm\" }");
    let (code, out, err) = solve(
        dir.path(),
        &["--time", "1e-4", "--write-surface", "worn.csv"],
    );
    assert_eq!(code, Some(0), "{err}");
    let json: Value = serde_json::from_str(&out).unwrap();
    let worn = std::fs::read_to_string(dir.path().join("worn.csv")).unwrap();
    assert!(worn.starts_with("# wearlab: the punch surface U at t = 1e-4 s"));
    let heights: Vec<f64> = worn
        .lines()
        .filter(|l| !l.starts_with('#'))
        .flat_map(|l| l.split(',').map(|c| c.parse::<f64>().unwrap()))
        .collect();
    assert_eq!(heights.len(), 64);
    let rms = (heights.iter().map(|h| h * h).sum::<f64>() / 64.0).sqrt();
    let reported = json["surface"]["rms_height"].as_f64().unwrap();
    assert!((rms - reported).abs() <= 1e-15 * reported);
    assert!(reported < 1e-7 / 2f64.sqrt());
    // the worn map is a preset's surface again
    with_surface(dir.path(), "{ file = \"worn.csv\", length_x = \"1 mm\" }");
    let (code, again, err) = solve(dir.path(), &["--time", "0"]);
    assert_eq!(code, Some(0), "{err}");
    let again: Value = serde_json::from_str(&again).unwrap();
    let read_back = again["surface"]["rms_height"].as_f64().unwrap();
    assert!((read_back - reported).abs() <= 1e-14 * reported);
}

#[test]
fn refusals_say_what_is_wrong() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("wave.csv"), cosine_row()).unwrap();
    let refused = |surface: &str, args: &[&str], code: i32, says: &str| {
        with_surface(dir.path(), surface);
        let (c, _, err) = solve(dir.path(), args);
        assert_eq!(c, Some(code), "{surface}: {err}");
        assert!(err.contains(says), "{surface}: {err}");
    };
    refused(
        "{ file = \"missing.csv\", length_x = 1e-3 }",
        &[],
        2,
        "missing.csv: cannot be read",
    );
    refused(
        "{ file = \"wave.csv\" }",
        &[],
        2,
        "spatial.surface needs length_x",
    );
    refused(
        "{ kind = \"fractal\", hurst = 0.8 }",
        &[],
        2,
        "kind = \"fractal\" is not a surface",
    );
    refused(
        "{ kind = \"self-affine\", hurst = 0.8, rms_height = 1e-7, rms_slope = 0.01, \
         rolloff_wavelength = 1e-4, cutoff_wavelength = 1e-5, length_x = 1e-3, length_y = 0, \
         grid = 64, seed = 1 }",
        &[],
        2,
        "rms_height or rms_slope (one of them)",
    );
    refused(
        "{ kind = \"self-affine\", hurst = 1.5, rms_height = 1e-7, rolloff_wavelength = 1e-4, \
         cutoff_wavelength = 1e-5, length_x = 1e-3, length_y = 0, grid = 64, seed = 1 }",
        &[],
        2,
        "hurst = 1.5: must be in (0, 1]",
    );
    std::fs::write(dir.path().join("bad.csv"), "1e-7,2e-7\n1e-7,nan\n").unwrap();
    refused(
        "{ file = \"bad.csv\", length_x = 1e-3, length_y = 1e-3 }",
        &[],
        2,
        "bad.csv:2:",
    );
    // both forms of the punch at once
    std::fs::write(
        dir.path().join("p.toml"),
        format!(
            "{PRESET}surface = {{ file = \"wave.csv\", length_x = 1e-3 }}\n\
             [[spatial.harmonics]]\namplitude = 1e-7\nwavenumber_x = 6283.185307179586\n\
             wavenumber_y = 0.0\nphase_x = 0.0\nphase_y = 1.5707963267948966\n"
        ),
    )
    .unwrap();
    let (c, _, err) = solve(dir.path(), &[]);
    assert_eq!(c, Some(2));
    assert!(
        err.contains("p.toml:12: give spatial.surface or [[spatial.harmonics]], not both"),
        "{err}"
    );
}

#[test]
fn write_surface_needs_a_height_map() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("p.toml"),
        format!(
            "{PRESET}[[spatial.harmonics]]\namplitude = 1e-7\nwavenumber_x = 6283.185307179586\n\
             wavenumber_y = 0.0\nphase_x = 0.0\nphase_y = 1.5707963267948966\n"
        ),
    )
    .unwrap();
    let (c, _, err) = solve(dir.path(), &["--write-surface", "out.csv"]);
    assert_eq!(c, Some(2));
    assert!(
        err.contains("--write-surface writes a height-map punch"),
        "{err}"
    );
    // a surface that cannot be written: exit 1, nothing printed
    std::fs::write(dir.path().join("wave.csv"), cosine_row()).unwrap();
    with_surface(dir.path(), "{ file = \"wave.csv\", length_x = \"1 mm\" }");
    let (c, out, err) = solve(dir.path(), &["--write-surface", "no/such/dir/out.csv"]);
    assert_eq!(c, Some(1), "{err}");
    assert!(
        out.is_empty() && err.contains("cannot write the surface"),
        "{err}"
    );
}

#[test]
fn a_generated_surface_survives_a_save() {
    let text = format!(
        "{PRESET}surface = {{ kind = \"self-affine\", hurst = 0.7, rms_slope = 0.01, \
         rolloff_wavelength = \"0.2 mm\", cutoff_wavelength = \"20 um\", length_x = \"1 mm\", \
         length_y = \"1 mm\", grid = 32, seed = 11 }}\n"
    );
    let p = wearlab::preset::parse(&text, Path::new("lab/p.toml")).unwrap();
    let again =
        wearlab::preset::parse(&wearlab::preset::to_toml(&p), Path::new("lab/p.toml")).unwrap();
    assert_eq!(p.spatial.surface, again.spatial.surface);
    let map = &p.spatial.surface.as_ref().unwrap().surface;
    assert_eq!((map.nx, map.ny), (32, 32));
}
