//! A generated surface's keys changed by `--set spatial.surface.NAME=VALUE` with the checks of the
//! preset file, and `spatial.grid` refused beside a height map (the map's own grid is solved).

use crate::run::SURFACE_PRESET as PRESET;
use std::path::Path;
use std::time::Duration;

use assert_cmd::Command;
use serde_json::Value;

const GENERATED: &str = "surface = { kind = \"self-affine\", hurst = 0.8, rms_height = \"2 nm\", \
    rolloff_wavelength = \"250 um\", cutoff_wavelength = \"50 um\", length_x = \"1 mm\", \
    length_y = \"1 mm\", grid = 32, seed = 3 }\n";

/// `wearlab solve p.toml --time 0` with `args` in `dir`: (exit code, stdout, stderr).
fn solve(dir: &Path, preset: &str, args: &[&str]) -> (Option<i32>, String, String) {
    std::fs::write(dir.join("p.toml"), preset).unwrap();
    let out = Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .timeout(Duration::from_secs(60))
        .current_dir(dir)
        .args(["solve", "p.toml", "--time", "0"])
        .args(args)
        .output()
        .unwrap();
    let text = |b: &[u8]| String::from_utf8_lossy(b).to_string();
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

fn surface_of(out: &str) -> Value {
    serde_json::from_str::<Value>(out).unwrap()["surface"].clone()
}

#[test]
fn set_changes_a_generated_surfaces_keys() {
    let dir = tempfile::tempdir().unwrap();
    let preset = format!("{PRESET}{GENERATED}");
    let (code, base, err) = solve(dir.path(), &preset, &[]);
    assert_eq!(code, Some(0), "{err}");
    let base = surface_of(&base);
    // the rms height is the generator's to round-off, with a unit text as in the file
    let (code, out, err) = solve(
        dir.path(),
        &preset,
        &["--set", "spatial.surface.rms_height=5 nm"],
    );
    assert_eq!(code, Some(0), "{err}");
    let rms = surface_of(&out)["rms_height"].as_f64().unwrap();
    assert!((rms - 5e-9).abs() < 1e-13 * 5e-9, "{rms}");
    // the same amplitudes with other phases: the rms height and slope stay, the heights move
    let (code, out, err) = solve(dir.path(), &preset, &["--set", "spatial.surface.seed=4"]);
    assert_eq!(code, Some(0), "{err}");
    let other = surface_of(&out);
    assert!((other["rms_height"].as_f64().unwrap() - 2e-9).abs() < 1e-21);
    assert_ne!(other["skewness"], base["skewness"]);
    // the grid: 64 x 64 nodes, the same band of waves
    let (code, out, err) = solve(dir.path(), &preset, &["--set", "spatial.surface.grid=64"]);
    assert_eq!(code, Some(0), "{err}");
    assert!((surface_of(&out)["rms_height"].as_f64().unwrap() - 2e-9).abs() < 1e-21);
    // rms_slope replaces rms_height: the surface is scaled to the slope instead
    let (code, out, err) = solve(
        dir.path(),
        &preset,
        &["--set", "spatial.surface.rms_slope=1e-4"],
    );
    assert_eq!(code, Some(0), "{err}");
    let slope = surface_of(&out)["rms_slope"].as_f64().unwrap();
    assert!((slope - 1e-4).abs() < 1e-13 * 1e-4, "{slope}");
}

#[test]
fn set_refuses_what_the_file_refuses() {
    let dir = tempfile::tempdir().unwrap();
    let preset = format!("{PRESET}{GENERATED}");
    let refused = |setting: &str, says: &str| {
        let (code, out, err) = solve(dir.path(), &preset, &["--set", setting]);
        assert_eq!(code, Some(2), "{setting}: {err}");
        assert!(out.is_empty());
        assert!(err.contains(says), "{setting}: {err}");
    };
    refused(
        "spatial.surface.hurst=1.5",
        "spatial.surface.hurst=1.5: hurst = 1.5: must be in (0, 1]",
    );
    refused(
        "spatial.surface.grid=1",
        "spatial.surface.grid = 1: must be a whole number >= 2",
    );
    refused(
        "spatial.surface.seed=-1",
        "spatial.surface.seed = -1: must be a whole number >= 0",
    );
    refused(
        "spatial.surface.rms_height=abc",
        "spatial.surface.rms_height = ",
    );
    refused(
        "spatial.surface.colour=3",
        "unknown key 'spatial.surface.colour': a generated surface's keys are",
    );
    refused(
        "spatial.surface.cutoff_wavelength=2mm",
        "spatial.surface.cutoff_wavelength=2mm: cutoff_wavelength = 0.002 m is longer than rolloff_wavelength",
    );
    // a height-map file's heights are the file's
    std::fs::write(dir.path().join("wave.csv"), "1e-7,0,-1e-7,0\n").unwrap();
    let file = format!("{PRESET}surface = {{ file = \"wave.csv\", length_x = \"1 mm\" }}\n");
    let (code, _, err) = solve(dir.path(), &file, &["--set", "spatial.surface.hurst=0.5"]);
    assert_eq!(code, Some(2));
    assert!(
        err.contains("this preset's surface is a height-map file"),
        "{err}"
    );
}

#[test]
fn spatial_grid_is_refused_beside_a_height_map() {
    let dir = tempfile::tempdir().unwrap();
    let preset = format!("{PRESET}grid = 128\n{GENERATED}");
    let (code, out, err) = solve(dir.path(), &preset, &[]);
    assert_eq!(code, Some(2), "{err}");
    assert!(out.is_empty());
    assert!(
        err.contains(
            "p.toml:12: spatial.grid does not apply to a height map (spatial.surface): the map \
             is solved on its own grid of 32 x 32 nodes"
        ),
        "{err}"
    );
    let preset = format!("{PRESET}{GENERATED}");
    let (code, _, err) = solve(dir.path(), &preset, &["--set", "spatial.grid=128"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("spatial.grid does not apply to a height map"),
        "{err}"
    );
}
