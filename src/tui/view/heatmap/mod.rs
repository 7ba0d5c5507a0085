//! The heatmap: a scalar field drawn with half blocks (two grid rows per text row, so that a
//! square cell looks square) in filled bands at nice values, as matplotlib's `contourf` draws
//! it, one viridis colour a band (one shade without colour), with a bar of the bands whose every
//! edge is labelled, and the unit and step. A fixed scale (kept while time plays) keeps the
//! bands and says so.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};

use crate::tui::backend::colour_bytes;
use crate::tui::charts::Map;
use crate::tui::charts::range::bounds;
use crate::tui::charts::ticks::bands;
use crate::tui::map_cursor;
use crate::tui::view::theme::{ASCII_SHADES, RenderOptions, SHADES};
use crate::tui::view::wrap;

mod cells;
use cells::{CODES, DEFAULT, EMPTY_CODE, fewest_bytes};

/// The symbol of the map's values, in the bar's title and the cursor's readout.
pub const SYMBOL: &str = "p";

/// Columns of the colour bar and its labels.
const BAR: u16 = 8;

/// The most bands: few enough that each is told apart from its neighbours and found on the bar,
/// and that a map redraws in under 8 kB over SSH at 120x40 in 256 colours (bytes go
/// with the colour changes along each row). Measured on the four bundled maps, 6 is the most
/// that all meet it: at 7 dispersion.toml has 7 bands of 0.25 MPa (9.9 kB), at 8 also
/// jgh-egg-box.toml 8 of 25 MPa (8.9 kB) and contact-lost.toml 8 of 2 MPa (8.6 kB).
pub const MOST_BANDS: usize = 6;

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

/// The shades without colour, the blank first (`theme::shade`).
fn shades(style: RenderOptions) -> usize {
    if style.ascii {
        ASCII_SHADES.len()
    } else {
        SHADES.len()
    }
}

/// The most bands a bar of `rows` rows shows: in colour an edge on a row of its own, each
/// splitting its row between the bands above and below it; without colour also a row of its own
/// for each band between blank rows at the edges, and no more bands than shades but the blank.
fn most_bands(style: RenderOptions, rows: u16) -> usize {
    let rows = rows.max(1) as usize;
    let most = if style.color {
        MOST_BANDS.min(rows - 1)
    } else {
        MOST_BANDS.min(shades(style) - 1).min((rows - 1) / 2)
    };
    most.max(1)
}

