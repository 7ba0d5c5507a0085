//! `update` for every action of the key table, and the prompts.

use crate::physics::Spacing;
use crate::preset::Problem;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use super::*;
use crate::tui::app::Mode;
use crate::tui::charts::{Chart, PlaneChart};
use crate::tui::harmonic_keys::MAX_HARMONICS;

pub(super) fn message(app: &App) -> String {
    app.ui
        .message
        .as_ref()
        .map(|m| m.text.clone())
        .unwrap_or_default()
}

#[test]
fn prev_and_next_field_wrap() {
    let mut app = app("polymer-coating.toml");
    let n = app.rows().len();
    press(&mut app, KeyCode::Up);
    assert_eq!(app.ui.selected, n - 1);
    press(&mut app, KeyCode::Char('j'));
    assert_eq!(app.ui.selected, 0);
    press(&mut app, KeyCode::Down);
    press(&mut app, KeyCode::Char('k'));
    assert_eq!(app.ui.selected, 0);
}

#[test]
fn nudges_small_and_large_ask_for_a_solve_or_say_why_not() {
    let mut app = app("polymer-coating.toml");
    select(&mut app, "P", None);
    let cmds = press(&mut app, KeyCode::Right);
    assert!(
        matches!(cmds.as_slice(), [Command::Solve(1, r)] if (r.preset.plane.load - 5500.0).abs() < 1e-9)
    );
    assert!(app.doc.dirty);
    update(
        &mut app,
        Msg::Key(KeyEvent::new(KeyCode::Left, KeyModifiers::SHIFT)),
    );
    assert!((app.doc.preset.plane.load - 2750.0).abs() < 1e-9);
    press(&mut app, KeyCode::Char('L'));
    assert!((app.doc.preset.plane.load - 5500.0).abs() < 1e-9);
    press(&mut app, KeyCode::Char('h'));
    assert!((app.doc.preset.plane.load - 5000.0).abs() < 1e-9);
    select(&mut app, "nu", None);
    press(&mut app, KeyCode::Char('l'));
    assert!((app.doc.preset.material.poisson_ratio - 0.36).abs() < 1e-12);
    app.doc.preset.material.poisson_ratio = 0.49;
    assert!(press(&mut app, KeyCode::Right).is_empty());
    assert_eq!(app.doc.preset.material.poisson_ratio, 0.49);
    assert_eq!(
        message(&app),
        "material.poisson_ratio = 0.5 is out of range: allowed 0 <= nu < 0.5"
    );
}

#[test]
fn enter_types_a_value_with_units_and_refuses_garbage_keeping_the_text() {
    let mut app = app("polymer-coating.toml");
    select(&mut app, "E", None);
    press(&mut app, KeyCode::Enter);
    assert_eq!(app.ui.mode, Mode::Editing(Default::default()));
    assert_eq!(message(&app), "type E (1e2 <= E <= 1e13 (Pa))");
    type_text(&mut app, "7 GPa");
    assert_eq!(press(&mut app, KeyCode::Enter).len(), 1);
    assert_eq!(app.doc.preset.material.youngs_modulus, 7e9);
    assert_eq!(app.ui.mode, Mode::Normal);
    select(&mut app, "nu", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "lots");
    assert!(press(&mut app, KeyCode::Enter).is_empty());
    assert_eq!(
        message(&app),
        "material.poisson_ratio = 'lots' is not a number (allowed 0 <= nu < 0.5)"
    );
    assert_eq!(app.ui.mode, Mode::Editing("lots".into()));
    for _ in 0..4 {
        press(&mut app, KeyCode::Backspace);
    }
    type_text(&mut app, "0.7");
    press(&mut app, KeyCode::Enter);
    assert_eq!(
        message(&app),
        "material.poisson_ratio = 0.7 is out of range: allowed 0 <= nu < 0.5"
    );
    press(&mut app, KeyCode::Esc);
    assert_eq!(app.ui.mode, Mode::Normal);
    assert_eq!(app.doc.preset.material.poisson_ratio, 0.35);
}

#[test]
fn ctrl_letters_are_never_typed_as_text() {
    let mut app = app("polymer-coating.toml");
    select(&mut app, "E", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "3");
    update(
        &mut app,
        Msg::Key(KeyEvent::new(KeyCode::Char('u'), KeyModifiers::CONTROL)),
    );
    update(
        &mut app,
        Msg::Key(KeyEvent::new(KeyCode::Char('x'), KeyModifiers::ALT)),
    );
    assert_eq!(app.ui.mode, Mode::Editing("3".into()));
}

