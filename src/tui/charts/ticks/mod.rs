//! Axis scales and ticks, for the terminal and the SVG alike: nice steps (1, 2, 2.5, 5 times a
//! power of ten) on linear axes,
//! decades (or 1-2-5, or 1..9 within them) on log axes, zero and powers of ten on both sides on
//! symmetric-log axes. Labels are always distinct; the axis title carries the unit with its SI
//! prefix, and an offset when the span is tiny against the values ("mu* - 0.3 (x1e-5)").

use std::f64::consts::LN_10;

use crate::units::{prefix, prefixable};

mod log;
use log::{logarithmic, symlog};

/// How values are placed along an axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scale {
    /// The value itself.
    Linear,
    /// log10 of the value; values <= 0 are not drawn.
    Log,
    /// sign(v) log10(1 + |v|/c): linear within about ±c (the constant, in the axis' unit),
    /// logarithmic beyond, so that small values of both signs stay apart.
    SymLog(f64),
}

impl Scale {
    /// A value in plot coordinates; None where it cannot be drawn.
    pub fn to_plot(self, v: f64) -> Option<f64> {
        let p = match self {
            Scale::Linear => v,
            Scale::Log if v <= 0.0 => return None,
            Scale::Log => v.log10(),
            Scale::SymLog(c) => v.signum() * (v.abs() / c).ln_1p() / LN_10,
        };
        p.is_finite().then_some(p)
    }

    /// The value at a plot coordinate.
    pub fn value_at(self, p: f64) -> f64 {
        match self {
            Scale::Linear => p,
            Scale::Log => 10f64.powf(p),
            Scale::SymLog(c) => p.signum() * c * (p.abs() * LN_10).exp_m1(),
        }
    }

    /// The symmetric-log scale for these values: its linear core is a power of ten a tenth of the
    /// smaller branch's largest magnitude (so both signs span at least a decade), and at most six
    /// decades under the largest magnitude.
    pub fn symlog_for(values: impl Iterator<Item = f64>) -> Scale {
        let (pos, neg) = values
            .filter(|v| v.is_finite())
            .fold((0f64, 0f64), |(p, n), v| (p.max(v), n.max(-v)));
        let big = pos.max(neg);
        if big == 0.0 {
            return Scale::SymLog(1.0);
        }
        let small = if pos > 0.0 && neg > 0.0 {
            pos.min(neg)
        } else {
            big
        };
        let c = (small / 10.0).max(big * 1e-6);
        Scale::SymLog(10f64.powi((c.log10() + 1e-9).floor() as i32))
    }
}

/// The fraction of an axis at either end that may be left without a label (the range's ends are
/// read off the labels nearest them): about a sixth (a log axis from 1M to 200M labelled up to
/// 100M leaves 0.15 of it; jgh-egg-box's k, 3.5e3 to 8.9e4 labelled to 5e4 at 80x24, 0.17).
pub const BARE_END: f64 = 0.17;

/// The ticks of an axis and its title.
#[derive(Clone, Debug, PartialEq)]
pub struct Ticks {
    /// Tick positions in plot coordinates, with their labels, increasing.
    pub ticks: Vec<(f64, String)>,
    /// The axis title: label, offset, unit with prefix or a scale factor, scale.
    pub title: String,
}

/// At most `max` (at least 2) ticks over `range` (plot coordinates, lo < hi) of an axis named
/// `label` with values in `unit`.
pub fn ticks(range: [f64; 2], scale: Scale, label: &str, unit: &str, max: usize) -> Ticks {
    let max = max.max(2);
    match scale {
        Scale::Linear => linear(range, label, unit, max),
        Scale::Log => logarithmic(range, label, unit, max),
        Scale::SymLog(c) => symlog(range, c, label, unit, max),
    }
}

