//! The regime map (`M`) as SVG: the quantity over the two swept inputs as coloured cells, the
//! axes in the inputs' units (log where the map's axis is log), the colour bar with its ticks and
//! range, the library's lines (theta = 0, the models' validity limits, complete contact, yield
//! onset) each in its own style with the letter the terminal draws it with, the preset's own
//! point, and under it a legend naming each. It draws the map the view has: its samples, its
//! lines, its point.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::map::{CELLS, Heat, bar, cells};
use super::{Area, Chart2d, LINE, err, font};
use crate::sweeps::map::{LineKind, Map, MapSpec};
use crate::tui::charts::map_lines::line_key;
use crate::tui::charts::palette::EMPTY;
use crate::tui::charts::range::{bounds, clip};
use crate::tui::charts::sweep::x_axis;
use crate::units::format_si;

/// Height of the cells and the bar [px].
const HEAT: u32 = 480;

/// The colour of a line and whether it is dashed (the lines stay apart without colour too).
fn ink(kind: LineKind) -> (RGBColor, bool) {
    match kind {
        LineKind::ThetaZero => (BLACK, false),
        LineKind::MuStarEqualsMu => (RGBColor(0, 158, 115), true),
        LineKind::Validity(m) if m.name() == "wide" => (RGBColor(213, 94, 0), false),
        LineKind::Validity(_) => (RGBColor(204, 121, 167), true),
        LineKind::CompleteContact => (BLACK, true),
        LineKind::Yield => (RGBColor(0, 114, 178), false),
    }
}

/// The quantity at grid point (i, j), the nearest computed one while the map is coarse.
fn value(map: &Map, i: usize, j: usize) -> Option<f64> {
    map.sample(i, j)?.value.as_ref().ok().copied()
}

/// The SVG of a regime map: `title` on top, the figure, the `caption` lines (the preset's name
/// and parameters) under it.
pub fn regime(
    spec: &MapSpec,
    map: &Map,
    title: &str,
    caption: &[String],
) -> Result<String, String> {
    let (nx, ny) = (map.x.len(), map.y.len());
    if nx < 2 || ny < 2 {
        return Err("the map has fewer than two points a side".into());
    }
    let drawn: Vec<_> = map
        .lines
        .iter()
        .filter(|l| !l.segments.is_empty())
        .collect();
    let body = HEAT + LINE * (2 + drawn.len() as u32) + 16;
    let every = || (0..ny).flat_map(|j| (0..nx).map(move |i| (i, j)));
    let range = bounds(every().filter_map(|(i, j)| value(map, i, j)));
    let empty = every().any(|(i, j)| value(map, i, j).is_none());
    let axes = [
        x_axis(spec.x.key, spec.x.range.spacing),
        x_axis(spec.y.key, spec.y.range.spacing),
    ];
    let scales = [axes[0].scale, axes[1].scale];
    super::document(title, caption, body, |root, main| {
        let (heat_area, legend_area) = main.split_vertically(HEAT);
        let (map_area, bar_area) = heat_area.split_horizontally(CELLS);
        let at = |i, j| value(map, i, j);
        let heat = Heat {
            axes,
            x: &map.x,
            y: &map.y,
            value: &at,
            range,
        };
        let mut chart = cells(root, &map_area, &heat)?;
        let q = spec.quantity;
        bar(root, &bar_area, range, &q.symbol(), q.quantity().unit)?;
        let plot = |[x, y]: [f64; 2]| Some((scales[0].to_plot(x)?, scales[1].to_plot(y)?));
        let frame = |f: &dyn Fn([f64; 2]) -> Option<(f64, f64)>| {
            let lo = f([map.x[0], map.y[0]])?;
            let hi = f([map.x[nx - 1], map.y[ny - 1]])?;
            Some(([lo.0, hi.0], [lo.1, hi.1]))
        };
        let Some((fx, fy)) = frame(&plot) else {
            return Err("the map's ends cannot be drawn on its axes".into());
        };
        for line in &drawn {
            let (colour, dashed) = ink(line.kind);
            let inside =
                (line.segments.iter()).filter_map(|[a, b]| clip(plot(*a)?, plot(*b)?, fx, fy));
            for (a, b) in inside {
                let under = PathElement::new(vec![a, b], WHITE.stroke_width(4));
                chart.draw_series(std::iter::once(under)).map_err(err)?;
                let style = colour.stroke_width(2);
                if dashed {
                    let dashes = DashedLineSeries::new(vec![a, b], 6, 4, style);
                    chart.draw_series(dashes).map_err(err)?;
                } else {
                    let solid = PathElement::new(vec![a, b], style);
                    chart.draw_series(std::iter::once(solid)).map_err(err)?;
                }
            }
            letter(root, &chart, line.kind, &line.segments, &plot)?;
        }
        let own = plot(map.current)
            .filter(|p| (fx[0]..=fx[1]).contains(&p.0) && (fy[0]..=fy[1]).contains(&p.1));
        if let Some(p) = own {
            let (x, y) = chart.backend_coord(&p);
            for (width, colour) in [(4, WHITE), (2, BLACK)] {
                for arm in [[(x - 7, y), (x + 7, y)], [(x, y - 7), (x, y + 7)]] {
                    let stroke = PathElement::new(arm.to_vec(), colour.stroke_width(width));
                    root.draw(&stroke).map_err(err)?;
                }
            }
        }
        legend(&legend_area, spec, map, range, empty, own.is_some(), &drawn)
    })
}

