//! Preset files: bundled ones load and solve; broken ones give path, line and reason; saves are
//! atomic; load/save/load round-trips.

use std::io::Write;
use std::path::Path;

use wearlab::physics::plane::solve;
use wearlab::physics::spatial::contact::check;
use wearlab::physics::spatial::{self, Cell, pipeline};
use wearlab::preset::{self, BUNDLED, BUNDLED_DATA, Problem, parse, write_atomically};

const BASE: &str = include_str!("../../presets/hertz-check.toml");

fn error_of(text: &str) -> String {
    parse(text, Path::new("lab/broken.toml"))
        .unwrap_err()
        .to_string()
}

fn line_of(text: &str, needle: &str) -> usize {
    text.lines().position(|l| l.starts_with(needle)).unwrap() + 1
}

#[test]
fn every_bundled_preset_loads_and_solves() {
    for b in BUNDLED {
        let p = b.load().unwrap_or_else(|e| panic!("{e}"));
        assert!(
            !p.name.is_empty() && p.description.contains("Look at"),
            "{}",
            b.file
        );
        match p.problem {
            Problem::Plane => {
                let sol = solve(&p.plane_inputs(), p.plane.model)
                    .unwrap_or_else(|e| panic!("{}: {e}", b.file));
                assert!(sol.mu_star.is_finite());
            }
            Problem::Spatial if p.spatial.surface.is_some() => {
                // a height map is solved on its grid (its figures: tests/presets/surfaces.rs)
                let r = pipeline::solve(&p.spatial_inputs(), &p.spatial_state_at(), &[], false)
                    .unwrap_or_else(|e| panic!("{}: {e}", b.file));
                assert!(r.mu_star.is_finite());
            }
            Problem::Spatial => {
                let inputs = p.spatial_inputs();
                let sol = spatial::solve(&inputs, p.spatial.time)
                    .unwrap_or_else(|e| panic!("{}: {e}", b.file));
                let contact = check(&sol, &Cell::of(inputs.harmonics()));
                // every spatial preset but the two running-in lessons is in complete contact
                assert_eq!(
                    contact.complete,
                    !["contact-lost.toml", "rubber-running-in.toml"].contains(&b.file),
                    "{}: {contact:?}",
                    b.file
                );
                if !contact.complete {
                    let later =
                        spatial::solve(&inputs, contact.complete_after.unwrap() * 1.01).unwrap();
                    assert!(check(&later, &Cell::of(inputs.harmonics())).complete);
                }
            }
        }
    }
    // every file in presets/ is bundled (a preset, or a data file a preset names)
    let mut on_disk: Vec<String> = std::fs::read_dir("presets")
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    on_disk.sort();
    let mut bundled: Vec<String> = BUNDLED
        .iter()
        .chain(BUNDLED_DATA)
        .map(|b| b.file.to_string())
        .collect();
    bundled.sort();
    assert_eq!(on_disk, bundled);
}

