//! The `[explore]` section of a preset: checked with `path:line: reason`, saved and read back, and
//! run by `wearlab sweep PRESET` when no `--vary` is given.

use std::path::Path;

use assert_cmd::Command;
use wearlab::physics::Spacing;
use wearlab::preset::{bundled, parse, to_toml};

const MAP: &str = include_str!("../../presets/friction-or-wear-map.toml");

fn error_of(text: &str) -> String {
    parse(text, Path::new("lab/x.toml"))
        .unwrap_err()
        .to_string()
}

fn line_of(text: &str, needle: &str) -> usize {
    text.lines().position(|l| l.starts_with(needle)).unwrap() + 1
}

#[test]
fn the_bundled_lessons_read_their_section() {
    let map = bundled("friction-or-wear-map.toml").unwrap().unwrap();
    let e = map.explore.as_ref().unwrap();
    assert_eq!(e.quantity.to_string(), "mu_star_minus_mu");
    assert_eq!(e.axes.len(), 2);
    assert_eq!(e.axes[1].key.to_string(), "wear.coefficient");
    assert_eq!((e.axes[1].range.max, e.axes[1].range.points), (2e-10, 41));
    let sweep = bundled("coating-thickness-sweep.toml").unwrap().unwrap();
    let e = sweep.explore.as_ref().unwrap();
    assert_eq!(e.axes[0].range.spacing, Spacing::Log);
    // a preset without the section has none
    assert!(
        bundled("hertz-check.toml")
            .unwrap()
            .unwrap()
            .explore
            .is_none()
    );
}

#[test]
fn the_section_survives_a_save() {
    for file in [
        "friction-or-wear-map.toml",
        "coating-thickness-sweep.toml",
        "lab-friction.toml",
    ] {
        let p = bundled(file).unwrap().unwrap();
        let again = parse(&to_toml(&p), Path::new("saved.toml")).unwrap();
        assert_eq!(again, p, "{file}");
    }
}

#[test]
fn a_data_file_is_named_by_the_section() {
    let lab = include_str!("../../presets/lab-friction.toml");
    let p = parse(lab, Path::new("x.toml")).unwrap();
    assert_eq!(p.explore.unwrap().data.as_deref(), Some("lab-friction.csv"));
    let empty = lab.replace("data = \"lab-friction.csv\"", "data = \" \"");
    assert_eq!(
        error_of(&empty),
        format!(
            "lab/x.toml:{}: data names no file: a data file's name, e.g. data = \"friction.csv\"",
            line_of(&empty, "data = ")
        )
    );
}

#[test]
fn defaults_and_faults_with_their_line() {
    let short = MAP.replace(", points = 41, scale = \"linear\" }", " }");
    let p = parse(&short, Path::new("x.toml")).unwrap();
    let e = p.explore.unwrap();
    // a map's default: 20 points per side, linear
    assert_eq!(e.axes[0].range.points, 20);
    assert_eq!(e.axes[0].range.spacing, Spacing::Linear);
    let cases = [
        (
            MAP.replace("\"mu_star_minus_mu\"", "\"mu_star_minus\""),
            "quantity =",
            "unknown output 'mu_star_minus': the outputs of a plane preset are load,",
        ),
        (
            MAP.replace("\"wear.coefficient\"", "\"wear.coeff\""),
            "y =",
            "unknown key 'wear.coeff': the keys of a plane preset are",
        ),
        (
            MAP.replace("from = 0.0, to = 1.0", "from = 1.0, to = 0.5"),
            "x =",
            "friction.coefficient: bad range: TO = 0.5 must be larger than FROM = 1",
        ),
        (
            MAP.replace("to = 2.0e-10, points = 41", "to = 2.0e-10, points = 1"),
            "y =",
            "points = 1 is out of range: allowed a whole number from 2 to 2000",
        ),
        (
            MAP.replace(
                "to = 1.0, points = 41, scale = \"linear\"",
                "to = 1.0, points = 41, scale = \"log\"",
            ),
            "x =",
            "friction.coefficient: a log range needs FROM > 0 (FROM = 0)",
        ),
        (
            MAP.replace("\"wear.coefficient\"", "\"friction.coefficient\""),
            "y =",
            "x and y both vary friction.coefficient: vary two different parameters",
        ),
        (
            MAP.replace("\"wear.coefficient\"", "\"spatial.time\""),
            "y =",
            "spatial.time applies to spatial presets only",
        ),
        (
            MAP.replace(
                "scale = \"linear\" }\ny",
                "scale = \"linear\", step = 2 }\ny",
            ),
            "x =",
            "unknown key \"step\"",
        ),
    ];
    for (text, line, reason) in cases {
        let err = error_of(&text);
        let at = format!("lab/x.toml:{}: ", line_of(&text, line));
        assert!(err.starts_with(&at), "{err}\nwanted it at {at}");
        assert!(err.contains(reason), "{err}\nwanted {reason}");
    }
    // a quantity the model does not have
    let narrow = MAP
        .replace("\"mu_star_minus_mu\"", "\"theta\"")
        .replace("thickness = inf", "thickness = 1.0e-4")
        .replace("model = \"wide\"", "model = \"narrow\"");
    assert!(error_of(&narrow).ends_with("output 'theta': the narrow model has no theta"));
}

