//! The frame of a plot: where its parts go, the axis lines with tick marks and labels, the
//! reference lines (vertical marks labelled on the x axis line, horizontal ones named in the
//! legend) and shaded ranges.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;

use crate::tui::charts::range::Frame;
use crate::tui::charts::ticks::{BARE_END, Ticks, ticks};

mod reference_lines;
pub use reference_lines::{mark_labels, marks, shade, with_marks, y_mark_rows};

/// Where the parts of one plot go.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Geometry {
    /// The header row: the y axis title (and the legend when it fits).
    pub header: Rect,
    /// The column of y tick labels.
    pub labels: Rect,
    /// The data area.
    pub plot: Rect,
    /// The row of the x axis line.
    pub axis_row: u16,
    /// The row of the x tick labels (the last plot only).
    pub x_labels: Option<u16>,
    /// The row of the x axis title when it has one of its own, under the labels.
    pub x_title: Option<u16>,
}

/// Rows of data of a plot in `share` with `rows` legend rows and `under` rows under its axis
/// line (none, the x labels, the x labels and the x title).
pub fn plot_height(share: Rect, rows: u16, under: u16) -> u16 {
    share.height.saturating_sub(2 + rows + under).max(1)
}

impl Geometry {
    /// The parts of a plot in `share`, with a y label column `label_width` wide, `rows` legend
    /// rows and `under` rows under its axis line (none, the x labels, the labels and the title).
    pub fn new(share: Rect, label_width: u16, rows: u16, under: u16) -> Geometry {
        let height = plot_height(share, rows, under);
        let plot = Rect {
            x: share.x + label_width + 1,
            y: share.y + 1 + rows,
            width: share.width.saturating_sub(label_width + 1).max(1),
            height,
        };
        let axis_row = plot.y + plot.height;
        Geometry {
            header: Rect { height: 1, ..share },
            labels: Rect {
                x: share.x,
                width: label_width,
                ..plot
            },
            plot,
            axis_row,
            x_labels: (under > 0).then_some(axis_row + 1),
            x_title: (under > 1).then_some(axis_row + 2),
        }
    }

    /// The plot area relative to itself (for the raster).
    pub fn local_plot(&self) -> Rect {
        Rect {
            x: 0,
            y: 0,
            ..self.plot
        }
    }
}

/// `n` stacked shares of `area`, the first ones a row taller when it does not divide.
pub fn split(area: Rect, n: u16) -> Vec<Rect> {
    let n = n.max(1);
    let (each, more) = (area.height / n, area.height % n);
    let mut y = area.y;
    (0..n)
        .map(|i| {
            let height = each + (i < more) as u16;
            let r = Rect { y, height, ..area };
            y += height;
            r
        })
        .collect()
}

/// The column of a fraction of the plot width.
fn column(f: f64, width: u16) -> u16 {
    (f.clamp(0.0, 1.0) * (width.max(1) - 1) as f64).round() as u16
}

/// The row of a fraction of the plot height (from the bottom).
fn row(f: f64, height: u16) -> u16 {
    ((1.0 - f.clamp(0.0, 1.0)) * (height.max(1) - 1) as f64).round() as u16
}

fn frac(v: f64, [lo, hi]: [f64; 2]) -> f64 {
    (v - lo) / (hi - lo)
}

/// The x tick labels and the axis title placed on a row `width` wide whose plot starts at
/// column `left`: the labels that fit (tick index, start column, text), each covering its tick's
/// column (centred where it can be, the last one pulled in from the row's end) and none touching
/// another, and the title's column on that row: at the row's end where it is clear of the labels,
/// else at the row's start (`kh (log)  1  2  5`), else (`clear`) at the end with the labels under
/// it left out, else None: on a row of its own, never over a label.
fn place_x(
    t: &Ticks,
    range: [f64; 2],
    (left, width): (u16, u16),
    clear: bool,
) -> (Vec<(usize, u16, String)>, Option<u16>) {
    let plot_width = width.saturating_sub(left);
    let mut labels: Vec<(usize, u16, String)> = Vec::new();
    let mut free = 0u16;
    for (i, (pos, label)) in t.ticks.iter().enumerate() {
        let len = label.chars().count() as u16;
        let centre = left + column(frac(*pos, range), plot_width);
        let start = (centre.saturating_sub(len / 2).max(free)).min(width.saturating_sub(len));
        if start < free || start > centre || start + len <= centre {
            continue;
        }
        free = start + len + 2;
        labels.push((i, start, label.clone()));
    }
    let title = t.title.chars().count() as u16;
    let end = |l: &(usize, u16, String)| l.1 + l.2.chars().count() as u16;
    let right = width.saturating_sub(title);
    let at = if labels.last().is_none_or(|l| end(l) < right) {
        Some(right)
    } else if labels.first().is_some_and(|l| l.1 > title) {
        Some(0)
    } else if clear {
        labels.retain(|l| end(l) < right);
        Some(right)
    } else {
        None
    };
    (labels, at)
}

/// How far the labels `shown` (tick indices of `t`) leave the ends of `range` bare: the larger
/// of the fractions of the axis before the first and after the last.
fn bare_end(t: &Ticks, shown: &[usize], range: [f64; 2]) -> f64 {
    match (shown.first(), shown.last()) {
        (Some(&a), Some(&b)) => frac(t.ticks[a].0, range).max(1.0 - frac(t.ticks[b].0, range)),
        _ => 1.0,
    }
}

