//! `wearlab solve` of a spatial preset under the wear law n != 1: simulated on the grid and said
//! so in the JSON; refused in words where it cannot be simulated.

use assert_cmd::Command;
use serde_json::Value;

fn solve(args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .arg("solve")
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn a_spatial_preset_takes_the_wear_law_and_says_it_is_simulated() {
    // the wave of wave-thick-layer (complete contact, 1/beta = 49 s) under n = 2, p0 = pbar
    let (code, out, err) = solve(&[
        "presets/wave-thick-layer.toml",
        "--time",
        "10",
        "--set",
        "wear.exponent=2",
        "--set",
        "wear.reference_pressure=2e7",
    ]);
    assert_eq!(code, Some(0), "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(
        v["running_in"],
        "wear exponent n = 2: the running-in is simulated on the grid; the closed form holds for \
         n = 1 only"
    );
    assert_eq!(v["harmonics_hold"], "for n = 1 only");
    let contact = &v["contact"];
    assert_eq!(contact["complete"], true);
    // the bound pbar - sum A/M and its time are the linear law's closed form: the bound is the
    // simulated shape's nodal minimum instead, and no time is given
    assert_eq!(contact["lower_bound"], contact["min_pressure"]);
    assert!(contact["complete_after"].is_null());
    // n = 1 says nothing of it
    let (code, out, err) = solve(&["presets/wave-thick-layer.toml", "--time", "10"]);
    assert_eq!(code, Some(0), "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    assert!(v.get("running_in").is_none() && v["harmonics_hold"] == "now");
}

#[test]
fn the_spatial_wear_law_is_refused_in_words_where_it_cannot_be_simulated() {
    // the plane problem's rule: n != 1 needs p0 (exit 2)
    let (code, _, err) = solve(&["presets/wave-thick-layer.toml", "--set", "wear.exponent=2"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("needs wear.reference_pressure"), "{err}");
    // the shear cap stays a plane-only key (exit 2)
    let (code, _, err) = solve(&[
        "presets/wave-thick-layer.toml",
        "--set",
        "friction.shear_strength=1e7",
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("without a shear cap"), "{err}");
    // incommensurate harmonics have no period cell to simulate on (exit 3)
    let (code, _, err) = solve(&[
        "presets/dispersion.toml",
        "--set",
        "spatial.harmonics.1.wavenumber_x=4442.882938158366",
        "--set",
        "wear.exponent=2",
        "--set",
        "wear.reference_pressure=1e7",
    ]);
    assert_eq!(code, Some(3), "{err}");
    assert!(err.contains("simulated on the grid"), "{err}");
    // n = 4 with p0 = 1 mPa under 20 MPa: rates 1e31 times the linear law's, bounded (exit 3)
    let (code, _, err) = solve(&[
        "presets/wave-thick-layer.toml",
        "--time",
        "10",
        "--set",
        "wear.exponent=4",
        "--set",
        "wear.reference_pressure=1e-3",
    ]);
    assert_eq!(code, Some(3), "{err}");
    assert!(err.contains("raise wear.reference_pressure"), "{err}");
}

#[test]
fn a_duration_left_out_follows_the_wear_law_s_rate_at_the_mean_pressure() {
    // wave-thick-layer without its duration: five of the slowest decay times; under n = 2 with
    // p0 = pbar/4 a small wave decays at n (pbar/p0)^(n-1) = 8 times the linear law's rate
    // (tests/spatial/spatial_wear_law.rs checks that rate against the simulation)
    let text: String = std::fs::read_to_string("presets/wave-thick-layer.toml")
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with("duration"))
        .map(|l| format!("{l}\n"))
        .collect();
    let squared = text.replace(
        "[wear]\n",
        "[wear]\nexponent = 2.0\nreference_pressure = 5.0e6\n",
    );
    let path = std::path::Path::new("presets/wave.toml");
    let linear = wearlab::preset::parse(&text, path).unwrap();
    let squared = wearlab::preset::parse(&squared, path).unwrap();
    assert_eq!(squared.wear_exponent, 2.0);
    let ratio = linear.spatial.duration / squared.spatial.duration;
    assert!((ratio - 8.0).abs() < 1e-12, "{ratio}");
}
