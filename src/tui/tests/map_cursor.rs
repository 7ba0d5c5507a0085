//! The pressure map's cell cursor (`x` on the map shows it and
//! draws it): the keys move it over the grid, the readout is the map's own value at its grid
//! point, it stays while time changes, and the screens read as a student would.

use ratatui::crossterm::event::KeyCode;

use super::*;
use crate::tui::charts::Map;
use crate::tui::keys::CursorMove;
use crate::tui::map_cursor;
use crate::tui::view::map_readout::{self, readout};
use crate::units::format_si;

/// A 3 x 2 map whose every value differs (units of Pa), one of them no contact.
fn small() -> Map {
    Map {
        name: "pressure",
        x: vec![1e-4, 2e-4, 3e-4],
        y: vec![5e-4, 1e-3],
        values: vec![1.5e6, 2.5e6, 0.0, 4.5e6, 5.5e6, 6.5e6],
        unit: "Pa",
        caption: String::new(),
        empty: Some("no contact"),
    }
}

#[test]
fn the_readout_is_the_map_value_at_the_cursor_cell() {
    let map = small();
    // (i, j) reads values[j * nx + i] at x_i, y_j (the row-major layout of `charts::Map`)
    assert_eq!(
        readout(&map, (1, 1)),
        ["cursor x = 200 um", "y = 1.00 mm:", "p = 5.50 MPa"]
    );
    assert_eq!(readout(&map, (0, 0))[2], "p = 1.50 MPa");
    // an empty cell (p = 0 drawn apart) reads as what it is
    assert_eq!(readout(&map, (2, 0))[2], "no contact");
    // a grid point past the map (a coarser grid after an edit) is clamped to its edge
    assert_eq!(readout(&map, (9, 9))[2], "p = 6.50 MPa");
}

#[test]
fn the_cursor_moves_a_grid_point_and_stays_on_the_grid() {
    // [ ] one point along x, { } (a step of 10 in the key table) one along y
    assert_eq!(
        map_cursor::moved_cell((1, 0), CursorMove::Forward, (3, 2)),
        (2, 0)
    );
    assert_eq!(
        map_cursor::moved_cell((1, 0), CursorMove::LongForward, (3, 2)),
        (1, 1)
    );
    assert_eq!(
        map_cursor::moved_cell((1, 1), CursorMove::LongBack, (3, 2)),
        (1, 0)
    );
    // at an edge it stays
    assert_eq!(
        map_cursor::moved_cell((0, 0), CursorMove::Back, (3, 2)),
        (0, 0)
    );
    assert_eq!(
        map_cursor::moved_cell((2, 1), CursorMove::LongForward, (3, 2)),
        (2, 1)
    );
}

#[test]
fn x_and_brackets_move_a_cell_cursor_that_stays_while_time_changes() {
    let mut app = solved("dispersion.toml");
    assert!(map_cursor::on_map(&app));
    press(&mut app, KeyCode::Char('['));
    assert_eq!(app.ui.map_cell, None);
    press(&mut app, KeyCode::Char('x'));
    // the grid's middle: dispersion.toml has a 64 x 64 grid
    assert_eq!(app.ui.map_cell, Some((32, 32)));
    for c in [']', ']', ']', '{'] {
        press(&mut app, KeyCode::Char(c));
    }
    assert_eq!(app.ui.map_cell, Some((35, 31)));
    let at_zero = map_cursor::visible(&app).unwrap();
    let s = screen(&app, 80, 24, PLAIN);
    let value = format_si(at_zero.values[31 * 64 + 35], "Pa");
    assert!(s.contains(&format!("p = {value}")), "{s}");
    assert!(s.contains("X cursor"), "{s}");
    // time moves on: the cursor stays at its grid point and reads the new map there
    select(&mut app, "t", None);
    let cmds = press(&mut app, KeyCode::Right);
    settle(&mut app, cmds);
    assert_eq!(app.ui.map_cell, Some((35, 31)));
    let later = map_cursor::visible(&app).unwrap();
    assert_eq!((later.x[35], later.y[31]), (at_zero.x[35], at_zero.y[31]));
    let moved = later.values[31 * 64 + 35];
    assert_ne!(moved, at_zero.values[31 * 64 + 35]);
    assert_eq!(
        map_readout::status(&app).unwrap()[2],
        format!("p = {}", format_si(moved, "Pa"))
    );
    press(&mut app, KeyCode::Char('x'));
    assert_eq!(app.ui.map_cell, None);
    assert!(!screen(&app, 80, 24, PLAIN).contains("X cursor"));
}

#[test]
fn map_cursor_screens() {
    let mut app = solved("dispersion.toml");
    press(&mut app, KeyCode::Char('x'));
    for _ in 0..8 {
        press(&mut app, KeyCode::Char(']'));
    }
    insta::assert_snapshot!("map_cursor_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("map_cursor_120x40", screen(&app, 120, 40, PLAIN));
    insta::assert_snapshot!("map_cursor_ascii_80x24", screen(&app, 80, 24, ASCII));
    // contact-lost.toml: the cursor on a zone out of contact
    let mut lost = solved("contact-lost.toml");
    press(&mut lost, KeyCode::Char('x'));
    insta::assert_snapshot!(
        "map_cursor_lost_ascii_120x40",
        screen(&lost, 120, 40, ASCII)
    );
}
