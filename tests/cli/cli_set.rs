//! `wearlab solve --set KEY=VALUE`: the same answer as the preset file edited by hand, and exit 2
//! with a message naming the key, the value and what is allowed.

use assert_cmd::Command;

fn wearlab() -> Command {
    Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
}

fn run(args: &[&str]) -> (i32, String, String) {
    let out = wearlab().args(args).output().unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn set_gives_the_report_of_the_edited_file_byte_for_byte() {
    let text = std::fs::read_to_string("presets/polymer-coating.toml").unwrap();
    let edited = text
        .replace("thickness = 1.0e-2", "thickness = 1.0e-3")
        .replace("model = \"wide\"", "model = \"strip\"");
    assert_ne!(edited, text);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("edited.toml");
    std::fs::write(&path, edited).unwrap();
    let by_file = run(&["solve", path.to_str().unwrap(), "--points", "11"]);
    let by_set = run(&[
        "solve",
        "presets/polymer-coating.toml",
        "--points",
        "11",
        "--set",
        "material.thickness=1mm",
        "--set",
        "plane.model=strip",
    ]);
    assert_eq!(by_file.0, 0, "{}", by_file.2);
    assert_eq!(by_set, by_file);
}

#[test]
fn set_on_a_spatial_preset_reaches_a_harmonic() {
    let text = std::fs::read_to_string("presets/wave-thick-layer.toml").unwrap();
    let (_, base, _) = run(&["solve", "presets/wave-thick-layer.toml"]);
    let (code, out, err) = run(&[
        "solve",
        "presets/wave-thick-layer.toml",
        "--set",
        "spatial.harmonics.0.amplitude=0",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    // a flat punch: no deformation friction, mu* = mu (wave-thick-layer.toml's coefficient)
    assert_eq!(v["psi"].as_f64(), Some(0.0));
    let mu: toml::Value = toml::from_str(&text).unwrap();
    assert_eq!(
        v["mu_star"].as_f64(),
        mu["friction"]["coefficient"].as_float()
    );
    assert_ne!(out, base);
}

#[test]
fn bad_settings_are_exit_2_naming_key_value_and_what_is_allowed() {
    let cases: [(&str, &str); 7] = [
        (
            "material.thickness=10km",
            "error: material.thickness=10km: material.thickness = 10000 is out of range: allowed 1e-9 <= h <= 1e3 (m) or inf",
        ),
        (
            "material.thikness=1",
            "error: material.thikness=1: unknown key 'material.thikness': the keys of a plane preset are material.name, material.youngs_modulus,",
        ),
        (
            "friction.coefficient=abc",
            "error: friction.coefficient=abc: friction.coefficient = 'abc' is not a number (allowed 0 <= mu <= 10)",
        ),
        (
            "plane.model=thin",
            "error: plane.model=thin: plane.model = 'thin' is not a choice: allowed one of wide, narrow, strip",
        ),
        (
            "material.thickness",
            "error: 'material.thickness' is not KEY=VALUE (e.g. material.thickness=10um)",
        ),
        (
            "spatial.time=1",
            "error: spatial.time=1: spatial.time applies to spatial presets only; this preset solves problem = \"plane\"",
        ),
        (
            "plane.sweep.load_max=1",
            "error: the values set break a rule: plane.sweep.load_max = 1 must be larger than plane.sweep.load_min = 100",
        ),
    ];
    for (setting, message) in cases {
        let (code, out, err) = run(&["solve", "presets/polymer-coating.toml", "--set", setting]);
        assert_eq!(code, 2, "{setting}: {err}");
        assert!(out.is_empty());
        assert!(err.starts_with(message), "{setting}: {err}");
    }
}

#[test]
fn a_wear_coefficient_in_mm3_per_newton_metre_is_the_same_as_in_one_over_pascal() {
    // 0.02 mm^3/(N m) = 0.02e-9 m^2/N = 2e-11 1/Pa
    let points = ["--points", "5"];
    let si = run(&[
        &[
            "solve",
            "presets/polymer-coating.toml",
            "--set",
            "wear.coefficient=2e-11",
        ][..],
        &points,
    ]
    .concat());
    let quoted = run(&[
        &[
            "solve",
            "presets/polymer-coating.toml",
            "--set",
            "wear.coefficient=0.02 mm3/Nm",
        ][..],
        &points,
    ]
    .concat());
    assert_eq!(si.0, 0, "{}", si.2);
    assert_eq!(quoted, si);
}

#[test]
fn set_warns_of_a_value_that_looks_like_a_unit_mistake_as_a_file_does() {
    // k = 1e-7 1/Pa: 0.1 m of wear per metre at 1 MPa (Archard: h = k p s), the plausibility
    // rule's "more than 1 mm"; in a file the same value gives the same warning
    let text = std::fs::read_to_string("presets/polymer-coating.toml").unwrap();
    let edited = text.replace("coefficient = 2.0e-11", "coefficient = 1.0e-7");
    assert_ne!(edited, text);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("edited.toml");
    std::fs::write(&path, edited).unwrap();
    let (_, _, by_file) = run(&["solve", path.to_str().unwrap()]);
    let (code, _, by_set) = run(&[
        "solve",
        "presets/polymer-coating.toml",
        "--set",
        "wear.coefficient=1e-7",
    ]);
    let why = "was a specific wear rate in mm3/Nm written as 1/Pa?";
    assert!(by_file.contains(why), "{by_file}");
    assert!(
        by_set.contains("warning: --set wear.coefficient=1e-7: k = 1e-7: more"),
        "{by_set}"
    );
    assert!(by_set.contains(why), "{by_set}");
    // a warning, not a refusal: the answer comes or the physics refuses it, never exit 2
    assert_ne!(code, 2, "{by_set}");
}
