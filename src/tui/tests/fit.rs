//! The fit from the explorer (`F`): the form offers mu and k first and refuses a key the lesson
//! locks; the fit runs on the fit thread (here its function, as the thread runs it), Esc or an
//! edit stops it; its best values enter the form as one undo step and a window reports them.

use std::path::PathBuf;
use std::sync::atomic::AtomicBool;

use ratatui::crossterm::event::KeyCode;

use super::*;
use crate::engine::fit_worker::{self, FitJob, FitRequest};
use crate::tui::app::Mode;
use crate::tui::effects;
use crate::tui::fit_state::FitReport;

/// The lab preset with its data file read and its first solve delivered.
fn lab() -> App {
    let mut app = app("lab-friction.toml");
    app.doc.source = Some("bundled: lab-friction.toml".into());
    let cmds = app.start();
    for c in &cmds {
        if let Command::ReadData(paths, preset) = c {
            update(&mut app, effects::read_data(paths, preset));
        }
    }
    settle(&mut app, cmds.clone());
    super::explore::explored(&mut app, &cmds);
    assert!(app.ui.data.is_some());
    app
}

fn message(app: &App) -> String {
    app.ui
        .message
        .as_ref()
        .map(|m| m.text.clone())
        .unwrap_or_default()
}

/// `F`, space on each of the first `free` inputs, Enter: the fit request sent.
fn start(app: &mut App, free: usize) -> (u64, FitRequest) {
    press(app, KeyCode::Char('F'));
    assert!(matches!(app.ui.mode, Mode::FitForm(_)), "{:?}", app.ui.mode);
    for _ in 0..free {
        press(app, KeyCode::Char(' '));
        press(app, KeyCode::Down);
    }
    let cmds = press(app, KeyCode::Enter);
    match cmds.as_slice() {
        [Command::Fit(generation, job)] => match &**job {
            FitJob::Fit(request) => (*generation, (**request).clone()),
            FitJob::Cancel => panic!("a cancel"),
        },
        _ => panic!("{cmds:?}"),
    }
}

/// Runs the fit as the fit thread does and delivers its answer.
fn finish(app: &mut App, generation: u64, request: &FitRequest) -> Vec<Command> {
    let answer = fit_worker::run(generation, request, &AtomicBool::new(false)).unwrap();
    let cmds = update(app, Msg::Fitted(Box::new(answer)));
    settle(app, cmds.clone());
    super::explore::explored(app, &cmds);
    cmds
}

fn report(app: &App) -> FitReport {
    match &app.ui.mode {
        Mode::FitResult(report, _) => (**report).clone(),
        mode => panic!("{mode:?}"),
    }
}

#[test]
fn the_form_offers_mu_and_k_first_and_not_the_datas_x() {
    let mut app = lab();
    press(&mut app, KeyCode::Char('F'));
    let Mode::FitForm(form) = &app.ui.mode else {
        panic!("{:?}", app.ui.mode)
    };
    let names: Vec<&str> = form.offered.iter().map(|o| o.key.param().key).collect();
    assert_eq!(names[..2], ["friction.coefficient", "wear.coefficient"]);
    assert!(names.contains(&"material.youngs_modulus"), "{names:?}");
    // the data's x (each row sets it) and the charts' settings are not offered
    assert!(!names.contains(&"plane.load"), "{names:?}");
    assert!(!names.iter().any(|n| n.contains(".sweep.")), "{names:?}");
    assert!(form.offered.iter().all(|o| !o.free && !o.locked));
    // Enter with nothing free says so and stays
    let cmds = press(&mut app, KeyCode::Enter);
    assert!(cmds.is_empty() && matches!(app.ui.mode, Mode::FitForm(_)));
    assert!(
        message(&app).contains("no input is free"),
        "{}",
        message(&app)
    );
    press(&mut app, KeyCode::Esc);
    assert_eq!(app.ui.mode, Mode::Normal);
    assert!(app.ui.fitting.is_none());
}

#[test]
fn the_fit_recovers_the_mu_of_the_datas_notes_and_one_undo_takes_it_back() {
    let mut app = lab();
    let before = app.doc.preset.clone();
    let steps = app.doc.undo.len();
    let (generation, request) = start(&mut app, 1);
    assert_eq!(request.keys.len(), 1);
    assert!(message(&app).starts_with("fitting mu to lab-friction.csv (20 points)"));
    assert!(app.ui.fitting.is_some());
    let cmds = finish(&mut app, generation, &request);
    assert!(
        cmds.iter().any(|c| matches!(c, Command::Solve(..))),
        "{cmds:?}"
    );
    // the data's notes: made at mu = 0.3 with noise sd 0.002 (presets/lab-friction.csv)
    let mu = app.doc.preset.friction.coefficient;
    let fit = crate::fit::fit(&before, &request.data, &request.keys).unwrap();
    let e = &fit.estimates[0];
    assert_eq!(mu, e.value);
    assert!(
        e.determined && e.interval[0] < 0.3 && 0.3 < e.interval[1],
        "{e:?}"
    );
    let text = report(&app).paragraphs.join("\n");
    // the interval's half-width, 8.7e-4, supports five decimals: the form, the status and the
    // legend read mu = 0.29973, not the minimisation's sixteen digits
    assert_eq!(format!("{mu}"), "0.29973");
    let said = "mu = 0.29973, 95 % interval 0.29886 .. 0.30061";
    assert!(text.contains(said), "{text}");
    assert!(text.contains("chi-square"), "{text}");
    assert_eq!(app.doc.undo.len(), steps + 1);
    // the window closes; one undo gives back every value the fit set
    press(&mut app, KeyCode::Esc);
    assert_eq!(app.ui.mode, Mode::Normal);
    press(&mut app, KeyCode::Char('u'));
    assert_eq!(app.doc.preset, before);
    assert!(
        message(&app).starts_with("undo: fit mu = "),
        "{}",
        message(&app)
    );
}

