//! A save of a preset opened from a file keeps the file as its author wrote it: comments, key
//! order, units and layout, with only the edited values rewritten (in the unit the author wrote
//! them in); a data file it names is still found from the folder it is saved to; without the
//! author's file the preset is written as before.

use std::fs;
use std::path::Path;

use wearlab::physics::plane::Shape;
use wearlab::preset::{Key, Links, Origin, Preset, load, save_edited, to_toml};

/// A preset as an instructor writes it by hand: comments, units, its own key order.
const AUTHOR: &str = r#"# Lab 3: a thin coating, written by hand
schema = 1
name = "Lab 3"
description = """
A polymer coating on steel.
Look at the pressure chart."""
problem = "plane"

[material]
thickness = "2 mm"        # the coating
youngs_modulus = "0.5 GPa"
poisson_ratio = 0.35

# the pair's friction, measured on the tribometer
[friction]
coefficient = 0.1

[wear]
coefficient = "4e-5 mm3/Nm"   # specific wear rate

[plane]
model = "wide"
load = "10 kN/m"
radius = "50 mm"
"#;

fn edited(preset: &Preset, key: &str, value: f64) -> Preset {
    let mut next = preset.clone();
    next.set(Key::of(key).unwrap(), value).unwrap();
    next
}

/// Writes `text` to `dir/name`, loads it, saves `edit` of it to `to`; the text saved.
fn save_of(text: &str, dir: &Path, edit: impl Fn(&Preset) -> Preset, to: &Path) -> String {
    let from = dir.join("lab.toml");
    fs::write(&from, text).unwrap();
    let opened = load(&from).unwrap();
    let origin = Origin {
        path: from,
        preset: opened.clone(),
    };
    let (saved, kept) = save_edited(&edit(&opened), Some(&origin), to, Links::Follow).unwrap();
    assert_eq!(kept, None);
    // the file reads as the preset saved; a plane preset without a [spatial] section gets the
    // default duration of its wear, which the plane problem does not use
    let read = load(to).unwrap();
    let mut expected = saved;
    if expected.problem == wearlab::preset::Problem::Plane {
        expected.spatial.duration = read.spatial.duration;
    }
    assert_eq!(read, expected, "the file reads as the preset saved");
    fs::read_to_string(to).unwrap()
}

#[test]
fn an_edited_value_is_rewritten_in_its_unit_and_every_other_byte_stays() {
    let dir = tempfile::tempdir().unwrap();
    let at = dir.path().join("lab.toml");
    let cases: [(&str, f64, &str, &str); 4] = [
        (
            "material.thickness",
            3e-3,
            "thickness = \"2 mm\"",
            "thickness = \"3 mm\"",
        ),
        (
            "friction.coefficient",
            0.3,
            "coefficient = 0.1",
            "coefficient = 0.3",
        ),
        (
            "wear.coefficient",
            5e-14,
            "coefficient = \"4e-5 mm3/Nm\"",
            "coefficient = \"5e-5 mm3/Nm\"",
        ),
        // the sweep the file left to its default (P/100 .. 100 P) stays where it was shown
        (
            "plane.load",
            2.5e4,
            "load = \"10 kN/m\"\nradius = \"50 mm\"\n",
            "load = \"25 kN/m\"\nradius = \"50 mm\"\nsweep = { load_min = 100.0, load_max = \
             1000000.0, points = 60, scale = \"log\" }\n",
        ),
    ];
    for (key, value, was, now) in cases {
        let text = save_of(AUTHOR, dir.path(), |p| edited(p, key, value), &at);
        assert_eq!(text, AUTHOR.replacen(was, now, 1), "{key}");
    }
    // nothing edited: the file as it was, byte for byte
    assert_eq!(save_of(AUTHOR, dir.path(), Clone::clone, &at), AUTHOR);
}

#[test]
fn a_saved_copy_keeps_the_text_and_says_where_it_came_from() {
    let dir = tempfile::tempdir().unwrap();
    let copy = dir.path().join("copy.toml");
    let text = save_of(
        AUTHOR,
        dir.path(),
        |p| {
            let mut next = edited(p, "friction.coefficient", 0.3);
            next.name = format!("{} (edited)", p.name);
            next.description = format!("Edited from \"Lab 3\": mu 0.1 -> 0.3.\n{}", p.description);
            next
        },
        &copy,
    );
    // the name, the description and mu rewritten; the comments, the units and the key order
    // are the author's
    let expected = AUTHOR
        .replacen("name = \"Lab 3\"", "name = \"Lab 3 (edited)\"", 1)
        .replacen(
            "\"\"\"\nA polymer",
            "\"\"\"\nEdited from \"Lab 3\": mu 0.1 -> 0.3.\nA polymer",
            1,
        )
        .replacen("coefficient = 0.1", "coefficient = 0.3", 1);
    assert_eq!(text, expected);
}

