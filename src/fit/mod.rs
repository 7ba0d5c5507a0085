//! Fits of a preset's parameters to measured data (`data::DataSet`): weighted least squares by
//! Levenberg-Marquardt (`lm`) over the free parameters, each in its fitting coordinate
//! (`model::Free`: the logarithm of a positive dimensional value), with honest uncertainty: 95 %
//! intervals from the Jacobian (`uncertainty`; the noise estimated from the residuals when the
//! data give no sd, with Student's t, `student`), and a profile of the sum of squares along each
//! parameter (`profile`) that says in words when the data do not determine it and which other
//! measurement would (`advice`). `synthetic` makes data from the model with a known noise.

pub mod advice;
pub mod lm;
pub mod memo;
pub mod model;
pub mod profile;
pub mod student;
pub mod synthetic;
pub mod uncertainty;
pub mod written;

use nalgebra::DVector;
use rayon::prelude::*;

use crate::data::DataSet;
use crate::physics::stop::Stop;
use crate::preset::{Key, Preset};
use crate::units::{format_si, format_si_exact, supported};

pub use model::{Free, Model};

/// The two-sided 95 % point of the standard normal distribution, for data with their standard
/// deviations given (Abramowitz & Stegun (1964) table 26.1).
pub const NORMAL_95: f64 = 1.959_963_984_540_054;

/// A log parameter whose 95 % range spans more than this factor is not determined (two decades).
pub const UNDETERMINED_SPAN: f64 = 100.0;

/// Why a fit has no answer.
#[derive(Clone, Debug, PartialEq)]
pub enum FitError {
    /// The request does not make sense (the command line exits 2).
    Invalid(String),
    /// The model cannot be fitted (no answer at the start, no convergence; exit 3).
    NoFit(String),
}

/// One free parameter's result.
#[derive(Clone, Debug, PartialEq)]
pub struct Estimate {
    /// The parameter.
    pub key: Key,
    /// The value written into the fitted preset [the parameter's SI unit] (`written`): when
    /// determined, the best value to the digits its interval supports; when not, the preset's
    /// value where that fits within the noise, else the end of the range that fits nearest to
    /// it.
    pub value: f64,
    /// The value the fit started from, the preset's [SI].
    pub start: f64,
    /// The 95 % interval [SI]: from the Jacobian when determined, else the range of values that
    /// fit within the noise (the profile's; from 0 for a logarithmic parameter whose profile
    /// stays within the noise down to the end of its scan: any value up to the high end fits).
    pub interval: [f64; 2],
    /// The range of the profile [SI] (the values that fit within the noise, to the scan's ends).
    pub profile: [f64; 2],
    /// Whether the data determine it.
    pub determined: bool,
    /// Why not, in words, with the measurement that would (None when determined).
    pub reason: Option<String>,
}

impl Estimate {
    /// The value and the interval's ends as text: when determined, each to the digits the
    /// interval supports (`units::supported`, written with every such digit); when not, the
    /// value as written and the range that fits to four digits.
    pub fn texts(&self) -> (String, [String; 2]) {
        let unit = self.key.param().unit;
        if !self.determined {
            return (
                format_si_exact(self.value, unit),
                self.interval.map(|v| show(v, unit)),
            );
        }
        let half = 0.5 * (self.interval[1] - self.interval[0]);
        let text = |v: f64| format_si_exact(supported(v, half), unit);
        (text(self.value), self.interval.map(text))
    }

    /// An undetermined parameter in words, named `name` (its symbol or its key): where its
    /// written value comes from and the range that fits, e.g. "k not determined by these data:
    /// kept at the preset's 1e-12 1/Pa (any k up to 6.158e-11 1/Pa fits)"; None when determined.
    pub fn undetermined_words(&self, name: &str) -> Option<String> {
        if self.determined {
            return None;
        }
        let (value, [low, high]) = self.texts();
        // a logarithmic parameter's range from 0: it fits down to the end of its scan
        let fits = if self.interval[0] == 0.0 && self.profile[0] > 0.0 {
            format!("any {name} up to {high} fits")
        } else {
            format!("any {name} from {low} to {high} fits")
        };
        let kept = if self.value == self.start {
            format!("kept at the preset's {value}")
        } else {
            format!(
                "{value}, the value nearest the preset's {} that fits",
                format_si_exact(self.start, self.key.param().unit)
            )
        };
        Some(format!(
            "{name} not determined by these data: {kept} ({fits})"
        ))
    }
}

