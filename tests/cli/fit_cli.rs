//! `wearlab fit`: the JSON keys of `docs/cli.md`, the fitted preset written and solved again, and
//! the refusals of bad data files and requests (exit 2, `file:line: reason`).

use crate::run::wearlab as run;
use std::path::Path;

const PRESET: &str = "examples/lab/friction-against-load.toml";
const DATA: &str = "examples/lab/friction-against-load.csv";

/// The JSON keys that docs/cli.md's `wearlab fit` section lists (the backquoted names of its
/// "JSON keys" list).
fn documented_keys() -> Vec<String> {
    let page = std::fs::read_to_string("docs/cli.md").unwrap();
    let section = page
        .split("## `wearlab fit`")
        .nth(1)
        .and_then(|s| s.split("JSON keys:").nth(1))
        .and_then(|s| s.split("`--write OUT.toml`").next())
        .unwrap();
    let mut keys = Vec::new();
    for (i, part) in section.split('`').enumerate() {
        if i % 2 == 1 && part.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
            keys.push(part.to_string());
        }
    }
    keys
}

#[test]
fn the_fit_of_the_lab_data_has_every_documented_key() {
    let (code, out, err) = run(&[
        "fit",
        PRESET,
        "--data",
        DATA,
        "--free",
        "friction.coefficient,wear.coefficient",
    ]);
    assert_eq!(code, 0, "{err}");
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    let keys = documented_keys();
    assert_eq!(keys.len(), 20, "{keys:?}");
    for key in &keys {
        assert!(json.get(key).is_some(), "no key {key} in {out}");
    }
    assert_eq!(json["determined"]["friction.coefficient"], true);
    assert_eq!(json["determined"]["wear.coefficient"], false);
    let why = json["reasons"]["wear.coefficient"].as_str().unwrap();
    assert!(
        why.starts_with("k is not determined by these data: "),
        "{why}"
    );
    assert!(json["reasons"].get("friction.coefficient").is_none());
    assert_eq!(json["residuals"].as_array().unwrap().len(), 20);
    assert!(
        json["notes"][0].as_str().unwrap().contains("SYNTHETIC"),
        "{out}"
    );
}

/// The preset written by `--write`, solved again, gives the fitted curve: its mu* at each load of
/// the data is the data minus the residual.
#[test]
fn the_written_preset_gives_the_fitted_curve() {
    let dir = tempfile::tempdir().unwrap();
    let out_path = dir.path().join("fitted.toml");
    let out_text = out_path.to_str().unwrap();
    let (code, out, err) = run(&[
        "fit",
        PRESET,
        "--data",
        DATA,
        "--free",
        "friction.coefficient",
        "--write",
        out_text,
    ]);
    assert_eq!(code, 0, "{err}");
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(json["written"], out_text);
    let text = std::fs::read_to_string(DATA).unwrap();
    let rows: Vec<(f64, f64)> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.contains('['))
        .map(|l| {
            let (x, y) = l.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect();
    let residuals = json["residuals"].as_array().unwrap();
    for (i, (load, mu)) in rows.iter().enumerate().step_by(6) {
        let set = format!("plane.load={load}");
        let (code, solved, err) = run(&[
            "solve", out_text, "--output", "mu_star", "--format", "json", "--set", &set,
        ]);
        assert_eq!(code, 0, "{err}");
        let solved: serde_json::Value = serde_json::from_str(&solved).unwrap();
        let model = mu - residuals[i].as_f64().unwrap();
        let again = solved["mu_star"].as_f64().unwrap();
        // the preset is written with every digit the fit found: the same curve to rounding
        assert!(
            (again - model).abs() < 1e-12,
            "load {load}: {again} against {model}"
        );
    }
}

fn refused(data: &str, free: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("lab.csv");
    std::fs::write(&path, data).unwrap();
    let (code, out, err) = run(&[
        "fit",
        PRESET,
        "--data",
        path.to_str().unwrap(),
        "--free",
        free,
    ]);
    assert_eq!(code, 2, "{out}{err}");
    assert!(out.is_empty());
    err.replace(&format!("{}", path.display()), "lab.csv")
}

#[test]
fn bad_data_files_exit_2_with_file_line_and_reason() {
    let mu = "friction.coefficient";
    assert_eq!(
        refused("load [N/m],mu [-]\n1e3,0.3\n2e3\n", mu),
        "error: lab.csv:3: 1 values, but the header names 2 columns\n"
    );
    assert!(refused("load [N/m],mu [furlong]\n1e3,0.3\n", mu).starts_with("error: lab.csv:1: "));
    assert_eq!(
        refused("load [N/m],mu [-]\n1e3,NaN\n", mu),
        "error: lab.csv:2: mu = NaN is not a measurement (a finite number)\n"
    );
    assert!(refused("", mu).starts_with("error: lab.csv:1: empty"));
    let e = refused("load [N/m],colour [-]\n1e3,0.3\n", mu);
    assert!(
        e.contains("'colour' matches no quantity") && e.contains("mu (mu_star)"),
        "{e}"
    );
    let e = refused("load [N/m],mu [-]\n1e3,0.3\n2e3,0.3\n", "plane.load");
    assert!(e.contains("the data's x axis"), "{e}");
    let e = refused("load [N/m],mu [-]\n1e3,0.3\n2e3,0.3\n", "friction.colour");
    assert!(
        e.starts_with("error: --free unknown key 'friction.colour'"),
        "{e}"
    );
    let e = refused("load [N/m],mu [-]\n1e3,0.3\n", mu);
    assert!(
        e.contains("1 measured values cannot determine 1 free parameters"),
        "{e}"
    );
}

#[test]
fn a_huge_data_file_is_refused_unread() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("huge.csv");
    let file = std::fs::File::create(&path).unwrap();
    file.set_len(1 << 30).unwrap();
    let start = std::time::Instant::now();
    let (code, _, err) = run(&[
        "fit",
        PRESET,
        "--data",
        path.to_str().unwrap(),
        "--free",
        "friction.coefficient",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("1073741824 bytes"), "{err}");
    assert!(start.elapsed().as_secs_f64() < 5.0);
    assert!(Path::new(&path).exists());
}

/// A model without an answer at the data's loads: exit 3, the reason naming the data's line.
#[test]
fn a_model_without_answer_exits_3_and_says_where() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("lab.csv");
    std::fs::write(&path, "load [N/m],mu [-]\n1e2,0.3\n1e3,0.3\n1e4,0.3\n").unwrap();
    let (code, out, err) = run(&[
        "fit",
        "presets/flat-pin-coating.toml",
        "--set",
        "plane.model=wide",
        "--data",
        path.to_str().unwrap(),
        "--free",
        "friction.coefficient",
    ]);
    assert_eq!(code, 3, "{out}{err}");
    assert!(out.is_empty());
    assert!(
        err.starts_with("error: the fit cannot be done: line 2: "),
        "{err}"
    );
}

