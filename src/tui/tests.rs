//! Tests of the explorer: update() for every key, and screen snapshots (TestBackend + insta).

use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use wearlab::engine::{Engine, Request};
use wearlab::preset::{BUNDLED, Preset, Problem};

use crate::tui::app::{App, Command, Mode, Msg, update};
use crate::tui::form::{self, Key};
use crate::tui::view::{RenderOptions, view};

fn bundled(file: &str) -> Preset {
    wearlab::preset::bundled(file).unwrap().unwrap()
}

fn key(code: KeyCode) -> Msg {
    Msg::Key(KeyEvent::new(code, KeyModifiers::NONE))
}

fn press(app: &mut App, code: KeyCode) -> Vec<Command> {
    update(app, key(code))
}

fn type_text(app: &mut App, text: &str) {
    for c in text.chars() {
        press(app, KeyCode::Char(c));
    }
}

fn select(app: &mut App, k: Key) {
    app.selected = form::rows(&app.preset)
        .iter()
        .position(|r| r.key == k)
        .unwrap();
}

/// An app whose output is filled synchronously by the engine (what the worker would send).
fn solved(preset: Preset) -> App {
    let mut app = App::new(preset, None, None);
    let cmds = app.start();
    settle(&mut app, cmds);
    app
}

fn settle(app: &mut App, cmds: Vec<Command>) {
    let mut engine = Engine::new();
    for c in cmds {
        if let Command::Solve(generation, preset) = c {
            let out = engine.run(&full(*preset));
            update(app, Msg::Solved(generation, Box::new(out)));
        }
    }
}

#[test]
fn up_down_and_j_k_move_through_the_form_and_wrap() {
    let mut app = App::new(bundled("polymer-coating.toml"), None, None);
    let n = form::rows(&app.preset).len();
    press(&mut app, KeyCode::Up);
    assert_eq!(app.selected, n - 1);
    press(&mut app, KeyCode::Char('j'));
    assert_eq!(app.selected, 0);
    press(&mut app, KeyCode::Down);
    press(&mut app, KeyCode::Char('k'));
    assert_eq!(app.selected, 0);
}

#[test]
fn left_right_nudge_and_request_a_solve() {
    let mut app = App::new(bundled("polymer-coating.toml"), None, None);
    select(&mut app, Key::Load);
    let cmds = press(&mut app, KeyCode::Right);
    assert!(
        matches!(cmds.as_slice(), [Command::Solve(1, p)] if (p.plane.load - 5500.0).abs() < 1e-9)
    );
    assert!(app.dirty);
    let shifted = update(
        &mut app,
        Msg::Key(KeyEvent::new(KeyCode::Left, KeyModifiers::SHIFT)),
    );
    assert_eq!(shifted.len(), 1);
    assert!((app.preset.plane.load - 2750.0).abs() < 1e-9);
    select(&mut app, Key::PoissonRatio);
    press(&mut app, KeyCode::Char('l'));
    assert!((app.preset.material.poisson_ratio - 0.36).abs() < 1e-12);
    // a nudge past the allowed range is refused with the reason
    app.preset.material.poisson_ratio = 0.49;
    let cmds = press(&mut app, KeyCode::Right);
    assert!(cmds.is_empty());
    assert_eq!(app.preset.material.poisson_ratio, 0.49);
    assert_eq!(
        app.message.as_ref().unwrap().0,
        "nu: nu = 0.5 is out of range: allowed 0 <= nu < 0.5"
    );
}

#[test]
fn enter_types_a_value_with_units() {
    let mut app = App::new(bundled("polymer-coating.toml"), None, None);
    select(&mut app, Key::YoungsModulus);
    press(&mut app, KeyCode::Enter);
    assert_eq!(app.mode, Mode::Editing(String::new()));
    type_text(&mut app, "7 GPa");
    let cmds = press(&mut app, KeyCode::Enter);
    assert_eq!(cmds.len(), 1);
    assert_eq!(app.preset.material.youngs_modulus, 7e9);
    assert_eq!(app.mode, Mode::Normal);
    select(&mut app, Key::Radius);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "20mm");
    press(&mut app, KeyCode::Enter);
    assert_eq!(app.preset.plane.radius, 0.02);
}

