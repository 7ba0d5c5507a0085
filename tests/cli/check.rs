//! `wearlab check PRESET`: the answer key of a lesson, each answer equal to `solve --output` at
//! the question's inputs; JSON; exit 2 for a preset without questions and a bad lesson, 3 for a
//! question the solver cannot answer.

use crate::run::wearlab as run;

/// `solve --output KEY --format json` at the preset with `settings`.
fn solved(preset: &str, key: &str, settings: &[&str]) -> serde_json::Value {
    let mut args = vec!["solve", preset, "--output", key, "--format", "json"];
    for s in settings {
        args.extend(["--set", s]);
    }
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    serde_json::from_str::<serde_json::Value>(&out).unwrap()[key].clone()
}

#[test]
fn the_answer_key_of_each_bundled_lesson_is_solve_s_answer() {
    for (preset, count) in [
        ("presets/hertz-check.toml", 3),
        ("presets/friction-half-plane.toml", 3),
    ] {
        let (code, out, err) = run(&["check", preset, "--format", "json"]);
        assert_eq!(code, 0, "{err}");
        let items: Vec<serde_json::Value> = serde_json::from_str(&out).unwrap();
        assert_eq!(items.len(), count, "{out}");
        let first = out.lines().nth(1).unwrap();
        assert!(first.starts_with("  {\"text\": "), "{out}");
        let text: Vec<_> = ["\"text\"", "\"answer\"", "\"value\"", "\"unit\""]
            .iter()
            .map(|k| first.find(k).unwrap())
            .collect();
        assert!(text.is_sorted(), "keys in the documented order: {first}");
        let (code, lines, _) = run(&["check", preset]);
        assert_eq!(code, 0);
        assert_eq!(lines.lines().count(), 2 * count, "{lines}");
        for item in &items {
            let key = item["answer"].as_str().unwrap();
            let text = item["text"].as_str().unwrap();
            // the questions at another load say it, as `at` sets it
            let at: &[&str] = if text.contains("P = 40 kN/m") {
                &["plane.load=40 kN/m"]
            } else if text.contains("P = 10 kN/m") && preset.contains("friction") {
                &["plane.load=10 kN/m"]
            } else {
                &[]
            };
            assert_eq!(item["value"], solved(preset, key, at), "{preset}: {text}");
            assert!(lines.contains(text), "{lines}");
        }
    }
}

#[test]
fn the_hertz_lesson_s_answers_are_hertz_s() {
    // a = sqrt(4 R P/(pi E*)), E* = E/(1 - nu^2) (Johnson, Contact Mechanics, eq. 4.43), at
    // R = 50 mm, E = 210 GPa, nu = 0.3: 52.5 um at 10 kN/m, twice that at four times the load
    let (code, out, err) = run(&["check", "presets/hertz-check.toml", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let items: Vec<serde_json::Value> = serde_json::from_str(&out).unwrap();
    let e_star = 2.1e11 / (1.0 - 0.3f64 * 0.3);
    let hertz = |p: f64| (4.0 * 0.05 * p / (std::f64::consts::PI * e_star)).sqrt();
    for (item, p) in items.iter().zip([1e4, 4e4]) {
        let a = item["value"].as_f64().unwrap();
        assert!(
            (a / hertz(p) - 1.0).abs() < 1e-6,
            "{a} against {}",
            hertz(p)
        );
        assert_eq!(item["unit"], "m");
    }
    assert_eq!(items[2]["answer"], "mu_star");
    assert!(items[2]["value"].as_f64().unwrap().abs() < 1e-9);
}

#[test]
fn refusals_and_unanswerable_questions_say_why() {
    let (code, out, err) = run(&["check", "presets/polymer-coating.toml"]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert!(err.contains("has no [[lesson.questions]]"), "{err}");
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string("presets/friction-half-plane.toml").unwrap();
    let bad = dir.path().join("bad.toml");
    std::fs::write(&bad, text.replace("answer = \"a\"", "answer = \"width\"")).unwrap();
    let (code, _, err) = run(&["check", bad.to_str().unwrap()]);
    assert_eq!(code, 2);
    let line = 1 + text.lines().position(|l| l == "answer = \"a\"").unwrap();
    assert!(
        err.contains(&format!(
            "bad.toml:{line}: answer = \"width\" is not a quantity"
        )),
        "{err}"
    );
    // an adhesive shear of 10 GPa: a contact whose normal force is far from the load, which
    // `solve` refuses with exit 3 too
    let unsolvable = dir.path().join("unsolvable.toml");
    std::fs::write(
        &unsolvable,
        text.replace(
            "at = [\"plane.load=10 kN/m\"]",
            "at = [\"friction.adhesion=1e10\"]",
        ),
    )
    .unwrap();
    let (code, out, err) = run(&["check", unsolvable.to_str().unwrap()]);
    assert_eq!(code, 3, "{err}");
    assert!(out.is_empty());
    assert!(err.contains("question 2"), "{err}");
}
