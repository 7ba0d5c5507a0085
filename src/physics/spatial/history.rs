//! Time histories (A_n(t), mu*(t)) and the mu*(pbar) sweep of the spatial problem.

use serde::Serialize;

use crate::physics::spatial::harmonic::{Evolution, Harmonic, evolution};
use crate::physics::spatial::{SpatialInputs, solve_with};
use crate::physics::{Spacing, SweepRange, limits};

/// Values at evenly spaced times over [0, duration].
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct History {
    /// t [s].
    pub time: Vec<f64>,
    /// A_n(t) [m], one vector per harmonic.
    pub amplitudes: Vec<Vec<f64>>,
    /// mu*(t).
    pub mu_star: Vec<f64>,
}

/// The history over [0, duration] at `points` >= 2 times.
pub fn history(
    inputs: &SpatialInputs,
    evolutions: &[Evolution],
    duration: f64,
    points: usize,
) -> History {
    let time = Spacing::Linear.points(0.0, duration, points);
    let sols: Vec<_> = time
        .iter()
        .map(|&t| solve_with(inputs, evolutions, t))
        .collect();
    History {
        amplitudes: (0..inputs.harmonics().len())
            .map(|n| {
                sols.iter()
                    .map(|s| s.harmonics[n].state.amplitude)
                    .collect()
            })
            .collect(),
        mu_star: sols.iter().map(|s| s.mu_star).collect(),
        time,
    }
}

/// mu* against pbar at one time; None where contact is not complete or P <= 0.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MeanPressureSweep {
    /// pbar [Pa].
    pub mean_pressure: Vec<f64>,
    /// P = pbar - mu psi [Pa].
    pub load: Vec<f64>,
    /// mu*, null where p_min <= 0 or P <= 0.
    pub mu_star: Vec<Option<f64>>,
}

/// Sweeps pbar at time t. psi does not depend on pbar, and p_min = pbar + (p_min - pbar) at the
/// inputs' own pbar, so `oscillation_min` (p_min - pbar, from the contact check) decides where
/// contact is complete. A range outside `limits::MEAN_PRESSURE` gives an empty sweep.
pub fn pressure_sweep(
    inputs: &SpatialInputs,
    evolutions: &[Evolution],
    time: f64,
    oscillation_min: f64,
    spec: &SweepRange,
) -> MeanPressureSweep {
    let pressures = match spec.check(["pressure_min", "pressure_max"], &limits::MEAN_PRESSURE) {
        Ok(()) => spec.values(),
        Err(_) => Vec::new(),
    };
    let psi = solve_with(inputs, evolutions, time).psi;
    let mu = inputs.friction.coefficient;
    MeanPressureSweep {
        load: pressures.iter().map(|p| p - mu * psi).collect(),
        mu_star: pressures
            .iter()
            .map(|p| {
                let load = p - mu * psi;
                (p + oscillation_min > 0.0 && load > 0.0).then(|| mu + (1.0 + mu * mu) * psi / load)
            })
            .collect(),
        mean_pressure: pressures,
    }
}

/// Drift velocity against wavenumber for a few directions of the wave vector (dispersion).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Dispersion {
    /// The abscissa: kh for a layer, k [rad/m] for the half-space (where c does not depend on k).
    pub k: Vec<f64>,
    /// True when `k` holds kh (finite thickness).
    pub scaled_by_thickness: bool,
    /// Directions of the wave vector from the sliding line [rad].
    pub angles: Vec<f64>,
    /// c [m/s] for each direction, along `k`.
    pub drift_velocity: Vec<Vec<f64>>,
}

/// c against k (or kh) from a third of the smallest to ten times the largest wavenumber of the
/// harmonics, for wave vectors at 0, 45 and 75 degrees to the sliding line.
pub fn dispersion(inputs: &SpatialInputs, points: usize) -> Dispersion {
    let h = inputs.material.thickness;
    let ks = inputs.harmonics().iter().map(Harmonic::wavenumber);
    let (k_lo, k_hi) = ks.fold((f64::INFINITY, 0.0f64), |(a, b), k| (a.min(k), b.max(k)));
    let scaled = h.is_finite();
    let unit = if scaled { h } else { 1.0 };
    let k = Spacing::Log.points(k_lo * unit / 3.0, k_hi * unit * 10.0, points);
    let angles: Vec<f64> = [0.0f64, 45.0, 75.0]
        .iter()
        .map(|d| d.to_radians())
        .collect();
    let drift_velocity = angles
        .iter()
        .map(|a| {
            k.iter()
                .map(|x| {
                    let kk = x / unit;
                    let wave = Harmonic {
                        amplitude: 0.0,
                        wavenumber_x: kk * a.cos(),
                        wavenumber_y: kk * a.sin(),
                        phase_x: 0.0,
                        phase_y: 0.0,
                    };
                    evolution(
                        &inputs.material,
                        &inputs.friction,
                        inputs.wear_rate(),
                        &wave,
                    )
                    .drift_velocity
                })
                .collect()
        })
        .collect();
    Dispersion {
        k,
        scaled_by_thickness: scaled,
        angles,
        drift_velocity,
    }
}