#[test]
fn invalid_text_says_why_and_keeps_the_last_valid_value() {
    let mut app = App::new(bundled("polymer-coating.toml"), None, None);
    select(&mut app, Key::PoissonRatio);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "lots");
    assert!(press(&mut app, KeyCode::Enter).is_empty());
    assert_eq!(
        app.message.as_ref().unwrap(),
        &("nu: 'lots' is not a number".to_string(), true)
    );
    assert_eq!(
        app.mode,
        Mode::Editing("lots".into()),
        "the text stays for correction"
    );
    for _ in 0..4 {
        press(&mut app, KeyCode::Backspace);
    }
    type_text(&mut app, "0.7");
    press(&mut app, KeyCode::Enter);
    assert_eq!(
        app.message.as_ref().unwrap().0,
        "nu: nu = 0.7 is out of range: allowed 0 <= nu < 0.5"
    );
    assert_eq!(app.preset.material.poisson_ratio, 0.35);
    press(&mut app, KeyCode::Esc);
    assert_eq!(app.mode, Mode::Normal);
    assert_eq!(app.preset.material.poisson_ratio, 0.35);
    assert!(!app.dirty);
}

#[test]
fn undo_restores_the_previous_value() {
    let mut app = App::new(bundled("polymer-coating.toml"), None, None);
    select(&mut app, Key::Friction);
    press(&mut app, KeyCode::Right);
    press(&mut app, KeyCode::Right);
    assert!((app.preset.friction.coefficient - 0.32).abs() < 1e-12);
    let cmds = press(&mut app, KeyCode::Char('u'));
    assert_eq!(cmds.len(), 1);
    assert!((app.preset.friction.coefficient - 0.31).abs() < 1e-12);
    press(&mut app, KeyCode::Char('u'));
    assert_eq!(app.preset.friction.coefficient, 0.3);
    assert!(press(&mut app, KeyCode::Char('u')).is_empty());
    assert_eq!(app.message.as_ref().unwrap().0, "nothing to undo");
}

#[test]
fn tab_problem_model_and_play() {
    let mut app = App::new(bundled("polymer-coating.toml"), None, None);
    press(&mut app, KeyCode::Tab);
    assert_eq!(app.chart, 1);
    press(&mut app, KeyCode::BackTab);
    assert_eq!(app.chart, 0);
    press(&mut app, KeyCode::Char('m'));
    assert_eq!(app.preset.plane.model.name(), "narrow");
    press(&mut app, KeyCode::Char('m'));
    assert_eq!(app.preset.plane.model.name(), "strip");
    press(&mut app, KeyCode::Char('m'));
    assert_eq!(app.preset.plane.model.name(), "wide");
    press(&mut app, KeyCode::Char('p'));
    assert_eq!(app.preset.problem, Problem::Spatial);
    assert!(update(&mut app, Msg::Tick).is_empty(), "not playing yet");
    press(&mut app, KeyCode::Char(' '));
    assert!(app.playing);
    let t0 = app.preset.spatial.time;
    assert_eq!(update(&mut app, Msg::Tick).len(), 1);
    assert!(app.preset.spatial.time > t0);
    press(&mut app, KeyCode::Char(' '));
    assert!(!app.playing);
}

#[test]
fn the_narrow_model_refuses_a_half_plane() {
    let mut app = App::new(bundled("hertz-check.toml"), None, None);
    assert!(press(&mut app, KeyCode::Char('m')).is_empty());
    assert_eq!(
        app.message.as_ref().unwrap().0,
        "the narrow model needs a finite thickness h: set h first"
    );
}

