//! The `[lesson]` section: what it reads, what it refuses (with the line), the round trip through
//! a save, and the grading of typed answers.

use std::path::Path;

use crate::preset::{BUNDLED, Preset, Tolerance, grade, parse, to_toml};
use crate::sweeps::quantity::by_name;
use crate::views::{Chart, PlaneChart, View};

/// The default preset (plane, wide model) with `lesson` appended.
fn with_lesson(lesson: &str) -> String {
    format!("{}\n{lesson}", BUNDLED[0].text)
}

fn read(lesson: &str) -> Result<Preset, String> {
    parse(&with_lesson(lesson), Path::new("lab.toml")).map_err(|e| e.to_string())
}

/// The 1-based line of the first line of `text` that starts with `start`.
fn line_of(text: &str, start: &str) -> usize {
    1 + text.lines().position(|l| l.starts_with(start)).unwrap()
}

const LESSON: &str = r#"[lesson]
view = "mu* against load"
locked = ["material.thickness", "plane.model"]

[[lesson.questions]]
text = "What is mu* at the preset's load?"
answer = "mu_star"
tolerance = "0.5 %"

[[lesson.questions]]
text = "How wide is the contact at 2 kN/m?"
answer = "a"
tolerance = "1 um"
reveal = true
at = ["plane.load=2 kN/m"]

[[lesson.questions]]
text = "Does the wide model hold here?"
answer = "validity.ok"
"#;

#[test]
fn a_lesson_reads_its_view_locked_keys_and_questions() {
    let preset = read(LESSON).unwrap();
    let lesson = preset.lesson.clone().unwrap();
    assert_eq!(
        lesson.view,
        Some(View::Chart(Chart::Plane(PlaneChart::MuStar)))
    );
    let locked: Vec<String> = lesson.locked.iter().map(|k| k.to_string()).collect();
    assert_eq!(locked, ["material.thickness", "plane.model"]);
    assert!(lesson.locks(preset.key("plane.model").unwrap()));
    assert!(!lesson.locks(preset.key("plane.load").unwrap()));
    let q = &lesson.questions;
    assert_eq!(q.len(), 3);
    assert_eq!(q[0].answer.to_string(), "mu_star");
    assert_eq!(q[0].tolerance, Tolerance::Percent(0.5));
    assert!(!q[0].reveal);
    // "1 um" in the unit of a [m]: 1e-6 as the decimal typed
    assert_eq!(q[1].tolerance, Tolerance::Absolute(1e-6));
    assert_eq!(q[1].at, ["plane.load=2 kN/m"]);
    assert!(q[1].reveal);
    assert_eq!(q[2].tolerance, crate::preset::DEFAULT_TOLERANCE);
}

#[test]
fn a_question_is_answered_at_its_own_inputs() {
    let preset = read(LESSON).unwrap();
    let q = &preset.lesson.as_ref().unwrap().questions;
    let at_load = q[1].solve(&preset).unwrap();
    let mut moved = preset.clone();
    moved.plane.load = 2e3;
    let a = crate::physics::plane::solve(&moved.plane_inputs(), moved.plane.model)
        .unwrap()
        .a;
    assert_eq!(at_load, a);
    assert_eq!(q[0].solve(&preset).unwrap(), {
        crate::physics::plane::solve(&preset.plane_inputs(), preset.plane.model)
            .unwrap()
            .mu_star
    });
}

#[test]
fn a_save_keeps_the_lesson() {
    let preset = read(LESSON).unwrap();
    let text = to_toml(&preset);
    assert!(text.contains("[lesson]"), "{text}");
    assert!(text.contains("[[lesson.questions]]"), "{text}");
    let again = parse(&text, Path::new("saved.toml")).unwrap();
    assert_eq!(again.lesson, preset.lesson);
    // a preset without a lesson is written without one
    let plain = parse(BUNDLED[0].text, Path::new("x.toml")).unwrap();
    assert!(!to_toml(&plain).contains("lesson"));
}

#[test]
fn refusals_name_the_line_and_what_is_allowed() {
    let cases = [
        (
            LESSON.replace("view = \"mu* against load\"", "view = \"mu against load\""),
            "view = ",
            "view = \"mu against load\" is not a view of a plane preset: the views are \
             \"pressure and shear\", \"wear\", \"mu* against load\", \"contact edges against \
             load\", \"punch and strip surface\", \"energy losses against load\" (\"sweep\" and \"regime map\" need an [explore] section with one or two axes)",
        ),
        (
            LESSON.replace("\"plane.model\"]", "\"plane.modle\"]"),
            "locked = ",
            "locked: unknown key 'plane.modle'",
        ),
        (
            LESSON.replacen("answer = \"mu_star\"", "answer = \"mustar\"", 1),
            "answer = \"mustar\"",
            "answer = \"mustar\" is not a quantity of a plane preset: e.g. \"mu_star\", \
             \"mu_star_minus_mu\"",
        ),
        (
            LESSON.replace("tolerance = \"1 um\"", "tolerance = \"1 kPa\""),
            "tolerance = \"1 kPa\"",
            "tolerance = \"1 kPa\": '1 kPa': unknown unit",
        ),
        (
            LESSON.replace("tolerance = \"0.5 %\"", "tolerance = \"-1 %\""),
            "tolerance = \"-1 %\"",
            "the tolerance must be above 0 and finite; e.g. tolerance = \"0.5 %\" or 0.01",
        ),
        (
            LESSON.replace("plane.load=2 kN/m", "plane.load=2 kPa"),
            "at = ",
            "at: plane.load=2 kPa: plane.load = '2 kPa': unknown unit",
        ),
        (
            LESSON.replace("reveal = true", "reveal = true\nhint = \"x\""),
            "hint",
            "unknown",
        ),
    ];
    for (lesson, line, why) in cases {
        let text = with_lesson(&lesson);
        let err = read(&lesson).unwrap_err();
        let at = format!("lab.toml:{}: ", line_of(&text, line));
        assert!(err.starts_with(&at), "{err} (expected {at})");
        assert!(err.contains(why), "{err}\n(expected {why})");
    }
}

#[test]
fn typed_answers_are_graded_with_units_and_the_tolerance() {
    let a = by_name(crate::preset::Problem::Plane, "a").unwrap();
    let mu = by_name(crate::preset::Problem::Plane, "mu_star").unwrap();
    let ok = by_name(crate::preset::Problem::Plane, "validity.ok").unwrap();
    let um = Tolerance::Absolute(1e-6);
    // a = 52.5 um typed in um, in mm, in m
    assert_eq!(grade("52 um", 52.5e-6, a, um), Ok(true));
    assert_eq!(grade("0.0525 mm", 52.5e-6, a, um), Ok(true));
    assert_eq!(grade("5.25e-5", 52.5e-6, a, um), Ok(true));
    assert_eq!(grade("50 um", 52.5e-6, a, um), Ok(false));
    assert!(
        grade("52 kPa", 52.5e-6, a, um)
            .unwrap_err()
            .contains("unknown unit")
    );
    let half = Tolerance::Percent(0.5);
    assert_eq!(grade("0.398", 0.3995, mu, half), Ok(true));
    assert_eq!(grade("0.39", 0.3995, mu, half), Ok(false));
    assert_eq!(grade("yes", 1.0, ok, half), Ok(true));
    assert_eq!(grade("No", 1.0, ok, half), Ok(false));
    assert!(grade("maybe", 1.0, ok, half).is_err());
}
