//! An axis of a sweep or a map: a parameter (`preset::Key`) and the range it runs over
//! (`physics::SweepRange`: from, to, points, log or linear), as typed on the command line
//! (`KEY=FROM:TO[:N][:log]`), written in a preset's `[explore]` section, or defaulted for the
//! explorer from the parameter's value and limits.

use std::f64::consts::PI;

use crate::physics::{Spacing, SweepRange, limits};
use crate::preset::{Key, Preset};
use crate::units::{clean, parse_si};

/// A varied parameter and its range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Axis {
    /// The parameter.
    pub key: Key,
    /// Its values: `range.min` to `range.max` (the parameter's unit), both included.
    pub range: SweepRange,
}

/// Points of a curve when the range does not say.
pub const CURVE_POINTS: usize = 50;
/// Points per side of a grid (two varied parameters) when the range does not say.
pub const GRID_POINTS: usize = 20;

impl Axis {
    /// An axis over `key` from `from` to `to`: a number of the preset's problem that is not a
    /// count, both ends finite and allowed by its limit, from < to, 2 to 2000 points, and from > 0
    /// for a log range. Err names the key and the fault.
    pub fn new(
        preset: &Preset,
        key: Key,
        [from, to]: [f64; 2],
        points: usize,
        spacing: Spacing,
    ) -> Result<Axis, String> {
        let param = key.param();
        let Some(limit) = param.limit() else {
            return Err(format!(
                "{key} is a choice ({}): it cannot be varied; set it with --set {key}=NAME",
                param.allowed().trim_start_matches("one of ")
            ));
        };
        if param.is_whole() {
            return Err(format!(
                "{key} is a count ({}): it changes no result and cannot be varied",
                limit.allowed
            ));
        }
        preset.get(key)?;
        for (end, v) in [("FROM", from), ("TO", to)] {
            if !v.is_finite() {
                return Err(format!(
                    "{key}: {end} = {v}: the ends of a range must be finite"
                ));
            }
            limit.check(&format!("{key}: {end}"), v)?;
        }
        if from >= to {
            return Err(format!(
                "{key}: bad range: TO = {} must be larger than FROM = {}",
                limits::show(to),
                limits::show(from)
            ));
        }
        if spacing == Spacing::Log && from <= 0.0 {
            return Err(format!(
                "{key}: a log range needs FROM > 0 (FROM = {}); use a linear range or a positive FROM",
                limits::show(from)
            ));
        }
        limits::SWEEP_POINTS.check(&format!("{key}: N"), points as f64)?;
        Ok(Axis {
            key,
            range: SweepRange {
                min: from,
                max: to,
                points,
                spacing,
            },
        })
    }

    /// Parses `KEY=FROM:TO[:N][:log|:linear]` for a preset (values with optional SI prefix and
    /// unit, "1um:10mm:40:log"); N defaults to `default_points`, the scale to linear.
    pub fn parse(preset: &Preset, text: &str, default_points: usize) -> Result<Axis, String> {
        let syntax = || {
            format!(
                "'{text}' is not KEY=FROM:TO[:N][:log], e.g. material.thickness=1um:10mm:40:log"
            )
        };
        let (key, range) = text.split_once('=').ok_or_else(syntax)?;
        let key = preset.key(key)?;
        let parts: Vec<&str> = range.split(':').map(str::trim).collect();
        let (ends, rest) = match parts.as_slice() {
            [from, to, rest @ ..] if rest.len() <= 2 => ([*from, *to], rest),
            _ => return Err(syntax()),
        };
        let mut points = default_points;
        let mut spacing = Spacing::Linear;
        for (i, part) in rest.iter().enumerate() {
            match *part {
                "log" if i + 1 == rest.len() => spacing = Spacing::Log,
                "lin" | "linear" if i + 1 == rest.len() => spacing = Spacing::Linear,
                n if i == 0 => {
                    points = n.parse().map_err(|_| {
                        format!(
                            "{key}: N = '{n}' is not a number of points: allowed {}",
                            limits::SWEEP_POINTS.allowed
                        )
                    })?
                }
                _ => return Err(syntax()),
            }
        }
        let unit = key.param().unit;
        let mut values = [0.0; 2];
        for (value, (end, text)) in values.iter_mut().zip(["FROM", "TO"].iter().zip(ends)) {
            *value = parse_si(text, unit).map_err(|why| format!("{key}: {end} = {why}"))?;
        }
        Axis::new(preset, key, values, points, spacing)
    }

    /// The values, both ends included exactly.
    pub fn values(&self) -> Vec<f64> {
        self.range.values()
    }

    /// The range the explorer offers first for `key`: a decade either side of the value (of the
    /// parameter's typical magnitude when the value is 0), log, clamped to the limit; a phase
    /// runs linearly over pi either side. Both ends are rounded outwards to three significant
    /// digits (5.79e-13 to 5.8e-11 about k = 5.793239928544991e-12), so the form's text and the
    /// `--vary` command are short and read back to this very range; below an excluded maximum
    /// (nu < 1/2) the top end is a thousandth under it (0.4995).
    pub fn default_for(preset: &Preset, key: Key) -> Result<Axis, String> {
        let param = key.param();
        let (Some(limit), Some(typical)) = (param.limit(), param.typical()) else {
            return Axis::new(preset, key, [0.0, 0.0], CURVE_POINTS, Spacing::Linear);
        };
        let value = preset.get(key)?;
        let (lo, hi, spacing) = if limit.min < 0.0 {
            (value - PI, value + PI, Spacing::Linear)
        } else {
            let centre = if value.is_finite() && value > 0.0 {
                value
            } else {
                typical
            };
            (centre / 10.0, centre * 10.0, Spacing::Log)
        };
        let lo = outward(lo, false).max(limit.min);
        let hi = outward(hi, true).min(limit.max);
        let hi = if limit.accepts(hi) {
            hi
        } else {
            clean(limit.max - 1e-3 * limit.max.abs())
        };
        Axis::new(preset, key, [lo, hi], CURVE_POINTS, spacing)
    }
}

/// `v` rounded to three significant digits away from the middle of a range: down for its lower
/// end (`up` false), up for its upper end; a value already at three digits stays as it is.
fn outward(v: f64, up: bool) -> f64 {
    if v == 0.0 || !v.is_finite() {
        return v;
    }
    let step = 10f64.powi(v.abs().log10().floor() as i32 - 2);
    let n = v / step;
    let whole = n.round();
    let n = if (n - whole).abs() <= 1e-9 * whole.abs() {
        whole
    } else if up {
        n.ceil()
    } else {
        n.floor()
    };
    clean(n * step)
}
