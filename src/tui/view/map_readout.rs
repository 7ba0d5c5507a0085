//! The status's readout at the pressure map's cursor (`map_cursor`): the map's own value at the
//! grid point, read from the figure drawn (no physics here).

use crate::tui::app::App;
use crate::tui::charts::Map;
use crate::tui::map_cursor::{cell, visible};
use crate::tui::view::heatmap;
use crate::units::format_si;

/// The status's readout at the cursor: x and y of the grid point and the map's value there with
/// its unit (`units::format_si`), or that there is no contact.
pub fn readout(map: &Map, at: (usize, usize)) -> Vec<String> {
    let (i, j) = cell(map, at);
    let v = map.values[j * map.x.len() + i];
    let value = match map.empty {
        Some(label) if v == 0.0 => label.to_string(),
        _ => format!("{} = {}", heatmap::SYMBOL, format_si(v, map.unit)),
    };
    vec![
        format!("cursor x = {}", format_si(map.x[i], "m")),
        format!("y = {}:", format_si(map.y[j], "m")),
        value,
    ]
}

/// The readout of the visible map's cursor, when it is on.
pub fn status(app: &App) -> Option<Vec<String>> {
    let at = app.ui.map_cell?;
    visible(app).map(|map| readout(&map, at))
}