/// Draws the map into `area`: the field on the left, the bar right of it, the caption under
/// it. `fixed`: the colour scale to use instead of the map's own range; `cursor`: the grid
/// point (column, row) marked `X` (`map_cursor`).
pub fn draw(
    map: &Map,
    fixed: Option<[f64; 2]>,
    cursor: Option<(usize, usize)>,
    style: RenderOptions,
    buf: &mut Buffer,
    area: Rect,
) {
    let (nx, ny) = (map.x.len(), map.y.len());
    if nx < 2 || ny < 2 || area.width < BAR + 4 || area.height < 3 {
        return;
    }
    let range = fixed.unwrap_or_else(|| bounds(map.values.iter().copied()));
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
    let (edges, step) = bands(range, SYMBOL, map.unit, most_bands(style, h));
    let n = edges.ticks.len() - 1;
    let (e0, e1) = (edges.ticks[0].0, edges.ticks[n].0);
    // band i holds the values in (edge i, edge i + 1], the lowest also its lower edge
    let band = |v: f64| -> u8 {
        let x = (v - e0) / (e1 - e0) * n as f64;
        ((x - 1e-9).ceil() as i64 - 1).clamp(0, n as i64 - 1) as u8
    };
    // None: an empty value (no contact), drawn apart from the bands
    let sample = |col: u16, half_row: u16| -> Option<f64> {
        let i = ((col as usize * nx) / w as usize).min(nx - 1);
        // row 0 at the top is the largest y
        let j = ny - 1 - ((half_row as usize * ny) / (2 * h as usize)).min(ny - 1);
        let v = map.values[j * nx + i];
        (map.empty.is_none() || v != 0.0).then_some(v)
    };
    // without colour one shade a band, spread over the shades from the lightest but the blank
    let shade = |b: u8| {
        let k = 1.0 + b as f64 * (shades(style) - 2) as f64 / (n - 1).max(1) as f64;
        style.shade(k / (shades(style) - 1) as f64)
    };
    let empty = style.empty();
    let colours = style.bands(n);
    let colour = |code: u8| match code {
        EMPTY_CODE => empty.1,
        DEFAULT => Color::Reset,
        // a code of no band (n < MOST_BANDS) is never drawn
        b => colours.get(b as usize).copied().unwrap_or(Color::Reset),
    };
    let weight: Vec<u32> = (0..CODES as u8).map(|c| colour_bytes(colour(c))).collect();
    for row in 0..h {
        let halves = (0..w).map(|col| (sample(col, 2 * row), sample(col, 2 * row + 1)));
        if !style.color {
            // a text cell holds two rows: the band of those with a value
            for (col, (top, bottom)) in halves.enumerate() {
                let glyph = match (top, bottom) {
                    (Some(a), Some(b)) => shade(band(0.5 * (a + b))),
                    (Some(a), None) | (None, Some(a)) => shade(band(a)),
                    (None, None) => empty.0,
                };
                buf[(area.x + col as u16, area.y + row)].set_char(glyph);
            }
            continue;
        }
        let code = |v: Option<f64>| v.map_or(EMPTY_CODE, band);
        let codes: Vec<(u8, u8)> = halves.map(|(a, b)| (code(a), code(b))).collect();
        for (col, (glyph, fg, bg)) in fewest_bytes(&codes, &weight).into_iter().enumerate() {
            buf[(area.x + col as u16, area.y + row)]
                .set_char(glyph)
                .set_style(Style::default().fg(colour(fg)).bg(colour(bg)));
        }
    }
    if let Some((i, j)) = cursor.map(|at| map_cursor::cell(map, at)) {
        mark(
            style,
            buf,
            area,
            (i * w as usize / nx, (ny - 1 - j) * h as usize / ny),
        );
    }
    // the bar: the bands from the top, each edge on a row of its own with its label
    let bx = area.x + w + 1;
    let edge_row = |i: usize| area.y + ((n - i) as f64 * (h - 1) as f64 / n as f64).round() as u16;
    for (b, &fill) in colours.iter().enumerate() {
        for y in edge_row(b + 1) + 1..edge_row(b) {
            let cell = &mut buf[(bx, y)];
            if style.color {
                cell.set_char(' ').set_style(Style::default().bg(fill));
            } else {
                cell.set_char(shade(b as u8));
            }
        }
    }
    let mut used = Vec::new();
    for (i, (_, label)) in edges.ticks.iter().enumerate() {
        let y = edge_row(i);
        if used.contains(&y) {
            continue;
        }
        used.push(y);
        // in colour the edge splits its row: the band above in the upper half, below in the
        // lower; without colour its row is blank between the bands' shades
        if style.color {
            let (glyph, fg, bg) = match (i < n, i > 0) {
                (true, true) => ('▀', colours[i], colours[i - 1]),
                (true, false) => ('▀', colours[i], Color::Reset),
                (false, _) => ('▄', colours[n - 1], Color::Reset),
            };
            buf[(bx, y)]
                .set_char(glyph)
                .set_style(Style::default().fg(fg).bg(bg));
        }
        buf.set_stringn(
            bx + 1,
            y,
            format!("{}{label}", style.bar_tick()),
            (BAR - 1) as usize,
            Style::default(),
        );
    }
    let named = if cursor.is_some() { "X cursor. " } else { "" };
    let title = match fixed {
        Some(_) => format!(
            "{} in bands of {step}, scale fixed while only t changes",
            edges.title
        ),
        None => format!("{} in bands of {step}", edges.title),
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
        let words = format!("{named}{title}. {}", map.caption);
        for (i, line) in wrap(&words, width)
            .iter()
            .take(h as usize - rows)
            .enumerate()
        {
            let row = y + (i + rows) as u16;
            buf.set_stringn(x, row, line, width, Style::default());
        }
    } else {
        let words = format!("{named}{title}. {}", map.caption);
        let width = (area.x + area.width).saturating_sub(x_words) as usize;
        buf.set_stringn(x_words, y, words, width, Style::default());
    }
}

/// Marks the cursor's text cell (column, row of the field) with `X`, in colour as the regime
/// map marks it (bold yellow on black, seen on every band), else bold.
fn mark(style: RenderOptions, buf: &mut Buffer, area: Rect, (col, row): (usize, usize)) {
    let ink = if style.color {
        Style::default().fg(Color::Yellow).bg(Color::Black)
    } else {
        Style::default()
    };
    buf[(area.x + col as u16, area.y + row as u16)]
        .set_char('X')
        .set_style(ink.add_modifier(Modifier::BOLD));
}
