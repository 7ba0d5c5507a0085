//! The figure export (`E`): the visible chart as SVG, drawn with plotters' SVG backend from the
//! same figure, ranges, scales and ticks as the terminal, its pins included, the legend beside
//! the plot, and the preset's name and parameters in a caption.

mod legend;
mod map;
mod regime;

pub use regime::regime;

use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::tui::charts::range::{Frame, clip, frames, plotted};
use crate::tui::charts::ticks::{Ticks, ticks};
use crate::tui::charts::{Figure, Plot, Scale};

/// Width of the figure [px].
const WIDTH: u32 = 960;
/// Height of one plot [px].
const PLOT: u32 = 340;
/// Columns of the legend right of the plot [px].
const LEGEND: u32 = 250;
/// Rows of the caption [px each].
const LINE: u32 = 18;

/// Colours of the curves: Okabe and Ito's colour-blind-safe set (Color Universal Design, 2008).
const COLOURS: [RGBColor; 7] = [
    RGBColor(0, 114, 178),
    RGBColor(230, 159, 0),
    RGBColor(0, 158, 115),
    RGBColor(213, 94, 0),
    RGBColor(204, 121, 167),
    RGBColor(86, 180, 233),
    RGBColor(0, 0, 0),
];

pub(super) const GREY: RGBColor = RGBColor(120, 120, 120);

/// The colour of measured points and their error bars: Okabe and Ito's vermillion is a curve's,
/// so a dark red no curve has.
pub(super) const DATA: RGBColor = RGBColor(160, 20, 40);

/// The opacity of a curve's parts where its model's own check fails.
const DIM: f64 = 0.35;

fn colour(i: usize) -> RGBColor {
    COLOURS[i % COLOURS.len()]
}

pub(super) fn font(size: u32) -> TextStyle<'static> {
    TextStyle::from(("sans-serif", size).into_font())
}

pub(super) fn err(e: impl std::fmt::Display) -> String {
    format!("cannot draw the figure: {e}")
}

pub(super) type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;
pub(super) type Chart2d<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// What the SVG shows besides the figure.
pub struct Page<'a> {
    /// The chart's title.
    pub title: &'a str,
    /// The caption: the preset's name and its parameters, one line each.
    pub caption: Vec<String>,
    /// The pins' plots and legend names.
    pub pins: Vec<(&'a [Plot], String)>,
    /// The y axes toggled (`y`).
    pub toggled: bool,
    /// The colour scale of a map (None: its own range).
    pub scale: Option<[f64; 2]>,
}

/// The SVG text of a figure.
pub fn svg(figure: &Figure, page: &Page) -> Result<String, String> {
    let body = match figure {
        Figure::Plots(plots) => PLOT * plots.len() as u32,
        Figure::Map(_) => 520,
    };
    document(page.title, &page.caption, body, |root, main| match figure {
        Figure::Plots(plots) => {
            let pinned: Vec<&[Plot]> = page.pins.iter().map(|p| p.0).collect();
            let names: Vec<String> = page.pins.iter().map(|p| p.1.clone()).collect();
            let fs = frames(plots, &pinned, page.toggled);
            let areas = main.split_evenly((fs.len(), 1));
            for (f, area) in fs.iter().zip(&areas) {
                plot(root, area, f, &names)?;
            }
            Ok(())
        }
        Figure::Map(m) => map::map(root, main, m, page.scale),
    })
}

