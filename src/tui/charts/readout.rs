//! The cursor readout: the x under the cursor and every curve's value there, with units.

use crate::units::{format_fraction, format_si, prefixable};

use crate::tui::charts::range::{Frame, plotted};
use crate::tui::charts::{Scale, Series};

/// A value as the readout writes it: three significant digits with an SI prefix where the unit
/// takes one, else six significant digits (mu* differs from mu in the fifth), or on a linear axis
/// spanning `span` (same unit) as many decimals as resolve a hundredth of it, trailing zeros kept
/// either way (mu* on an axis "mu* - 0.3 (x1e-7)" reads 0.2999999700, not 0.3; beside 0.303962,
/// mu* strip reads 0.304060, not 0.30406).
pub fn value(v: f64, unit: &str, span: Option<f64>) -> String {
    if prefixable(unit) || !v.is_finite() {
        return format_si(v, unit);
    }
    let fine = span
        .filter(|s| *s > 0.0 && s.is_finite())
        .map(|s| (2.0 - s.log10()).ceil().clamp(0.0, 15.0) as usize);
    let text = if v == 0.0 {
        "0".to_string()
    } else {
        let e = v.abs().log10().floor() as i32;
        match fine {
            Some(d) if (-4..6).contains(&e) && d as i32 > 5 - e => format!("{v:.d$}"),
            _ if (-4..6).contains(&e) => {
                // six significant digits of the rounded value (0.9999996 is 1.00000)
                let f = 10f64.powi(5 - e);
                let r = (v * f).round() / f;
                let d = (5 - r.abs().log10().floor() as i32).max(0) as usize;
                format!("{r:.d$}")
            }
            _ => format!("{v:.5e}"),
        }
    };
    match unit {
        "" => text,
        u => format!("{text} {u}"),
    }
}

/// The name the readout gives a curve: its legend text up to the first ", " (what follows is a
/// remark: "mu*, contact complete from pbar = 428 kPa" reads "mu* = 0.3...").
pub fn short_name(name: &str) -> &str {
    name.split(", ").next().unwrap_or(name)
}

/// A curve's value at plot coordinate `x` (linear between its points in plot coordinates), or
/// None outside its points.
pub fn at(series: &Series, x: f64, xs: Scale, ys: Scale) -> Option<f64> {
    let p = plotted(&series.points, xs, ys);
    p.windows(2).find_map(|w| {
        let (a, b) = (w[0], w[1]);
        let (lo, hi) = (a.0.min(b.0), a.0.max(b.0));
        if !(lo..=hi).contains(&x) {
            return None;
        }
        let t = if b.0 == a.0 {
            0.0
        } else {
            (x - a.0) / (b.0 - a.0)
        };
        Some(ys.value_at(a.1 + t * (b.1 - a.1)))
    })
}

/// Whether plot coordinate `x` lies on one of a curve's points (to a millionth of the x range
/// `span`), not between two.
fn on_a_point(series: &Series, x: f64, xs: Scale, span: f64) -> bool {
    plotted(&series.points, xs, Scale::Linear)
        .iter()
        .any(|p| (p.0 - x).abs() <= 1e-6 * span)
}

/// What the readout says of a curve that has no point at the cursor (it ends before, or its model
/// has no answer there).
const NO_VALUE: &str = "no value here";

/// The readout at `cursor` (a fraction of the x range): "x = ...", then "(interpolated)" where a
/// value read lies between two data points of its curve, then "name = value" for every
/// curve of every plot (its short name), tagged where the cursor is on a dim part of it, as the
/// legend names them ("mu* wide = 0.429323 (fails)", "(partial)" for the spatial contact), and for
/// the pins' curves "[n] name = value"; "name: no value here" off a curve's ends.
pub fn readout(frames: &[Frame], cursor: f64) -> Vec<String> {
    let Some(first) = frames.first() else {
        return Vec::new();
    };
    let [lo, hi] = first.x;
    let xp = lo + cursor.clamp(0.0, 1.0) * (hi - lo);
    let x_axis = &first.plot.x;
    let mut items = vec![format!(
        "{} = {}",
        x_axis.label,
        format_si(x_axis.scale.value_at(xp), x_axis.unit)
    )];
    let mut between = false;
    for f in frames {
        let unit = f.plot.y.unit;
        let span = (f.y_scale == Scale::Linear).then_some(f.y[1] - f.y[0]);
        let read = |s: &Series| {
            at(s, xp, f.plot.x.scale, f.y_scale).map(|v| {
                if f.plot.fraction {
                    format_fraction(v)
                } else {
                    value(v, unit, span)
                }
            })
        };
        // the dim parts of curve i under the cursor: plane models "fail", the spatial contact
        // is partial
        let tag = |i: usize| {
            (f.plot.dim.iter())
                .find(|(j, d)| *j == i && at(d, xp, f.plot.x.scale, f.y_scale).is_some())
                .map_or("", |(_, d)| {
                    if d.name.is_empty() {
                        " (partial)"
                    } else {
                        " (fails)"
                    }
                })
        };
        between |= (f
            .plot
            .series
            .iter()
            .chain(f.pins.iter().flat_map(|p| &p.series)))
        .any(|s| read(s).is_some() && !on_a_point(s, xp, f.plot.x.scale, hi - lo));
        items.extend((f.plot.series.iter().enumerate()).map(|(i, s)| {
            let name = short_name(&s.name);
            read(s).map_or(format!("{name}: {NO_VALUE}"), |v| {
                format!("{name} = {v}{}", tag(i))
            })
        }));
        for (n, pin) in f.pins.iter().enumerate() {
            items.extend(pin.series.iter().map(|s| {
                let name = format!("[{}] {}", n + 1, short_name(&s.name));
                read(s).map_or(format!("{name}: {NO_VALUE}"), |v| format!("{name} = {v}"))
            }));
        }
    }
    if between {
        items.insert(1, "(interpolated)".into());
    }
    items
}
