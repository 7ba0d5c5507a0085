//! Pinned curves told apart: each curve of a pin has its own mark without colour (the pin's
//! number and the curve's own character in turn) and its own legend entry, in its colour with
//! colour.

use ratatui::crossterm::event::KeyCode;

use super::*;

/// polymer-coating.toml's pressure chart (pressure q2 and shear q1) pinned at P = 5 kN/m, then
/// drawn at twice the load.
fn pinned() -> App {
    let mut app = solved("polymer-coating.toml");
    press(&mut app, KeyCode::Char('c'));
    select(&mut app, "P", None);
    let cmds = press(&mut app, KeyCode::Char('L'));
    settle(&mut app, cmds);
    app
}

/// The rows of the chart (the screen's rows above the status), legend included.
fn chart(s: &str) -> String {
    (s.lines())
        .take_while(|l| !l.contains("operating point"))
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn each_curve_of_a_pin_has_its_own_mark_and_legend_entry() {
    let app = pinned();
    for style in [PLAIN, ASCII] {
        for (w, h) in [(80u16, 24u16), (120, 40)] {
            let s = screen(&app, w, h, style);
            // as the main curves' * and +: the pinned pressure 1*1*, the pinned shear 1+1+
            assert!(s.contains("1* pin: P = 5.00 kN/m, pressure q2"), "{s}");
            assert!(s.contains("1+ shear q1"), "{s}");
            let plot = chart(&s);
            for glyph in ['*', '+'] {
                let (after, before) = (format!("1{glyph}"), format!("{glyph}1"));
                let drawn = plot.matches(&after).count() + plot.matches(&before).count();
                assert!(drawn > 4, "1{glyph} not drawn:\n{plot}");
            }
        }
    }
    // with colour each pinned curve is drawn in its curve's colour, its number dim, and each
    // has a legend entry
    let s = screen(&app, 120, 40, COLOUR);
    assert!(s.contains("11 pin: P = 5.00 kN/m, pressure q2"), "{s}");
    assert!(s.contains("11 shear q1"), "{s}");
}