/// An SVG page: the title on top, a body `body` pixels high drawn by `draw` (given the whole
/// page and the body's area), the caption's lines under it.
pub(super) fn document(
    title: &str,
    caption: &[String],
    body: u32,
    draw: impl FnOnce(&Area, &Area) -> Result<(), String>,
) -> Result<String, String> {
    let caption_height = LINE * caption.len() as u32 + 16;
    let height = 40 + body + caption_height;
    let mut text = String::new();
    {
        let root = SVGBackend::with_string(&mut text, (WIDTH, height)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let (top, rest) = root.split_vertically(40);
        let (main, bottom) = rest.split_vertically(body);
        top.draw(&Text::new(
            title.to_string(),
            (WIDTH as i32 / 2, 12),
            font(20).pos(Pos::new(HPos::Center, VPos::Top)),
        ))
        .map_err(err)?;
        for (i, line) in caption.iter().enumerate() {
            bottom
                .draw(&Text::new(
                    line.clone(),
                    (16, 8 + (LINE * i as u32) as i32),
                    font(13),
                ))
                .map_err(err)?;
        }
        draw(&root, &main)?;
        root.present().map_err(err)?;
    }
    Ok(text)
}

/// A plot area over ranges x, y with its axis lines and titles (the ticks are drawn by
/// `axes`), `right` pixels kept free right of it.
pub(super) fn cartesian<'a, 'b>(
    area: &'a Area<'b>,
    [x, y]: [[f64; 2]; 2],
    [x_title, y_title]: [&str; 2],
    right: u32,
) -> Result<Chart2d<'a, 'b>, String> {
    let mut chart = ChartBuilder::on(area)
        .margin(14)
        .margin_right(right)
        .x_label_area_size(48)
        .y_label_area_size(70)
        .build_cartesian_2d(x[0]..x[1], y[0]..y[1])
        .map_err(err)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_labels(0)
        .y_labels(0)
        .x_desc(x_title)
        .y_desc(y_title)
        .axis_desc_style(font(14))
        .draw()
        .map_err(err)?;
    Ok(chart)
}

/// The pieces of a curve inside the frame (plot coordinates).
fn pieces(points: &[(f64, f64)], f: &Frame, ys: Scale) -> Vec<Vec<(f64, f64)>> {
    let p = plotted(points, f.plot.x.scale, ys);
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    for w in p.windows(2) {
        let Some((a, b)) = clip(w[0], w[1], f.x, f.y) else {
            out.push(Vec::new());
            continue;
        };
        match out.last_mut() {
            Some(last) if last.last() == Some(&a) => last.push(b),
            _ => out.push(vec![a, b]),
        }
    }
    out.retain(|piece| piece.len() >= 2);
    out
}

/// Tick marks and labels on both axes, at the pixels of the chart's coordinates; the axes meet
/// at `origin` (plot coordinates).
pub(super) fn axes(
    root: &Area,
    chart: &Chart2d,
    origin: (f64, f64),
    x: &Ticks,
    y: &Ticks,
) -> Result<(), String> {
    for (pos, label) in &x.ticks {
        let (px, py) = chart.backend_coord(&(*pos, origin.1));
        root.draw(&PathElement::new(vec![(px, py), (px, py + 6)], BLACK))
            .map_err(err)?;
        root.draw(&Text::new(
            label.clone(),
            (px, py + 9),
            font(13).pos(Pos::new(HPos::Center, VPos::Top)),
        ))
        .map_err(err)?;
    }
    for (pos, label) in &y.ticks {
        let (px, py) = chart.backend_coord(&(origin.0, *pos));
        root.draw(&PathElement::new(vec![(px - 6, py), (px, py)], BLACK))
            .map_err(err)?;
        root.draw(&Text::new(
            label.clone(),
            (px - 9, py),
            font(13).pos(Pos::new(HPos::Right, VPos::Center)),
        ))
        .map_err(err)?;
    }
    Ok(())
}

fn plot(root: &Area, area: &Area, f: &Frame, pin_names: &[String]) -> Result<(), String> {
    let p = f.plot;
    let x = ticks(f.x, p.x.scale, &p.x.label, p.x.unit, 9);
    let y = ticks(f.y, f.y_scale, &p.y.label, p.y.unit, 7);
    let mut chart = cartesian(area, [f.x, f.y], [&x.title, &y.title], LEGEND)?;
    let xs = p.x.scale;
    for s in &p.shaded {
        if let (Some(a), Some(b)) = (xs.to_plot(s.from), xs.to_plot(s.to)) {
            let shade = Rectangle::new([(a, f.y[0]), (b, f.y[1])], GREY.mix(0.15).filled());
            chart.draw_series(std::iter::once(shade)).map_err(err)?;
        }
    }
    for m in &p.x_marks {
        if let Some(v) = xs.to_plot(m.at) {
            let line = DashedLineSeries::new(vec![(v, f.y[0]), (v, f.y[1])], 3, 3, GREY.into());
            chart.draw_series(line).map_err(err)?;
            let (px, py) = chart.backend_coord(&(v, f.y[1]));
            root.draw(&Text::new(
                m.label.clone(),
                (px, py - 2),
                font(12).pos(Pos::new(HPos::Center, VPos::Bottom)),
            ))
            .map_err(err)?;
        }
    }
    for m in &p.y_marks {
        if let Some(v) = f.y_scale.to_plot(m.at) {
            let line = DashedLineSeries::new(vec![(f.x[0], v), (f.x[1], v)], 6, 4, GREY.into());
            chart.draw_series(line).map_err(err)?;
        }
    }
    for (n, pin) in f.pins.iter().enumerate() {
        for (i, s) in pin.series.iter().enumerate() {
            for piece in pieces(&s.points, f, f.y_scale) {
                let style = colour(i).mix(0.5).stroke_width(1);
                let dash = 2 + 3 * n as u32;
                let line = DashedLineSeries::new(piece, dash, 3, style);
                chart.draw_series(line).map_err(err)?;
            }
        }
    }
    for (i, s) in p.series.iter().enumerate().rev() {
        for piece in pieces(&s.points, f, f.y_scale) {
            chart
                .draw_series(LineSeries::new(piece, colour(i).stroke_width(2)))
                .map_err(err)?;
        }
    }
    // where a model's own check fails: its curve paler there
    for (i, s) in &p.dim {
        for piece in pieces(&s.points, f, f.y_scale) {
            let under = LineSeries::new(piece.clone(), WHITE.stroke_width(3));
            chart.draw_series(under).map_err(err)?;
            let pale = LineSeries::new(piece, colour(*i).mix(DIM).stroke_width(2));
            chart.draw_series(pale).map_err(err)?;
        }
    }
    if let Some(m) = &p.markers {
        let dots = plotted(&m.points, xs, f.y_scale)
            .into_iter()
            .filter(|q| (f.x[0]..=f.x[1]).contains(&q.0) && (f.y[0]..=f.y[1]).contains(&q.1))
            .map(|q| Circle::new(q, 4, BLACK.filled()));
        chart.draw_series(dots).map_err(err)?;
    }
    // measured points: open circles over the curves, each with its error bar of one sd
    for d in &p.data {
        for ends in d.bars() {
            for piece in pieces(&ends, f, f.y_scale) {
                let bar = PathElement::new(piece, DATA.stroke_width(1));
                chart.draw_series(std::iter::once(bar)).map_err(err)?;
            }
        }
        let dots = plotted(&d.points, xs, f.y_scale)
            .into_iter()
            .filter(|q| (f.x[0]..=f.x[1]).contains(&q.0) && (f.y[0]..=f.y[1]).contains(&q.1))
            .map(|q| Circle::new(q, 4, DATA.stroke_width(2)));
        chart.draw_series(dots).map_err(err)?;
    }
    axes(root, &chart, (f.x[0], f.y[0]), &x, &y)?;
    legend::legend(root, &chart, f, pin_names)
}