/// A fit.
#[derive(Clone, Debug)]
pub struct Fit {
    /// The free parameters, in the order asked.
    pub estimates: Vec<Estimate>,
    /// Data minus model for each measured value, row by row [the quantity's SI unit], at the
    /// values written into `preset`.
    pub residuals: Vec<f64>,
    /// The sum of squared weighted residuals at the values written.
    pub sum_of_squares: f64,
    /// True when the data give standard deviations (the residuals weighted by 1/sd).
    pub weighted: bool,
    /// The residual variance s^2 used for the intervals: S/(n - p) without sd, 1 with sd.
    pub residual_variance: f64,
    /// Measured values minus free parameters.
    pub degrees_of_freedom: usize,
    /// Iterations of the minimisation.
    pub iterations: usize,
    /// The preset at the values written (`Estimate::value`).
    pub preset: Preset,
}

fn weights(data: &DataSet) -> Result<(Vec<f64>, bool), FitError> {
    let with_sd = data.measured.iter().filter(|m| m.sd.is_some()).count();
    if with_sd == 0 && data.measured.len() > 1 {
        return Err(FitError::Invalid(
            "several measured columns without sd columns: quantities in different units share \
             no noise level; give each an sd column (`mu sd [-]`) or fit one at a time"
                .into(),
        ));
    }
    if with_sd != 0 && with_sd != data.measured.len() {
        return Err(FitError::Invalid(
            "some measured columns have an sd column and some not: give every one an sd \
             column, or none"
                .into(),
        ));
    }
    let w = (0..data.len())
        .flat_map(|i| {
            data.measured
                .iter()
                .map(move |m| m.sd.as_ref().map_or(1.0, |sd| 1.0 / sd[i]))
        })
        .collect();
    Ok((w, with_sd > 0))
}

/// The free parameters of `keys`, each once.
pub fn free_parameters(preset: &Preset, data: &DataSet, keys: &[Key]) -> Result<Vec<Free>, String> {
    if keys.is_empty() {
        return Err("no free parameter: name at least one key to fit".into());
    }
    let mut free: Vec<Free> = Vec::new();
    for key in keys {
        if free.iter().any(|f| f.key == *key) {
            return Err(format!("{key} is named twice"));
        }
        free.push(Free::new(preset, *key, data.x.key)?);
    }
    Ok(free)
}

fn show(value: f64, unit: &str) -> String {
    format_si(value, unit)
}

/// Fits `keys` of `preset` to `data`.
pub fn fit(preset: &Preset, data: &DataSet, keys: &[Key]) -> Result<Fit, FitError> {
    fit_until(preset, data, keys, Stop::Never)
}

/// As [`fit`], every solve of the model asking `stop` (`Model::stop`): once it says so the fit
/// ends within its bounded loops, each prediction failing at once; the caller that stopped it
/// reads `stop`, not the error.
pub fn fit_until(
    preset: &Preset,
    data: &DataSet,
    keys: &[Key],
    stop: Stop,
) -> Result<Fit, FitError> {
    let free = free_parameters(preset, data, keys).map_err(FitError::Invalid)?;
    let (weights, weighted) = weights(data)?;
    let (n, p) = (weights.len(), free.len());
    if n <= p {
        return Err(FitError::Invalid(format!(
            "{n} measured values cannot determine {p} free parameters and the noise: a fit needs \
             more values than free parameters"
        )));
    }
    let model = Model::new(preset, data, &free, weights, stop);
    let start = DVector::from_iterator(
        p,
        free.iter()
            .map(|f| f.coordinate(preset.get(f.key).unwrap_or(f64::NAN))),
    );
    let f = |theta: &DVector<f64>| model.residuals(theta);
    let best = lm::minimize(&f, start, lm::MAX_ITERATIONS)
        .map_err(|why| FitError::NoFit(format!("the fit cannot be done: {why}")))?;
    let dof = n - p;
    let s2 = if weighted {
        1.0
    } else {
        best.sum_of_squares / dof as f64
    };
    let quantile = if weighted {
        NORMAL_95
    } else {
        student::two_sided(0.95, dof as f64)
    };
    let errors = uncertainty::errors(&best.jacobian, s2);
    let threshold = quantile * quantile * s2;
    // the parameters' profiles are independent of each other: scanned in parallel (rayon)
    let mut estimates = free
        .par_iter()
        .enumerate()
        .map(|(j, fr)| {
            let se = errors.standard[j];
            let step = match (se, fr.log) {
                (Some(se), true) if se > 0.0 => (quantile * se / 4.0).min(profile::LOG_STEP),
                (_, true) => profile::LOG_STEP,
                (Some(se), false) if se > 0.0 => quantile * se / 4.0,
                (_, false) => 0.1 * best.x[j].abs().max(fr.key.param().typical().unwrap_or(1.0)),
            };
            let range = profile::range(&model, &best, j, step, threshold);
            let start = preset.get(fr.key).unwrap_or(f64::NAN);
            judge(
                *fr,
                best.x[j],
                start,
                se,
                errors.deficient[j],
                range,
                quantile,
            )
        })
        .collect::<Vec<_>>();
    let values = written::values(&model, &best, &mut estimates, &errors.standard, quantile)?;
    let no_answer = |why| FitError::NoFit(format!("the fitted model has no answer: {why}"));
    let fitted = model.preset_at(&values).map_err(no_answer)?;
    let predicted = model.predictions_of(fitted.clone()).map_err(no_answer)?;
    let residuals: Vec<f64> = (model.observed().iter())
        .zip(&predicted)
        .map(|(o, m)| o - m)
        .collect();
    let sum_of_squares = (residuals.iter().zip(&model.weights))
        .map(|(r, w)| (r * w) * (r * w))
        .sum();
    Ok(Fit {
        estimates,
        residuals,
        sum_of_squares,
        weighted,
        residual_variance: s2,
        degrees_of_freedom: dof,
        iterations: best.iterations,
        preset: fitted,
    })
}

