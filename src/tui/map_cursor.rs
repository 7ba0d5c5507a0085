//! The pressure map's cell cursor (chart 1/5), the UI side (part of `update`: pure) and its
//! readout: `x` shows or hides it at the grid point in the middle of the map, `[ ]` move it a
//! grid point along x, `{ }` along y, as on the regime map. It is a grid point (column, row), so
//! that while time plays it stays at its x, y and the status reads the value there as it changes
//! (`view::map_readout`).

use crate::tui::app::App;
use crate::tui::charts::{Chart, Figure, Map, SpatialChart};
use crate::tui::keys::{Action, CursorMove};
use crate::tui::on_screen::on_screen;

/// Whether the visible chart is the pressure map (the keys `x [ ] { }` then work its cursor).
pub fn on_map(app: &App) -> bool {
    app.explore.view.is_none() && app.ui.chart == Chart::Spatial(SpatialChart::PressureMap)
}

/// The map on screen, when the visible chart is the map and a result has arrived.
pub fn visible(app: &App) -> Option<Map> {
    if !on_map(app) {
        return None;
    }
    let (answer, _) = on_screen(app).answer()?;
    match app.ui.chart.build(answer) {
        Ok(Figure::Map(map)) => Some(map),
        _ => None,
    }
}

/// Carries out `x`, `[ ]` or `{ }` on the pressure map.
pub fn act(app: &mut App, action: Action) {
    let Some(map) = visible(app) else {
        app.say("the map has not arrived yet: x works once it is drawn");
        return;
    };
    let dims = (map.x.len(), map.y.len());
    let (cell, said) = cursor_key(action, app.ui.map_cell, dims, || (dims.0 / 2, dims.1 / 2));
    app.ui.map_cell = cell;
    app.say(match said {
        Some(CursorChange::On) => {
            "cursor X: [ ] move it along x, { } along y; the status reads p there"
        }
        Some(CursorChange::Off) => "cursor off",
        Some(CursorChange::NotShown) => "x shows the cursor first",
        None => return,
    });
}

/// What a grid cursor's key did, for the caller's message.
pub enum CursorChange {
    /// `x` showed it.
    On,
    /// `x` hid it.
    Off,
    /// `[ ] { }` while it is hidden.
    NotShown,
}

/// A grid cursor after `x` (shown at `start`, or hidden), `[ ]` or `{ }` (`moved_cell`) on a grid of
/// `nx` x `ny` points, and what to say (None: it moved): the pressure map's and the regime map's
/// cursors alike.
pub fn cursor_key(
    action: Action,
    cell: Option<(usize, usize)>,
    dims: (usize, usize),
    start: impl FnOnce() -> (usize, usize),
) -> (Option<(usize, usize)>, Option<CursorChange>) {
    match (action, cell) {
        (Action::Cursor, Some(_)) => (None, Some(CursorChange::Off)),
        (Action::Cursor, None) => (Some(start()), Some(CursorChange::On)),
        (Action::MoveCursor(by), Some(at)) => (Some(moved_cell(at, by, dims)), None),
        (_, cell) => (cell, Some(CursorChange::NotShown)),
    }
}

/// A grid cursor (column, row) on a grid of `nx` x `ny` points after `[ ]` (a point along x) or
/// `{ }` (a point along y), kept on the grid: the pressure map's and the regime map's cursors
/// alike.
pub fn moved_cell(
    (i, j): (usize, usize),
    by: CursorMove,
    (nx, ny): (usize, usize),
) -> (usize, usize) {
    let step = |k: usize, d: i32, n: usize| {
        (k.min(n - 1) as i64 + d as i64).clamp(0, n as i64 - 1) as usize
    };
    let (dx, dy) = by.grid_step();
    (step(i, dx, nx), step(j, dy, ny))
}

/// The grid point of the cursor on `map` (a grid of another size, after an edit, clamps it).
pub fn cell(map: &Map, (i, j): (usize, usize)) -> (usize, usize) {
    (i.min(map.x.len() - 1), j.min(map.y.len() - 1))
}
