//! A crowded status counts what it leaves out with the key that shows it ("+2 more: i"), and the
//! `i` window gives the status in full: the cursor's readout and every value of the point.

use ratatui::crossterm::event::KeyCode;

use super::*;
use crate::tui::view::popups::about_lines;

#[test]
fn what_a_crowded_status_counts_the_i_window_shows() {
    // polymer-coating.toml's pressure chart pinned, the load doubled, the cursor on: at 80x24
    // the readout of four curves and the point's values do not all fit
    let mut app = solved("polymer-coating.toml");
    press(&mut app, KeyCode::Char('c'));
    select(&mut app, "P", None);
    let cmds = press(&mut app, KeyCode::Char('L'));
    settle(&mut app, cmds);
    press(&mut app, KeyCode::Char('x'));
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains(" more: i"), "{s}");
    assert!(!s.contains(" more │") && !s.contains(" more  "), "{s}");
    let full: String = about_lines(&app, PLAIN, 76)
        .iter()
        .map(|l| format!("{l} "))
        .collect();
    let full = full.split_whitespace().collect::<Vec<_>>().join(" ");
    for value in [
        "the status in full:",
        "cursor x =",
        "pressure q2 =",
        "shear q1 =",
        "[1] pressure q2 =",
        "[1] shear q1 =",
        "Q2 = 10.0 kN/m",
        "psi =",
        "mu* =",
        "I-J residual",
    ] {
        assert!(full.contains(value), "{value} not in the i window:\n{full}");
    }
    // the window opens on it, above the description
    press(&mut app, KeyCode::Char('i'));
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains("the status in full:"), "{s}");
}