/// Ticks of a nice step (1, 2, 2.5 or 5 times a power of ten) in [lo, hi]: the smallest step giving at most `max` multiples, and at
/// least two: when the step that fits gives one, the finer step before it, thinned to every
/// j-th multiple. Returns (step, mantissa, exponent, the multiples k of the step).
fn nice_step(lo: f64, hi: f64, max: usize) -> (f64, f64, i32, Vec<f64>) {
    let e0 = (hi - lo).log10().floor() as i32 - 2;
    let mut finer = None;
    for e in e0..e0 + 6 {
        for m in [1.0, 2.0, 2.5, 5.0] {
            let step = m * 10f64.powi(e);
            let first = (lo / step - 1e-9).ceil();
            let last = (hi / step + 1e-9).floor();
            let count = (last - first + 1.0).max(0.0) as usize;
            if count > max {
                finer = Some((step, m, e, first, last, count));
                continue;
            }
            if count >= 2 {
                return (
                    step,
                    m,
                    e,
                    (first as i64..=last as i64).map(|k| k as f64).collect(),
                );
            }
            let Some((step, m, e, first, last, count)) = finer else {
                return (
                    step,
                    m,
                    e,
                    (first as i64..=last as i64).map(|k| k as f64).collect(),
                );
            };
            let j = (count - 1).div_ceil(max - 1) as i64;
            let ks = (first as i64..=last as i64)
                .filter(|k| (k - first as i64) % j == 0)
                .map(|k| k as f64)
                .collect();
            return (step, m, e, ks);
        }
    }
    unreachable!("a step of ten times the span has at most two multiples in it")
}

/// Powers of ten of an axis' labels: engineering (multiples of 3) for prefixable units, none
/// for unitless numbers from 0.01 to 1e4, scientific beyond.
fn label_exponent(top: f64, unit: &str) -> i32 {
    if top == 0.0 {
        return 0;
    }
    let e = top.log10().floor() as i32;
    if prefixable(unit) {
        3 * e.div_euclid(3)
    } else if (-2..4).contains(&e) {
        0
    } else {
        e
    }
}

/// A number with up to 12 significant digits, without trailing zeros ("0.3", "20", "-1.25").
pub fn plain(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let decimals = (11 - v.abs().log10().floor() as i32).clamp(0, 30) as usize;
    let text = format!("{v:.decimals$}");
    let text = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.')
    } else {
        &text
    };
    text.to_string()
}

/// "label [prefix unit]", or with a scale factor where no prefix applies.
fn titled(label: &str, unit: &str, exp: i32) -> String {
    match (prefixable(unit), exp) {
        (_, 0) if unit.is_empty() => label.to_string(),
        (true, e) => match prefix(e) {
            Some(p) => format!("{label} [{p}{unit}]"),
            None => format!("{label} [1e{e} {unit}]"),
        },
        (false, 0) => format!("{label} [{unit}]"),
        (false, e) if unit.is_empty() => format!("{label} (x1e{e})"),
        (false, e) => format!("{label} [{unit}] (x1e{e})"),
    }
}

fn linear([lo, hi]: [f64; 2], label: &str, unit: &str, max: usize) -> Ticks {
    let (step, m, e, ks) = nice_step(lo, hi, max);
    labelled([lo, hi], (step, m, e), &ks, label, unit).0
}

/// The ticks at the multiples `ks` of a nice step (`nice_step`: the step, its mantissa and power
/// of ten) over `[lo, hi]`, and the step as labelled.
fn labelled(
    [lo, hi]: [f64; 2],
    (step, m, e): (f64, f64, i32),
    ks: &[f64],
    label: &str,
    unit: &str,
) -> (Ticks, String) {
    let (first, last) = (ks[0], ks[ks.len() - 1]);
    let top = first.abs().max(last.abs()) * step;
    let digits = if top > 0.0 {
        top.log10().floor() as i32 - e + 1
    } else {
        1
    };
    // an offset when the labels would need more than four significant digits: a round number
    // near the middle, a whole number of steps, so that the differences are exact
    let k0 = if digits > 4 && (first > 0.0 || last < 0.0) {
        let p = ((hi - lo).log10().ceil() as i32).max(e + 1);
        let per = 10f64.powi(p - e) / m;
        (0.5 * (first + last) / per).round() * per
    } else {
        0.0
    };
    let top = (first - k0).abs().max((last - k0).abs()) * step;
    let exp = label_exponent(top, unit);
    // 2.5 steps need one decimal more than their power of ten
    let decimals = (exp - e + (m == 2.5) as i32).max(0) as usize;
    let ticks = ks
        .iter()
        .map(|&k| {
            let v = (k - k0) * m * 10f64.powi(e - exp);
            let text = if k == k0 {
                "0".to_string()
            } else {
                format!("{v:.decimals$}")
            };
            (k * step, text)
        })
        .collect();
    let name = if k0 == 0.0 {
        label.to_string()
    } else {
        let offset = k0 * step;
        let sign = if offset > 0.0 { "-" } else { "+" };
        let oexp = label_exponent(offset.abs(), unit);
        match prefix(oexp).filter(|_| prefixable(unit)) {
            Some(p) => format!(
                "{label} {sign} {} {p}{unit}",
                plain(offset.abs() / 10f64.powi(oexp))
            ),
            // the offset in the axis' own unit
            None => format!("{label} {sign} {}", compact(offset.abs(), "", 12)),
        }
    };
    let ticks = Ticks {
        ticks,
        title: titled(&name, unit, exp),
    };
    (ticks, format!("{:.decimals$}", m * 10f64.powi(e - exp)))
}

