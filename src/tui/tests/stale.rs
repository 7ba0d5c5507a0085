//! Results are labelled by the inputs they carry: never a stale result under new labels,
//! and the loop shows a result without waiting for a key.

use std::sync::mpsc::channel;
use std::time::{Duration, Instant};

use crate::engine::{Engine, Output};
use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyModifiers};

use super::*;
use crate::tui::app::PickerEntry;
use crate::tui::{Loop, LoopEvent};

fn entry(file: &str) -> PickerEntry {
    PickerEntry {
        title: bundled(file).name,
        source: format!("bundled: {file}"),
        path: None,
        preset: Ok(bundled(file)),
        folder: "lab".into(),
    }
}

#[test]
fn a_wide_result_is_never_shown_under_a_narrow_preset() {
    // open wear-dominated.toml (wide), then thin-strip-winkler.toml (narrow) from the picker
    let mut app = solved("wear-dominated.toml");
    let wide = screen(&app, 120, 40, PLAIN);
    assert!(
        wide.contains("theta = ") && wide.contains("wide model holds"),
        "{wide}"
    );
    update(
        &mut app,
        Msg::PresetsListed(vec![entry("thin-strip-winkler.toml")]),
    );
    let cmds = press(&mut app, KeyCode::Enter);
    assert_eq!(app.doc.preset.plane.model.name(), "narrow");
    // before the narrow answer: the wide result is labelled as the previous preset's
    let waiting = screen(&app, 120, 40, PLAIN);
    let old = format!("[\"{}\"] solving…", bundled("wear-dominated.toml").name);
    assert!(
        waiting.contains(&format!(" operating point  {old}")),
        "{waiting}"
    );
    assert!(
        waiting.contains(&format!("pressure and shear  {old}")),
        "{waiting}"
    );
    // after it: no theta (a narrow solution has none), the narrow verdict, no label
    settle(&mut app, cmds);
    let narrow = screen(&app, 120, 40, PLAIN);
    assert!(!narrow.contains("theta"), "{narrow}");
    assert!(!narrow.contains("solving"), "{narrow}");
    assert!(narrow.contains("narrow model holds"), "{narrow}");
}

#[test]
fn a_model_switch_labels_the_previous_models_result() {
    let mut app = solved("polymer-coating.toml");
    press(&mut app, KeyCode::Char('m'));
    let waiting = screen(&app, 120, 40, PLAIN);
    assert!(waiting.contains("[wide model] solving…"), "{waiting}");
}

/// On dispersion.toml at grid 512, playing, `p` then `e`: what the export holds once the plane
/// answer comes (the spatial map stays on screen until then).
fn export_after_switch(plane_load: f64) -> (Vec<Command>, String) {
    let mut preset = bundled("dispersion.toml");
    preset.spatial.grid = 512;
    preset.plane.load = plane_load;
    let mut app = App::new(preset, None, Places::default());
    let first = app.start();
    settle(&mut app, first);
    press(&mut app, KeyCode::Char(' '));
    update(&mut app, Msg::Tick);
    let switch = press(&mut app, KeyCode::Char('p'));
    assert!(
        press(&mut app, KeyCode::Char('e')).is_empty(),
        "nothing of the chart to export yet"
    );
    assert!(app.ui.message.as_ref().unwrap().text.contains("waits"));
    let mut engine = Engine::new();
    let mut exported = Vec::new();
    for a in answers(&mut engine, &switch) {
        let complete = a.complete;
        let cmds = update(&mut app, Msg::Answer(Box::new(a)));
        assert!(
            complete || cmds.is_empty(),
            "the export waits for the complete answer"
        );
        exported.extend(cmds);
    }
    (exported, app.ui.message.clone().unwrap().text)
}

#[test]
fn an_export_after_a_problem_switch_waits_for_the_charts_own_result() {
    // the plane section of dispersion.toml: the wide model holds the punch tip at 100 N/m, and
    // carries at most 6.2 kN/m
    let (exported, _) = export_after_switch(1e2);
    let [Command::Export { path, text, .. }] = exported.as_slice() else {
        panic!("{exported:?}")
    };
    assert_eq!(path.to_str(), Some("wearlab-pressure-and-shear.csv"));
    assert!(text.contains("problem = \"plane\""));
    assert!(text.contains("\npressure q2,"));
    assert!(text.lines().count() < 1000, "not the spatial map");
    // where the plane has no solution, the export says so (and writes no map under its name)
    let (exported, message) = export_after_switch(1e4);
    assert!(exported.is_empty());
    assert!(
        message.starts_with("nothing to export: the wide-strip model has no contact"),
        "{message}"
    );
}

#[test]
fn the_loop_shows_a_result_without_waiting_for_a_key() {
    let (tx, rx) = channel();
    let watchdog = tx.clone();
    let terminal = Terminal::new(TestBackend::new(100, 30)).unwrap();
    let start = Instant::now();
    let mut l = Loop::new(terminal, app("polymer-coating.toml"), PLAIN, tx, rx).unwrap();
    assert!(!l.terminal.backend().to_string().contains("valid:"));
    // the only key is a watchdog's, 20 s later: the worker's answer must wake the loop first
    std::thread::spawn(move || {
        std::thread::sleep(Duration::from_secs(20));
        let quit = KeyEvent::new(KeyCode::Char('c'), KeyModifiers::CONTROL);
        let _ = watchdog.send(LoopEvent::Input(Event::Key(quit)));
    });
    assert!(l.step().unwrap());
    assert!(start.elapsed() < Duration::from_secs(10));
    let s = l.terminal.backend().to_string();
    assert!(s.contains("valid: (a+b)/h = 0.061"), "{s}");
}

#[test]
fn a_check_against_the_strip_model_is_never_shown_for_other_inputs() {
    // polymer-coating.toml (wide, holds) solved to the end; nu = 0.49, then h = 0.1 mm: the
    // contact is then some 6 thicknesses wide, where the wide model does not hold
    let mut app = solved("polymer-coating.toml");
    let before = screen(&app, 120, 40, PLAIN);
    assert!(before.contains("wide: contact width within"), "{before}");
    select(&mut app, "nu", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "0.49");
    let first = press(&mut app, KeyCode::Enter);
    settle(&mut app, first);
    select(&mut app, "h", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "0.1 mm");
    let cmds = press(&mut app, KeyCode::Enter);
    // while solving, the old check stays under the old result's label, dimmed
    let waiting = screen(&app, 120, 40, PLAIN);
    assert!(waiting.contains("[previous inputs] solving…"), "{waiting}");
    // the new point comes alone first: its status has no check yet, none of the old one
    let mut engine = Engine::new();
    let answers = answers(&mut engine, &cmds);
    update(&mut app, Msg::Answer(Box::new(answers[0].clone())));
    let Output::Plane(out) = &answers[0].output else {
        panic!()
    };
    assert!(out.strip_check.is_none());
    let first = screen(&app, 120, 40, PLAIN);
    assert!(!first.contains("of the exact strip solution"), "{first}");
    // the verdict comes with the point (measured where the study's estimate doubts the model)
    assert!(
        first.contains("! outside the tolerances: use the strip model"),
        "{first}"
    );
    // then the check of the new inputs
    for a in &answers[1..] {
        update(&mut app, Msg::Answer(Box::new(a.clone())));
    }
    let after = screen(&app, 120, 40, PLAIN);
    assert!(
        after.contains("wide: off the exact strip solution by"),
        "{after}"
    );
}