#[test]
fn harmonics_can_be_added_edited_and_removed() {
    let mut app = App::new(bundled("wave-thick-layer.toml"), None, None);
    press(&mut app, KeyCode::Char('+'));
    assert_eq!(app.preset.spatial.harmonics.len(), 2);
    select(&mut app, Key::WavenumberY(1));
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "1000");
    press(&mut app, KeyCode::Enter);
    assert_eq!(app.preset.spatial.harmonics[1].wavenumber_y, 1000.0);
    // a harmonic may not repeat a wave vector
    select(&mut app, Key::WavenumberX(1));
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "6283.185307179586");
    press(&mut app, KeyCode::Enter);
    select(&mut app, Key::WavenumberY(1));
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "0");
    press(&mut app, KeyCode::Enter);
    assert_eq!(
        app.message.as_ref().unwrap().0,
        "wy: harmonics 1 and 2 have the same wave vector: give each wave vector once"
    );
    press(&mut app, KeyCode::Esc);
    press(&mut app, KeyCode::Char('-'));
    assert_eq!(app.preset.spatial.harmonics.len(), 1);
    press(&mut app, KeyCode::Char('-'));
    assert_eq!(
        app.message.as_ref().unwrap().0,
        "the punch needs at least one harmonic"
    );
}

#[test]
fn stale_results_are_dropped() {
    let mut app = App::new(bundled("polymer-coating.toml"), None, None);
    let first = app.start();
    select(&mut app, Key::Load);
    let second = press(&mut app, KeyCode::Right);
    assert!(app.solving());
    let mut engine = Engine::new();
    let (Command::Solve(g1, p1), Command::Solve(g2, p2)) = (&first[0], &second[0]) else {
        panic!()
    };
    let (out1, out2) = (
        engine.run(&full(*p1.clone())),
        engine.run(&full(*p2.clone())),
    );
    // the newer answer arrives first: shown, and nothing is pending any more
    update(&mut app, Msg::Solved(*g2, Box::new(out2)));
    assert!(!app.solving());
    let shown = format!("{:?}", app.output);
    // the older one arrives late: dropped
    update(&mut app, Msg::Solved(*g1, Box::new(out1)));
    assert_eq!(
        format!("{:?}", app.output),
        shown,
        "generation {g1} is older than {g2}"
    );
    assert_eq!(app.shown, *g2);
}

#[test]
fn playing_time_moves_the_screen_although_every_tick_supersedes_the_last_request() {
    let mut app = solved(bundled("wave-thick-layer.toml"));
    let mut engine = Engine::new();
    press(&mut app, KeyCode::Char(' '));
    let mut pending = update(&mut app, Msg::Tick);
    for _ in 0..3 {
        // the next tick comes before the answer to the previous one
        let next = update(&mut app, Msg::Tick);
        for c in pending {
            if let Command::Solve(g, p) = c {
                update(&mut app, Msg::Solved(g, Box::new(engine.run(&full(*p)))));
            }
        }
        pending = next;
    }
    let Some(wearlab::engine::Output::Spatial(Ok(out))) = &app.output else {
        panic!()
    };
    assert!(out.state.solution.time > 0.0, "the screen moved on");
    assert!(app.solving(), "and the newest tick is still pending");
}

#[test]
fn quit_asks_when_there_are_unsaved_edits() {
    let mut app = App::new(bundled("polymer-coating.toml"), None, None);
    assert_eq!(press(&mut app, KeyCode::Char('q')), vec![Command::Quit]);
    select(&mut app, Key::Load);
    press(&mut app, KeyCode::Right);
    assert!(press(&mut app, KeyCode::Char('q')).is_empty());
    assert_eq!(app.mode, Mode::ConfirmQuit);
    press(&mut app, KeyCode::Char('n'));
    assert_eq!(app.mode, Mode::Normal);
    press(&mut app, KeyCode::Char('q'));
    assert_eq!(press(&mut app, KeyCode::Char('y')), vec![Command::Quit]);
    let ctrl_c = Msg::Key(KeyEvent::new(KeyCode::Char('c'), KeyModifiers::CONTROL));
    let mut clean = App::new(bundled("polymer-coating.toml"), None, None);
    assert_eq!(update(&mut clean, ctrl_c), vec![Command::Quit]);
}