#[test]
fn sweep_without_vary_runs_the_section() {
    let out = Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .args([
            "sweep",
            "presets/friction-or-wear-map.toml",
            "--output",
            "theta",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(text.lines().count(), 1 + 41 * 41);
    assert!(text.starts_with("friction.coefficient,wear.coefficient,theta,status\n"));
    // the section's quantity joins the default outputs
    let out = Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .args([
            "sweep",
            "presets/friction-or-wear-map.toml",
            "--set",
            "friction.coefficient=0.5",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.lines()
            .next()
            .unwrap()
            .ends_with(",mu_star_minus_mu,status")
    );
    // --set can break the section: it says so
    let out = Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .args([
            "sweep",
            "presets/coating-thickness-sweep.toml",
            "--set",
            "material.thickness=inf",
            "--set",
            "plane.model=wide",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let out = Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .args(["sweep", "presets/hertz-check.toml"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("has no [explore] section"));
}

#[test]
fn the_section_opens_a_curve_or_a_map_and_the_groups_are_the_problems() {
    use wearlab::sweeps::{Opening, opening, quantity};
    let sweep = bundled("coating-thickness-sweep.toml").unwrap().unwrap();
    let Some(Ok(Opening::Curve(spec))) = opening(&sweep) else {
        panic!("a curve")
    };
    // the preset's strip model first, then the overlays
    let names: Vec<&str> = spec.models.iter().map(|m| m.name()).collect();
    assert_eq!(names, ["strip", "wide", "narrow"]);
    let map = bundled("friction-or-wear-map.toml").unwrap().unwrap();
    assert!(matches!(opening(&map), Some(Ok(Opening::Map(_)))));
    // an edit that removes the quantity: the opening says why
    let narrow = sweep.with_settings(&["plane.model=narrow"]).unwrap();
    let mut broken = narrow.clone();
    broken.explore.as_mut().unwrap().quantity =
        wearlab::sweeps::QuantityKey::parse("theta", &sweep).unwrap();
    assert!(
        opening(&broken)
            .unwrap()
            .unwrap_err()
            .contains("the narrow model has no theta")
    );
    assert!(opening(&bundled("hertz-check.toml").unwrap().unwrap()).is_none());
    // the plane groups: (a+b)/h, (a+b)/R, k m, mu chi, theta, P/(m R)
    let symbols: Vec<&str> = quantity::groups(&sweep)
        .iter()
        .map(|q| q.quantity().symbol)
        .collect();
    assert_eq!(
        symbols,
        ["theta", "(a+b)/h", "(a+b)/R", "k m", "mu chi", "P/(m R)"]
    );
    let spatial = bundled("dispersion.toml").unwrap().unwrap();
    let names: Vec<String> = quantity::groups(&spatial)
        .iter()
        .map(|q| q.to_string())
        .collect();
    assert!(names.contains(&"harmonics.3.kh".to_string()) && names.len() == 4 * 4);
}
