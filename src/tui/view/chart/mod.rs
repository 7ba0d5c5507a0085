//! The chart widget: a figure's plots stacked, sharing one x axis (labelled under the last). Each
//! plot has a header row (the y axis title, and the legend when it fits there), its curves, pins
//! and marks, an axis line with tick marks and the labels of vertical marks, and under the last
//! plot the x tick labels with the x axis title at their right. Nothing is written on a data
//! cell: the legend goes in the header, else in an empty corner, else in rows of its own.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};

use crate::tui::charts::range::{Frame, plotted};
use crate::tui::charts::ticks::{Ticks, ticks};
use crate::tui::view::axis::{self, Geometry};
use crate::tui::view::legend::{self, Entry, Place};
use crate::tui::view::raster::Raster;
use crate::tui::view::theme::RenderOptions;

mod legend_entries;
use legend_entries::entries;

/// What is drawn with the plots besides their own curves.
#[derive(Clone, Debug, Default)]
pub struct Extras {
    /// The cursor, as a fraction of the x range.
    pub cursor: Option<f64>,
    /// The legend names of the pins, oldest first ("pin: k = 2e-11 1/Pa").
    pub pins: Vec<String>,
}

/// A fraction of a range.
fn frac(v: f64, [lo, hi]: [f64; 2]) -> f64 {
    (v - lo) / (hi - lo)
}

/// The curves, pins, markers and measured points of a frame in a raster of the plot area.
fn rasterize(frame: &Frame, style: RenderOptions, plot: Rect) -> Raster {
    let mut raster = Raster::new(plot.width, plot.height, style.braille());
    let (xs, ys) = (frame.plot.x.scale, frame.y_scale);
    let fit = |points: &[(f64, f64)]| -> Vec<(f64, f64)> {
        plotted(points, xs, ys)
            .into_iter()
            .map(|(x, y)| (frac(x, frame.x), frac(y, frame.y)))
            .collect()
    };
    for (p, pin) in frame.pins.iter().enumerate() {
        for (i, s) in pin.series.iter().enumerate() {
            raster.line(&fit(&s.points), style.pin_ink(p, i));
        }
    }
    // the first curve last, on top; each curve's dim parts over it, under the curves before it
    for (i, s) in frame.plot.series.iter().enumerate().rev() {
        raster.line(&fit(&s.points), style.series_ink(i));
        for (_, d) in frame.plot.dim.iter().rev().filter(|(j, _)| *j == i) {
            raster.line(&fit(&d.points), style.dim_ink(i));
        }
    }
    if let Some(m) = &frame.plot.markers {
        for p in fit(&m.points) {
            raster.point(p, style.marker_ink());
        }
    }
    // measured points over everything, each error bar under its point
    let (point, bar) = style.data_inks();
    for d in &frame.plot.data {
        for ends in d.bars() {
            raster.line(&fit(&ends), bar);
        }
        for p in fit(&d.points) {
            raster.point(p, point);
        }
    }
    raster
}

/// One plot laid out: its geometry, ticks, raster, legend entries and place.
pub struct Laid {
    /// Where its parts go.
    pub geometry: Geometry,
    /// The y ticks and title.
    pub y_ticks: Ticks,
    /// Its curves.
    pub raster: Raster,
    /// Its legend.
    pub entries: Vec<Entry>,
    /// Where the legend goes.
    pub place: Place,
    /// The legend's entries in full where `entries` folds some away ("+3 more: i").
    pub full: Option<Vec<Entry>>,
}

/// The y ticks of the stacked frames in `shares` with `extra[i]` legend rows above plot i, the
/// last with the x title on a row of its own (`own`) or not.
fn y_ticks(frames: &[Frame], shares: &[Rect], extra: &[u16], own: bool) -> Vec<Ticks> {
    frames
        .iter()
        .zip(shares)
        .zip(extra)
        .enumerate()
        .map(|(i, ((f, share), &rows))| {
            let under = if i + 1 == frames.len() {
                1 + own as u16
            } else {
                0
            };
            let h = axis::plot_height(*share, rows, under);
            let max = (h as usize / 2).clamp(2, 8);
            match crate::tui::charts::range::constant(f) {
                // a constant: one tick, at it (among fine ones, the nearest), so that it reads
                // "0┤●───" rather than sitting between -1 and 1
                Some(v) => {
                    let mut t = ticks(f.y, f.y_scale, &f.plot.y.label, f.plot.y.unit, 9);
                    let near = |p: &(f64, String)| (p.0 - v).abs();
                    t.ticks.sort_by(|a, b| near(a).total_cmp(&near(b)));
                    t.ticks.truncate(1);
                    t
                }
                None => ticks(f.y, f.y_scale, &f.plot.y.label, f.plot.y.unit, max),
            }
        })
        .collect()
}