/// An interval cut to the parameter's allowed values (an interval of mu near 0 stops at 0).
pub(crate) fn within_limit(key: Key, [low, high]: [f64; 2]) -> [f64; 2] {
    let Some(limit) = key.param().limit() else {
        return [low, high];
    };
    let floor = if limit.check("", 0.0).is_ok() {
        limit.min.min(0.0)
    } else {
        limit.min
    };
    [low.max(floor), high.min(limit.max)]
}

/// The verdict on one parameter from its estimate (coordinate `c`), its starting value `start`
/// [SI], standard error, rank and profile range.
fn judge(
    fr: Free,
    c: f64,
    start: f64,
    se: Option<f64>,
    deficient: bool,
    range: profile::Range,
    quantile: f64,
) -> Estimate {
    let key = fr.key;
    let unit = key.param().unit;
    let span = [fr.value(range.low), fr.value(range.high)];
    let flat = if fr.log {
        range.low_open || range.high_open || span[1] > UNDETERMINED_SPAN * span[0]
    } else {
        range.low_open && range.high_open
    };
    let determined = !deficient && !flat && se.is_some();
    // a positive parameter that fits within the noise down to the end of its scan (16 decades):
    // any value up to the high end fits, the scan's end is no bound worth a number
    let down_to_zero = fr.log && range.low_open;
    let reason = (!determined).then(|| {
        let symbol = key.symbol();
        let [low, high] = span.map(|v| show(v, unit));
        let fits = match (down_to_zero, range.low_open, range.high_open) {
            (true, _, false) => format!("any {symbol} up to {high} fits within the noise"),
            (true, _, true) => {
                format!("any {symbol} up to {high}, where the scan stops, fits within the noise")
            }
            (false, false, false) => format!("{low} .. {high} fit within the noise"),
            (false, true, false) => format!(
                "any {symbol} up to {high} fits within the noise (no lower end down to {low}, \
                 where the scan stops)"
            ),
            (false, false, true) => format!(
                "any {symbol} from {low} up fits within the noise (no upper end up to {high}, \
                 where the scan stops)"
            ),
            (false, true, true) => format!(
                "every {symbol} from {low} to {high}, where the scan stops, fits within the noise"
            ),
        };
        let flat = if deficient {
            format!(
                "the measured values do not change with {symbol} at the best fit (the Jacobian \
                 is rank-deficient); "
            )
        } else {
            String::new()
        };
        format!(
            "{symbol} is not determined by these data: {flat}{fits}; {}",
            advice::measurement_for(key)
        )
    });
    let (value, interval) = match (determined, se) {
        (true, Some(se)) => (
            fr.value(c),
            within_limit(
                key,
                [fr.value(c - quantile * se), fr.value(c + quantile * se)],
            ),
        ),
        _ => (
            written::kept(fr, start, &range),
            [if down_to_zero { 0.0 } else { span[0] }, span[1]],
        ),
    };
    Estimate {
        key,
        value,
        start,
        interval,
        profile: span,
        determined,
        reason,
    }
}
