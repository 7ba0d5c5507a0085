//! The discrete operators of docs/physics/spatial-partial.md sections 1.1 and 2: Fourier
//! multipliers on the nodes of the cell, applied with a real FFT along x and a complex FFT along y.
//!
//! With u_z^ = -A p^ + i sx B tau^ (docs/physics/spatial.md section 2) and tau = mu p + tau0 1_C:
//!   S^ = A,  W^ = -i mu sx B,  T^ = i sx B,  K = S + W,  all zero at k = 0.
//! The odd multipliers W and T (and d/dx) are zero at the x-Nyquist wavenumber (section 2), so that
//! every operator maps real fields to real fields exactly as analysed.

use std::f64::consts::PI;
use std::sync::Arc;

use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};

use crate::physics::Material;
use crate::physics::spatial::harmonic::layer_response;
use crate::physics::spatial::partial::grid::Grid;

type C64 = Complex<f64>;

/// A diagonal [m/Pa] added to K: c dt k_w in an implicit wear step.
#[derive(Clone, Copy, Debug)]
pub enum Diagonal<'a> {
    /// The same c >= 0 at every node (0 for a plain contact; the linear wear law's step).
    Uniform(f64),
    /// c_i >= 0 at node i (a Newton iterate of the step of a nonlinear wear law).
    Nodal(&'a [f64]),
}

impl Diagonal<'_> {
    /// Its mean over the nodes [m/Pa]: the uniform stand-in of the preconditioner.
    pub fn mean(&self) -> f64 {
        match self {
            Diagonal::Uniform(c) => *c,
            Diagonal::Nodal(c) => c.iter().sum::<f64>() / c.len() as f64,
        }
    }
}

/// The multipliers at every spectral node, stored column by column: index kx ny + j for
/// kx = 0..=nx/2 (real FFT along x) and j = 0..ny (complex FFT along y).
#[derive(Clone, Debug, PartialEq)]
pub struct Multipliers {
    /// The grid.
    pub grid: Grid,
    /// A(k) [m/Pa]: S^ (0 at k = 0).
    normal: Vec<f64>,
    /// mu sx B(k) [m/Pa]: W^ = -i coupling (0 at k = 0 and at the x-Nyquist).
    coupling: Vec<f64>,
    /// sx B(k) [m/Pa]: T^ = i shear (0 at k = 0 and at the x-Nyquist).
    shear: Vec<f64>,
    /// wx [rad/m] for d/dx (0 at the x-Nyquist).
    wx: Vec<f64>,
}

impl Multipliers {
    /// The multipliers of the layer `material` under friction coefficient `mu` on `grid`.
    pub fn new(material: &Material, mu: f64, grid: Grid) -> Multipliers {
        let nkx = grid.nx / 2 + 1;
        let size = nkx * grid.ny;
        let (mut normal, mut coupling) = (vec![0.0; size], vec![0.0; size]);
        let (mut shear, mut wxs) = (vec![0.0; size], vec![0.0; size]);
        for kx in 0..nkx {
            let nyquist = grid.nx % 2 == 0 && kx == grid.nx / 2;
            let wx = 2.0 * PI * kx as f64 / grid.lx;
            for j in 0..grid.ny {
                let l = if 2 * j <= grid.ny {
                    j as f64
                } else {
                    j as f64 - grid.ny as f64
                };
                let k = wx.hypot(2.0 * PI * l / grid.ly);
                let i = kx * grid.ny + j;
                if k == 0.0 {
                    continue;
                }
                let r = layer_response(material, k);
                normal[i] = r.a;
                if !nyquist {
                    shear[i] = wx / k * r.b;
                    coupling[i] = mu * shear[i];
                    wxs[i] = wx;
                }
            }
        }
        Multipliers {
            grid,
            normal,
            coupling,
            shear,
            wx: wxs,
        }
    }

    /// max A over the grid's modes [m/Pa] (the scale of the gap per unit pressure).
    pub fn max_normal(&self) -> f64 {
        self.normal.iter().copied().fold(0.0, f64::max)
    }

    /// tan phi_max = max over the grid's modes of |mu sx B/A| (section 1.2).
    pub fn tan_phi_max(&self) -> f64 {
        self.normal
            .iter()
            .zip(&self.coupling)
            .filter(|(a, _)| **a > 0.0)
            .map(|(a, c)| (c / a).abs())
            .fold(0.0, f64::max)
    }
}

