//! Synthetic measurements: the model's values at given x with Gaussian noise of a known standard
//! deviation, from a seeded generator (SplitMix64, Steele, Lea & Flood (2014); normal deviates by
//! the Box-Muller transform, Box & Muller (1958)), so that the same seed gives the same data on
//! every machine. For tests of the fit and for the bundled teaching datasets, which say that
//! they are synthetic.

use crate::physics::spatial::surface::SplitMix64;
use crate::preset::{Key, Preset};
use crate::sweeps::{QuantityKey, point};

/// A source of standard normal deviates.
pub struct Normal {
    rng: SplitMix64,
}

impl Normal {
    /// The deviates of `seed`.
    pub fn new(seed: u64) -> Normal {
        Normal {
            rng: SplitMix64::new(seed),
        }
    }

    /// The next deviate: sqrt(-2 ln u1) cos(2 pi u2), with u1 in (0, 1].
    pub fn deviate(&mut self) -> f64 {
        let u1 = 1.0 - self.rng.next_unit();
        let u2 = self.rng.next_unit();
        (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
    }
}

/// The model's `quantity` at each x of parameter `x` (the preset's other values as they are),
/// plus `sd` times a standard normal deviate from `seed`.
pub fn measure(
    preset: &Preset,
    x: Key,
    xs: &[f64],
    quantity: QuantityKey,
    sd: f64,
    seed: u64,
) -> Result<Vec<f64>, String> {
    let mut noise = Normal::new(seed);
    xs.iter()
        .map(|v| {
            let mut at = preset.clone();
            at.set(x, *v)?;
            let p = point::solve(&at).map_err(|e| e.to_string())?;
            Ok(quantity.value(&p)? + sd * noise.deviate())
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deviates_have_mean_zero_and_unit_variance() {
        let mut n = Normal::new(7);
        let draws: Vec<f64> = (0..20_000).map(|_| n.deviate()).collect();
        let mean = draws.iter().sum::<f64>() / draws.len() as f64;
        let var = draws.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / draws.len() as f64;
        // standard errors of the mean and the variance of 20000 normal draws: 0.007 and 0.01
        assert!(mean.abs() < 0.03, "{mean}");
        assert!((var - 1.0).abs() < 0.04, "{var}");
    }
}