#[test]
fn k_is_said_not_determined_with_the_measurement_that_would_determine_it() {
    let mut app = lab();
    let (generation, request) = start(&mut app, 2);
    assert_eq!(
        request.keys.iter().map(|k| k.symbol()).collect::<Vec<_>>(),
        ["mu", "k"]
    );
    finish(&mut app, generation, &request);
    let text = report(&app).paragraphs.join("\n");
    assert!(text.contains("k is not determined by these data"), "{text}");
    assert!(
        text.contains("wear depth against sliding distance"),
        "{text}"
    );
    assert!(!text.contains("mu is not determined"), "{text}");
    insta::assert_snapshot!("fit_report_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("fit_report_120x40", screen(&app, 120, 40, PLAIN));
}

#[test]
fn the_forms_screens() {
    let mut app = lab();
    press(&mut app, KeyCode::Char('F'));
    press(&mut app, KeyCode::Char(' '));
    press(&mut app, KeyCode::Down);
    insta::assert_snapshot!("fit_form_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("fit_form_120x40", screen(&app, 120, 40, PLAIN));
}

#[test]
fn esc_or_an_edit_stops_a_running_fit_and_its_late_answer_changes_nothing() {
    let mut app = lab();
    let before = app.doc.preset.clone();
    let (generation, request) = start(&mut app, 1);
    let cmds = press(&mut app, KeyCode::Esc);
    assert!(
        matches!(cmds.as_slice(), [Command::Fit(_, job)] if **job == FitJob::Cancel),
        "{cmds:?}"
    );
    assert!(app.ui.fitting.is_none());
    finish(&mut app, generation, &request);
    assert_eq!(app.doc.preset, before);
    assert_eq!(app.ui.mode, Mode::Normal);

    let (generation, request) = start(&mut app, 1);
    let cmds = press(&mut app, KeyCode::Right);
    assert!(
        cmds.iter()
            .any(|c| matches!(c, Command::Fit(_, job) if **job == FitJob::Cancel)),
        "{cmds:?}"
    );
    assert!(app.ui.fitting.is_none());
    let edited = app.doc.preset.clone();
    finish(&mut app, generation, &request);
    assert_eq!(app.doc.preset, edited);
}

#[test]
fn a_key_the_lesson_locks_is_not_freed_and_no_data_no_form() {
    let mut app = solved("friction-half-plane.toml");
    press(&mut app, KeyCode::Char('F'));
    assert_eq!(app.ui.mode, Mode::Normal);
    assert!(
        message(&app).contains("draw one first"),
        "{}",
        message(&app)
    );
    let dir = tempfile::tempdir().unwrap();
    let path: PathBuf = dir.path().join("mu.csv");
    std::fs::write(&path, "load [N/m],mu [-]\n1e3,0.41\n1e4,0.42\n1e5,0.43\n").unwrap();
    let read = effects::read_data(&[path], &app.doc.preset);
    update(&mut app, read);
    press(&mut app, KeyCode::Char('F'));
    let Mode::FitForm(form) = &app.ui.mode else {
        panic!("{:?}", app.ui.mode)
    };
    assert!(form.offered[0].locked, "{:?}", form.offered[0]);
    press(&mut app, KeyCode::Char(' '));
    let Mode::FitForm(form) = &app.ui.mode else {
        panic!("{:?}", app.ui.mode)
    };
    assert!(!form.offered[0].free);
    assert_eq!(
        message(&app),
        "mu is locked by the lesson: it stays 0.4; a fit cannot free it"
    );
}

/// A mu typed with many digits (a fit's value pasted in) is written in the status as every
/// number there is, to four significant digits: "(mu 0.2998)", not its sixteen digits.
#[test]
fn the_status_writes_a_long_typed_mu_to_four_digits() {
    let preset = bundled("polymer-coating.toml")
        .with_settings(&["friction.coefficient=0.2997513918560902"])
        .unwrap();
    let mut app = App::new(preset, None, Places::default());
    let cmds = app.start();
    settle(&mut app, cmds);
    for (w, h) in [(80, 24), (120, 40)] {
        let s = screen(&app, w, h, PLAIN);
        assert!(s.contains(" (mu 0.2998)"), "{s}");
        assert!(!s.contains("0.29975139"), "{s}");
    }
}
