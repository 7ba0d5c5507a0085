//! A preset's lesson in the explorer: it opens on the lesson's view, its locked keys refuse every
//! edit with the reason, and the questions window grades a right and a wrong typed answer (the
//! program's value shown only where the lesson reveals it); snapshots of the window.

use ratatui::crossterm::event::KeyCode;

use super::update::message;
use super::{PLAIN, app, press, screen, type_text};
use crate::tui::app::{App, Command, Mode, Msg};
use crate::tui::charts::{Chart, PlaneChart};
use crate::tui::effects;
use crate::tui::update::update;

/// The friction-half-plane lesson with the questions window open and the program's answers in.
fn quiz() -> App {
    let mut app = app("friction-half-plane.toml");
    let commands = press(&mut app, KeyCode::Char('a'));
    let [Command::AnswerLesson(preset)] = commands.as_slice() else {
        panic!("{commands:?}");
    };
    update(&mut app, effects::answer_lesson((**preset).clone()));
    assert!(matches!(app.ui.mode, Mode::Questions(_)));
    app
}

/// The program's answer to question `n` of the app's lesson.
fn value(app: &App, n: usize) -> f64 {
    *app.lesson.values.as_ref().unwrap()[n].as_ref().unwrap()
}

#[test]
fn a_lesson_opens_on_its_view_and_says_it_has_questions() {
    let app = app("friction-half-plane.toml");
    assert_eq!(app.ui.chart, Chart::Plane(PlaneChart::MuStar));
    assert_eq!(message(&app), "a lesson: a opens its 3 questions");
}

#[test]
fn locked_keys_refuse_every_edit_with_the_reason() {
    let mut app = app("friction-half-plane.toml");
    let mu = app
        .rows()
        .iter()
        .position(|r| r.to_string() == "friction.coefficient")
        .unwrap();
    app.ui.selected = mu - 1;
    press(&mut app, KeyCode::Down);
    assert_eq!(message(&app), "mu is locked by the lesson: it stays 0.4");
    let before = app.doc.preset.clone();
    for k in [KeyCode::Right, KeyCode::Left, KeyCode::Enter] {
        assert!(press(&mut app, k).is_empty());
        assert_eq!(message(&app), "mu is locked by the lesson: it stays 0.4");
        assert_eq!(app.ui.mode, Mode::Normal);
    }
    assert_eq!(app.doc.preset, before);
    assert!(!app.doc.dirty);
    // the form marks it; a free key still moves
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains("= mu"), "{s}");
    let load = app
        .rows()
        .iter()
        .position(|r| r.to_string() == "plane.load")
        .unwrap();
    app.ui.selected = load;
    assert_eq!(press(&mut app, KeyCode::Right).len(), 1);
    assert!(app.doc.preset.plane.load > before.plane.load);
}

#[test]
fn a_right_and_a_wrong_answer_are_told_and_only_a_revealed_value_is_shown() {
    let mut app = quiz();
    // question 1: mu* at 1 kN/m within 1e-4, not revealed; mu = 0.4 itself is 5.5e-4 off
    let mu_star = value(&app, 0);
    type_text(&mut app, &format!("{:.4}", mu_star));
    press(&mut app, KeyCode::Enter);
    assert_eq!(message(&app), "question 1: right");
    type_text(&mut app, "0.4");
    press(&mut app, KeyCode::Enter);
    assert_eq!(message(&app), "question 1: not right");
    let s = screen(&app, 80, 24, PLAIN);
    assert!(!s.contains("the program:"), "{s}");
    // question 3: a in um, revealed
    press(&mut app, KeyCode::Down);
    press(&mut app, KeyCode::Down);
    let s = screen(&app, 80, 24, PLAIN);
    assert!(
        s.contains("answer with its unit, m or prefixed (within 2 %):"),
        "{s}"
    );
    let a = value(&app, 2);
    type_text(&mut app, &format!("{} um", a * 1e6));
    press(&mut app, KeyCode::Enter);
    assert!(
        message(&app).starts_with("question 3: right (the program: "),
        "{}",
        message(&app)
    );
    // a unit of another quantity is not graded: typed again
    type_text(&mut app, "3 kPa");
    press(&mut app, KeyCode::Enter);
    assert!(message(&app).contains("unknown unit"), "{}", message(&app));
    assert_eq!(app.lesson.marks[2].as_ref().map(|m| m.right), Some(true));
    press(&mut app, KeyCode::Esc);
    assert_eq!(app.ui.mode, Mode::Normal);
}

#[test]
fn the_answers_are_those_of_the_preset_as_opened() {
    let mut app = app("friction-half-plane.toml");
    let load = app
        .rows()
        .iter()
        .position(|r| r.to_string() == "plane.load")
        .unwrap();
    app.ui.selected = load;
    press(&mut app, KeyCode::Right);
    let commands = press(&mut app, KeyCode::Char('a'));
    let [Command::AnswerLesson(preset)] = commands.as_slice() else {
        panic!("{commands:?}");
    };
    assert_eq!(preset.plane.load, 1e3);
    // answers for other inputs (another preset opened meanwhile) are not taken
    let edited = Box::new(app.doc.preset.clone());
    update(&mut app, Msg::LessonAnswered(edited, vec![Ok(1.0); 3]));
    assert!(app.lesson.values.is_none());
}

#[test]
fn a_preset_without_questions_says_so() {
    let mut app = app("polymer-coating.toml");
    assert!(press(&mut app, KeyCode::Char('a')).is_empty());
    assert!(message(&app).starts_with("this preset has no lesson questions"));
}

#[test]
fn the_questions_window_at_80x24_and_120x40() {
    let mut app = quiz();
    type_text(&mut app, "0.3");
    press(&mut app, KeyCode::Enter);
    press(&mut app, KeyCode::Down);
    press(&mut app, KeyCode::Down);
    type_text(&mut app, "120 um");
    press(&mut app, KeyCode::Enter);
    press(&mut app, KeyCode::Up);
    type_text(&mut app, "-0.05");
    insta::assert_snapshot!("questions_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("questions_120x40", screen(&app, 120, 40, PLAIN));
}

#[test]
fn undoing_an_open_brings_back_the_lesson() {
    let mut app = app("friction-half-plane.toml");
    let other = crate::tui::app::PickerEntry {
        title: "polymer".into(),
        source: "bundled: polymer-coating.toml".into(),
        path: None,
        preset: Ok(super::bundled("polymer-coating.toml")),
        folder: "lab".into(),
    };
    crate::tui::actions::open(&mut app, other);
    assert!(app.lesson.marks.is_empty());
    press(&mut app, KeyCode::Char('u'));
    assert_eq!(app.lesson.marks.len(), 3);
    assert_eq!(app.lesson.preset.name, app.doc.preset.name);
}
