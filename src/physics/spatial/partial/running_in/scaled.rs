//! A running-in of the linear wear law carried over to another wear rate by scaling its time:
//! the same steps, read at the times of the other rate (`fit::model` fits k to a running-in
//! trace with one running-in for every k it tries).

use crate::physics::spatial::partial::Setup;
use crate::physics::spatial::partial::running_in::{RunningIn, Sample, Snapshot, Stepping};

impl RunningIn {
    /// The running-in of `setup`, a problem of the linear wear law that differs from this one's
    /// only in its wear rate k_w [m/(Pa s)] (`SpatialInputs::wear_rate`), from this one's steps.
    /// Under the linear law every step's contact problem has the operator K + c k_w with c a
    /// multiple of the step h (`Stepper::trial`), the steps are sized in decay times 1/beta_min
    /// with beta proportional to k_w, the wear depth is k_w pbar t, and the closed form after
    /// complete contact decays with k_w t: the running-in depends on k_w only through k_w t.
    /// So the state at t under k_w is this one's at t k_w/k_w(here): the same steps and shapes,
    /// every time multiplied by k_w(here)/k_w and every rate (the slope U', beta_min) divided by
    /// it; [`RunningIn::state_at`] then replays the same steps as a running-in of `setup` from
    /// t = 0 would take, to the round-off of the scaled times. None for a nonlinear law (whose
    /// running-in is stepped to the time asked), or where either wear rate is not positive.
    pub(crate) fn scaled_to(&self, setup: &Setup) -> Option<RunningIn> {
        let (here, there) = (self.setup.inputs.wear_rate(), setup.inputs.wear_rate());
        let linear = self.setup.inputs.linear_wear() && setup.inputs.linear_wear();
        let positive = here > 0.0 && there > 0.0 && here.is_finite() && there.is_finite();
        if !(linear && positive) {
            return None;
        }
        let factor = here / there;
        let time = |t: f64| t * factor;
        let rate = |r: f64| r / factor;
        let previous = |p: &Option<(f64, Vec<f64>)>| p.as_ref().map(|(t, u)| (time(*t), u.clone()));
        Some(RunningIn {
            setup: setup.clone(),
            stepping: self.stepping.map(|s| Stepping {
                rate: rate(s.rate),
                first: time(s.first),
                horizon: time(s.horizon),
                ..s
            }),
            samples: (self.samples.iter())
                .map(|s| Sample {
                    time: time(s.time),
                    ..*s
                })
                .collect(),
            time_to_complete: self.time_to_complete.map(time),
            complete_from: self.complete_from.map(time),
            rejected: self.rejected,
            end_shape: self.end_shape.clone(),
            end_previous: previous(&self.end_previous),
            end_contact: self.end_contact.clone(),
            end_slope: self.end_slope.iter().map(|v| rate(*v)).collect(),
            next_step: time(self.next_step),
            snapshots: (self.snapshots.iter())
                .map(|s| Snapshot {
                    step: s.step,
                    previous: previous(&s.previous),
                    shape: s.shape.clone(),
                    contact: s.contact.clone(),
                })
                .collect(),
            stride: self.stride,
        })
    }
}