#[test]
fn broken_files_name_path_line_and_reason() {
    let nu = BASE.replace("poisson_ratio = 0.3", "poisson_ratio = 0.5");
    assert_eq!(
        error_of(&nu),
        format!(
            "lab/broken.toml:{}: poisson_ratio = 0.5 is out of range: allowed 0 <= nu < 0.5",
            line_of(&nu, "poisson_ratio")
        )
    );
    let neg = BASE.replace("thickness = inf", "thickness = -1.0e-3");
    assert_eq!(
        error_of(&neg),
        format!(
            "lab/broken.toml:{}: thickness = -0.001 is out of range: allowed 1e-9 <= h <= 1e3 (m) or inf",
            line_of(&neg, "thickness")
        )
    );
    let unknown = BASE.replace("[wear]\n", "[wear]\nrate = 3\n");
    assert_eq!(
        error_of(&unknown),
        format!(
            "lab/broken.toml:{}: unknown key \"rate\"; allowed here: one of \"coefficient\", \"archard_coefficient\", \"exponent\", \"reference_pressure\"",
            line_of(&unknown, "rate")
        )
    );
    let bad_toml = BASE.replace("load = 1.0e4", "load = 1.0e4 +");
    assert_eq!(
        error_of(&bad_toml),
        format!(
            "lab/broken.toml:{}: string values must be quoted, expected literal string",
            line_of(&bad_toml, "load =")
        )
    );
    let wrong_type = BASE.replace("radius = 0.05", "radius = \"big\"");
    assert_eq!(
        error_of(&wrong_type),
        format!(
            "lab/broken.toml:{}: radius = \"big\": 'big' is not a number; e.g. radius = \"10 mm\" or 1e-2",
            line_of(&wrong_type, "radius")
        )
    );
    let start = BASE.find("[material]").unwrap();
    let end = BASE.find("[friction]").unwrap();
    let no_material = format!("{}{}", &BASE[..start], &BASE[end..]);
    assert_eq!(
        error_of(&no_material),
        "lab/broken.toml: missing section [material] (every preset needs it)"
    );
    let no_plane = &BASE[..BASE.find("[plane]").unwrap()];
    assert_eq!(
        error_of(no_plane),
        format!(
            "lab/broken.toml:{}: problem = \"plane\" needs a [plane] section (model, radius, load)",
            line_of(no_plane, "problem")
        )
    );
    let schema = BASE.replace("schema = 1", "schema = 2");
    assert_eq!(
        error_of(&schema),
        "lab/broken.toml:1: schema = 2 is not supported: this wearlab reads schema = 1"
    );
    let sweep = BASE.replace("points = 60", "points = 1");
    assert!(
        error_of(&sweep)
            .ends_with("points = 1 is out of range: allowed a whole number from 2 to 2000")
    );
}

#[test]
fn a_missing_file_names_its_path() {
    let err = preset::load(Path::new("no/such/preset.toml"))
        .unwrap_err()
        .to_string();
    assert!(
        err.starts_with("no/such/preset.toml: cannot read the file: "),
        "{err}"
    );
}

#[test]
fn round_trip_is_identical() {
    let dir = tempfile::tempdir().unwrap();
    // the data files a bundled preset reads lie beside it, as in presets/
    for d in preset::BUNDLED_DATA {
        std::fs::write(dir.path().join(d.file), d.text).unwrap();
    }
    for b in BUNDLED {
        let p = b.load().unwrap();
        let path = dir.path().join(b.file);
        preset::save(&p, &path).unwrap();
        let again = preset::load(&path).unwrap();
        assert_eq!(p, again, "{}", b.file);
        let second = dir.path().join("second.toml");
        preset::save(&again, &second).unwrap();
        assert_eq!(
            std::fs::read_to_string(&path).unwrap(),
            std::fs::read_to_string(&second).unwrap()
        );
    }
}

#[test]
fn a_save_that_fails_midway_leaves_the_old_file_intact() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("lab.toml");
    std::fs::write(&path, BASE).unwrap();
    let result = write_atomically(&path, wearlab::preset::Links::Follow, |f| {
        f.write_all(b"schema = 1\nname = \"half writ")?;
        Err(std::io::Error::other("disk full"))
    });
    assert_eq!(result.unwrap_err().to_string(), "disk full");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), BASE);
    // and no temporary file is left behind
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, vec![std::ffi::OsString::from("lab.toml")]);
}

#[test]
fn defaults_for_optional_sections() {
    let minimal = "schema = 1\nproblem = \"plane\"\n[material]\nyoungs_modulus = 1e9\npoisson_ratio = 0.3\n\
                   thickness = inf\n[plane]\nmodel = \"wide\"\nradius = 0.1\nload = 100.0\n";
    let p = parse(minimal, Path::new("m.toml")).unwrap();
    assert_eq!(
        (p.friction.coefficient, p.friction.adhesion, p.wear),
        (0.0, 0.0, 0.0)
    );
    assert_eq!(p.plane.sweep, preset::default_load_sweep(100.0));
}