#[test]
fn enter_on_a_choice_row_shows_the_choices() {
    let mut app = app("polymer-coating.toml");
    select(&mut app, "model", None);
    press(&mut app, KeyCode::Enter);
    assert_eq!(app.ui.mode, Mode::Choosing(0));
    assert_eq!(message(&app), "model: one of wide, narrow, strip");
    press(&mut app, KeyCode::Down);
    press(&mut app, KeyCode::Down);
    press(&mut app, KeyCode::Down);
    assert_eq!(app.ui.mode, Mode::Choosing(2), "the list ends at strip");
    assert_eq!(press(&mut app, KeyCode::Enter).len(), 1);
    assert_eq!(app.doc.preset.plane.model.name(), "strip");
    select(&mut app, "scale", None);
    press(&mut app, KeyCode::Enter);
    assert_eq!(message(&app), "scale: one of log, linear");
    press(&mut app, KeyCode::Char('j'));
    press(&mut app, KeyCode::Esc);
    assert_eq!(
        app.doc.preset.plane.sweep.spacing,
        Spacing::Log,
        "Esc changes nothing"
    );
    press(&mut app, KeyCode::Right);
    assert_eq!(
        app.doc.preset.plane.sweep.spacing,
        Spacing::Linear,
        "Right cycles"
    );
}

#[test]
fn whole_number_rows_refuse_fractions_and_the_sweep_keeps_its_order() {
    let mut app = app("polymer-coating.toml");
    select(&mut app, "points", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "1");
    press(&mut app, KeyCode::Enter);
    assert_eq!(
        message(&app),
        "plane.sweep.points = 1 is out of range: allowed a whole number from 2 to 2000"
    );
    press(&mut app, KeyCode::Esc);
    press(&mut app, KeyCode::Right);
    assert_eq!(app.doc.preset.plane.sweep.points, 70);
    select(&mut app, "P min", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "200 kN/m");
    assert!(press(&mut app, KeyCode::Enter).is_empty());
    assert_eq!(
        message(&app),
        "plane.sweep.load_max = 100000 must be larger than plane.sweep.load_min = 200000"
    );
}

#[test]
fn tab_cycles_the_charts_and_asks_for_overlays_only_for_the_chart_that_draws_them() {
    let mut app = solved("polymer-coating.toml");
    assert!(!app.solve.overlays);
    assert!(press(&mut app, KeyCode::Tab).is_empty());
    let cmds = press(&mut app, KeyCode::Tab);
    assert_eq!(app.ui.chart, Chart::Plane(PlaneChart::MuStar));
    assert!(matches!(cmds.as_slice(), [Command::Solve(_, r)] if r.overlays));
    press(&mut app, KeyCode::BackTab);
    press(&mut app, KeyCode::BackTab);
    let cmds = press(&mut app, KeyCode::BackTab);
    assert_eq!(app.ui.chart, Chart::Plane(PlaneChart::Energy), "wraps");
    // the energy chart asks for the losses along the load sweep
    assert!(matches!(cmds.as_slice(), [Command::Solve(_, r)] if r.energies));
}

#[test]
fn p_switches_the_problem_and_undo_says_what_it_undid() {
    let mut app = app("polymer-coating.toml");
    select(&mut app, "E", None);
    press(&mut app, KeyCode::Right);
    press(&mut app, KeyCode::Char('p'));
    assert_eq!(app.doc.preset.problem, Problem::Spatial);
    assert_eq!(app.ui.chart.problem(), Problem::Spatial);
    assert_eq!(press(&mut app, KeyCode::Char('u')).len(), 1);
    assert_eq!(message(&app), "undo: problem spatial -> plane");
    press(&mut app, KeyCode::Char('u'));
    assert_eq!(message(&app), "undo: E 3.30 GPa -> 3.00 GPa");
    assert!(press(&mut app, KeyCode::Char('u')).is_empty());
    assert_eq!(message(&app), "nothing to undo");
}

#[test]
fn m_cycles_every_model_and_says_why_not_where_it_cannot() {
    let mut app = app("polymer-coating.toml");
    for name in ["narrow", "strip", "wide"] {
        press(&mut app, KeyCode::Char('m'));
        assert_eq!(app.doc.preset.plane.model.name(), name);
        assert_eq!(message(&app), format!("model: {name}"));
    }
    let mut half_plane = super::app("hertz-check.toml");
    assert!(press(&mut half_plane, KeyCode::Char('m')).is_empty());
    assert!(
        message(&half_plane).starts_with("plane.model = narrow needs a finite material.thickness")
    );
    let mut spatial = super::app("dispersion.toml");
    assert!(press(&mut spatial, KeyCode::Char('m')).is_empty());
    assert_eq!(
        message(&spatial),
        "m: cycle the plane model (wide, narrow, strip) is for the plane problem (p switches)"
    );
}

#[test]
fn space_plays_time_and_ticks_advance_it() {
    let mut app = app("wave-thick-layer.toml");
    assert!(update(&mut app, Msg::Tick).is_empty(), "not playing yet");
    press(&mut app, KeyCode::Char(' '));
    assert!(app.ui.playing);
    let t0 = app.doc.preset.spatial.time;
    assert_eq!(update(&mut app, Msg::Tick).len(), 1);
    assert!(app.doc.preset.spatial.time > t0);
    press(&mut app, KeyCode::Char(' '));
    assert!(!app.ui.playing);
}

