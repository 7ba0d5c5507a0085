//! The chart widget: draws a `Plot` (data coordinates, SI units) with its axes, ticks with SI
//! prefixes, a legend and marked points. Log axes are drawn in log10 and ticked in the real values.

use ratatui::Frame;
use ratatui::layout::{Constraint, Rect};
use ratatui::widgets::{Axis as AxisWidget, Chart, Dataset, GraphType, LegendPosition};
use wearlab::units::format_si;

use crate::tui::charts::{Axis, Plot};
use crate::tui::view::theme::RenderOptions;

/// A value in plot coordinates (log10 on a log axis); None where it cannot be drawn (not finite,
/// or <= 0 on a log axis).
pub fn to_plot(v: f64, log: bool) -> Option<f64> {
    let p = if log {
        (v > 0.0).then(|| v.log10())?
    } else {
        v
    };
    p.is_finite().then_some(p)
}

/// The points of a series in plot coordinates.
fn plotted(points: &[(f64, f64)], x: &Axis, y: &Axis) -> Vec<(f64, f64)> {
    points
        .iter()
        .filter_map(|&(a, b)| Some((to_plot(a, x.log)?, to_plot(b, y.log)?)))
        .collect()
}

/// The range [lo, hi] (plot coordinates) spanned by `values`: [0, 1] when there are none; padded
/// by 5 % of the value (or by 1 around 0) when they are all equal.
pub fn bounds(values: impl Iterator<Item = f64>) -> [f64; 2] {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return [0.0, 1.0];
    }
    if hi - lo <= 1e-12 * hi.abs().max(lo.abs()).max(f64::MIN_POSITIVE) {
        let pad = if lo == 0.0 { 1.0 } else { 0.05 * lo.abs() };
        return [lo - pad, hi + pad];
    }
    [lo, hi]
}

/// The x range: every curve and marker.
pub fn x_bounds(plot: &Plot) -> [f64; 2] {
    let xs = plot
        .series
        .iter()
        .chain(&plot.markers)
        .flat_map(|s| plotted(&s.points, &plot.x, &plot.y));
    bounds(xs.map(|p| p.0))
}

/// The y range: the focus curves and the markers (overlays are clipped to it).
pub fn y_bounds(plot: &Plot) -> [f64; 2] {
    let ys = plot
        .series
        .iter()
        .take(plot.focus)
        .chain(&plot.markers)
        .flat_map(|s| plotted(&s.points, &plot.x, &plot.y));
    bounds(ys.map(|p| p.1))
}

/// Three tick labels (low, middle, high) of a range in plot coordinates, in the axis' unit with
/// SI prefixes; on a log axis the middle is the geometric mean and the labels are real values.
pub fn ticks(range: [f64; 2], axis: &Axis) -> [String; 3] {
    let label = |v: f64| {
        let real = if axis.log { 10f64.powf(v) } else { v };
        format_si(real, axis.unit)
    };
    [
        label(range[0]),
        label(0.5 * (range[0] + range[1])),
        label(range[1]),
    ]
}

/// Draws a plot into `area`.
pub fn draw(plot: &Plot, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let xb = x_bounds(plot);
    let yb = y_bounds(plot);
    let series: Vec<Vec<(f64, f64)>> = plot
        .series
        .iter()
        .map(|s| plotted(&s.points, &plot.x, &plot.y))
        .collect();
    let marked = plot
        .markers
        .as_ref()
        .map(|m| plotted(&m.points, &plot.x, &plot.y));
    let mut datasets: Vec<Dataset> = plot
        .series
        .iter()
        .zip(&series)
        .enumerate()
        .map(|(i, (s, points))| {
            Dataset::default()
                .name(s.name.clone())
                .marker(style.line_marker())
                .graph_type(GraphType::Line)
                .style(style.series(i))
                .data(points)
        })
        .collect();
    if let (Some(m), Some(points)) = (&plot.markers, &marked)
        && !points.is_empty()
    {
        datasets.push(
            Dataset::default()
                .name(m.name.clone())
                .marker(ratatui::symbols::Marker::Block)
                .graph_type(GraphType::Scatter)
                .style(style.marker())
                .data(points),
        );
    }
    let title = |a: &Axis| {
        if a.log {
            format!("{} (log)", a.label)
        } else {
            a.label.clone()
        }
    };
    let chart = Chart::new(datasets)
        .x_axis(
            AxisWidget::default()
                .title(title(&plot.x))
                .bounds(xb)
                .labels(ticks(xb, &plot.x).to_vec()),
        )
        .y_axis(
            AxisWidget::default()
                .title(title(&plot.y))
                .bounds(yb)
                .labels(ticks(yb, &plot.y).to_vec()),
        )
        .legend_position(Some(LegendPosition::TopRight))
        .hidden_legend_constraints((Constraint::Percentage(60), Constraint::Percentage(60)));
    frame.render_widget(chart, area);
}