#[test]
fn broken_spatial_sections_name_the_line() {
    let base = include_str!("../../presets/wave-thick-layer.toml");
    let zero = base.replace("wavenumber_x = 6283.185307179586", "wavenumber_x = 0.0");
    let err = error_of(&zero);
    assert_eq!(
        err,
        format!(
            "lab/broken.toml:{}: harmonic 1: the wave vector is zero (wavenumber_x = wavenumber_y = 0); a constant belongs in the mean pressure, not in a harmonic",
            line_of(&zero, "[[spatial.harmonics]]")
        )
    );
    let negative = base.replace("amplitude = 1.0e-6", "amplitude = -1.0e-6");
    assert_eq!(
        error_of(&negative),
        format!(
            "lab/broken.toml:{}: amplitude = -0.000001 is out of range: allowed 0 <= A <= 1 (m)",
            line_of(&negative, "amplitude")
        )
    );
    let start = base.find("[[spatial.harmonics]]").unwrap();
    let none = &base[..start];
    assert_eq!(
        error_of(none),
        format!(
            "lab/broken.toml:{}: [spatial] has no [[spatial.harmonics]]: the punch needs at least one harmonic",
            line_of(none, "[spatial]")
        )
    );
}

#[test]
fn the_flat_pin_preset_shows_what_its_description_says() {
    let p = preset::bundled("flat-pin-coating.toml").unwrap().unwrap();
    let model = p.plane.model;
    let sol = solve(&p.plane_inputs(), model).unwrap();
    // "a = 0.507 mm behind, b = 0.521 mm ahead": just past the face c = 0.5 mm
    assert!((sol.a - 0.507e-3).abs() < 0.5e-6 && (sol.b - 0.521e-3).abs() < 0.5e-6);
    assert!(sol.a > 0.5e-3 && sol.b > 0.5e-3);
    // "some 5.5 times from x = -0.4 mm to x = +0.4 mm"
    let ratio = sol.pressure(0.4e-3) / sol.pressure(-0.4e-3);
    assert!((5.0..6.0).contains(&ratio), "{ratio}");
    // "mu* - mu is only 1.4e-4"; "about tenfold per decade of load"
    let excess = |load: f64| {
        solve(&p.plane_inputs().with_load(load), model)
            .unwrap()
            .mu_star
            - p.friction.coefficient
    };
    assert!((excess(1e4) - 1.4e-4).abs() < 0.05e-4, "{}", excess(1e4));
    let per_decade = excess(1e4) / excess(1e3);
    assert!((8.0..12.0).contains(&per_decade), "{per_decade}");
    // "some 50 coating thicknesses wide"; "the study behind the verdicts covers the parabola only"
    let v = wearlab::physics::plane::validity::estimate(&sol);
    assert!((45.0..55.0).contains(&v.contact_width_over_thickness));
    assert!(
        v.warnings
            .iter()
            .any(|w| w.contains("only for the parabolic punch"))
    );
}

#[test]
fn the_polymer_coating_preset_turns_to_a_warning_where_its_description_says() {
    use wearlab::physics::plane::strip_check::{judged, strip_check, verdict};
    use wearlab::physics::plane::validity::estimate;
    let p = preset::bundled("polymer-coating.toml").unwrap().unwrap();
    let model = p.plane.model;
    let at = |load: f64| {
        let sol = solve(&p.plane_inputs().with_load(load), model).unwrap();
        let estimated = estimate(&sol);
        let verdict = judged(&estimated, &strip_check(&sol), model);
        (estimated, verdict)
    };
    // "turns to a warning once the contact is wider than about 0.4 coating thicknesses (P above
    // ~2.1e5 N/m: ... mu* - mu is then more than 5 % off the exact strip solution, measured)"
    let (_, below) = at(2.0e5);
    let (_, above) = at(2.2e5);
    assert!(below.ok && !above.ok, "{below:?} {above:?}");
    let measured = above.measured_error.unwrap();
    assert!(measured.mu_star_minus_mu > 0.05 && measured.contact_width < 0.02);
    assert!((0.38..0.42).contains(&above.contact_width_over_thickness));
    // "beyond the mu*(P) chart"; the verdict is the one `verdict` gives everywhere
    assert!(p.plane.sweep.max < 2.0e5);
    let sol = solve(&p.plane_inputs().with_load(2.2e5), model).unwrap();
    assert_eq!(verdict(&sol), above);
}

