//! The heatmap: a scalar field drawn with half blocks (two grid rows per text row, so that a
//! square cell looks square), in a quantised viridis map, with a colour bar, its ticks and the
//! unit; shades without colour. A fixed scale (kept while time plays) says so above the bar.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};

use crate::tui::charts::Map;
use crate::tui::charts::Scale;
use crate::tui::charts::palette::{LEVELS, level};
use crate::tui::charts::range::bounds;
use crate::tui::charts::ticks::ticks;
use crate::tui::view::theme::RenderOptions;
use crate::tui::view::wrap;

/// Columns of the colour bar and its labels.
const BAR: u16 = 8;

/// The size in cells (columns, text rows) of a map of aspect `lx/ly` that fits in `width` x
/// `height` cells, a text row holding two grid rows.
pub fn fit(aspect: f64, width: u16, height: u16) -> (u16, u16) {
    let (w, h2) = (width.max(1) as f64, 2.0 * height.max(1) as f64);
    if w / h2 > aspect {
        (((h2 * aspect).round() as u16).clamp(1, width), height)
    } else {
        (width, ((w / aspect / 2.0).round() as u16).clamp(1, height))
    }
}

/// Draws the map into `area`: the field on the left, the bar right of it, the caption under
/// it. `fixed`: the colour scale to use instead of the map's own range.
pub fn draw(
    map: &Map,
    fixed: Option<[f64; 2]>,
    style: RenderOptions,
    buf: &mut Buffer,
    area: Rect,
) {
    let (nx, ny) = (map.x.len(), map.y.len());
    if nx < 2 || ny < 2 || area.width < BAR + 4 || area.height < 3 {
        return;
    }
    let [lo, hi] = fixed.unwrap_or_else(|| bounds(map.values.iter().copied()));
    let aspect = (map.x[nx - 1] - map.x[0]) / (map.y[ny - 1] - map.y[0]);
    // the words right of the bar when there is room for them, else in a row under the map
    const SIDE: u16 = 14;
    let side = fit(aspect, area.width - BAR - 1, area.height);
    let beside = area.width.saturating_sub(side.0 + BAR + 2) >= SIDE;
    let (w, h) = if beside {
        side
    } else {
        fit(aspect, area.width - BAR - 1, area.height - 1)
    };
    // None: an empty value (no contact), drawn apart from the scale
    let sample = |col: u16, half_row: u16| -> Option<f64> {
        let i = ((col as usize * nx) / w as usize).min(nx - 1);
        // row 0 at the top is the largest y
        let j = ny - 1 - ((half_row as usize * ny) / (2 * h as usize)).min(ny - 1);
        let v = map.values[j * nx + i];
        (map.empty.is_none() || v != 0.0).then(|| (v - lo) / (hi - lo))
    };
    let empty = style.empty();
    for row in 0..h {
        for col in 0..w {
            let (top, bottom) = (sample(col, 2 * row), sample(col, 2 * row + 1));
            let cell = &mut buf[(area.x + col, area.y + row)];
            if !style.color {
                // a text cell holds two rows: the shade of those with a value
                let shade = match (top, bottom) {
                    (Some(a), Some(b)) => style.shade(0.5 * (a + b)),
                    (Some(a), None) | (None, Some(a)) => style.shade(a),
                    (None, None) => empty.0,
                };
                cell.set_char(shade);
                continue;
            }
            let colour = |t: Option<f64>| t.map_or(empty.1, |t| style.heat(level(t)));
            let (a, b) = (colour(top), colour(bottom));
            // one colour code for a cell of one level: fewer bytes to send
            if a == b {
                cell.set_char(' ')
                    .set_style(Style::default().fg(Color::Reset).bg(a));
            } else {
                cell.set_char('▀').set_style(Style::default().fg(a).bg(b));
            }
        }
    }
    // the bar: the levels from the top, with ticks of the values
    let bx = area.x + w + 1;
    for row in 0..h {
        let t = 1.0 - row as f64 / (h - 1).max(1) as f64;
        let cell = &mut buf[(bx, area.y + row)];
        if style.color {
            let l = level(t).min(LEVELS - 1);
            cell.set_char(' ')
                .set_style(Style::default().bg(style.heat(l)));
        } else {
            cell.set_char(style.shade(t));
        }
    }
    let t = ticks(
        [lo, hi],
        Scale::Linear,
        "p",
        map.unit,
        (h as usize / 2).clamp(2, 8),
    );
    let mut used = Vec::new();
    for (v, label) in &t.ticks {
        let row = ((1.0 - (v - lo) / (hi - lo)) * (h - 1) as f64).round() as u16;
        if used.contains(&row) {
            continue;
        }
        used.push(row);
        buf.set_stringn(
            bx + 1,
            area.y + row,
            format!("┤{label}"),
            (BAR - 1) as usize,
            Style::default(),
        );
    }
    let title = match fixed {
        Some(_) => format!("{}, scale fixed while only t changes", t.title),
        None => t.title.clone(),
    };
    // the empty values' sample and name first, then the words
    let (x, y) = if beside {
        (bx + BAR + 1, area.y)
    } else {
        (area.x, area.y + h)
    };
    let mut x_words = x;
    if let Some(label) = map.empty {
        let swatch = if style.color {
            (' ', Style::default().bg(empty.1))
        } else {
            (empty.0, Style::default())
        };
        buf[(x, y)].set_char(swatch.0).set_style(swatch.1);
        let (end, _) = buf.set_stringn(x + 1, y, format!(" {label}. "), 40, Style::default());
        x_words = end;
    }
    if beside {
        let width = ((area.x + area.width - x) as usize).min(40);
        let rows = if map.empty.is_some() { 1 } else { 0 };
        let words = format!("{title}. {}", map.caption);
        for (i, line) in wrap(&words, width)
            .iter()
            .take(h as usize - rows)
            .enumerate()
        {
            let row = y + (i + rows) as u16;
            buf.set_stringn(x, row, line, width, Style::default());
        }
    } else {
        let words = format!("{title}. {}", map.caption);
        let width = (area.x + area.width).saturating_sub(x_words) as usize;
        buf.set_stringn(x_words, y, words, width, Style::default());
    }
}