/// The 2-D real FFT with its buffers.
struct Fft2 {
    nx: usize,
    ny: usize,
    r2c: Arc<dyn RealToComplex<f64>>,
    c2r: Arc<dyn ComplexToReal<f64>>,
    forward: Arc<dyn Fft<f64>>,
    inverse: Arc<dyn Fft<f64>>,
    /// The rows' spectra, row-major (j nkx + kx).
    rows: Vec<C64>,
    /// The same, column-major (kx ny + j): the layout of the multipliers.
    spectrum: Vec<C64>,
    row: Vec<f64>,
    scratch: Vec<C64>,
}

impl Fft2 {
    fn new(grid: &Grid) -> Fft2 {
        let (nx, ny) = (grid.nx, grid.ny);
        let r2c = RealFftPlanner::<f64>::new().plan_fft_forward(nx);
        let c2r = RealFftPlanner::<f64>::new().plan_fft_inverse(nx);
        let mut planner = FftPlanner::<f64>::new();
        let forward = planner.plan_fft_forward(ny);
        let inverse = planner.plan_fft_inverse(ny);
        let scratch_len = [
            r2c.get_scratch_len(),
            c2r.get_scratch_len(),
            forward.get_inplace_scratch_len(),
            inverse.get_inplace_scratch_len(),
        ]
        .into_iter()
        .max()
        .unwrap_or(0);
        Fft2 {
            nx,
            ny,
            rows: vec![C64::default(); (nx / 2 + 1) * ny],
            spectrum: vec![C64::default(); (nx / 2 + 1) * ny],
            row: vec![0.0; nx],
            scratch: vec![C64::default(); scratch_len],
            r2c,
            c2r,
            forward,
            inverse,
        }
    }

    /// out = F^-1[m F[f]], with the multiplier m(i) at spectral index i. The rows' spectra are
    /// transposed (cache-blocked) so that the y transforms run on contiguous columns; a grid of
    /// one row (or one column) skips the transforms of length 1.
    fn filter(&mut self, f: &[f64], out: &mut [f64], m: impl Fn(usize) -> C64) {
        let (nx, ny) = (self.nx, self.ny);
        let nkx = nx / 2 + 1;
        let scale = 1.0 / (nx * ny) as f64;
        if nx == 1 {
            for (s, v) in self.spectrum.iter_mut().zip(f) {
                *s = C64::new(*v, 0.0);
            }
            self.columns(&m);
            for (o, s) in out.iter_mut().zip(&self.spectrum) {
                *o = s.re * scale;
            }
            return;
        }
        for j in 0..ny {
            self.row.copy_from_slice(&f[j * nx..(j + 1) * nx]);
            self.r2c
                .process_with_scratch(
                    &mut self.row,
                    &mut self.rows[j * nkx..(j + 1) * nkx],
                    &mut self.scratch,
                )
                .expect("buffer lengths come from the plan");
        }
        if ny == 1 {
            for (i, v) in self.rows.iter_mut().enumerate() {
                *v *= m(i);
            }
        } else {
            transpose::transpose(&self.rows, &mut self.spectrum, nkx, ny);
            self.columns(&m);
            transpose::transpose(&self.spectrum, &mut self.rows, ny, nkx);
        }
        for j in 0..ny {
            let row_spectrum = &mut self.rows[j * nkx..(j + 1) * nkx];
            // the zero and Nyquist bins of a real signal are real: drop the round-off
            row_spectrum[0].im = 0.0;
            if nx % 2 == 0 {
                row_spectrum[nx / 2].im = 0.0;
            }
            self.c2r
                .process_with_scratch(row_spectrum, &mut self.row, &mut self.scratch)
                .expect("buffer lengths come from the plan; the invalid bins were zeroed");
            for (o, r) in out[j * nx..(j + 1) * nx].iter_mut().zip(&self.row) {
                *o = r * scale;
            }
        }
    }

    /// The y transform of every column of `spectrum`, the multiplier, and the inverse transform.
    fn columns(&mut self, m: &impl Fn(usize) -> C64) {
        self.forward
            .process_with_scratch(&mut self.spectrum, &mut self.scratch);
        for (i, v) in self.spectrum.iter_mut().enumerate() {
            *v *= m(i);
        }
        self.inverse
            .process_with_scratch(&mut self.spectrum, &mut self.scratch);
    }
}

