//! The discrete spectrum of a height map and its radially averaged power spectral density
//! (docs/physics/spatial-surface.md section 2). The transforms use rustfft's scalar planner, whose
//! arithmetic does not depend on the CPU's vector extensions.

use std::f64::consts::PI;

use rustfft::FftPlannerScalar;
use rustfft::num_complex::Complex;

use super::Surface;

pub(crate) type C64 = Complex<f64>;

/// In-place 2-D DFT of an nx x ny row-major array: H_k = sum_n h_n e^{-2 pi i k.n/N} (forward),
/// or the unnormalised inverse with e^{+...}.
pub(crate) fn fft2(data: &mut [C64], nx: usize, ny: usize, inverse: bool) {
    let mut planner = FftPlannerScalar::<f64>::new();
    let (row_fft, col_fft) = if inverse {
        (planner.plan_fft_inverse(nx), planner.plan_fft_inverse(ny))
    } else {
        (planner.plan_fft_forward(nx), planner.plan_fft_forward(ny))
    };
    data.chunks_exact_mut(nx)
        .for_each(|row| row_fft.process(row));
    if ny > 1 {
        let mut column = vec![C64::default(); ny];
        for i in 0..nx {
            for (j, c) in column.iter_mut().enumerate() {
                *c = data[j * nx + i];
            }
            col_fft.process(&mut column);
            for (j, c) in column.iter().enumerate() {
                data[j * nx + i] = *c;
            }
        }
    }
}

/// The spectrum H_k of a surface's heights (forward DFT, unnormalised).
pub(crate) fn spectrum(surface: &Surface) -> Vec<C64> {
    let mut data: Vec<C64> = surface.heights.iter().map(|&h| C64::new(h, 0.0)).collect();
    fft2(&mut data, surface.nx, surface.ny, false);
    data
}

/// The signed mode number of DFT index k on an n-point axis: k for k <= n/2, k - n above.
pub(crate) fn signed_mode(k: usize, n: usize) -> i64 {
    if 2 * k <= n {
        k as i64
    } else {
        k as i64 - n as i64
    }
}

/// True for the Nyquist index of an even axis (its wave has no defined phase or derivative).
pub(crate) fn is_nyquist(k: usize, n: usize) -> bool {
    n % 2 == 0 && 2 * k == n
}

/// Wave vector (qx, qy) [rad/m] of DFT index (kx, ky).
pub(crate) fn wave_vector(surface: &Surface, kx: usize, ky: usize) -> (f64, f64) {
    let qx = 2.0 * PI * signed_mode(kx, surface.nx) as f64 / surface.lx;
    let qy = if surface.ny > 1 {
        2.0 * PI * signed_mode(ky, surface.ny) as f64 / surface.ly
    } else {
        0.0
    };
    (qx, qy)
}

/// The wave vectors (qx, qy) [rad/m] of the modes of `surface` whose amplitude |H_k| exceeds
/// `relative` times the largest, one of each conjugate pair (qx > 0, or qx = 0 and qy >= 0).
pub fn mode_wave_vectors(surface: &Surface, relative: f64) -> Vec<(f64, f64)> {
    let h = spectrum(surface);
    let largest = h.iter().map(|c| c.norm()).fold(0.0, f64::max);
    let mut modes = Vec::new();
    for ky in 0..surface.ny {
        for kx in 0..surface.nx {
            let (qx, qy) = wave_vector(surface, kx, ky);
            let half = qx > 0.0 || (qx == 0.0 && qy > 0.0);
            if half && h[ky * surface.nx + kx].norm() > relative * largest {
                modes.push((qx, qy));
            }
        }
    }
    modes
}

/// One point of the radially averaged PSD.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PsdPoint {
    /// Mean wavenumber |q| of the modes in the bin [rad/m].
    pub wavenumber: f64,
    /// Mean C(q) of those modes: [m^4] for a map, C(q) = lx ly |H_k|^2/(nx ny)^2, so that
    /// h_rms^2 = sum_k C(q_k)/(lx ly); [m^3] for a profile, C1(q) = lx |H_k|^2/nx^2, so that
    /// h_rms^2 = sum_k C1(q_k)/lx.
    pub psd: f64,
}

/// The PSD averaged over `bins` logarithmic bins of |q| between the smallest and the largest
/// nonzero wavenumber of the grid (empty bins left out; Nyquist lines excluded).
pub fn radial_psd(surface: &Surface, bins: usize) -> Vec<PsdPoint> {
    let spectrum = spectrum(surface);
    let n = (surface.nx * surface.ny) as f64;
    let area = if surface.is_profile() {
        surface.lx
    } else {
        surface.lx * surface.ly
    };
    let modes: Vec<(f64, f64)> = (0..surface.ny)
        .flat_map(|ky| (0..surface.nx).map(move |kx| (kx, ky)))
        .filter(|&(kx, ky)| !is_nyquist(kx, surface.nx) && !is_nyquist(ky, surface.ny))
        .map(|(kx, ky)| {
            let (qx, qy) = wave_vector(surface, kx, ky);
            let h = spectrum[ky * surface.nx + kx];
            (qx.hypot(qy), area * h.norm_sqr() / (n * n))
        })
        .filter(|&(q, _)| q > 0.0)
        .collect();
    let (q_min, q_max) = modes
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), &(q, _)| {
            (lo.min(q), hi.max(q))
        });
    if modes.is_empty() || bins == 0 {
        return Vec::new();
    }
    let span = (q_max / q_min).ln().max(f64::EPSILON);
    let mut sums = vec![(0.0, 0.0, 0usize); bins];
    for &(q, c) in &modes {
        let b = (((q / q_min).ln() / span) * bins as f64) as usize;
        let bin = &mut sums[b.min(bins - 1)];
        bin.0 += q;
        bin.1 += c;
        bin.2 += 1;
    }
    sums.into_iter()
        .filter(|s| s.2 > 0)
        .map(|(q, c, count)| PsdPoint {
            wavenumber: q / count as f64,
            psd: c / count as f64,
        })
        .collect()
}
