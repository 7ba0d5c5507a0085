//! The spatial problem's dimensionless groups, of one harmonic or of the whole contact; the
//! formulas are those of `docs/physics/spatial.md`. The sweeps' quantity table and the explorer's
//! dimensionless view both evaluate these.

use crate::physics::spatial::SpatialSolution;

/// kh: the harmonic's wavenumber k = |(wx, wy)| [rad/m] times the layer thickness h [m]; below
/// about 1 the layer is thin for this wave, above about 3 it acts as a half-space. +inf on a
/// half-space (h = inf).
pub fn kh(k: f64, h: f64) -> f64 {
    k * h
}

/// beta t: the decay rate beta = k V A_c/M^2 [1/s] times the time t [s], the decay exponent
/// A(t)/A(0) = e^(-beta t) (`docs/physics/spatial.md`); without friction beta t = k V t/A_c.
pub fn decay_exponent(decay_rate: f64, time: f64) -> f64 {
    decay_rate * time
}

/// A/(M pbar): the pressure amplitude A/M [Pa] of a harmonic of shape amplitude A [m] over the
/// mean pressure pbar [Pa]; the contact is surely complete while these sum below 1.
pub fn pressure_ratio(amplitude: f64, pressure_per_amplitude: f64, mean_pressure: f64) -> f64 {
    amplitude * pressure_per_amplitude / mean_pressure
}

/// The sum over the harmonics of A/(M pbar), 1 - (pbar - sum A/M)/pbar: the contact is surely
/// complete while it is below 1 (the lower bound of the pressure is then positive).
pub fn pressure_ratio_sum(s: &SpatialSolution) -> f64 {
    s.harmonics
        .iter()
        .map(|h| {
            pressure_ratio(
                h.state.amplitude,
                h.evolution.pressure_per_amplitude(),
                s.inputs.mean_pressure,
            )
        })
        .sum()
}
