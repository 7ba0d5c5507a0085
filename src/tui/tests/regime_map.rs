//! The regime map: its cell cursor on the grid (`x`, `[`/`]`, `{`/`}`), the dimensionless
//! groups toggle, its screens, and the cursor's mu* read to six decimals.

use ratatui::crossterm::event::KeyCode;

use super::explore::explored;
use super::*;

#[test]
fn the_map_cursor_moves_on_the_grid_and_d_toggles_the_groups() {
    let mut app = solved("friction-or-wear-map.toml");
    press(&mut app, KeyCode::Char('x'));
    assert_eq!(app.explore.cell, Some((20, 20)));
    press(&mut app, KeyCode::Char(']'));
    press(&mut app, KeyCode::Char('}'));
    assert_eq!(app.explore.cell, Some((21, 21)));
    for _ in 0..50 {
        press(&mut app, KeyCode::Char('{'));
    }
    assert_eq!(app.explore.cell, Some((21, 0)));
    press(&mut app, KeyCode::Char('D'));
    assert!(app.explore.dimensionless);
    press(&mut app, KeyCode::Char('D'));
    assert!(!app.explore.dimensionless);
}

#[test]
fn map_screens() {
    let mut app = app("friction-or-wear-map.toml");
    let cmds = app.start();
    settle(&mut app, cmds.clone());
    explored(&mut app, &cmds);
    insta::assert_snapshot!("map_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("map_120x40", screen(&app, 120, 40, COLOUR));
    press(&mut app, KeyCode::Char('x'));
    // at the preset's own point: mu = 0.3, k = 2e-11 on 41 x 41 points over 0..1 and 0..2e-10
    // (friction-or-wear-map.toml)
    assert_eq!(app.explore.cell, Some((12, 4)));
    insta::assert_snapshot!("map_cursor_120x40", screen(&app, 120, 40, ASCII));
}

#[test]
fn the_map_cursor_reads_mu_star_with_six_decimals() {
    // a map of mu* (not mu* - mu): the cursor gives mu* as the status does, six decimals, so
    // that mu* - mu reads off (friction-or-wear-map's mu* is 0.2998 to four digits, beside 0.3)
    let mut preset = bundled("friction-or-wear-map.toml");
    let mu_star = crate::sweeps::QuantityKey::parse("mu_star", &preset).unwrap();
    let section = preset.explore.as_mut().unwrap();
    section.quantity = mu_star;
    for axis in &mut section.axes {
        axis.range.points = 5;
    }
    let mut app = App::new(preset, None, Places::default());
    let cmds = app.start();
    settle(&mut app, cmds.clone());
    explored(&mut app, &cmds);
    press(&mut app, KeyCode::Char('x'));
    let items: Vec<String> = (crate::tui::view::sweep::readout(&app).unwrap().iter())
        .map(ToString::to_string)
        .collect();
    let read = items.iter().find(|i| i.starts_with("mu* = ")).unwrap();
    let decimals = read.trim_start_matches("mu* = ").split('.').nth(1).unwrap();
    assert_eq!(decimals.len(), 6, "{items:?}");
}
