//! `g` sends the chart's cursor to a typed x, in the x axis' unit; a reading between two data
//! points says "(interpolated)".

use ratatui::crossterm::event::KeyCode;

use super::*;
use crate::tui::app::Mode;
use crate::tui::charts::{Chart, PlaneChart};

#[test]
fn g_sends_the_cursor_to_a_typed_x_and_a_reading_between_points_says_so() {
    // mu* against load on polymer-coating.toml: a log sweep of 60 loads, 100 N/m to 100 kN/m
    let mut app = app("polymer-coating.toml");
    app.ui.chart = Chart::Plane(PlaneChart::MuStar);
    let cmds = app.start();
    settle(&mut app, cmds);
    press(&mut app, KeyCode::Char('g'));
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains("cursor to P (") && s.contains("in N/m):"), "{s}");
    // 20 kN/m lies between two loads of the sweep
    type_text(&mut app, "20 kN/m");
    press(&mut app, KeyCode::Enter);
    assert!(matches!(app.ui.mode, Mode::Normal));
    let s = screen(&app, 120, 40, PLAIN);
    assert!(s.contains("cursor P = 20.0 kN/m:  (interpolated)"), "{s}");
    // 100 N/m is the sweep's first load: a computed value, not one between two
    press(&mut app, KeyCode::Char('g'));
    type_text(&mut app, "100");
    press(&mut app, KeyCode::Enter);
    let s = screen(&app, 120, 40, PLAIN);
    assert!(
        s.contains("cursor P = 100 N/m:") && !s.contains("interpolated"),
        "{s}"
    );
    // off the chart: refused, the prompt stays for a correction
    press(&mut app, KeyCode::Char('g'));
    type_text(&mut app, "1 MN/m");
    press(&mut app, KeyCode::Enter);
    assert!(matches!(app.ui.mode, Mode::GoTo(_)));
    let s = screen(&app, 120, 40, PLAIN);
    assert!(s.contains("P = 1.00 MN/m is off the chart:"), "{s}");
    // the chart's range and what sets it (the message wraps at 120 columns)
    assert_eq!(
        super::update::message(&app),
        "P = 1.00 MN/m is off the chart: 100 N/m .. 100 kN/m, the form's P min and P max"
    );
    press(&mut app, KeyCode::Esc);
    assert!(matches!(app.ui.mode, Mode::Normal));
}