/// A value in few characters: an SI prefix letter for prefixable units ("2.5k", "100u"),
/// plain between 1e-3 and 1e4, else scientific ("2e-5"), with `sig` significant digits at most.
fn compact(v: f64, unit: &str, sig: usize) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let rounded = {
        let e = v.abs().log10().floor() as i32;
        let f = 10f64.powi(sig as i32 - 1 - e);
        (v * f).round() / f
    };
    let e = rounded.abs().log10().floor() as i32;
    if prefixable(unit) {
        let pe = 3 * e.div_euclid(3);
        if let Some(p) = prefix(pe) {
            return format!("{}{p}", plain(rounded / 10f64.powi(pe)));
        }
    } else if (-3..4).contains(&e) {
        return plain(rounded);
    }
    format!("{}e{e}", plain(rounded / 10f64.powi(e)))
}

/// Labels of real values, with as few significant digits as keep them all distinct.
fn distinct_labels(values: &[f64], unit: &str) -> Vec<String> {
    (1..=17)
        .map(|sig| values.iter().map(|&v| compact(v, unit, sig)).collect())
        .find(|labels: &Vec<String>| {
            labels
                .iter()
                .enumerate()
                .all(|(i, l)| !labels[..i].contains(l))
        })
        .unwrap_or_else(|| values.iter().map(|v| format!("{v:e}")).collect())
}

fn with_labels(scale: Scale, values: Vec<f64>, unit: &str) -> Vec<(f64, String)> {
    let drawn: Vec<(f64, f64)> = values
        .into_iter()
        .filter_map(|v| Some((scale.to_plot(v)?, v)))
        .collect();
    let real: Vec<f64> = drawn.iter().map(|d| d.1).collect();
    drawn
        .iter()
        .map(|d| d.0)
        .zip(distinct_labels(&real, unit))
        .collect()
}

/// Filled bands over `[lo, hi]` (lo < hi), as matplotlib's `contourf` draws a field: edges at
/// the multiples of a nice step (`nice_step`) from the last at or under lo to the first at or
/// over hi, the finest step giving at most `max` bands. The edges (increasing) with their labels
/// and the title, as a linear axis over them labels them; and the step as labelled.
pub fn bands([lo, hi]: [f64; 2], label: &str, unit: &str, max: usize) -> (Ticks, String) {
    let max = max.max(1);
    // a step with at most max bands has at most max + 1 multiples in [lo, hi]
    let mut multiples = max + 1;
    loop {
        let (step, m, e, _) = nice_step(lo, hi, multiples);
        let first = (lo / step + 1e-9).floor() as i64;
        let last = ((hi / step - 1e-9).ceil() as i64).max(first + 1);
        if last - first <= max as i64 || multiples <= 2 {
            let ks: Vec<f64> = (first..=last).map(|k| k as f64).collect();
            let edges = [first as f64 * step, last as f64 * step];
            return labelled(edges, (step, m, e), &ks, label, unit);
        }
        multiples -= 1;
    }
}