#[test]
fn the_lab_friction_preset_shows_what_its_description_says() {
    use wearlab::fit;
    let p = preset::bundled("lab-friction.toml").unwrap().unwrap();
    let e = p.explore.as_ref().unwrap();
    assert_eq!(e.data.as_deref(), Some("lab-friction.csv"));
    let file = BUNDLED_DATA
        .iter()
        .find(|d| d.file == "lab-friction.csv")
        .unwrap();
    let data =
        wearlab::data::read_text(Path::new("presets/lab-friction.csv"), file.text, &p).unwrap();
    // "SYNTHETIC", its parameters and noise in the header notes; 20 loads from 1 to 100 kN/m
    assert!(data.notes[0].starts_with("SYNTHETIC data, not a measurement"));
    assert!(data.notes.join(" ").contains("mu = 0.3, k = 2e-11 1/Pa"));
    assert!(
        data.notes
            .join(" ")
            .contains("noise of sd 0.002 in mu (seed 25")
    );
    assert_eq!(data.len(), 20);
    assert_eq!(data.x.values[0], 1e3);
    assert_eq!(data.x.values[19], 1e5);
    // the same values as examples/lab's file, with the sd as a column
    let example =
        wearlab::data::read(Path::new("examples/lab/friction-against-load.csv"), &p).unwrap();
    assert_eq!(data.measured[0].values, example.measured[0].values);
    assert_eq!(data.measured[0].sd, Some(vec![0.002; 20]));
    // "every point lies about 0.1 above the curve" (the start, mu = 0.2)
    let model = p.plane.model;
    for (&x, &y) in data.x.values.iter().zip(&data.measured[0].values) {
        let at = solve(&p.plane_inputs().with_load(x), model)
            .unwrap()
            .mu_star;
        assert!((y - at - 0.1).abs() < 0.01, "{x}: {y} against {at}");
    }
    // "at these loads the wear term of mu* is under 0.002, the noise" (mu = 0.3, k = 2e-11)
    let mut truth = p.clone();
    truth.friction.coefficient = 0.3;
    truth.wear = 2e-11;
    for &x in &data.x.values {
        let excess = solve(&truth.plane_inputs().with_load(x), model)
            .unwrap()
            .mu_star
            - 0.3;
        assert!(excess.abs() < 0.002, "{x}: {excess}");
    }
    // "mu = 0.300 with a 95 % interval of about +-0.001"
    let mu = p.key("friction.coefficient").unwrap();
    let k = p.key("wear.coefficient").unwrap();
    let one = fit::fit(&p, &data, &[mu]).unwrap();
    let e = &one.estimates[0];
    assert!((e.value - 0.300).abs() < 0.001, "{e:?}");
    assert!(e.interval[0] < 0.3 && 0.3 < e.interval[1], "{e:?}");
    let half = 0.5 * (e.interval[1] - e.interval[0]);
    assert!((0.0005..0.002).contains(&half), "{e:?}");
    // "mu is still found, but k is 'not determined by these data' (a range over two decades
    // fits within the noise), and wear depth against sliding distance would determine it"
    let both = fit::fit(&p, &data, &[mu, k]).unwrap();
    assert!(both.estimates[0].determined && (both.estimates[0].value - 0.3).abs() < 0.002);
    let k = &both.estimates[1];
    assert!(!k.determined);
    assert!(k.interval[1] / k.interval[0] > 100.0, "{k:?}");
    let why = k.reason.as_deref().unwrap();
    assert!(
        why.starts_with("k is not determined by these data"),
        "{why}"
    );
    assert!(why.contains("wear depth against sliding distance"), "{why}");
}
