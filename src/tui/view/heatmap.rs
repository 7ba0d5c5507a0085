//! The heatmap: a scalar field drawn with half blocks (two grid rows per text row), with a colour
//! bar and its range; shades without colour.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::widgets::{Paragraph, Widget};
use wearlab::units::format_si;

use crate::tui::charts::Map;
use crate::tui::charts::range::bounds;
use crate::tui::view::theme::RenderOptions;

/// Columns of the colour bar and its labels.
const BAR: u16 = 12;

/// Draws the map into `area`: the field on the left, the bar on the right, the caption under it.
pub fn draw(map: &Map, style: RenderOptions, buf: &mut Buffer, area: Rect) {
    let [lo, hi] = bounds(map.values.iter().copied());
    let (nx, ny) = (map.x.len(), map.y.len());
    if nx == 0 || ny == 0 {
        return;
    }
    let w = area.width.saturating_sub(BAR + 1).max(4);
    let h = area.height.saturating_sub(1).max(2);
    let sample = |col: u16, half_row: u16| -> f64 {
        let i = ((col as usize * nx) / w as usize).min(nx - 1);
        // row 0 at the top is the largest y
        let j = ny - 1 - ((half_row as usize * ny) / (2 * h as usize)).min(ny - 1);
        (map.values[j * nx + i] - lo) / (hi - lo)
    };
    for row in 0..h.min(area.height) {
        for col in 0..w.min(area.width) {
            let (top, bottom) = (sample(col, 2 * row), sample(col, 2 * row + 1));
            let cell = &mut buf[(area.x + col, area.y + row)];
            if style.color {
                cell.set_char('▀')
                    .set_fg(style.heat(top))
                    .set_bg(style.heat(bottom));
            } else {
                cell.set_char(style.shade(0.5 * (top + bottom)));
            }
        }
    }
    let bx = area.x + w + 1;
    if bx + BAR > area.x + area.width {
        return;
    }
    for row in 0..h {
        let t = 1.0 - row as f64 / (h - 1).max(1) as f64;
        let cell = &mut buf[(bx, area.y + row)];
        if style.color {
            cell.set_char('█').set_fg(style.heat(t));
        } else {
            cell.set_char(style.shade(t));
        }
    }
    let mut label = |v: f64, y: u16| {
        let rect = Rect {
            x: bx + 2,
            y,
            width: BAR - 2,
            height: 1,
        };
        Paragraph::new(format_si(v, map.unit)).render(rect, buf);
    };
    label(hi, area.y);
    label(lo, area.y + h - 1);
    let caption = Rect {
        x: area.x,
        y: area.y + h,
        width: area.width,
        height: 1,
    };
    Paragraph::new(map.caption.as_str()).render(caption, buf);
}