/// The x ticks of the shared axis, each labelled, and whether the axis title needs a row of its
/// own. Of the candidate tick sets (the labels left out for want of room only at the ends of a
/// set, never between two shown), the first by: labels within `BARE_END` of both ends of the
/// axis (so that where the range ends can be read; else as near them as can be), the title stating its scale ("(log)", or
/// "log") with at least two labels, the title on the label row (else on a row of its own, never
/// over a label), the most labels, the full title; of equals the finer set (a log axis keeps 1-2-5
/// over bare decades). The ticks left out are not drawn either: no tick without its value.
pub fn x_ticks(frame: &Frame, plot_width: u16, left: u16) -> (Ticks, bool) {
    let x = &frame.plot.x;
    let width = plot_width + left;
    // the title as it comes ("k [rad/m] (log)"), with the scale shorter ("k [rad/m] log"),
    // without it ("k [rad/m]")
    let candidates = |form: u8| {
        (2..=(plot_width as usize / 6).max(2))
            .rev()
            .map(move |max| {
                let mut t = ticks(frame.x, x.scale, &x.label, x.unit, max);
                for scale in ["log", "symlog"] {
                    let long = format!(" ({scale})");
                    if let Some(s) = t.title.strip_suffix(&long).filter(|_| form > 0) {
                        t.title = match form {
                            1 => format!("{s} {scale}"),
                            _ => s.to_string(),
                        };
                    }
                }
                (t, form)
            })
    };
    // the labels shown, if they are a run of the set (none missing between two shown), and
    // whether the title is on their row
    let run = |t: &Ticks, clear: bool| -> Option<(Vec<usize>, bool)> {
        let (labels, at) = place_x(t, frame.x, (left, width), clear);
        let k: Vec<usize> = labels.into_iter().map(|l| l.0).collect();
        k.windows(2)
            .all(|w| w[1] == w[0] + 1)
            .then_some((k, at.is_some()))
    };
    let key = |(t, form, clear): &(Ticks, u8, bool)| {
        run(t, *clear).map(|(k, on_row)| {
            (
                std::cmp::Reverse((bare_end(t, &k, frame.x).max(BARE_END) * 1e3).round() as i64),
                *form < 2 && k.len() >= 2,
                k.len().min(4),
                on_row,
                k.len(),
                *form == 0,
            )
        })
    };
    let best = candidates(0)
        .chain(candidates(1))
        .chain(candidates(2))
        .flat_map(|(t, form)| [(t.clone(), form, false), (t, form, true)])
        .fold(None, |best: Option<(Ticks, u8, bool)>, c| match best {
            Some(b) if key(&b) >= key(&c) => Some(b),
            _ => Some(c),
        })
        .map(|(t, _, clear)| (t, clear))
        .unwrap_or_else(|| (ticks(frame.x, x.scale, &x.label, x.unit, 2), false));
    let (labels, at) = place_x(&best.0, frame.x, (left, width), best.1);
    let k: Vec<usize> = labels.into_iter().map(|l| l.0).collect();
    let shown = Ticks {
        ticks: (best.0.ticks.iter().enumerate())
            .filter(|(i, _)| k.contains(i))
            .map(|(_, t)| t.clone())
            .collect(),
        title: best.0.title,
    };
    (shown, at.is_none())
}

/// Draws the axis lines with tick marks, the tick labels, and the vertical marks' labels on the
/// x axis line.
pub fn frame(frame: &Frame, g: &Geometry, y: &Ticks, x: &Ticks, buf: &mut Buffer) {
    let p = g.plot;
    let axis_x = p.x - 1;
    for r in p.y..p.y + p.height {
        buf[(axis_x, r)].set_char('│');
    }
    buf[(axis_x, g.axis_row)].set_char('└');
    for col in p.x..p.x + p.width {
        buf[(col, g.axis_row)].set_char('─');
    }
    let mut used = Vec::new();
    for (pos, label) in &y.ticks {
        let r = p.y + row(frac(*pos, frame.y), p.height);
        if used.contains(&r) {
            continue;
        }
        used.push(r);
        buf[(axis_x, r)].set_char('┤');
        let len = label.chars().count() as u16;
        let x0 = g.labels.x + g.labels.width.saturating_sub(len);
        buf.set_stringn(x0, r, label, g.labels.width as usize, Style::default());
    }
    for (pos, _) in &x.ticks {
        buf[(p.x + column(frac(*pos, frame.x), p.width), g.axis_row)].set_char('┬');
    }
    for (start, label) in mark_labels(frame, p) {
        buf.set_string(start, g.axis_row, label, Style::default());
    }
    if let Some(r) = g.x_labels {
        let left = p.x - g.header.x;
        let width = g.header.width;
        let (labels, at) = place_x(x, frame.x, (left, width), false);
        for (_, start, label) in labels {
            buf.set_string(g.header.x + start, r, label, Style::default());
        }
        let len = x.title.chars().count() as u16;
        // on a row of its own when the layout gave it one, at that row's end
        let (row, col) = match (g.x_title, at) {
            (Some(own), _) => (own, width.saturating_sub(len)),
            (None, Some(col)) => (r, col),
            (None, None) => (r, width.saturating_sub(len)),
        };
        buf.set_stringn(
            g.header.x + col,
            row,
            &x.title,
            len as usize,
            Style::default(),
        );
    }
}
