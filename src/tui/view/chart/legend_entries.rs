//! The legend entries of a plot: its curves, markers, reference lines, shaded ranges and pins
//! (each curve of a pin of several), each named as the legend shows it.

use crate::tui::charts::range::{Frame, plotted};
use crate::tui::charts::readout::short_name;
use crate::tui::view::hidden::{self, Hidden};
use crate::tui::view::legend::Entry;
use crate::tui::view::theme::RenderOptions;
use crate::units::format_si;

/// The legend entries of a frame in a plot area `size`: its curves (those off the y range named
/// with their range, those that cannot be seen with why, each followed by where it has no
/// answer), markers, reference lines, shaded ranges and pins.
pub(super) fn entries(
    frame: &Frame,
    style: RenderOptions,
    pins: &[String],
    size: (u16, u16),
) -> Vec<Entry> {
    let plot = frame.plot;
    let (xs, ys) = (plot.x.scale, frame.y_scale);
    let hidden = hidden::hidden(frame, style, size);
    let mut out: Vec<Entry> = plot
        .series
        .iter()
        .enumerate()
        .flat_map(|(i, s)| {
            let ink = match hidden[i] {
                Some(Hidden::Fails) => style.dim_ink(i),
                _ => style.series_ink(i),
            };
            let drawn = plotted(&s.points, xs, ys);
            let inside = drawn
                .iter()
                .any(|p| (frame.y[0]..=frame.y[1]).contains(&p.1));
            let gaps: Vec<&str> = (plot.unanswered.iter())
                .filter(|u| u.curve == i)
                .map(|u| u.words.as_str())
                .collect();
            // a curve with nothing to draw says why in its own entry ("mu* wide: no answer at
            // any of the 60 loads"), its gaps then need no entry of their own
            let said = if drawn.is_empty() { gaps.len() } else { 0 };
            let text = if drawn.is_empty() {
                match gaps.is_empty() {
                    false => format!("{}: {}", s.name, gaps.join("; ")),
                    true => format!("{}: no values to draw", s.name),
                }
            } else if !inside {
                let [lo, hi] = crate::tui::charts::range::bounds(s.points.iter().map(|p| p.1));
                format!(
                    "{}: off scale, {}..{}",
                    s.name,
                    format_si(lo, plot.y.unit),
                    format_si(hi, plot.y.unit)
                )
            } else {
                match hidden[i] {
                    Some(Hidden::Fails) if plot.unjudged => {
                        format!("{}: not judged for these inputs", s.name)
                    }
                    Some(Hidden::Fails) => format!("{}: fails over the whole range", s.name),
                    Some(Hidden::Under(j)) => {
                        format!("{}: under {}", s.name, short_name(&plot.series[j].name))
                    }
                    None => s.name.clone(),
                }
            };
            // the points where the curve has no answer: an entry of their own after it, with its
            // sample ("++ no answer at P >= 1.70 kN/m (11 of 40 loads)")
            let entry = move |text: String| Entry {
                sample: style.sample(ink),
                style: ink.style,
                text,
            };
            std::iter::once(entry(text))
                .chain((gaps.into_iter().skip(said)).map(move |w| entry(w.to_string())))
        })
        .collect();
    let marker = style.marker_ink();
    out.extend(plot.markers.iter().map(|m| Entry {
        sample: style.sample(marker),
        style: marker.style,
        text: m.name.clone(),
    }));
    let (point, _) = style.data_inks();
    out.extend(plot.data.iter().map(|d| Entry {
        sample: style.sample(point),
        style: point.style,
        text: if d.sd.is_some() {
            format!("{} (bars: 1 sd)", d.name)
        } else {
            d.name.clone()
        },
    }));
    let (_, horizontal) = style.mark_glyphs();
    let marks_under = hidden::marks_under(frame, style, size);
    out.extend(
        plot.y_marks
            .iter()
            .zip(marks_under)
            .map(|(m, under)| Entry {
                sample: horizontal.to_string().repeat(2),
                style: style.mark(),
                text: match under {
                    Some(j) => format!("{}: under {}", m.label, short_name(&plot.series[j].name)),
                    None => m.label.clone(),
                },
            }),
    );
    // the dim parts that show (a curve off scale shows none): once, or without colour each
    // curve's mark with its name ("'' narrow fails")
    let shows = |d: &crate::tui::charts::Series| {
        plotted(&d.points, xs, ys)
            .iter()
            .any(|p| (frame.y[0]..=frame.y[1]).contains(&p.1))
    };
    let mut owners: Vec<(usize, &str)> = (plot.dim.iter())
        .filter(|(i, d)| shows(d) && hidden[*i] != Some(Hidden::Fails))
        .map(|(i, d)| (*i, &*d.name))
        .collect();
    owners.sort_by_key(|o| o.0);
    owners.dedup_by_key(|o| o.0);
    let each = !style.braille() && plot.series.len() > 1 && owners.iter().all(|o| !o.1.is_empty());
    // one entry for the dim parts of several curves: its sample in no curve's colour
    let shared = !each && owners.len() > 1;
    if !each {
        owners.truncate(1);
    }
    out.extend(owners.into_iter().map(|(i, name)| {
        let ink = style.dim_ink(i);
        Entry {
            sample: style.sample(ink),
            style: if shared { style.mark() } else { ink.style },
            text: if each {
                name.to_string()
            } else {
                plot.dim_label.clone()
            },
        }
    }));
    let (shade_glyph, shade_style) = style.shaded();
    out.extend(plot.shaded.iter().map(|s| Entry {
        sample: shade_glyph.to_string().repeat(2),
        style: shade_style,
        text: s.label.clone(),
    }));
    // a pin of several curves: an entry for each, the first with the pin's name ("1* pin: h =
    // 50 um, mu* wide", "1+ mu* narrow"), so that its curves are told apart by their marks
    for (p, (name, pin)) in pins.iter().zip(&frame.pins).enumerate() {
        let many = pin.series.len() > 1;
        out.extend(pin.series.iter().enumerate().map(|(i, s)| {
            let ink = style.pin_ink(p, i);
            let text = match (many, i) {
                (false, _) => name.clone(),
                (true, 0) => format!("{name}, {}", short_name(&s.name)),
                (true, _) => short_name(&s.name).to_string(),
            };
            Entry {
                sample: style.sample(ink),
                style: ink.style,
                text,
            }
        }));
    }
    out
}