#[test]
fn save_asks_for_a_name_and_never_overwrites_silently() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = App::new(
        bundled("polymer-coating.toml"),
        None,
        Some(dir.path().to_path_buf()),
    );
    press(&mut app, KeyCode::Char('s'));
    type_text(&mut app, "mine");
    let cmds = press(&mut app, KeyCode::Enter);
    let target = dir.path().join("mine.toml");
    assert!(matches!(cmds.as_slice(), [Command::Save(p, _)] if *p == target));
    std::fs::write(&target, "taken").unwrap();
    press(&mut app, KeyCode::Char('s'));
    type_text(&mut app, "mine");
    assert!(press(&mut app, KeyCode::Enter).is_empty());
    assert_eq!(app.mode, Mode::ConfirmOverwrite(target.clone()));
    assert!(press(&mut app, KeyCode::Char('n')).is_empty());
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "taken");
}

#[test]
fn a_broken_preset_in_the_picker_shows_its_error_and_keeps_the_state() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("zz-broken.toml"),
        "schema = 1\nproblem = \"plane\"\n[material]\nyoungs_modulus = -1.0\n",
    )
    .unwrap();
    let mut app = App::new(
        bundled("polymer-coating.toml"),
        None,
        Some(dir.path().to_path_buf()),
    );
    let before = app.preset.clone();
    press(&mut app, KeyCode::Char('o'));
    let Mode::Picker { entries, .. } = &app.mode else {
        panic!("picker expected")
    };
    let n = entries.len();
    assert_eq!(n, BUNDLED.len() + 1);
    for _ in 0..n {
        press(&mut app, KeyCode::Down);
    }
    assert!(press(&mut app, KeyCode::Enter).is_empty());
    let (msg, is_error) = app.message.clone().unwrap();
    assert!(
        is_error && msg.contains("zz-broken.toml:3: missing field `poisson_ratio`"),
        "{msg}"
    );
    assert_eq!(app.preset, before);
    // a good one opens
    press(&mut app, KeyCode::Char('o'));
    press(&mut app, KeyCode::Down);
    assert_eq!(press(&mut app, KeyCode::Enter).len(), 1);
    assert_eq!(app.preset, bundled("hertz-check.toml"));
}

fn screen(app: &App, w: u16, h: u16, options: RenderOptions) -> String {
    let mut terminal = Terminal::new(TestBackend::new(w, h)).unwrap();
    terminal.draw(|f| view(app, options, f)).unwrap();
    terminal.backend().to_string()
}

const PLAIN: RenderOptions = RenderOptions {
    ascii: false,
    color: false,
};