/// The operators on one grid: shared multipliers and this operator's own FFT buffers.
pub struct Operator {
    /// The multipliers.
    pub multipliers: Arc<Multipliers>,
    fft: Fft2,
    /// A - i mu sx B at every spectral node.
    kernel: Vec<C64>,
    /// c and 1/(A - i mu sx B + c) (0 at k = 0), for the last c asked.
    inverse: (f64, Vec<C64>),
}

impl Operator {
    /// An operator (with fresh buffers) for `multipliers`.
    pub fn new(multipliers: Arc<Multipliers>) -> Operator {
        let m = &multipliers;
        let kernel: Vec<C64> = (0..m.normal.len())
            .map(|i| C64::new(m.normal[i], -m.coupling[i]))
            .collect();
        Operator {
            fft: Fft2::new(&multipliers.grid),
            inverse: (f64::NAN, Vec::new()),
            kernel,
            multipliers,
        }
    }

    /// The grid.
    pub fn grid(&self) -> Grid {
        self.multipliers.grid
    }

    /// out = K[p] + c p [m] for p [Pa]: the gap change (K excludes the mean; c p includes it).
    pub fn apply(&mut self, p: &[f64], out: &mut [f64], c: f64) {
        let kernel = &self.kernel;
        self.fft.filter(p, out, |i| kernel[i]);
        if c != 0.0 {
            out.iter_mut().zip(p).for_each(|(o, p)| *o += c * p);
        }
    }

    /// out = (K + D)[p] [m] for p [Pa] with the diagonal D (uniform or per node).
    pub fn apply_diagonal(&mut self, p: &[f64], out: &mut [f64], d: Diagonal) {
        match d {
            Diagonal::Uniform(c) => self.apply(p, out, c),
            Diagonal::Nodal(c) => {
                self.apply(p, out, 0.0);
                out.iter_mut()
                    .zip(p.iter().zip(c))
                    .for_each(|(o, (p, c))| *o += c * p);
            }
        }
    }

    /// out = (K + c)^-1 [u] on the modes k != 0, zero mean [Pa] for u [m].
    pub fn inverse(&mut self, u: &[f64], out: &mut [f64], c: f64) {
        if self.inverse.0 != c {
            let normal = &self.multipliers.normal;
            let inverse = self
                .kernel
                .iter()
                .zip(normal)
                .map(|(k, a)| {
                    if *a == 0.0 {
                        C64::default()
                    } else {
                        (k + c).inv()
                    }
                })
                .collect();
            self.inverse = (c, inverse);
        }
        let inverse = &self.inverse.1;
        self.fft.filter(u, out, |i| inverse[i]);
    }

    /// out = S[p] [m]: the symmetric part of K.
    pub fn symmetric(&mut self, p: &[f64], out: &mut [f64]) {
        let m = &self.multipliers;
        self.fft.filter(p, out, |i| C64::new(m.normal[i], 0.0));
    }

    /// out = T[f] [m/Pa per unit of f]: the normal displacement into the punch, with sign as in
    /// the gap, under a shear field f.
    pub fn shear(&mut self, f: &[f64], out: &mut [f64]) {
        let m = &self.multipliers;
        self.fft.filter(f, out, |i| C64::new(0.0, m.shear[i]));
    }

    /// out = d f/dx, spectral (exact for the sampled harmonics).
    pub fn derivative_x(&mut self, f: &[f64], out: &mut [f64]) {
        let m = &self.multipliers;
        self.fft.filter(f, out, |i| C64::new(0.0, m.wx[i]));
    }

    /// The closed-form wear of a shape in complete contact (section 5): every Fourier mode of u
    /// multiplied by exp(-k_w t/(A - i mu sx B)), `wear_time` = k_w t [m/Pa].
    pub fn decay(&mut self, u: &[f64], out: &mut [f64], wear_time: f64) {
        let (m, kernel) = (&self.multipliers, &self.kernel);
        self.fft.filter(u, out, |i| {
            if m.normal[i] == 0.0 {
                C64::default()
            } else {
                (-wear_time * kernel[i].inv()).exp()
            }
        });
    }
}
