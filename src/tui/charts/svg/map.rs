//! Heat maps as SVG: coloured cells (continuous viridis) centred on their grid points, the axes
//! in the grid's own units and scales (log where the grid is log), and a colour bar with its ticks
//! and unit; the spatial problem's pressure map is one.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::{Area, Chart2d, axes, cartesian, err, font};
use crate::tui::charts::palette::{EMPTY, viridis};
use crate::tui::charts::range::bounds;
use crate::tui::charts::ticks::ticks;
use crate::tui::charts::{Axis, Map, Scale, axis};

/// Width of the cells' area; the colour bar and its labels take the rest [px].
pub(super) const CELLS: u32 = 640;

/// A grid of values as the SVG draws it.
pub(super) struct Heat<'a> {
    /// The axes along x and y: label, unit, scale.
    pub axes: [Axis; 2],
    /// The grid's values along x (data units, increasing).
    pub x: &'a [f64],
    /// Along y.
    pub y: &'a [f64],
    /// The value at grid point (i, j); None where there is none (drawn light grey).
    pub value: &'a dyn Fn(usize, usize) -> Option<f64>,
    /// The colour bar's range [lo, hi].
    pub range: [f64; 2],
}

/// The cells' edges along an axis (plot coordinates): halfway between neighbouring points, the
/// first and the last at the first and last point, so that the map spans the grid.
fn edges(points: &[f64]) -> Vec<f64> {
    let n = points.len();
    (0..=n)
        .map(|k| match k {
            0 => points[0],
            k if k == n => points[n - 1],
            k => 0.5 * (points[k - 1] + points[k]),
        })
        .collect()
}

/// Draws the cells (at most 128 a side) with the axes' ticks and titles in `area`; returns the
/// chart (plot coordinates) for what is drawn over them.
pub(super) fn cells<'a, 'b>(
    root: &Area,
    area: &'a Area<'b>,
    heat: &Heat,
) -> Result<Chart2d<'a, 'b>, String> {
    let [xa, ya] = &heat.axes;
    let place = |values: &[f64], scale: Scale| -> Vec<f64> {
        (values.iter())
            .map(|&v| scale.to_plot(v).unwrap_or(f64::NAN))
            .collect()
    };
    let (px, py) = (place(heat.x, xa.scale), place(heat.y, ya.scale));
    let (nx, ny) = (px.len(), py.len());
    let xr = [px[0], px[nx - 1]];
    let yr = [py[0], py[ny - 1]];
    let xt = ticks(xr, xa.scale, &xa.label, xa.unit, 6);
    let yt = ticks(yr, ya.scale, &ya.label, ya.unit, 6);
    let mut chart = cartesian(area, [xr, yr], [&xt.title, &yt.title], 14)?;
    let step = nx.max(ny).div_ceil(128);
    let (ex, ey) = (&edges(&px), &edges(&py));
    let [lo, hi] = heat.range;
    let rects = (0..ny).step_by(step).flat_map(|j| {
        (0..nx).step_by(step).map(move |i| {
            let (r, g, b) = match (heat.value)(i, j) {
                Some(v) => viridis((v - lo) / (hi - lo)),
                None => EMPTY,
            };
            let (i1, j1) = ((i + step).min(nx), (j + step).min(ny));
            Rectangle::new(
                [(ex[i], ey[j]), (ex[i1], ey[j1])],
                RGBColor(r, g, b).filled(),
            )
        })
    });
    chart.draw_series(rects).map_err(err)?;
    axes(root, &chart, (xr[0], yr[0]), &xt, &yt)?;
    Ok(chart)
}

/// The colour bar over [lo, hi] in `area`, its ticks and its title (`name` and its unit).
pub(super) fn bar(
    root: &Area,
    area: &Area,
    [lo, hi]: [f64; 2],
    name: &str,
    unit: &str,
) -> Result<(), String> {
    let vt = ticks([lo, hi], Scale::Linear, name, unit, 8);
    let mut bar = ChartBuilder::on(area)
        .margin(14)
        .margin_right(160)
        .x_label_area_size(48)
        .y_label_area_size(0)
        .build_cartesian_2d(0.0..1.0, lo..hi)
        .map_err(err)?;
    let bands = (0..100).map(|k| {
        let (a, b) = (k as f64 / 100.0, (k + 1) as f64 / 100.0);
        let (r, g, bl) = viridis(a);
        Rectangle::new(
            [(0.0, lo + a * (hi - lo)), (1.0, lo + b * (hi - lo))],
            RGBColor(r, g, bl).filled(),
        )
    });
    bar.draw_series(bands).map_err(err)?;
    for (pos, label) in &vt.ticks {
        let (px, py) = bar.backend_coord(&(1.0, *pos));
        root.draw(&PathElement::new(vec![(px, py), (px + 6, py)], BLACK))
            .map_err(err)?;
        root.draw(&Text::new(
            label.clone(),
            (px + 9, py),
            font(13).pos(Pos::new(HPos::Left, VPos::Center)),
        ))
        .map_err(err)?;
    }
    let (px, py) = bar.backend_coord(&(0.0, hi));
    root.draw(&Text::new(
        vt.title.clone(),
        (px, py - 4),
        font(14).pos(Pos::new(HPos::Left, VPos::Bottom)),
    ))
    .map_err(err)
}

/// The pressure map as coloured cells with a colour bar, its zero cells light grey where the
/// map names them (no contact), and its caption under it.
pub(super) fn map(
    root: &Area,
    area: &Area,
    m: &Map,
    scale: Option<[f64; 2]>,
) -> Result<(), String> {
    let range = scale.unwrap_or_else(|| bounds(m.values.iter().copied()));
    let nx = m.x.len();
    let value = |i: usize, j: usize| {
        let v = m.values[j * nx + i];
        (m.empty.is_none() || v != 0.0).then_some(v)
    };
    let heat = Heat {
        axes: [axis("x", "m", Scale::Linear), axis("y", "m", Scale::Linear)],
        x: &m.x,
        y: &m.y,
        value: &value,
        range,
    };
    let (map_area, bar_area) = area.split_horizontally(CELLS);
    let chart = cells(root, &map_area, &heat)?;
    bar(root, &bar_area, range, m.name, m.unit)?;
    let (px, py) = chart.backend_coord(&(m.x[0], m.y[0]));
    let caption = match m.empty {
        Some(label) => format!("{} Light grey: {label}.", m.caption),
        None => m.caption.clone(),
    };
    root.draw(&Text::new(
        caption,
        (px, py + 30),
        font(13).pos(Pos::new(HPos::Left, VPos::Top)),
    ))
    .map_err(err)
}
