//! A crowded status counts what it leaves out with the key that shows it ("+2 more: i"), and the
//! `i` window gives the status in full: the cursor's readout, every value of the point and every
//! harmonic's row.

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

#[test]
fn the_harmonics_a_crowded_status_counts_the_i_window_lists() {
    // dispersion.toml with five harmonics added (nine): at 80x24 the status has room for a few
    // rows, the others counted with the key, in the dimensional table and in groups; `i` lists
    // all nine under the table's header
    let mut app = app("dispersion.toml");
    for _ in 0..5 {
        press(&mut app, KeyCode::Char('+'));
    }
    let cmds = app.start();
    settle(&mut app, cmds);
    for dimensionless in [false, true] {
        if dimensionless {
            press(&mut app, KeyCode::Char('D'));
        }
        let s = screen(&app, 80, 24, PLAIN);
        assert!(s.contains(" more: i "), "{s}");
        let full: Vec<String> = about_lines(&app, PLAIN, 76)
            .iter()
            .map(|l| l.to_string())
            .collect();
        let at = (full.iter())
            .position(|l| l == "the harmonics in full:")
            .unwrap_or_else(|| panic!("{full:#?}"));
        assert!(full[at + 1].trim_start().starts_with("n "), "{full:#?}");
        for n in 1..=9 {
            let row = &full[at + 1 + n];
            assert!(row.starts_with(&format!("{n:>3} ")), "{n}: {full:#?}");
        }
        press(&mut app, KeyCode::Char('i'));
        let s = screen(&app, 80, 24, PLAIN);
        assert!(s.contains("the harmonics in full:"), "{s}");
        press(&mut app, KeyCode::Esc);
    }
}
