//! The spatial solution's physical checks, passed before anyone sees it: exit 0 means right. A
//! solution that fails one is `SolveError::NoSolution` naming the failed check (exit 3 on the
//! command line), never a number with a warning. They run inside `spatial::solve` and
//! `spatial::state_at`.

use crate::physics::spatial::SpatialSolution;
use crate::physics::{SolveError, check_finite};

/// The spatial solution's checks: every number finite, every layer compliance positive, and the
/// vertical force on the punch P = pbar - mu psi positive (mu* = T/P needs it).
pub fn check(sol: &SpatialSolution) -> Result<(), SolveError> {
    let what = "the spatial solution";
    for (n, h) in sol.harmonics.iter().enumerate() {
        let ev = &h.evolution;
        check_finite(
            &format!("harmonic {} of {what}", n + 1),
            &[
                ("M", ev.m),
                ("1/M", 1.0 / ev.m),
                ("decay rate", ev.decay_rate),
                ("phase rate", ev.phase_rate),
                ("drift velocity", ev.drift_velocity),
                ("phase lead", ev.phase_lead),
                ("amplitude", h.state.amplitude),
                ("phase_x", h.state.phase_x),
            ],
        )?;
        if ev.response.a.is_nan() || ev.response.a <= 0.0 {
            return Err(SolveError::NoSolution(format!(
                "harmonic {} of {what} fails a check: the layer's normal compliance at \
                 k = {:.4e} rad/m is {:e} m/Pa, not positive (round-off of the layer functions)",
                n + 1,
                h.initial.wavenumber(),
                ev.response.a
            )));
        }
    }
    check_finite(
        what,
        &[
            ("psi", sol.psi),
            ("P", sol.load),
            ("T", sol.tangential),
            ("mu*", sol.mu_star),
        ],
    )?;
    if sol.load <= 0.0 {
        return Err(SolveError::NoSolution(format!(
            "{what} fails a check: the vertical force on the punch P = pbar - mu psi = {:.4e} Pa \
             is not positive (friction on the slopes outweighs the mean pressure {:.4e} Pa), so \
             mu* = T/P is undefined",
            sol.load, sol.inputs.mean_pressure
        )));
    }
    Ok(())
}
