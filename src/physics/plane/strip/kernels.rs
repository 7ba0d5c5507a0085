//! The kernels the strip solver takes (`strip`): the exact strip's (docs/physics/plane.md section
//! 6, tabulated in `kernel_table`) or the wide-strip limit, through one trait, and the exact table kept
//! per Poisson ratio.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use crate::physics::elastic::chi_c12;
use crate::physics::plane::strip::kernel_table::StripKernels;

/// A kernel evaluated over a column of arguments: (z values, output).
pub type ColumnKernel<'a> = Box<dyn Fn(&[f64], &mut [f64]) + 'a>;

/// The regular kernels the solver uses (the exact strip, or the wide limit for checks).
pub trait Kernels {
    /// R2(z) = A2(z) - 1/z.
    fn r2(&self, z: f64) -> f64;
    /// chi B12(z).
    fn chi_b12(&self, z: f64) -> f64;
    /// chi l12(z).
    fn chi_l12(&self, z: f64) -> f64;
    /// R2(z) + mu chi B12(z).
    fn regular(&self, z: f64, mu: f64) -> f64 {
        self.r2(z) + mu * self.chi_b12(z)
    }
    /// R2 + mu chi B12 for one mu, as a function filling a column of values at the z of a
    /// column (built once per collocation system).
    fn regular_columns(&self, mu: f64) -> ColumnKernel<'_> {
        Box::new(move |zs, out| {
            for (o, z) in out.iter_mut().zip(zs) {
                *o = self.regular(*z, mu);
            }
        })
    }
}

impl Kernels for StripKernels {
    fn r2(&self, z: f64) -> f64 {
        StripKernels::r2(self, z)
    }
    fn chi_b12(&self, z: f64) -> f64 {
        StripKernels::chi_b12(self, z)
    }
    fn chi_l12(&self, z: f64) -> f64 {
        StripKernels::chi_l12(self, z)
    }
    fn regular_columns(&self, mu: f64) -> ColumnKernel<'_> {
        let regular = self.regular_for(mu);
        Box::new(move |zs, out| regular.column(zs, out))
    }
}

/// The wide-strip limit of the kernels: R2 -> 0, chi B12 -> chi c12, chi l12(z) -> chi c12 z
/// (section 4's kernel (4.1)); with it the solver must reproduce the wide closed form.
pub struct WideLimit {
    /// chi c12(nu).
    pub chi_c12: f64,
}

impl Kernels for WideLimit {
    fn r2(&self, _: f64) -> f64 {
        0.0
    }
    fn chi_b12(&self, _: f64) -> f64 {
        self.chi_c12
    }
    fn chi_l12(&self, z: f64) -> f64 {
        self.chi_c12 * z
    }
}

impl WideLimit {
    /// The limit for a Poisson ratio.
    pub fn new(nu: f64) -> WideLimit {
        WideLimit {
            chi_c12: chi_c12(nu),
        }
    }
}

/// The kernel table for nu, built once per nu and kept (a few tables at most).
pub fn kernels_for(nu: f64) -> Arc<StripKernels> {
    static CACHE: OnceLock<Mutex<HashMap<u64, Arc<StripKernels>>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
    let mut map = cache
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    if let Some(k) = map.get(&nu.to_bits()) {
        return Arc::clone(k);
    }
    if map.len() >= 4 {
        map.clear();
    }
    let k = Arc::new(StripKernels::new(nu));
    map.insert(nu.to_bits(), Arc::clone(&k));
    k
}
