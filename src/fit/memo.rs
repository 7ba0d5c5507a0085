//! The model's predictions kept by the point they were computed at, for a fit that asks again:
//! Levenberg-Marquardt evaluates the same point once for each damping it tries when the step
//! rounds to nothing (up to `lm`'s 40 trials near a minimum), and the profiles' refits start
//! where the last one stopped. The predictions of a point are a function of its coordinates, so
//! the kept ones are those a new solve would give, bit for bit.

use std::collections::HashMap;
use std::sync::Mutex;

use nalgebra::DVector;

/// Points kept at most: a fit evaluates a few hundred distinct points (about 500 for two
/// parameters with their profiles, each 20 values); beyond this the further ones are computed
/// and not kept.
pub const KEPT_POINTS: usize = 4096;

/// Predictions by point (the bits of each fitting coordinate).
#[derive(Debug, Default)]
pub struct Memo {
    kept: Mutex<HashMap<Vec<u64>, Vec<f64>>>,
}

impl Memo {
    /// The predictions at `theta`: the kept ones, else `compute`'s, kept when Ok (an error, a
    /// stop among them, is not kept: asked again, the model is asked again).
    pub fn get_or(
        &self,
        theta: &DVector<f64>,
        compute: impl FnOnce() -> Result<Vec<f64>, String>,
    ) -> Result<Vec<f64>, String> {
        let key: Vec<u64> = theta.iter().map(|c| c.to_bits()).collect();
        if let Some(known) = self.lock().get(&key) {
            return Ok(known.clone());
        }
        let values = compute()?;
        let mut kept = self.lock();
        if kept.len() < KEPT_POINTS {
            kept.insert(key, values.clone());
        }
        Ok(values)
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, HashMap<Vec<u64>, Vec<f64>>> {
        // a thread that panicked while holding the lock left whole entries only
        self.kept
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
    }
}

#[cfg(test)]
mod tests {
    use std::cell::Cell;

    use super::*;

    #[test]
    fn a_point_is_computed_once_and_an_error_every_time() {
        let memo = Memo::default();
        let calls = Cell::new(0);
        let at = DVector::from_vec(vec![0.3, -27.6]);
        let compute = || {
            calls.set(calls.get() + 1);
            Ok(vec![1.0, 2.0])
        };
        assert_eq!(memo.get_or(&at, compute), Ok(vec![1.0, 2.0]));
        assert_eq!(memo.get_or(&at, compute), Ok(vec![1.0, 2.0]));
        assert_eq!(calls.get(), 1);
        // the next representable coordinate is another point
        let next = DVector::from_vec(vec![0.3, f64::from_bits((-27.6f64).to_bits() + 1)]);
        memo.get_or(&next, compute).unwrap();
        assert_eq!(calls.get(), 2);
        let failing = || {
            calls.set(calls.get() + 1);
            Err("stopped".to_string())
        };
        let third = DVector::from_vec(vec![0.2, -27.6]);
        assert!(memo.get_or(&third, failing).is_err());
        assert!(memo.get_or(&third, failing).is_err());
        assert_eq!(calls.get(), 4);
        memo.get_or(&next, compute).unwrap();
        assert_eq!(calls.get(), 4);
    }
}