#[test]
fn snapshot_plane_screens() {
    let mut app = solved(bundled("polymer-coating.toml"));
    insta::assert_snapshot!("plane_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("plane_120x40", screen(&app, 120, 40, PLAIN));
    app.chart = 2;
    insta::assert_snapshot!("plane_mu_star_120x40", screen(&app, 120, 40, PLAIN));
    app.chart = 2;
    insta::assert_snapshot!(
        "plane_mu_star_ascii_80x24",
        screen(
            &app,
            80,
            24,
            RenderOptions {
                ascii: true,
                color: false
            }
        )
    );
}

#[test]
fn snapshot_spatial_screens() {
    let mut app = solved(bundled("dispersion.toml"));
    insta::assert_snapshot!("spatial_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("spatial_120x40", screen(&app, 120, 40, PLAIN));
    app.chart = 2;
    insta::assert_snapshot!("spatial_history_120x40", screen(&app, 120, 40, PLAIN));
    let lost = solved(bundled("contact-lost.toml"));
    insta::assert_snapshot!("spatial_contact_lost_80x24", screen(&lost, 80, 24, PLAIN));
}

#[test]
fn snapshot_help_picker_error_and_too_small() {
    let mut app = solved(bundled("polymer-coating.toml"));
    press(&mut app, KeyCode::Char('?'));
    insta::assert_snapshot!("help_80x24", screen(&app, 80, 24, PLAIN));
    press(&mut app, KeyCode::Char('x'));
    press(&mut app, KeyCode::Char('o'));
    insta::assert_snapshot!("picker_80x24", screen(&app, 80, 24, PLAIN));
    press(&mut app, KeyCode::Esc);
    select(&mut app, Key::Thickness);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "-3 mm");
    press(&mut app, KeyCode::Enter);
    insta::assert_snapshot!("error_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("too_small_60x20", screen(&app, 60, 20, PLAIN));
}

#[test]
fn undo_across_a_problem_switch_keeps_the_chart_in_range() {
    let mut app = App::new(bundled("polymer-coating.toml"), None, None);
    press(&mut app, KeyCode::Char('p'));
    for _ in 0..4 {
        press(&mut app, KeyCode::Tab);
    }
    assert_eq!(app.chart, 4);
    press(&mut app, KeyCode::Char('u'));
    assert_eq!(app.preset.problem, Problem::Plane);
    assert!(app.chart < 4);
    screen(&app, 80, 24, PLAIN);
}

#[test]
fn snapshot_dispersion_chart() {
    let mut app = solved(bundled("rubber-backward-drift.toml"));
    app.chart = 4;
    insta::assert_snapshot!("spatial_dispersion_120x40", screen(&app, 120, 40, PLAIN));
}

#[test]
fn export_writes_the_visible_chart() {
    let mut app = solved(bundled("polymer-coating.toml"));
    let (stem, text) = crate::tui::chart_csv(&app).unwrap();
    assert_eq!(stem, "pressure-and-shear");
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("curve,x,y"));
    assert_eq!(
        text.lines()
            .filter(|l| l.starts_with("pressure q2"))
            .count(),
        201
    );
    app.chart = 2;
    let (stem, text) = crate::tui::chart_csv(&app).unwrap();
    assert_eq!(stem, "mu-against-load");
    // log sweeps are written in load, not in log10(load)
    let first: Vec<&str> = text.lines().nth(1).unwrap().split(',').collect();
    assert_eq!(first[1].parse::<f64>().unwrap().round(), 100.0);
    let spatial = solved(bundled("jgh-egg-box.toml"));
    let (_, text) = crate::tui::chart_csv(&spatial).unwrap();
    assert_eq!(text.lines().next(), Some("x,y,pressure"));
    assert_eq!(text.lines().count(), 1 + 64 * 64);
}

#[test]
fn model_names_follow_the_model_order() {
    let names: Vec<&str> = wearlab::physics::plane::Model::ALL
        .iter()
        .map(|m| m.name())
        .collect();
    assert_eq!(names, form::MODELS);
}

#[test]
fn sweep_rows_edit_points_and_scale() {
    let mut app = App::new(bundled("polymer-coating.toml"), None, None);
    select(&mut app, Key::LoadScale);
    press(&mut app, KeyCode::Right);
    assert_eq!(
        app.preset.plane.sweep.spacing,
        wearlab::physics::Spacing::Linear
    );
    press(&mut app, KeyCode::Enter);
    assert_eq!(app.mode, Mode::Editing("linear".into()));
    for _ in 0..6 {
        press(&mut app, KeyCode::Backspace);
    }
    type_text(&mut app, "lin");
    press(&mut app, KeyCode::Enter);
    assert_eq!(
        app.message.as_ref().unwrap().0,
        "scale: type one of: log, linear"
    );
    press(&mut app, KeyCode::Esc);
    select(&mut app, Key::LoadPoints);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "1");
    press(&mut app, KeyCode::Enter);
    assert_eq!(
        app.message.as_ref().unwrap().0,
        "points: points = 1 is out of range: allowed a whole number from 2 to 2000"
    );
    press(&mut app, KeyCode::Esc);
    press(&mut app, KeyCode::Right);
    assert_eq!(app.preset.plane.sweep.points, 70);
}

#[test]
fn the_form_keeps_a_sweep_in_order_with_the_same_rule_as_the_file() {
    let mut app = App::new(bundled("polymer-coating.toml"), None, None);
    select(&mut app, Key::LoadMin);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "200 kN/m");
    assert!(press(&mut app, KeyCode::Enter).is_empty());
    assert_eq!(
        app.message.as_ref().unwrap().0,
        "P min: P max = 100 kN/m must be larger than P min = 200 kN/m"
    );
    assert_eq!(app.preset.plane.sweep.min, 100.0);
}

fn full(preset: Preset) -> Request {
    Request {
        preset,
        overlays: true,
    }
}
