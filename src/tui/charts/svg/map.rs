//! The pressure map as SVG: coloured cells (continuous viridis) with the axes in the cell's
//! units and a colour bar with its ticks and unit.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::{Area, axes, cartesian, err, font};
use crate::tui::charts::palette::{EMPTY, viridis};
use crate::tui::charts::range::{Frame, bounds};
use crate::tui::charts::ticks::ticks;
use crate::tui::charts::{Map, Plot, Scale};

/// The map as coloured cells (at most 128 a side) with a colour bar and its ticks.
pub(super) fn map(
    root: &Area,
    area: &Area,
    m: &Map,
    scale: Option<[f64; 2]>,
) -> Result<(), String> {
    let [lo, hi] = scale.unwrap_or_else(|| bounds(m.values.iter().copied()));
    let (nx, ny) = (m.x.len(), m.y.len());
    let (x0, x1) = (m.x[0], m.x[nx - 1]);
    let (y0, y1) = (m.y[0], m.y[ny - 1]);
    let (map_area, bar_area) = area.split_horizontally(640);
    let xt = ticks([x0, x1], Scale::Linear, "x", "m", 6);
    let yt = ticks([y0, y1], Scale::Linear, "y", "m", 6);
    let mut chart = cartesian(&map_area, [[x0, x1], [y0, y1]], [&xt.title, &yt.title], 14)?;
    let step = nx.max(ny).div_ceil(128);
    let (dx, dy) = ((x1 - x0) / nx as f64, (y1 - y0) / ny as f64);
    let cells = (0..ny).step_by(step).flat_map(|j| {
        (0..nx).step_by(step).map(move |i| {
            let v = m.values[j * nx + i];
            let t = (v - lo) / (hi - lo);
            let empty = m.empty.is_some() && v == 0.0;
            let (r, g, b) = if empty { EMPTY } else { viridis(t) };
            let (x, y) = (m.x[i], m.y[j]);
            let w = step as f64;
            Rectangle::new(
                [(x, y), ((x + w * dx).min(x1), (y + w * dy).min(y1))],
                RGBColor(r, g, b).filled(),
            )
        })
    });
    chart.draw_series(cells).map_err(err)?;
    let frame = Frame {
        plot: &Plot::new(
            crate::tui::charts::axis("x", "m", Scale::Linear),
            crate::tui::charts::axis("y", "m", Scale::Linear),
            Vec::new(),
        ),
        pins: Vec::new(),
        y_scale: Scale::Linear,
        x: [x0, x1],
        y: [y0, y1],
    };
    axes(root, &chart, &frame, &xt, &yt)?;
    // the colour bar
    let vt = ticks([lo, hi], Scale::Linear, m.name, m.unit, 8);
    let mut bar = ChartBuilder::on(&bar_area)
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
    .map_err(err)?;
    let (px, py) = chart.backend_coord(&(x0, y0));
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
