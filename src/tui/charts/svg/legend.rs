//! The legend right of a plot in the SVG: its curves, markers, measured points, reference lines,
//! shaded ranges, the parts where a model fails, and the pins; every curve that the plot cannot show whole is
//! named with its range ("off scale" wholly outside the y range, "partly off scale" where the
//! frame cuts it), so that a figure never drops part of a curve without saying so.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::{Area, Chart2d, DATA, DIM, GREY, colour, err, font};
use crate::tui::charts::Series;
use crate::tui::charts::range::{Frame, bounds, plotted};
use crate::tui::charts::readout::short_name;
use crate::units::format_si;

/// Pixels between two legend lines.
const STEP: i32 = 18;

/// The legend's lines of a curve: its name, and where the frame does not hold it whole a second
/// line saying so with the curve's y range (the legend is too narrow for both on one line).
pub fn curve_lines(s: &Series, f: &Frame) -> Vec<String> {
    let drawn = plotted(&s.points, f.plot.x.scale, f.y_scale);
    let inside = |q: &(f64, f64)| (f.y[0]..=f.y[1]).contains(&q.1);
    let range = || {
        let [lo, hi] = bounds(s.points.iter().map(|q| q.1));
        let unit = f.plot.y.unit;
        format!("{}..{}", format_si(lo, unit), format_si(hi, unit))
    };
    if drawn.is_empty() {
        vec![format!("{}: no values to draw", s.name)]
    } else if !drawn.iter().any(inside) {
        vec![s.name.clone(), format!("off scale, {}", range())]
    } else if !drawn.iter().all(inside) || drawn.len() < s.points.len() {
        vec![s.name.clone(), format!("partly off scale, {}", range())]
    } else {
        vec![s.name.clone()]
    }
}

/// Writes the legend's lines from `top`: the first beside a sample drawn by `sample`, the others
/// under it; returns the y of the next entry.
fn entry(
    root: &Area,
    (x, top): (i32, i32),
    lines: &[String],
    sample: impl FnOnce(i32, i32) -> Result<(), String>,
) -> Result<i32, String> {
    sample(x, top)?;
    let mut y = top;
    for line in lines {
        root.draw(&Text::new(
            line.clone(),
            (x + 30, y),
            font(13).pos(Pos::new(HPos::Left, VPos::Center)),
        ))
        .map_err(err)?;
        y += STEP;
    }
    Ok(y)
}

/// A line sample 22 pixels long.
fn line_sample(root: &Area, style: ShapeStyle) -> impl FnOnce(i32, i32) -> Result<(), String> {
    move |x, y| {
        root.draw(&PathElement::new(vec![(x, y), (x + 22, y)], style))
            .map_err(err)
    }
}

/// The legend right of the plot: curves, markers, reference lines, shaded ranges, the failing
/// parts, pins (and the pins' curves the plot cannot show whole).
pub fn legend(root: &Area, chart: &Chart2d, f: &Frame, pin_names: &[String]) -> Result<(), String> {
    let p = f.plot;
    let (right, top) = chart.backend_coord(&(f.x[1], f.y[1]));
    let x = right + 16;
    let mut y = top + 8;
    for (i, s) in p.series.iter().enumerate() {
        let style = colour(i).stroke_width(2);
        let mut lines = curve_lines(s, f);
        lines.extend(
            (p.unanswered.iter())
                .filter(|u| u.curve == i)
                .map(|u| u.words.clone()),
        );
        y = entry(root, (x, y), &lines, line_sample(root, style))?;
    }
    if let Some(m) = &p.markers {
        y = entry(root, (x, y), std::slice::from_ref(&m.name), |x, y| {
            root.draw(&Circle::new((x + 11, y), 4, BLACK.filled()))
                .map_err(err)
        })?;
    }
    for d in &p.data {
        let mut lines = vec![d.name.clone()];
        if d.sd.is_some() {
            lines.push("bars: one standard deviation".into());
        }
        y = entry(root, (x, y), &lines, |x, y| {
            root.draw(&Circle::new((x + 11, y), 4, DATA.stroke_width(2)))
                .map_err(err)
        })?;
    }
    for m in &p.y_marks {
        let grey = line_sample(root, GREY.into());
        y = entry(root, (x, y), std::slice::from_ref(&m.label), grey)?;
    }
    if let Some((i, _)) = p.dim.first() {
        let pale = line_sample(root, colour(*i).mix(DIM).stroke_width(2));
        y = entry(root, (x, y), std::slice::from_ref(&p.dim_label), pale)?;
    }
    for s in &p.shaded {
        y = entry(root, (x, y), std::slice::from_ref(&s.label), |x, y| {
            root.draw(&Rectangle::new(
                [(x, y - 6), (x + 22, y + 6)],
                GREY.mix(0.15).filled(),
            ))
            .map_err(err)
        })?;
    }
    // a pin of several curves: an entry for each in its own colour and the pin's dashes, the
    // first with the pin's name ("pin: h = 50 um, mu* wide", "mu* narrow"), as the terminal's
    // legend has them; a pinned curve the frame cuts says so under its name
    for (n, (name, pin)) in pin_names.iter().zip(&f.pins).enumerate() {
        let dash = 2 + 3 * n as u32;
        let many = pin.series.len() > 1;
        for (i, s) in pin.series.iter().enumerate() {
            let of = curve_lines(
                s,
                &Frame {
                    plot: pin,
                    ..f.clone()
                },
            );
            let title = match (many, i) {
                (false, _) => name.clone(),
                (true, 0) => format!("{name}, {}", short_name(&s.name)),
                (true, _) => short_name(&s.name).to_string(),
            };
            let mut lines = vec![title];
            match of.as_slice() {
                [_, cut] => lines.push(cut.clone()),
                [only] if *only != s.name => lines.push(only.clone()),
                _ => {}
            }
            y = entry(root, (x, y), &lines, |x, y| {
                // the pinned curve's colour and its pin's dashes: dash pixels on, 3 off
                let style = colour(i).mix(0.5).stroke_width(1);
                (0..22)
                    .step_by(dash as usize + 3)
                    .try_for_each(|d| {
                        let end = (d + dash as i32).min(22);
                        root.draw(&PathElement::new(vec![(x + d, y), (x + end, y)], style))
                    })
                    .map_err(err)
            })?;
        }
    }
    Ok(())
}