/// The width of the y label column of the stacked frames (`y_ticks`' arguments).
fn label_width(frames: &[Frame], shares: &[Rect], extra: &[u16], own: bool) -> u16 {
    y_ticks(frames, shares, extra, own)
        .iter()
        .flat_map(|t| t.ticks.iter().map(|(_, l)| l.chars().count()))
        .max()
        .unwrap_or(1) as u16
}

/// Lays out the stacked frames in `area` with `extra[i]` legend rows above plot i.
fn lay_out(
    frames: &[Frame],
    style: RenderOptions,
    extras: &Extras,
    area: Rect,
    extra: &[u16],
) -> Option<(Vec<Laid>, Ticks)> {
    let n = frames.len() as u16;
    let shares = axis::split(area, n);
    let last = frames.last()?;
    // the x title on the label row, else (when the ticks that read to the range's ends leave it
    // no room there) on a row of its own under the labels
    let (label_width, x_ticks, own, _) = [false, true]
        .into_iter()
        .map(|own| {
            let label_width = label_width(frames, &shares, extra, own);
            let plot_width = area.width.checked_sub(label_width + 1)?;
            let (x_ticks, wants) = axis::x_ticks(last, plot_width, label_width + 1);
            Some((label_width, x_ticks, own, wants))
        })
        .find(|t| t.as_ref().is_none_or(|t| t.2 || !t.3))??;
    let y_ticks = y_ticks(frames, &shares, extra, own);
    let laid = frames
        .iter()
        .zip(shares)
        .zip(y_ticks)
        .enumerate()
        .map(|(i, ((f, share), y_ticks))| {
            let under = if i + 1 == frames.len() {
                1 + own as u16
            } else {
                0
            };
            let geometry = Geometry::new(share, label_width, extra[i], under);
            let raster = rasterize(f, style, geometry.plot);
            let size = (geometry.plot.width, geometry.plot.height);
            let entries = entries(f, style, &extras.pins, size);
            Laid {
                geometry,
                y_ticks,
                raster,
                entries,
                place: Place::Rows(extra[i]),
                full: None,
            }
        })
        .collect();
    Some((laid, x_ticks))
}

/// The rows a plot keeps at least when its legend takes rows of its own.
const MIN_PLOT_ROWS: u16 = 3;

/// The rows of its own a legend takes above a plot `height` rows high without them, its first
/// line beside the title (`first` columns, the others `width`): as many as it needs, at most so
/// many that the plot keeps half its rows (and `MIN_PLOT_ROWS`), those of its folded form where
/// it needs more.
fn legend_rows(entries: &[Entry], first: usize, width: usize, height: u16) -> u16 {
    let lines = legend::lines_needed(entries, first, width);
    let keep = (height / 2).max(MIN_PLOT_ROWS);
    let most = lines.min(height.saturating_sub(keep) + 1);
    let folded = legend::fold(entries, first, width, most);
    legend::lines_needed(&folded, first, width).saturating_sub(1)
}

