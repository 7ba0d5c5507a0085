//! The reference lines of a plot (vertical marks labelled on the x axis line, horizontal ones
//! named in the legend) and its shaded x ranges.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;

use super::{Geometry, column, frac, row};
use crate::tui::charts::range::Frame;
use crate::tui::view::raster::{Ink, Raster};
use crate::tui::view::theme::RenderOptions;

/// Shades the plot's shaded x ranges (under everything else).
pub fn shade(frame: &Frame, g: &Geometry, style: RenderOptions, buf: &mut Buffer) {
    let (glyph, st) = style.shaded();
    let p = g.plot;
    for s in &frame.plot.shaded {
        let (Some(a), Some(b)) = (
            frame.plot.x.scale.to_plot(s.from),
            frame.plot.x.scale.to_plot(s.to),
        ) else {
            continue;
        };
        let (c0, c1) = (
            column(frac(a, frame.x), p.width),
            column(frac(b, frame.x), p.width),
        );
        for col in c0.min(c1)..=c0.max(c1) {
            for r in 0..p.height {
                let cell = &mut buf[(p.x + col, p.y + r)];
                cell.set_style(st);
                if !style.color {
                    cell.set_char(glyph);
                }
            }
        }
    }
}

/// The rows of a plot `height` rows high that its horizontal reference lines take.
pub fn y_mark_rows(frame: &Frame, height: u16) -> Vec<u16> {
    (frame.plot.y_marks.iter())
        .filter_map(|m| frame.y_scale.to_plot(m.at))
        .map(|v| row(frac(v, frame.y), height))
        .collect()
}

/// The plot's raster with its reference lines drawn in as data, in the cells `marks` draws
/// them: what a legend keeps clear of where it can.
pub fn with_marks(raster: &Raster, frame: &Frame) -> Raster {
    let mut r = raster.clone();
    let ink = Ink {
        glyph: '-',
        solid: true,
        second: None,
        style: Style::default(),
    };
    let clamped = |v: f64, range: [f64; 2]| frac(v, range).clamp(0.0, 1.0);
    for m in &frame.plot.y_marks {
        if let Some(v) = frame.y_scale.to_plot(m.at) {
            let f = clamped(v, frame.y);
            r.line(&[(0.0, f), (1.0, f)], ink);
        }
    }
    for m in &frame.plot.x_marks {
        if let Some(v) = frame.plot.x.scale.to_plot(m.at) {
            let f = clamped(v, frame.x);
            r.line(&[(f, 0.0), (f, 1.0)], ink);
        }
    }
    r
}

/// Draws the reference lines on the cells without data.
pub fn marks(frame: &Frame, g: &Geometry, raster: &Raster, style: RenderOptions, buf: &mut Buffer) {
    let p = g.plot;
    let (vertical, horizontal) = style.mark_glyphs();
    let mut put = |col: u16, r: u16, c: char| {
        if !raster.occupied(col, r) {
            buf[(p.x + col, p.y + r)]
                .set_char(c)
                .set_style(style.mark());
        }
    };
    for r in y_mark_rows(frame, p.height) {
        (0..p.width).for_each(|col| put(col, r, horizontal));
    }
    for m in &frame.plot.x_marks {
        if let Some(v) = frame.plot.x.scale.to_plot(m.at) {
            let col = column(frac(v, frame.x), p.width);
            (0..p.height).for_each(|r| put(col, r, vertical));
        }
    }
}

/// The labels of the vertical marks on the x axis line of plot area `p`, left to right: each
/// covering its own mark's column (centred where it can be, else shifted as little as it takes
/// to stay inside the plot and a column clear of the labels placed before it); "now" is placed
/// first, so that the operating point is always named; a mark at most a column from one named
/// joins its label ("now/complete", the left one first, covering both columns); one that can
/// be neither is left out, never put elsewhere.
pub fn mark_labels(frame: &Frame, p: Rect) -> Vec<(u16, String)> {
    let mut marks: Vec<(u16, &str)> = frame
        .plot
        .x_marks
        .iter()
        .filter_map(|m| {
            let v = frame.plot.x.scale.to_plot(m.at)?;
            Some((p.x + column(frac(v, frame.x), p.width), m.label.as_str()))
        })
        .collect();
    marks.sort_by_key(|m| (m.1 != "now", m.0));
    let end = p.x + p.width;
    // (start, the columns it covers, text)
    let mut out: Vec<(u16, [u16; 2], String)> = Vec::new();
    // the start of `text`, covering columns `cols`, nearest centred, clear of the others
    let place = |out: &[(u16, [u16; 2], String)], text: &str, [lo, hi]: [u16; 2], skip| {
        let len = text.chars().count() as u16;
        let centred = ((lo + hi) / 2).saturating_sub(len / 2);
        let mut starts: Vec<u16> = (hi.saturating_sub(len.saturating_sub(1))..=lo).collect();
        starts.sort_by_key(|s| s.abs_diff(centred));
        starts.into_iter().find(|&start| {
            start >= p.x
                && start + len <= end
                && (out.iter().enumerate()).all(|(k, (s, _, l))| {
                    Some(k) == skip || start + len < *s || s + (l.chars().count() as u16) < start
                })
        })
    };
    for (centre, label) in marks {
        if let Some(start) = place(&out, label, [centre, centre], None) {
            out.push((start, [centre, centre], label.to_string()));
            continue;
        }
        let near = (out.iter()).position(|o| o.1[0].abs_diff(centre) <= 1 && o.1[0] == o.1[1]);
        if let Some(k) = near {
            let own = out[k].1[0];
            let cols = [own.min(centre), own.max(centre)];
            let text = if centre < own {
                format!("{label}/{}", out[k].2)
            } else {
                format!("{}/{label}", out[k].2)
            };
            if let Some(start) = place(&out, &text, cols, Some(k)) {
                out[k] = (start, cols, text);
            }
        }
    }
    out.sort_by_key(|l| l.0);
    out.into_iter()
        .map(|(start, _, text)| (start, text))
        .collect()
}
