//! The model a fit compares with the data: the preset with its free parameters set (each in its
//! fitting coordinate, the logarithm for a positive dimensional value), solved at each row's x
//! through `sweeps::point`, the pipeline of `wearlab solve`, and read for each measured quantity.
//! Rows at times of the spatial problem are read from one running-in (`spatial::at_times`, the
//! same pipeline's results at each time) instead of one from t = 0 per row; under the linear wear
//! law one running-in serves every k the fit tries (`at_times::Kept`), its time scaled. Other
//! rows are solved in parallel, and a point the fit asks for again is not solved again (`memo`).

use nalgebra::DVector;
use rayon::prelude::*;

use super::memo::Memo;
use crate::data::DataSet;
use crate::physics::SolveError;
use crate::physics::spatial::at_times::Kept;
use crate::physics::spatial::partial::running_in::Stopped;
use crate::physics::stop::{STOPPED, Stop};
use crate::preset::{Key, Preset, Problem};
use crate::sweeps::point::{self, Point, SpatialPoint};

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
#[derive(Debug)]
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
    /// The running-ins of the linear law met so far, reused for every k (`at_times::Kept`).
    kept: Kept,
    /// The predictions at the points evaluated so far (`memo`).
    memo: Memo,
}

impl<'a> Model<'a> {
    /// The model of `data` by `base` with `free` parameters, `weights` and `stop` as in the
    /// fields.
    pub fn new(
        base: &'a Preset,
        data: &'a DataSet,
        free: &'a [Free],
        weights: Vec<f64>,
        stop: Stop<'a>,
    ) -> Model<'a> {
        Model {
            base,
            data,
            free,
            weights,
            stop,
            kept: Kept::default(),
            memo: Memo::default(),
        }
    }

    /// The running-ins stepped from t = 0 and kept so far (`at_times::Kept`; at most
    /// `at_times::KEPT`): one for a fit of k alone under the linear law.
    pub fn running_ins_stepped(&self) -> usize {
        self.kept.len()
    }

    /// The measured values, row by row (each row's columns in file order).
    pub fn observed(&self) -> Vec<f64> {
        (0..self.data.len())
            .flat_map(|i| self.data.measured.iter().map(move |m| m.values[i]))
            .collect()
    }

    /// The preset with the free parameters at `theta` (their limits and the rules between fields
    /// checked).
    pub fn preset(&self, theta: &DVector<f64>) -> Result<Preset, String> {
        let values: Vec<f64> = (self.free.iter().zip(theta.iter()))
            .map(|(f, c)| f.value(*c))
            .collect();
        self.preset_at(&values)
    }

    /// The preset with the free parameters at `values` [SI], one per free parameter (their
    /// limits and the rules between fields checked).
    pub fn preset_at(&self, values: &[f64]) -> Result<Preset, String> {
        let mut preset = self.base.clone();
        for (f, v) in self.free.iter().zip(values) {
            preset.assign(f.key, *v)?;
        }
        preset.check_rules()?;
        Ok(preset)
    }

    /// The model's value of each measured value, row by row; Err names the row's line and why the
    /// model has no answer there. Rows at times of the spatial problem share one running-in
    /// (`at_times`), read at every row's time; other rows are solved in parallel. A point
    /// evaluated before is not solved again (`memo`).
    pub fn predictions(&self, theta: &DVector<f64>) -> Result<Vec<f64>, String> {
        (self.memo).get_or(theta, || self.predictions_of(self.preset(theta)?))
    }

    /// As [`Model::predictions`] for the preset `at` (the base with the free parameters set).
    pub fn predictions_of(&self, mut at: Preset) -> Result<Vec<f64>, String> {
        let mut out = Vec::with_capacity(self.weights.len());
        if at.problem == Problem::Spatial && Key::of("spatial.time") == Some(self.data.x.key) {
            for (i, point) in self.along_the_running_in(&mut at)?.into_iter().enumerate() {
                let point = point.map_err(|e| self.at_line(i, SolveError::from(e)))?;
                self.read(i, &point, &mut out)?;
            }
            return Ok(out);
        }
        // the rows in as many runs of consecutive rows as there are threads (rayon), each run with
        // its own preset; the values joined in row order, the first row without an answer named
        let rows: Vec<usize> = (0..self.data.len()).collect();
        let run = rows.len().div_ceil(rayon::current_num_threads()).max(1);
        let runs: Vec<Result<Vec<f64>, String>> = rows
            .par_chunks(run)
            .map(|run| self.rows(at.clone(), run))
            .collect();
        for values in runs {
            out.extend(values?);
        }
        Ok(out)
    }

    /// The predictions of `rows` (a run of consecutive rows) with one preset: each row assigns
    /// the x it was measured at over the last.
    fn rows(&self, mut at: Preset, rows: &[usize]) -> Result<Vec<f64>, String> {
        let mut out = Vec::with_capacity(rows.len() * self.data.measured.len());
        for &i in rows {
            self.set_x(&mut at, i)?;
            if self.stop.now() {
                return Err(STOPPED.into());
            }
            let point = point::solve_until(&at, self.stop)
                .map_err(|e| self.at_line(i, SolveError::from(e)))?;
            self.read(i, &point, &mut out)?;
        }
        Ok(out)
    }

    /// The spatial problem of `at` at every row's time, from one running-in.
    fn along_the_running_in(&self, at: &mut Preset) -> Result<Vec<Result<Point, Stopped>>, String> {
        for i in 0..self.data.len() {
            self.set_x(at, i)?;
        }
        if self.stop.now() {
            return Err(STOPPED.into());
        }
        let inputs = at.spatial_inputs();
        let results = (self.kept)
            .solve_at_times_until(
                &inputs,
                &at.spatial_state_at(),
                &self.data.x.values,
                self.stop,
            )
            .map_err(|e| self.at_line(0, SolveError::from(e)))?;
        Ok((results.into_iter())
            .map(|r| {
                r.map(|result| {
                    Point::Spatial(Box::new(SpatialPoint {
                        inputs: inputs.clone(),
                        result,
                    }))
                })
            })
            .collect())
    }

    /// Row `i`'s x assigned to `at`, the rules between fields checked.
    fn set_x(&self, at: &mut Preset, i: usize) -> Result<(), String> {
        at.assign(self.data.x.key, self.data.x.values[i])
            .and_then(|()| at.check_rules())
            .map_err(|why| format!("line {}: {why}", self.data.lines[i]))
    }

    fn at_line(&self, i: usize, why: impl std::fmt::Display) -> String {
        format!("line {}: {why}", self.data.lines[i])
    }

    /// Each measured quantity of row `i` read from its solved `point`, onto `out`.
    fn read(&self, i: usize, point: &Point, out: &mut Vec<f64>) -> Result<(), String> {
        for m in &self.data.measured {
            let v = m
                .quantity
                .value(point)
                .map_err(|why| self.at_line(i, format!("{}: {why}", m.quantity)))?;
            if !v.is_finite() {
                return Err(self.at_line(i, format!("{} is not finite here", m.quantity)));
            }
            out.push(v);
        }
        Ok(())
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
