//! What a figure's plots are drawn over: scales and ranges in plot coordinates, shared by the
//! terminal chart, the cursor readout and the SVG, so that all three agree. Pinned plots of the
//! same chart are drawn with the plot and count in its ranges.

use crate::tui::charts::{Plot, Scale};

/// One plot as drawn.
#[derive(Clone, Debug)]
pub struct Frame<'a> {
    /// The plot.
    pub plot: &'a Plot,
    /// The same plot of each pin, oldest first.
    pub pins: Vec<&'a Plot>,
    /// The y scale drawn (the plot's own, or the other one when toggled).
    pub y_scale: Scale,
    /// The x range, plot coordinates (the same for every plot of a figure).
    pub x: [f64; 2],
    /// The y range, plot coordinates.
    pub y: [f64; 2],
}

/// The range [lo, hi] spanned by `values`: [0, 1] when there are none; padded by 5 % of the
/// value (or by 1 around 0) when they are all equal.
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

/// Points in plot coordinates (those that can be drawn).
pub fn plotted(points: &[(f64, f64)], x: Scale, y: Scale) -> Vec<(f64, f64)> {
    points
        .iter()
        .filter_map(|&(a, b)| Some((x.to_plot(a)?, y.to_plot(b)?)))
        .collect()
}

/// Every point of a plot that sets its ranges: all curves and markers for x, the focus curves
/// and markers for y (the other curves are overlays, clipped to that range), and the measured
/// points with the ends of their error bars for both.
fn setting(plot: &Plot, y: bool) -> impl Iterator<Item = (f64, f64)> + '_ {
    let take = if y { plot.focus } else { plot.series.len() };
    let measured = plot.data.iter().flat_map(|d| {
        d.points
            .iter()
            .copied()
            .chain(d.bars().into_iter().flatten())
    });
    plot.series
        .iter()
        .take(take)
        .chain(plot.dim.iter().filter(move |d| d.0 < take).map(|d| &d.1))
        .chain(&plot.markers)
        .flat_map(|s| s.points.iter().copied())
        .chain(measured)
}

/// The y scale of a plot: its own, or when `toggled` the other one: a linear axis becomes
/// logarithmic where every value is positive, else symmetric-log (but stays linear where every
/// value is the same: a log axis spreads nothing); a log axis becomes linear.
pub fn y_scale(plot: &Plot, pins: &[&Plot], toggled: bool) -> Scale {
    if !toggled {
        return plot.y.scale;
    }
    match plot.y.scale {
        Scale::Log | Scale::SymLog(_) => Scale::Linear,
        Scale::Linear => {
            let ys = || {
                std::iter::once(plot)
                    .chain(pins.iter().copied())
                    .flat_map(|p| setting(p, true))
                    .map(|p| p.1)
            };
            if flat(ys(), plot.resolution).is_some() {
                Scale::Linear
            } else if ys().all(|v| v > 0.0) {
                Scale::Log
            } else {
                Scale::symlog_for(ys())
            }
        }
    }
}

/// The frames of a figure's plots with their pins (`pins[i]`: the plots of pin i), the y axes
/// toggled or not. The x range spans every plot; a vertical mark at its end is moved off the
/// frame by 3 % of the span.
pub fn frames<'a>(plots: &'a [Plot], pins: &[&'a [Plot]], toggled: bool) -> Vec<Frame<'a>> {
    let pinned = |i: usize| -> Vec<&'a Plot> { pins.iter().filter_map(|p| p.get(i)).collect() };
    let every = || {
        plots
            .iter()
            .enumerate()
            .flat_map(move |(i, p)| std::iter::once(p).chain(pinned(i)))
    };
    let xs = every().flat_map(|p| {
        let s = p.x.scale;
        let marks = p.x_marks.iter().map(|m| m.at);
        let shades = p.shaded.iter().flat_map(|s| [s.from, s.to]);
        setting(p, false)
            .map(|q| q.0)
            .chain(marks)
            .chain(shades)
            .filter_map(move |v| s.to_plot(v))
            .collect::<Vec<_>>()
    });
    let [mut lo, mut hi] = bounds(xs);
    let span = hi - lo;
    let marked = |end: f64| {
        every().any(|p| {
            p.x_marks
                .iter()
                .filter_map(|m| p.x.scale.to_plot(m.at))
                .any(|m| (m - end).abs() <= 1e-9 * span)
        })
    };
    if marked(lo) {
        lo -= 0.03 * span;
    }
    if marked(hi) {
        hi += 0.03 * span;
    }
    plots
        .iter()
        .enumerate()
        .map(|(i, plot)| {
            let pins = pinned(i);
            let y_scale = y_scale(plot, &pins, toggled);
            let ys = y_values(plot, &pins, y_scale);
            let y = match flat(ys.iter().copied(), resolution(plot, y_scale)) {
                Some(v) => bounds(std::iter::once(v)),
                None => bounds(ys.into_iter()),
            };
            Frame {
                plot,
                pins,
                y_scale,
                x: [lo, hi],
                y,
            }
        })
        .collect()
}

/// The y values (plot coordinates) that set a plot's y range: its focus curves and markers
/// where x can be drawn, its horizontal marks, and the same of its pins.
fn y_values(plot: &Plot, pins: &[&Plot], y_scale: Scale) -> Vec<f64> {
    std::iter::once(plot)
        .chain(pins.iter().copied())
        .flat_map(|p| {
            let marks = p.y_marks.iter().map(|m| m.at);
            let xs = p.x.scale;
            setting(p, true)
                .filter(|q| xs.to_plot(q.0).is_some())
                .map(|q| q.1)
                .chain(marks)
                .filter_map(|v| y_scale.to_plot(v))
                .collect::<Vec<_>>()
        })
        .collect()
}

/// The one value of `values` when they all lie within `resolution` of each other: their middle
/// rounded to a multiple of `resolution` (0 for mu* = 0 give or take 1e-20), or with resolution
/// 0 the value itself when all are equal; else None (and None for no finite value).
fn flat(values: impl Iterator<Item = f64>, resolution: f64) -> Option<f64> {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() || hi - lo > resolution {
        return None;
    }
    let mid = 0.5 * (lo + hi);
    Some(if resolution > 0.0 {
        (mid / resolution).round() * resolution
    } else {
        mid
    })
}

/// A plot's resolution in plot coordinates: its own on a linear y axis, none on another (where a
/// difference of values is not a distance).
fn resolution(plot: &Plot, y_scale: Scale) -> f64 {
    match y_scale {
        Scale::Linear => plot.resolution,
        _ => 0.0,
    }
}

/// The one value (plot coordinate) of a frame whose y values are all the same, or the same to
/// within the plot's resolution (mu*(t) of a frictionless punch, 0 all along), else None.
pub fn constant(frame: &Frame) -> Option<f64> {
    let ys = y_values(frame.plot, &frame.pins, frame.y_scale);
    flat(ys.into_iter(), resolution(frame.plot, frame.y_scale))
}

/// Liang-Barsky: the part of segment a-b inside the rectangle xs x ys, if any.
pub fn clip(
    a: (f64, f64),
    b: (f64, f64),
    xs: [f64; 2],
    ys: [f64; 2],
) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a.0 - xs[0]),
        (dx, xs[1] - a.0),
        (-dy, a.1 - ys[0]),
        (dy, ys[1] - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    let finite = [a.0, a.1, b.0, b.1].iter().all(|v| v.is_finite());
    (t0 <= t1 && finite).then_some((
        (a.0 + t0 * dx, a.1 + t0 * dy),
        (a.0 + t1 * dx, a.1 + t1 * dy),
    ))
}
