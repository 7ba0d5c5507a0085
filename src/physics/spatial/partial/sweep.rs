//! mu* against the mean pressure over the whole range: partial contact below
//! the complete-contact load, the closed form above it, one curve.

use std::ops::ControlFlow;

use serde::Serialize;

use crate::physics::spatial::partial::Setup;
use crate::physics::spatial::partial::running_in::{Stopped, cancelled_or};
use crate::physics::stop::Stop;

/// mu* and the contact against pbar for one shape.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LoadCurve {
    /// pbar [Pa], as given.
    pub mean_pressure: Vec<f64>,
    /// P = pbar - mu psi - tau0 Delta [Pa].
    pub load: Vec<f64>,
    /// mu*, null where P <= 0 (far beyond the small-slope theory).
    pub mu_star: Vec<Option<f64>>,
    /// Fraction of the cell in contact.
    pub contact_fraction: Vec<f64>,
    /// The smallest pbar [Pa] with complete contact: -min over the nodes of (p_cc - pbar).
    pub complete_mean_pressure: f64,
}

/// mu* of the zero-mean shape `shape` [m] (on `setup`'s grid) at each mean pressure of
/// `pressures` [Pa] (> 0), each solve warm-started from the previous contact set. `progress` gets
/// the fraction of the points done; `ControlFlow::Break` abandons the work, and so does `stop`,
/// asked inside each solve (before every active-set iteration and every product of its linear solve).
pub fn load_curve(
    setup: &Setup,
    shape: &[f64],
    pressures: &[f64],
    stop: Stop,
    progress: &mut dyn FnMut(f64) -> ControlFlow<()>,
) -> Result<LoadCurve, Stopped> {
    let mut op = setup.operator();
    let mut oscillation = vec![0.0; shape.len()];
    op.inverse(shape, &mut oscillation, 0.0);
    let mut curve = LoadCurve {
        mean_pressure: pressures.to_vec(),
        load: Vec::with_capacity(pressures.len()),
        mu_star: Vec::with_capacity(pressures.len()),
        contact_fraction: Vec::with_capacity(pressures.len()),
        complete_mean_pressure: -oscillation.iter().copied().fold(f64::INFINITY, f64::min),
    };
    let mut contact: Option<Vec<bool>> = None;
    for (i, &pbar) in pressures.iter().enumerate() {
        let mut at = setup.clone();
        at.inputs.mean_pressure = pbar;
        at.inputs.validate()?;
        let state = at
            .unchecked_state(&mut op, shape.to_vec(), 0.0, contact.as_deref(), stop)
            .map_err(|why| cancelled_or(why, stop))?;
        let o = state.outputs;
        curve.load.push(o.normal_force);
        curve
            .mu_star
            .push((o.normal_force > 0.0).then_some(o.mu_star));
        curve.contact_fraction.push(state.outputs.contact_fraction);
        contact = Some(state.contact());
        if progress((i + 1) as f64 / pressures.len() as f64).is_break() {
            return Err(Stopped::Cancelled);
        }
    }
    Ok(curve)
}
