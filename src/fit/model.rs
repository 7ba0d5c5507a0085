//! The model a fit compares with the data: the preset with its free parameters set (each in its
//! fitting coordinate, the logarithm for a positive dimensional value), solved at each row's x
//! through `sweeps::point`, the pipeline of `wearlab solve`, and read for each measured quantity.

use nalgebra::DVector;

use crate::data::DataSet;
use crate::physics::SolveError;
use crate::physics::stop::{STOPPED, Stop};
use crate::preset::{Key, Preset};
use crate::sweeps::point;

/// A free parameter and its fitting coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Free {
    /// The parameter.
    pub key: Key,
    /// True when fitted as ln(value): a positive dimensional value that may span decades (E, h,
    /// k, tau0, R); mu, nu and the wear exponent are fitted as they are.
    pub log: bool,
}

impl Free {
    /// The free parameter `key` of `preset`: a number the program can vary (not a choice, not a
    /// count), finite at the start.
    pub fn new(preset: &Preset, key: Key, x: Key) -> Result<Free, String> {
        let param = key.param();
        if param.limit().is_none() || param.is_whole() {
            return Err(format!(
                "{key} is not a number a fit can vary ({})",
                param.allowed()
            ));
        }
        if key == x {
            return Err(format!(
                "{key} is the data's x axis: each row sets it, a fit cannot free it"
            ));
        }
        let value = preset.get(key)?;
        if !value.is_finite() {
            return Err(format!(
                "{key} = {value}: a fit starts from a finite value; set one with --set {key}=VALUE"
            ));
        }
        let unit = param.unit;
        let log = !unit.is_empty() && !unit.starts_with("rad") && value > 0.0;
        Ok(Free { key, log })
    }

    /// The fitting coordinate of a value.
    pub fn coordinate(self, value: f64) -> f64 {
        if self.log { value.ln() } else { value }
    }

    /// The value of a fitting coordinate.
    pub fn value(self, coordinate: f64) -> f64 {
        if self.log {
            coordinate.exp()
        } else {
            coordinate
        }
    }
}

/// The data, the preset and the free parameters: predictions and weighted residuals.
pub struct Model<'a> {
    /// The preset the fit starts from.
    pub base: &'a Preset,
    /// The measurements.
    pub data: &'a DataSet,
    /// The free parameters.
    pub free: &'a [Free],
    /// One weight per measured value (1/sd, or 1 without sd), row by row.
    pub weights: Vec<f64>,
    /// Asked before every row's solve and inside it: once it says so, every prediction fails
    /// at once, so the fit's bounded loops end quickly.
    pub stop: Stop<'a>,
}

impl Model<'_> {
    /// The measured values, row by row (each row's columns in file order).
    pub fn observed(&self) -> Vec<f64> {
        (0..self.data.len())
            .flat_map(|i| self.data.measured.iter().map(move |m| m.values[i]))
            .collect()
    }

    /// The preset with the free parameters at `theta` (their limits and the rules between fields
    /// checked).
    pub fn preset(&self, theta: &DVector<f64>) -> Result<Preset, String> {
        let mut preset = self.base.clone();
        for (f, c) in self.free.iter().zip(theta.iter()) {
            preset.assign(f.key, f.value(*c))?;
        }
        preset.check_rules()?;
        Ok(preset)
    }

    /// The model's value of each measured value, row by row; Err names the row's line and why the
    /// model has no answer there.
    pub fn predictions(&self, theta: &DVector<f64>) -> Result<Vec<f64>, String> {
        // one preset for every row: each row assigns the x it was measured at over the last
        let mut at = self.preset(theta)?;
        let mut out = Vec::with_capacity(self.weights.len());
        for (i, x) in self.data.x.values.iter().enumerate() {
            let line = self.data.lines[i];
            at.assign(self.data.x.key, *x)
                .and_then(|()| at.check_rules())
                .map_err(|why| format!("line {line}: {why}"))?;
            if self.stop.now() {
                return Err(STOPPED.into());
            }
            let p = point::solve_until(&at, self.stop)
                .map_err(|e| format!("line {line}: {}", SolveError::from(e)))?;
            for m in &self.data.measured {
                let v = m
                    .quantity
                    .value(&p)
                    .map_err(|why| format!("line {line}: {}: {why}", m.quantity))?;
                if !v.is_finite() {
                    return Err(format!("line {line}: {} is not finite here", m.quantity));
                }
                out.push(v);
            }
        }
        Ok(out)
    }

    /// The weighted residuals (model - data) * weight.
    pub fn residuals(&self, theta: &DVector<f64>) -> Result<DVector<f64>, String> {
        let predicted = self.predictions(theta)?;
        let observed = self.observed();
        Ok(DVector::from_iterator(
            predicted.len(),
            predicted
                .iter()
                .zip(&observed)
                .zip(&self.weights)
                .map(|((p, o), w)| (p - o) * w),
        ))
    }
}