/// A table-shape preset beside its profile.
const TABLE: &str = "schema = 1
problem = \"plane\"   # a worn pin, measured
[material]
youngs_modulus = 2.0e9
poisson_ratio = 0.4
thickness = \"20 um\"
[wear]
coefficient = 1.0e-11
[plane]
model = \"narrow\"
load = 1.0e4
shape = { kind = \"table\", file = \"worn.csv\" }
";

/// The profile of a parabola of radius 50 mm over |x| <= 2 mm, 201 rows.
fn parabola_csv() -> String {
    let mut out = String::from("x [m],g [m]\n");
    for i in 0..=200 {
        let x = -2e-3 + 2e-5 * i as f64;
        out += &format!("{x:e},{:e}\n", x * x / 0.1);
    }
    out
}

#[test]
fn a_profile_is_still_found_after_a_save_into_another_folder() {
    let dir = tempfile::tempdir().unwrap();
    let (lab, mine) = (dir.path().join("lab"), dir.path().join("mine"));
    fs::create_dir(&lab).unwrap();
    fs::create_dir(&mine).unwrap();
    fs::write(lab.join("worn.csv"), parabola_csv()).unwrap();
    let copy = mine.join("copy.toml");
    let text = save_of(TABLE, &lab, |p| edited(p, "plane.load", 2e4), &copy);
    assert_eq!(
        text,
        TABLE
            .replacen("load = 1.0e4", "load = 20000.0", 1)
            .replacen(
                "\"worn.csv\" }\n",
                "\"../lab/worn.csv\" }\nsweep = { load_min = 100.0, load_max = 1000000.0, points = \
             60, scale = \"log\" }\n",
                1
            )
    );
    // the copy reads the same profile
    let (from, to) = (load(&lab.join("lab.toml")).unwrap(), load(&copy).unwrap());
    let spline = |p: &Preset| match &p.plane.shape {
        Some(Shape::Table(t)) => t.spline.clone(),
        other => panic!("{other:?}"),
    };
    assert_eq!(spline(&from), spline(&to));
    // saved back into the profile's folder, the name is the author's again
    let back = lab.join("back.toml");
    let origin = Origin {
        path: copy.clone(),
        preset: to.clone(),
    };
    save_edited(&to, Some(&origin), &back, Links::Follow).unwrap();
    assert!(
        fs::read_to_string(&back)
            .unwrap()
            .contains("file = \"worn.csv\"")
    );
}

#[test]
fn without_the_author_s_file_the_preset_is_written_as_before() {
    let dir = tempfile::tempdir().unwrap();
    let from = dir.path().join("lab.toml");
    fs::write(&from, AUTHOR).unwrap();
    let opened = load(&from).unwrap();
    let next = edited(&opened, "friction.coefficient", 0.3);
    let to = dir.path().join("copy.toml");
    // no origin (a bundled or new preset)
    save_edited(&next, None, &to, Links::Follow).unwrap();
    assert_eq!(fs::read_to_string(&to).unwrap(), to_toml(&next));
    // the file changed on disk since it was opened: its text is not the base of the save
    fs::write(
        &from,
        AUTHOR.replace("poisson_ratio = 0.35", "poisson_ratio = 0.3"),
    )
    .unwrap();
    let origin = Origin {
        path: from.clone(),
        preset: opened,
    };
    save_edited(&next, Some(&origin), &to, Links::Follow).unwrap();
    assert_eq!(fs::read_to_string(&to).unwrap(), to_toml(&next));
}

/// A spatial preset that leaves its duration to the default (five of the slowest decay times).
const WAVES: &str = r#"schema = 1
problem = "spatial"
[material]
youngs_modulus = "10 MPa"   # rubber
poisson_ratio = 0.45
thickness = "5 mm"
[friction]
coefficient = 0.5
[wear]
coefficient = "1 mm3/Nm"
[spatial]
mean_pressure = "0.2 MPa"
sliding_speed = "0.1 m/s"
[[spatial.harmonics]]   # the long wave
amplitude = "2 um"
wavenumber_x = 6283.185307179586
wavenumber_y = 0.0
phase_x = 0.0
phase_y = 1.5707963267948966
[[spatial.harmonics]]   # its second harmonic
amplitude = "0.5 um"
wavenumber_x = 12566.370614359172
wavenumber_y = 0.0
phase_x = 0.0
phase_y = 1.5707963267948966
"#;

#[test]
fn a_default_that_follows_an_edit_is_written_and_harmonics_stay_in_place() {
    let dir = tempfile::tempdir().unwrap();
    let at = dir.path().join("lab.toml");
    // the wear doubled: the duration the file leaves out would follow it, so it is written
    let text = save_of(
        WAVES,
        dir.path(),
        |p| edited(p, "wear.coefficient", 2e-9),
        &at,
    );
    assert!(text.contains("coefficient = \"2 mm3/Nm\""), "{text}");
    assert!(text.contains("duration = "), "{text}");
    assert!(text.contains("[[spatial.harmonics]]   # its second harmonic"));
    // the second harmonic's amplitude, in the unit it was written in
    let text = save_of(
        WAVES,
        dir.path(),
        |p| {
            let mut next = p.clone();
            next.set(Key::harmonic(1, "amplitude").unwrap(), 7.5e-7)
                .unwrap();
            next
        },
        &at,
    );
    assert_eq!(
        text,
        WAVES.replacen("amplitude = \"0.5 um\"", "amplitude = \"0.75 um\"", 1)
    );
    // a harmonic added in the explorer is added after the author's
    let text = save_of(
        WAVES,
        dir.path(),
        |p| {
            let mut next = p.clone();
            let mut third = next.spatial.harmonics[1];
            third.wavenumber_x *= 1.5;
            next.spatial.harmonics.push(third);
            next
        },
        &at,
    );
    let added = text.strip_prefix(WAVES).expect("the author's text first");
    assert_eq!(added.matches("[[spatial.harmonics]]").count(), 1, "{added}");
}
