//! Yield on the regime map in the explorer: with a yield strength given, the map draws the yield
//! onset (`Y`) with its legend entry, the cell cursor's readout says whether the contact yields
//! there, and the SVG export draws and names the line; the screens at 80x24 and 120x40.

use ratatui::crossterm::event::KeyCode;

use super::charts::texts;
use super::explore::explored;
use super::*;
use crate::engine::sweep_worker::SweepResult;
use crate::physics::plane::yield_onset::peak;
use crate::physics::plane::{Model, solve};
use crate::sweeps::map::LineKind;
use crate::tui::charts::map_lines::line_key;

/// friction-or-wear-map on 9 x 9 points with Y = 7 MPa, a little above the largest von Mises
/// stress at the preset's own point (6.40 MPa, asserted below), so that the onset passes just
/// beside it; its map computed.
fn yield_map() -> App {
    let mut preset = bundled("friction-or-wear-map.toml");
    let own = solve(&preset.plane_inputs(), Model::Wide).unwrap();
    let stress = peak(&own).unwrap().stress;
    assert!((6.35e6..6.45e6).contains(&stress), "{stress}");
    preset.strength.yield_strength = Some(7e6);
    for axis in &mut preset.explore.as_mut().unwrap().axes {
        axis.range.points = 9;
    }
    let mut app = App::new(preset, None, Places::default());
    let cmds = app.start();
    settle(&mut app, cmds.clone());
    explored(&mut app, &cmds);
    app
}

#[test]
fn the_map_draws_and_names_where_the_contact_yields() {
    let mut app = yield_map();
    let (answer, _) = crate::tui::sweep_shown::shown(&app).unwrap();
    let SweepResult::Map(map) = &answer.explored else {
        panic!("a map")
    };
    let line = map.lines.iter().find(|l| l.kind == LineKind::Yield);
    assert!(line.is_some_and(|l| !l.segments.is_empty()), "{line:?}");
    let (glyph, meaning) = line_key(LineKind::Yield);
    let small = screen(&app, 80, 24, PLAIN);
    assert!(small.contains(&format!("{glyph} yield onset")), "{small}");
    insta::assert_snapshot!("map_yield_80x24", small);
    insta::assert_snapshot!("map_yield_120x40", screen(&app, 120, 40, COLOUR));
    // the SVG draws the line and names it as the terminal does
    let cmds = press(&mut app, KeyCode::Char('E'));
    let (_, text) = exported(&cmds);
    let t = texts(text);
    assert!(
        t.iter().any(|x| x == &format!("{glyph}  {meaning}")),
        "{t:?}"
    );
    // the cell cursor reads the point's own answer
    press(&mut app, KeyCode::Char('x'));
    let items: Vec<String> = (crate::tui::view::sweep::readout(&app).unwrap().iter())
        .map(ToString::to_string)
        .collect();
    assert!(
        items.iter().any(|i| i == "yields" || i == "no yield"),
        "{items:?}"
    );
}
