//! The running-in as time series for the charts: the stepped states, then the closed form.

use serde::Serialize;

use crate::physics::SolveError;
use crate::physics::spatial::partial::running_in::RunningIn;
use crate::physics::spatial::partial::state::Outputs;
use crate::physics::stop::Stop;

/// The outputs against time over [0, duration].
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct History {
    /// t [s], increasing.
    pub time: Vec<f64>,
    /// Fraction of the cell in contact.
    pub contact_fraction: Vec<f64>,
    /// p_max [Pa].
    pub max_pressure: Vec<f64>,
    /// mu*.
    pub mu_star: Vec<f64>,
    /// psi [Pa].
    pub psi: Vec<f64>,
    /// Mean gap [m].
    pub mean_gap: Vec<f64>,
    /// min over the nodes of p_cc [Pa]: negative while contact is partial.
    pub min_pressure_complete: Vec<f64>,
    /// The simulated time to complete contact [s] (None: complete at t = 0, or not reached).
    pub time_to_complete: Option<f64>,
    /// The estimated time-stepping error of the last stepped state, relative to the rms of the
    /// shape at t = 0 ([`RunningIn::time_error`]; None when nothing is stepped).
    pub time_error: Option<f64>,
}

impl History {
    fn push(&mut self, time: f64, o: &Outputs) {
        self.time.push(time);
        self.contact_fraction.push(o.contact_fraction);
        self.max_pressure.push(o.max_pressure);
        self.mu_star.push(o.mu_star);
        self.psi.push(o.psi);
        self.mean_gap.push(o.mean_gap);
        self.min_pressure_complete.push(o.min_pressure_complete);
    }
}

impl RunningIn {
    /// The history over [0, duration] [s]: every stepped state up to `duration`, then, once
    /// contact is complete, `points` closed-form states evenly spaced up to `duration` (up to the
    /// first that is no longer complete, if the harmonics drift into phase again).
    pub fn history(&self, duration: f64, points: usize) -> Result<History, SolveError> {
        let mut h = History {
            time_to_complete: self.time_to_complete,
            time_error: self.time_error(f64::INFINITY),
            ..History::default()
        };
        self.samples
            .iter()
            .filter(|s| s.time <= duration)
            .for_each(|s| h.push(s.time, &s.outputs));
        let Some(from) = self.complete_from.filter(|from| *from < duration) else {
            return Ok(h);
        };
        let setup = &self.setup;
        let mut op = setup.operator();
        let k_w = setup.inputs.wear_rate();
        let end_shape = self.end_shape();
        let mut shape = vec![0.0; end_shape.len()];
        for i in 1..=points.max(1) {
            let t = from + (duration - from) * i as f64 / points.max(1) as f64;
            op.decay(end_shape, &mut shape, k_w * (t - from));
            let state = setup.state(&mut op, shape.clone(), t, None, Stop::Never)?;
            if !state.outputs.complete {
                break;
            }
            h.push(t, &state.outputs);
        }
        Ok(h)
    }
}
