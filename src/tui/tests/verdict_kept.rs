//! The verdict is the last line the plane status gives up: at 80x24 and larger, on the lab's
//! sweep with its data drawn, with the sweep's cursor, on the chart of the point with a cursor
//! and a pin, on the regime map with its cell cursor, holding or failing; the values of the
//! point give up rows (counted, "+2 more") before it does.

use ratatui::crossterm::event::KeyCode;

use super::explore::explored;
use super::*;
use crate::tui::effects;
use crate::tui::sweep_state::View;

/// The status panel's rows of a screen: the lines under its title " operating point ", from its
/// left border on.
fn status_rows(screen: &str) -> Vec<String> {
    let lines: Vec<Vec<char>> = screen.lines().map(|l| l.chars().collect()).collect();
    let title: Vec<char> = "┌ operating point".chars().collect();
    let (top, column) = (lines.iter().enumerate())
        .find_map(|(n, l)| Some((n, l.windows(title.len()).position(|w| w == title)?)))
        .unwrap_or_else(|| panic!("no status:\n{screen}"));
    lines[top + 1..]
        .iter()
        .map(|l| l[column.min(l.len())..].iter().collect::<String>())
        .take_while(|l| !l.starts_with('└'))
        .collect()
}

/// The screen has the verdict `said` in its status, on a row of its own.
fn has_verdict(app: &App, w: u16, h: u16, said: &str, what: &str) {
    let s = screen(app, w, h, PLAIN);
    let rows = status_rows(&s);
    assert!(
        rows.iter().any(|r| r.contains(said)),
        "{what} at {w}x{h}: no \"{said}\"\n{s}"
    );
}

/// The lab's preset on its sweep, its data read and both the point and the sweep computed.
fn lab_sweep(load: Option<f64>) -> App {
    let mut preset = bundled("lab-friction.toml");
    if let Some(load) = load {
        preset.plane.load = load;
    }
    let mut app = App::new(preset, None, Places::default());
    app.doc.source = Some("bundled: lab-friction.toml".into());
    let cmds = app.start();
    assert_eq!(app.explore.view, Some(View::Sweep));
    if let Some(Command::ReadData(paths, preset)) =
        cmds.iter().find(|c| matches!(c, Command::ReadData(..)))
    {
        update(&mut app, effects::read_data(paths, preset));
    }
    settle(&mut app, cmds.clone());
    explored(&mut app, &cmds);
    assert!(app.ui.data.is_some(), "the lab's data are drawn");
    app
}

const HOLDS: &str = "wide model holds";

#[test]
fn the_lab_sweep_keeps_its_holding_verdict_at_80x24() {
    let mut app = lab_sweep(None);
    has_verdict(
        &app,
        80,
        24,
        "valid: (a+b)/h = 0.06105; wide model holds",
        "sweep",
    );
    // the values the verdict's row was taken from are counted; mu*, the lab's quantity, stays
    let s = screen(&app, 80, 24, PLAIN);
    let rows = status_rows(&s);
    assert!(rows.iter().any(|r| r.contains("more")), "{s}");
    assert!(rows.iter().any(|r| r.contains("mu* = 0.199773")), "{s}");
    for (w, h) in [(100, 30), (120, 40)] {
        has_verdict(&app, w, h, HOLDS, "sweep");
    }
    // the sweep's cursor reads the curves in the rows the verdict leaves
    press(&mut app, KeyCode::Char('x'));
    assert!(app.ui.cursor.is_some());
    for (w, h) in [(80, 24), (120, 40)] {
        has_verdict(&app, w, h, HOLDS, "sweep with its cursor");
        let s = screen(&app, w, h, PLAIN);
        assert!(status_rows(&s).iter().any(|r| r.contains("cursor")), "{s}");
    }
    insta::assert_snapshot!(
        "verdict_kept_sweep_cursor_80x24",
        screen(&app, 80, 24, PLAIN)
    );
}

#[test]
fn the_chart_of_the_point_with_a_cursor_and_a_pin_keeps_the_verdict() {
    let mut app = lab_sweep(None);
    // back to the chart of the point, the data still drawn on mu*: a cursor and a pin on
    press(&mut app, KeyCode::Char('v'));
    press(&mut app, KeyCode::Esc);
    app.explore.view = None;
    press(&mut app, KeyCode::Char('x'));
    press(&mut app, KeyCode::Char('c'));
    for (w, h) in [(80, 24), (120, 40)] {
        has_verdict(&app, w, h, HOLDS, "point chart with cursor and pin");
    }
}

#[test]
fn a_failing_verdict_keeps_its_first_reason_with_the_cursor_on() {
    // at 1 MN/m the lab's coating is far outside the wide model's tolerances
    let mut app = lab_sweep(Some(1e6));
    press(&mut app, KeyCode::Char('x'));
    let shown = crate::tui::on_screen::on_screen(&app);
    let point = match shown.answer().map(|(a, _)| &a.output) {
        Some(crate::engine::Output::Plane(out)) => out.point.clone().unwrap(),
        _ => panic!("no plane point"),
    };
    assert!(!point.validity.ok);
    let first: String = point.validity.reasons[0].text.to_string();
    let start: String = format!("! {}", first.chars().take(20).collect::<String>());
    for (w, h) in [(80, 24), (120, 40)] {
        has_verdict(&app, w, h, &start, "failing sweep with its cursor");
    }
}

#[test]
fn the_map_with_its_cell_cursor_keeps_the_verdict() {
    let mut app = app("friction-or-wear-map.toml");
    let cmds = app.start();
    settle(&mut app, cmds.clone());
    explored(&mut app, &cmds);
    press(&mut app, KeyCode::Char('x'));
    assert!(app.explore.cell.is_some());
    for (w, h) in [(80, 24), (120, 40)] {
        has_verdict(&app, w, h, "model holds", "map with its cell cursor");
    }
}