/// A lab preset as an instructor writes it by hand: comments, units, its own key order.
const HAND_WRITTEN: &str = r#"# Week 3: the tribometer run, with a guess for mu
schema = 1
name = "Week 3: friction against load"
description = "Fit mu to the run of friction-against-load.csv."
problem = "plane"

[plane]
model = "wide"
radius = "50 mm"       # the steel cylinder
load = "5 kN/m"

[material]
youngs_modulus = "3 GPa"  # the coating
poisson_ratio = 0.35
thickness = "10 mm"

[friction]
coefficient = 0.2   # a guess: the fit finds it
adhesion = 0.0

[wear]
coefficient = "2e-2 mm3/Nm"   # 2e-11 1/Pa
"#;

/// `--write` keeps the preset file's text: every line but the fitted value's as written, that
/// one with its comment and every digit the fit found.
#[test]
fn the_written_preset_keeps_the_authors_text_and_changes_only_the_fitted_value() {
    let dir = tempfile::tempdir().unwrap();
    let lab = dir.path().join("week3.toml");
    std::fs::write(&lab, HAND_WRITTEN).unwrap();
    let fitted = dir.path().join("fitted.toml");
    let (code, out, err) = run(&[
        "fit",
        lab.to_str().unwrap(),
        "--data",
        DATA,
        "--free",
        "friction.coefficient",
        "--write",
        fitted.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    let mu = json["estimates"]["friction.coefficient"].as_f64().unwrap();
    let text = std::fs::read_to_string(&fitted).unwrap();
    let (before, after): (Vec<&str>, Vec<&str>) =
        (HAND_WRITTEN.lines().collect(), text.lines().collect());
    assert_eq!(before.len(), after.len(), "{text}");
    let changed: Vec<usize> = (0..before.len())
        .filter(|&i| before[i] != after[i])
        .collect();
    // line 18: the friction coefficient
    assert_eq!(changed, [17], "{text}");
    let (value, comment) = after[17].split_once('#').unwrap();
    assert_eq!(comment, " a guess: the fit finds it");
    let written: f64 = value
        .trim()
        .strip_prefix("coefficient = ")
        .unwrap()
        .trim()
        .parse()
        .unwrap();
    assert_eq!(written, mu);
    assert_eq!(json["written"], fitted.to_str().unwrap());
    // the original is unchanged
    assert_eq!(std::fs::read_to_string(&lab).unwrap(), HAND_WRITTEN);
}

/// Without `--data` the fit reads the file the preset's `[explore]` section names, beside the
/// preset (the file the explorer draws): the same fit as with `--data` naming it.
#[test]
fn without_data_the_preset_s_own_data_file_is_fitted() {
    let free = ["--free", "friction.coefficient"];
    let (code, own, err) = run(&["fit", "presets/lab-friction.toml", free[0], free[1]]);
    assert_eq!(code, 0, "{err}");
    let (code, named, err) = run(&[
        "fit",
        "presets/lab-friction.toml",
        "--data",
        "presets/lab-friction.csv",
        free[0],
        free[1],
    ]);
    assert_eq!(code, 0, "{err}");
    let (own, named): (serde_json::Value, serde_json::Value) = (
        serde_json::from_str(&own).unwrap(),
        serde_json::from_str(&named).unwrap(),
    );
    assert_eq!(own["data"], "presets/lab-friction.csv");
    assert_eq!(own["estimates"], named["estimates"]);
    assert_eq!(own["residuals"], named["residuals"]);
}

/// A preset that names no data file, fitted without `--data`: exit 2, saying what to give.
#[test]
fn without_data_a_preset_naming_none_is_refused_in_words() {
    let (code, out, err) = run(&["fit", PRESET, "--free", "friction.coefficient"]);
    assert_eq!(code, 2, "{out}");
    assert!(out.is_empty(), "{out}");
    assert!(
        err.contains(&format!("no data to fit: {PRESET} names no data file"))
            && err.contains("give one with --data FILE"),
        "{err}"
    );
}
