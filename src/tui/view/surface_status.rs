//! The status of a height-map punch: the contact on the map's grid and where its running-in
//! stands (`contact_status`), then the surface's rms height and rms slope at the state shown
//! beside their values as given (t = 0), which the running-in wears down.

use crate::engine::SurfaceOutput;
use crate::units::format_si;
use ratatui::text::Line;

use crate::tui::view::contact_status;
use crate::tui::view::theme::RenderOptions;
use crate::tui::view::wrap;
use crate::tui::view::wrapping::pack;

/// The status lines of `out`, wrapped to `width`.
pub fn lines(out: &SurfaceOutput, style: RenderOptions, width: usize) -> Vec<Line<'static>> {
    let mut lines = match &out.cell {
        Ok(c) => contact_status::head(c, out.mu, out.wear_rate, style, width, false).0,
        Err(why) => wrap(&why.to_string(), width)
            .into_iter()
            .map(|l| Line::styled(l, style.error()))
            .collect(),
    };
    let given = &out.initial;
    let items = match (
        &out.shown,
        out.running_in().and_then(|c| c.state.as_ref().ok()),
    ) {
        (Some(s), Some(state)) if state.time > 0.0 => vec![
            format!(
                "rms height = {} (t = 0: {})",
                format_si(s.rms_height, "m"),
                format_si(given.rms_height, "m")
            ),
            format!(
                "rms slope = {} (t = 0: {})",
                format_si(s.rms_slope, ""),
                format_si(given.rms_slope, "")
            ),
        ],
        _ => vec![
            format!("rms height = {}", format_si(given.rms_height, "m")),
            format!("rms slope = {}", format_si(given.rms_slope, "")),
        ],
    };
    lines.extend(pack(&items, width, "").into_iter().map(Line::from));
    lines
}