/// A line's letter (as the terminal draws it) beside the middle of its longest piece.
fn letter(
    root: &Area,
    chart: &Chart2d,
    kind: LineKind,
    segments: &[[[f64; 2]; 2]],
    plot: &dyn Fn([f64; 2]) -> Option<(f64, f64)>,
) -> Result<(), String> {
    let pixels = (segments.iter()).filter_map(|[a, b]| {
        let (a, b) = (
            chart.backend_coord(&plot(*a)?),
            chart.backend_coord(&plot(*b)?),
        );
        let length = (a.0 - b.0).pow(2) + (a.1 - b.1).pow(2);
        Some((length, ((a.0 + b.0) / 2, (a.1 + b.1) / 2)))
    });
    let Some((_, (x, y))) = pixels.max_by_key(|p| p.0) else {
        return Ok(());
    };
    let (glyph, _) = line_key(kind);
    root.draw(&Text::new(
        glyph.to_string(),
        (x + 6, y - 6),
        font(15).pos(Pos::new(HPos::Left, VPos::Bottom)),
    ))
    .map_err(err)
}

/// Under the map: the colour's quantity and range (light grey where a point has no value, and
/// while coarse how the cells are filled), the preset's point, each line drawn.
fn legend(
    area: &Area,
    spec: &MapSpec,
    map: &Map,
    [lo, hi]: [f64; 2],
    empty: bool,
    own_inside: bool,
    drawn: &[&crate::sweeps::map::Line],
) -> Result<(), String> {
    let q = spec.quantity;
    let unit = q.quantity().unit;
    let mut colour = format!(
        "colour: {} from {} to {}",
        q.symbol(),
        format_si(lo, unit),
        format_si(hi, unit)
    );
    if empty {
        colour.push_str("; light grey: no value there");
    }
    if map.stride > 1 {
        colour.push_str(&format!(
            " (coarse: one point in {} computed along each axis, each cell shows the nearest)",
            map.stride
        ));
    }
    let text = |line: String, x: i32, row: u32| {
        area.draw(&Text::new(
            line,
            (x, 8 + (LINE * row) as i32),
            font(13).pos(Pos::new(HPos::Left, VPos::Center)),
        ))
        .map_err(err)
    };
    text(colour, 84, 0)?;
    if empty {
        let (r, g, b) = EMPTY;
        let swatch = Rectangle::new([(54, 2), (76, 14)], RGBColor(r, g, b).filled());
        area.draw(&swatch).map_err(err)?;
    }
    let own = if own_inside {
        "+  now: the preset's own point"
    } else {
        "+  now: the preset's own point is off the map"
    };
    text(own.into(), 60, 1)?;
    for (k, line) in drawn.iter().enumerate() {
        let (glyph, meaning) = line_key(line.kind);
        let (colour, dashed) = ink(line.kind);
        let y = 8 + (LINE * (k as u32 + 2)) as i32;
        let pieces: &[(i32, i32)] = if dashed {
            &[(54, 60), (64, 70), (74, 76)]
        } else {
            &[(54, 76)]
        };
        for &(a, b) in pieces {
            let stroke = PathElement::new(vec![(a, y), (b, y)], colour.stroke_width(2));
            area.draw(&stroke).map_err(err)?;
        }
        text(format!("{glyph}  {meaning}"), 84, k as u32 + 2)?;
    }
    Ok(())
}