/// The frames of a figure stacked in `area`, each legend placed: in the header, else in an
/// empty corner, else in empty rows across the plot, else beside the title and in rows of its
/// own above the plot, at most as many as leave the plot half its rows (and `MIN_PLOT_ROWS`),
/// folded into "+N more: i" where it needs more.
pub fn layout(
    frames: &[Frame],
    style: RenderOptions,
    extras: &Extras,
    area: Rect,
) -> Option<(Vec<Laid>, Ticks)> {
    let none = vec![0; frames.len()];
    let (mut laid, mut x_ticks) = lay_out(frames, style, extras, area, &none)?;
    let width = area.width as usize;
    let beside = |l: &Laid| width.saturating_sub(l.y_ticks.title.chars().count() + 2);
    // where each legend goes: the header, an empty corner, empty rows of the plot, rows of its
    // own
    let mut rows: Vec<Option<u16>> = vec![None; frames.len()];
    for (i, l) in laid.iter_mut().enumerate() {
        let g = &l.geometry;
        if legend::line_width(&l.entries) <= beside(l) {
            l.place = Place::Header;
            continue;
        }
        // clear of data and reference lines, else of data only
        let clear = axis::with_marks(&l.raster, &frames[i]);
        if let Some(c) = legend::corner(&clear, g.local_plot(), &l.entries, false) {
            l.place = c;
        } else if let Some(b) = legend::band(&clear, g.local_plot(), &l.entries) {
            l.place = b;
        } else if let Some(c) = legend::corner(&l.raster, g.local_plot(), &l.entries, false) {
            l.place = c;
        } else if let Some(b) = legend::band(&l.raster, g.local_plot(), &l.entries) {
            l.place = b;
        } else {
            rows[i] = Some(legend_rows(&l.entries, beside(l), width, g.plot.height));
        }
    }
    if rows.iter().any(Option::is_some) {
        let places: Vec<Place> = laid.iter().map(|l| l.place).collect();
        // the plot's height without legend rows, which bounds them
        let heights: Vec<u16> = laid.iter().map(|l| l.geometry.plot.height).collect();
        let mut extra: Vec<u16> = rows.iter().map(|r| r.unwrap_or(0)).collect();
        // a shorter plot may name its curves otherwise (a curve dim throughout says why in its
        // entry): the rows again for the entries at the new size, never fewer (so that it
        // settles), a few times at most
        for pass in 0..=3 {
            (laid, x_ticks) = lay_out(frames, style, extras, area, &extra)?;
            let again: Vec<u16> = (laid.iter().zip(&heights).zip(&rows).zip(&extra))
                .map(|(((l, &height), r), &e)| match r {
                    Some(_) => legend_rows(&l.entries, beside(l), width, height).max(e),
                    None => 0,
                })
                .collect();
            if again == extra || pass == 3 {
                break;
            }
            extra = again;
        }
        for (((l, place), r), e) in laid.iter_mut().zip(places).zip(&rows).zip(&extra) {
            let r = r.map(|_| *e);
            l.place = match r {
                Some(r) => {
                    let shown = legend::fold(&l.entries, beside(l), width, r + 1);
                    if shown != l.entries {
                        l.full = Some(std::mem::replace(&mut l.entries, shown));
                    }
                    Place::Rows(r)
                }
                None => place,
            };
        }
    }
    Some((laid, x_ticks))
}

/// Draws the frames of a figure stacked in `area`.
pub fn draw(frames: &[Frame], style: RenderOptions, extras: &Extras, buf: &mut Buffer, area: Rect) {
    let Some((laid, x_ticks)) = layout(frames, style, extras, area) else {
        return;
    };
    for (f, l) in frames.iter().zip(&laid) {
        draw_one(f, l, &x_ticks, style, extras, buf);
    }
}

fn draw_one(
    frame: &Frame,
    laid: &Laid,
    x_ticks: &Ticks,
    style: RenderOptions,
    extras: &Extras,
    buf: &mut Buffer,
) {
    let g = &laid.geometry;
    axis::shade(frame, g, style, buf);
    laid.raster.render(buf, g.plot);
    axis::marks(frame, g, &laid.raster, style, buf);
    axis::frame(frame, g, &laid.y_ticks, x_ticks, buf);
    if let Some(f) = extras.cursor {
        let col = ((f.clamp(0.0, 1.0) * (g.plot.width.max(1) - 1) as f64).round()) as u16;
        for row in 0..g.plot.height {
            let cell = &mut buf[(g.plot.x + col, g.plot.y + row)];
            if laid.raster.occupied(col, row) {
                cell.set_style(Style::default().add_modifier(Modifier::REVERSED));
            } else {
                cell.set_char(style.cursor_glyph())
                    .set_style(style.cursor());
            }
        }
    }
    let header = g.header;
    buf.set_stringn(
        header.x,
        header.y,
        &laid.y_ticks.title,
        header.width as usize,
        Style::default(),
    );
    // the header's row right of the y title
    let title = laid.y_ticks.title.chars().count() as u16 + 2;
    let rest = Rect {
        x: header.x + title.min(header.width),
        width: header.width.saturating_sub(title),
        height: 1,
        ..header
    };
    match laid.place {
        Place::Header => legend::render_lines(&laid.entries, buf, rest),
        Place::Rows(rows) => {
            let below = Rect {
                y: header.y + 1,
                height: rows,
                ..header
            };
            legend::render_beside_title(&laid.entries, buf, rest, below);
        }
        Place::Corner(x, y) => {
            legend::render_box(&laid.entries, buf, g.plot.x + x, g.plot.y + y);
        }
        Place::Band(y, rows) => {
            let band = Rect {
                y: g.plot.y + y,
                height: rows,
                ..g.plot
            };
            legend::render_lines(&laid.entries, buf, band);
        }
    }
}
