//! `wearlab sweep`: every row equals `wearlab solve --set` at its value bit for bit; the order
//! does not depend on the number of threads; points without an answer say why in their row; bad
//! arguments are exit 2 with a message that names the fault.

use assert_cmd::Command;
use serde_json::Value;

fn wearlab() -> Command {
    Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
}

fn run_env(args: &[&str], env: &[(&str, &str)]) -> (i32, String, String) {
    let mut cmd = wearlab();
    cmd.args(args);
    for (k, v) in env {
        cmd.env(k, v);
    }
    let out = cmd.output().unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

fn run(args: &[&str]) -> (i32, String, String) {
    run_env(args, &[])
}

/// A JSON value at a dotted output name (`contact.min_pressure`, `harmonics.0.decay_rate`).
fn at<'a>(v: &'a Value, name: &str) -> &'a Value {
    name.split('.')
        .fold(v, |v, part| match part.parse::<usize>() {
            Ok(n) => &v[n],
            Err(_) => &v[part],
        })
}

/// Sweeps `preset` over `vary` as JSON, then solves each row's point with `--set KEY=VALUE` (the
/// value as the sweep wrote it) and compares every output with `solve`'s key of the same name,
/// bit for bit.
fn rows_equal_solve(preset: &str, vary: &str, extra: &[&str]) -> usize {
    let mut args = vec!["sweep", preset, "--vary", vary, "--format", "json"];
    args.extend(extra);
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    let doc: Value = serde_json::from_str(&out).unwrap();
    let key = doc["vary"][0]["key"].as_str().unwrap().to_string();
    let outputs: Vec<String> = doc["outputs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|o| o["name"].as_str().unwrap().to_string())
        .collect();
    let rows = doc["rows"].as_array().unwrap();
    for row in rows {
        assert_eq!(row["status"], "ok", "{row}");
        let value = row[&key].as_f64().unwrap();
        let setting = format!("{key}={value:e}");
        let mut args = vec!["solve", preset, "--set", &setting];
        args.extend(extra);
        let (code, out, err) = run(&args);
        assert_eq!(code, 0, "{setting}: {err}");
        let solved: Value = serde_json::from_str(&out).unwrap();
        for name in &outputs {
            let (s, r) = (at(&solved, name), &row[name]);
            match (s.as_f64(), r.as_f64()) {
                (Some(s), Some(r)) => assert_eq!(s.to_bits(), r.to_bits(), "{setting}: {name}"),
                _ => assert_eq!(s, r, "{setting}: {name}"),
            }
        }
    }
    rows.len()
}

#[test]
fn every_row_is_solve_with_set_bit_for_bit() {
    // the wide model over the thickness (log), every default output
    assert_eq!(
        rows_equal_solve(
            "presets/polymer-coating.toml",
            "material.thickness=1mm:1:4:log",
            &[]
        ),
        4
    );
    // the strip model (through --set), over the wear coefficient
    rows_equal_solve(
        "presets/polymer-coating.toml",
        "wear.coefficient=0:2e-10:2",
        &["--set", "plane.model=strip"],
    );
    // spatial: a harmonic's wavenumber, with the contact check and per-harmonic outputs
    rows_equal_solve(
        "presets/dispersion.toml",
        "spatial.harmonics.1.wavenumber_x=2000:3000:3",
        &[],
    );
}

#[test]
fn the_order_does_not_depend_on_the_number_of_threads() {
    for (preset, vary) in [
        (
            "presets/wear-dominated.toml",
            ["friction.coefficient=0:1:12", "plane.load=1e2:1e5:9:log"],
        ),
        (
            "presets/wave-thick-layer.toml",
            [
                "spatial.harmonics.0.amplitude=1e-7:1e-5:7:log",
                "spatial.time=0:100:6",
            ],
        ),
    ] {
        let args = ["sweep", preset, "--vary", vary[0], "--vary", vary[1]];
        let one = run_env(&args, &[("RAYON_NUM_THREADS", "1")]);
        let two = run_env(&args, &[("RAYON_NUM_THREADS", "2")]);
        assert_eq!(one.0, 0, "{}", one.2);
        assert_eq!(one, two);
        if preset.contains("wear") {
            // the header, then the first --vary slowest: mu = 0 at nine loads, then mu = 1/11
            let lines: Vec<&str> = one.1.lines().collect();
            assert_eq!(lines.len(), 1 + 12 * 9);
            assert!(lines[1].starts_with("0e0,1e2,") && lines[9].starts_with("0e0,1e5,"));
            assert!(
                lines[10].starts_with("9.090909090909091e-2,1e2,"),
                "{}",
                lines[10]
            );
        }
    }
}

#[test]
fn a_point_without_an_answer_says_why_in_its_row() {
    let (code, out, err) = run(&[
        "sweep",
        "presets/wave-thick-layer.toml",
        "--vary",
        "spatial.harmonics.0.amplitude=1e-7:1e-5:3:log",
        "--output",
        "mu_star,contact.complete,contact.fraction,contact.time_to_complete",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.is_empty(), "no progress bar without a terminal: {err}");
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(
        lines[0],
        "spatial.harmonics.0.amplitude,mu_star,contact.complete,contact.fraction,\
         contact.time_to_complete,status"
    );
    // complete from t = 0: no time to complete, and the status says why that field is empty
    assert!(
        lines[1].ends_with(",true,1e0,,\"contact.time_to_complete: complete from t = 0, or still partial at the end of the running-in\""),
        "{}",
        lines[1]
    );
    // 10 um on a 1 mm wave at 20 MPa: partial contact, answered through the running-in
    let last: Vec<&str> = lines[3].split(',').collect();
    assert_eq!((last[0], last[2]), ("1e-5", "false"));
    assert!(last[3].parse::<f64>().unwrap() < 1.0 && last[4].parse::<f64>().unwrap() > 0.0);
    assert_eq!(last[5], "ok");
    // no period cell and contact not certified at every point: exit 3, the rows still printed
    let (code, out, err) = run(&[
        "sweep",
        "presets/dispersion.toml",
        "--set",
        "spatial.harmonics.1.wavenumber_x=4442.882938158366",
        "--vary",
        "spatial.harmonics.0.amplitude=2e-5:4e-5:2",
        "--format",
        "json",
    ]);
    assert_eq!(code, 3);
    assert!(
        err.starts_with(
            "error: no point of the sweep has an answer; the first: complete contact not certified"
        ),
        "{err}"
    );
    let doc: Value = serde_json::from_str(&out).unwrap();
    let row = &doc["rows"][0];
    assert!(row["mu_star"].is_null());
    assert!(row["status"].as_str().unwrap().contains("no common period"));
}

#[test]
fn a_value_the_rules_refuse_is_a_row_and_theta_is_not_offered_for_narrow() {
    // a wavenumber of 0 in both directions is refused at that point only
    let (code, out, _) = run(&[
        "sweep",
        "presets/wave-thick-layer.toml",
        "--set",
        "spatial.harmonics.0.wavenumber_y=0",
        "--vary",
        "spatial.harmonics.0.wavenumber_x=0:1e4:2",
        "--output",
        "mu_star",
    ]);
    assert_eq!(code, 0);
    let lines: Vec<&str> = out.lines().collect();
    assert!(
        lines[1].starts_with("0e0,,\"invalid input: harmonic 1: the wave vector is zero"),
        "{}",
        lines[1]
    );
    assert!(lines[2].ends_with(",ok"));
    let (code, out, _) = run(&[
        "sweep",
        "presets/thin-strip-winkler.toml",
        "--vary",
        "plane.load=1e2:1e3:2",
    ]);
    assert_eq!(code, 0);
    assert!(!out.lines().next().unwrap().contains("theta"));
}

#[test]
fn bad_arguments_are_exit_2_with_the_reason() {
    let plane = "presets/polymer-coating.toml";
    let cases: &[(&[&str], &str)] = &[
        (
            &["--vary", "material.thiknes=1:2"],
            "error: --vary unknown key 'material.thiknes': the keys of a plane preset are",
        ),
        (
            &["--vary", "material.thickness=1mm"],
            "error: --vary 'material.thickness=1mm' is not KEY=FROM:TO[:N][:log], e.g. material.thickness=1um:10mm:40:log",
        ),
        (
            &["--vary", "material.thickness=2mm:1mm"],
            "error: --vary material.thickness: bad range: TO = 0.001 must be larger than FROM = 0.002",
        ),
        (
            &["--vary", "material.thickness=1mm:2mm:1"],
            "error: --vary material.thickness: N = 1 is out of range: allowed a whole number from 2 to 2000",
        ),
        (
            &["--vary", "material.thickness=1mm:2mm:5000"],
            "error: --vary material.thickness: N = 5000 is out of range",
        ),
        (
            &["--vary", "material.thickness=1mm:2mm:many"],
            "error: --vary material.thickness: N = 'many' is not a number of points",
        ),
        (
            &["--vary", "friction.coefficient=0:1:log"],
            "error: --vary friction.coefficient: a log range needs FROM > 0 (FROM = 0)",
        ),
        (
            &["--vary", "material.thickness=1mm:2km"],
            "error: --vary material.thickness: TO = 2000 is out of range: allowed 1e-9 <= h <= 1e3 (m) or inf",
        ),
        (
            &["--vary", "material.thickness=1mm:inf"],
            "error: --vary material.thickness: TO = inf: the ends of a range must be finite",
        ),
        (
            &["--vary", "material.thickness=abc:1"],
            "error: --vary material.thickness: FROM = 'abc' is not a number",
        ),
        (
            &["--vary", "plane.model=1:2"],
            "error: --vary plane.model is a choice (wide, narrow, strip): it cannot be varied",
        ),
        (
            &["--vary", "plane.sweep.points=2:9"],
            "error: --vary plane.sweep.points is a count",
        ),
        (
            &["--vary", "spatial.time=0:1"],
            "error: --vary spatial.time applies to spatial presets only",
        ),
        (
            &[
                "--vary",
                "plane.load=1:2",
                "--vary",
                "plane.radius=1:2",
                "--vary",
                "wear.coefficient=0:1",
            ],
            "error: 3 --vary given: at most two (one gives a curve, two a grid)",
        ),
        (
            &["--vary", "plane.load=1:2", "--vary", "plane.load=3:4"],
            "error: --vary plane.load given twice",
        ),
        (
            &["--vary", "plane.load=1:2", "--output", "mu_star,mu_starr"],
            "error: --output unknown output 'mu_starr': the outputs of a plane preset are load,",
        ),
        (
            &[
                "--vary",
                "plane.load=1:2",
                "--output",
                "contact.min_pressure",
            ],
            "error: --output unknown output 'contact.min_pressure'",
        ),
        (
            &[
                "--vary",
                "plane.load=1:2",
                "--set",
                "plane.model=narrow",
                "--output",
                "theta",
            ],
            "error: --output output 'theta': the narrow model has no theta",
        ),
        (
            &[],
            "error: give --vary KEY=FROM:TO[:N][:log] (one for a curve, two for a grid)",
        ),
    ];
    for (extra, message) in cases {
        let mut args = vec!["sweep", plane];
        args.extend(*extra);
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{extra:?}: {err}");
        assert!(out.is_empty(), "{extra:?}");
        assert!(
            err.starts_with(message),
            "{extra:?}:\n{err}\nwanted\n{message}"
        );
    }
    let (code, _, err) = run(&[
        "sweep",
        "presets/dispersion.toml",
        "--vary",
        "spatial.time=0:1",
        "--output",
        "harmonics.4.decay_rate",
    ]);
    assert_eq!(code, 2);
    assert!(
        err.contains("there is no harmonic 4 (the preset has 4, numbered 0 to 3)"),
        "{err}"
    );
}