#[test]
fn plus_and_minus_add_and_remove_harmonics() {
    let mut app = app("wave-thick-layer.toml");
    press(&mut app, KeyCode::Char('+'));
    assert_eq!(app.doc.preset.spatial.harmonics.len(), 2);
    select(&mut app, "wx", Some(1));
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "6283.185307179586");
    press(&mut app, KeyCode::Enter);
    assert_eq!(
        message(&app),
        "harmonics 1 and 2 have the same wave vector: give each wave vector once"
    );
    press(&mut app, KeyCode::Esc);
    press(&mut app, KeyCode::Char('-'));
    assert_eq!(app.doc.preset.spatial.harmonics.len(), 1);
    assert_eq!(message(&app), "removed harmonic 2");
    press(&mut app, KeyCode::Char('-'));
    assert_eq!(message(&app), "the punch needs at least one harmonic");
}

#[test]
fn plus_on_a_wave_across_the_sliding_line_makes_a_new_harmonic_up_to_the_cap() {
    // wavenumber_x = 0: doubling wx alone never gave a new wave vector (the explorer froze)
    let mut app = app("wave-thick-layer.toml");
    let h = &mut app.doc.preset.spatial.harmonics[0];
    (h.wavenumber_x, h.wavenumber_y) = (0.0, 1000.0);
    for n in 2..=MAX_HARMONICS {
        assert_eq!(
            press(&mut app, KeyCode::Char('+')).len(),
            1,
            "{}",
            message(&app)
        );
        let added = app.doc.preset.spatial.harmonics[n - 1];
        assert_eq!(
            (added.wavenumber_x, added.wavenumber_y),
            (0.0, 1000.0 * n as f64)
        );
        assert_eq!(app.doc.preset.spatial.harmonics.len(), n);
    }
    assert!(press(&mut app, KeyCode::Char('+')).is_empty());
    assert_eq!(
        message(&app),
        "the punch has 64 harmonics, the most + adds: remove one with - first"
    );
    let hs = &app.doc.preset.spatial.harmonics;
    assert!(
        hs.iter()
            .all(|h| h.wavenumber_x == 0.0 && h.wavenumber_y >= 1000.0)
    );
}

#[test]
fn question_mark_opens_a_scrolling_help_that_any_other_key_closes() {
    let mut app = app("polymer-coating.toml");
    press(&mut app, KeyCode::Char('?'));
    assert_eq!(app.ui.mode, Mode::Help(0));
    press(&mut app, KeyCode::Down);
    press(&mut app, KeyCode::PageDown);
    assert_eq!(app.ui.mode, Mode::Help(11));
    press(&mut app, KeyCode::Up);
    assert_eq!(app.ui.mode, Mode::Help(10));
    press(&mut app, KeyCode::Char('x'));
    assert_eq!(app.ui.mode, Mode::Normal);
}

#[test]
fn help_scrolling_stops_at_the_end_of_the_text() {
    // PgDn past the end stops at the end, so that the first PgUp scrolls back at once
    for (w, h) in [(80, 24), (120, 40)] {
        let mut app = app("contact-lost.toml");
        app.ui.screen = ratatui::layout::Rect::new(0, 0, w, h);
        let last = crate::tui::view::popups::help_last(&app, app.ui.screen);
        assert!(
            last > 10,
            "{w}x{h}: the help fits without scrolling ({last})"
        );
        press(&mut app, KeyCode::Char('?'));
        for _ in 0..20 {
            press(&mut app, KeyCode::PageDown);
        }
        assert_eq!(app.ui.mode, Mode::Help(last), "{w}x{h}");
        press(&mut app, KeyCode::PageUp);
        assert_eq!(app.ui.mode, Mode::Help(last - 10), "{w}x{h}");
        press(&mut app, KeyCode::Home);
        assert_eq!(app.ui.mode, Mode::Help(0), "{w}x{h}");
        press(&mut app, KeyCode::End);
        assert_eq!(app.ui.mode, Mode::Help(last), "{w}x{h}");
        press(&mut app, KeyCode::Char('x'));
        assert_eq!(app.ui.mode, Mode::Normal);
    }
}

#[test]
fn every_parameter_of_the_registry_has_its_nudge() {
    use crate::tui::form::{STEPS, Step};
    for p in crate::preset::PARAMS {
        let step = STEPS.iter().find(|(k, _)| *k == p.key).map(|(_, s)| *s);
        let choice = p.choices().is_some();
        assert!(
            step.is_some_and(|s| (s == Step::Choice) == choice),
            "{}: {step:?}",
            p.key
        );
    }
    assert_eq!(
        STEPS.len(),
        crate::preset::PARAMS.len(),
        "no step for a parameter that is gone"
    );
}
