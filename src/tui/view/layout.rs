//! Where each part of the screen goes:
//!
//! ```text
//! ┌ problem ───────┐┌ n/N chart title [solving…] ───────────┐
//! │group           ││                                       │
//! │  label   value ││  chart (or heatmap)                   │
//! │  label   value ││                                       │
//! │group           │└──────────────────────── Tab: next chart┘
//! │  label   value │┌ operating point ──────────────────────┐
//! │                ││  status: values, validity, harmonics  │
//! └────────────────┘└───────────────────────────────────────┘
//! message line (or the prompt being typed)
//! footer: the keys
//! ```
//!
//! The form is 30 columns wide below 100 columns, 34 from there; the status takes 8 rows below
//! 32 rows, 10 from there. An expanded chart (`f`) takes the form's columns too, and below 32
//! rows the status gives it three of its rows; the status under a sweep or a map (`v`, `M`) gives
//! it two, for its legend and axes. Popups (help, picker, choices) are centred over
//! everything.

use ratatui::layout::{Constraint, Layout, Rect};

pub use crate::tui::app::MIN_SIZE;

/// The regions of the main screen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Areas {
    /// The parameter form.
    pub form: Rect,
    /// The chart.
    pub chart: Rect,
    /// The status (operating point).
    pub status: Rect,
    /// The message line.
    pub message: Rect,
    /// The key footer.
    pub footer: Rect,
}

/// The regions of a screen (the chart expanded or not; the status folded under a sweep or a
/// map or not), or None when it is smaller than `MIN_SIZE`.
pub fn areas(area: Rect, expanded: bool, folded: bool) -> Option<Areas> {
    if area.width < MIN_SIZE.0 || area.height < MIN_SIZE.1 {
        return None;
    }
    let [main, message, footer] = Layout::vertical([
        Constraint::Min(10),
        Constraint::Length(1),
        Constraint::Length(1),
    ])
    .areas(area);
    let form_width = match (expanded, area.width < 100) {
        (true, _) => 0,
        (false, true) => 30,
        (false, false) => 34,
    };
    let [form, right] =
        Layout::horizontal([Constraint::Length(form_width), Constraint::Min(40)]).areas(main);
    let status_height = match (area.height >= 32, expanded, folded) {
        (true, _, _) => 10,
        (false, true, _) => 5,
        // four lines: the operating point's a, b, mu* (and the cursor's readout when on)
        (false, false, true) => 6,
        (false, false, false) => 8,
    };
    let [chart, status] =
        Layout::vertical([Constraint::Min(8), Constraint::Length(status_height)]).areas(right);
    Some(Areas {
        form,
        chart,
        status,
        message,
        footer,
    })
}

/// A rectangle of at most w x h centred in `area`.
pub fn centered(area: Rect, w: u16, h: u16) -> Rect {
    let w = w.min(area.width);
    let h = h.min(area.height);
    Rect {
        x: area.x + (area.width - w) / 2,
        y: area.y + (area.height - h) / 2,
        width: w,
        height: h,
    }
}
