//! Fields on a grid over the cell: pressure p, shape U and punch wear W.
//!
//! Every harmonic is separable, c sin(wx x + px) sin(wy y + py): a field is a sum of products of
//! an x-table and a y-table, i.e. the matrix product of an (H x n) and an (H x n) table. The
//! tables come from sines rotated along the uniform grid; the product is a small blocked kernel
//! (4 x 8 grid points in registers while every harmonic adds to them, tables packed so that it
//! reads them contiguously), with AVX2 and fused multiply-adds where the processor has them.

use crate::physics::spatial::{Cell, HarmonicSolution, Period, SpatialSolution};

/// One term c sin(wx x + px) sin(wy y + py) of a separable sum.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Term {
    pub c: f64,
    pub wx: f64,
    pub px: f64,
    pub wy: f64,
    pub py: f64,
}

impl Term {
    fn x_table(&self, xs: &[f64]) -> Vec<f64> {
        xs.iter()
            .map(|x| self.c * (self.wx * x + self.px).sin())
            .collect()
    }

    fn y_table(&self, ys: &[f64]) -> Vec<f64> {
        ys.iter().map(|y| (self.wy * y + self.py).sin()).collect()
    }
}

/// Points where a uniform table is evaluated: first + i step, i < count.
#[derive(Clone, Copy)]
struct Grid {
    first: f64,
    step: f64,
    count: usize,
}

impl Grid {
    fn points(self) -> Vec<f64> {
        (0..self.count)
            .map(|i| self.first + i as f64 * self.step)
            .collect()
    }

    /// c sin(w x_i + p) at every point: sines by the angle-addition rotation, restarted from a
    /// direct evaluation every RESTART points so that rounding grows over RESTART steps at most
    /// (within 1e-13 c on a 4096-point grid, tested).
    fn sines(self, c: f64, w: f64, p: f64) -> Vec<f64> {
        const RESTART: usize = 64;
        let (sd, cd) = (w * self.step).sin_cos();
        let mut out = Vec::with_capacity(self.count);
        let (mut s, mut co) = (0.0, 0.0);
        for i in 0..self.count {
            if i % RESTART == 0 {
                (s, co) = (w * (self.first + i as f64 * self.step) + p).sin_cos();
            } else {
                (s, co) = (s * cd + co * sd, co * cd - s * sd);
            }
            out.push(c * s);
        }
        out
    }
}

/// offset + sum of terms on the grid xs x ys, row-major (index j * xs.len() + i).
pub(crate) fn synthesize(terms: &[Term], offset: f64, xs: &[f64], ys: &[f64]) -> Vec<f64> {
    let y = Tables::new(terms, |t| t.y_table(ys));
    let [out] = products([(offset, &Tables::new(terms, |t| t.x_table(xs)))], &y);
    out
}

/// One table per term (its values at the grid points), stored term after term.
struct Tables {
    len: usize,
    values: Vec<f64>,
}

impl Tables {
    fn new(terms: &[Term], table: impl Fn(&Term) -> Vec<f64>) -> Tables {
        Tables::from_rows(terms.iter().map(table))
    }

    fn from_rows(rows: impl Iterator<Item = Vec<f64>>) -> Tables {
        let mut values = Vec::new();
        let mut len = 0;
        for row in rows {
            len = row.len();
            values.extend(row);
        }
        Tables { len, values }
    }

    fn count(&self) -> usize {
        self.values.len().checked_div(self.len).unwrap_or(0)
    }

    /// The tables cut into blocks of B points, each block holding its B values of term 0, then of
    /// term 1, ...: the kernel reads a block's terms from contiguous memory. The last block is
    /// padded with zeros.
    fn packed<const B: usize>(&self) -> Vec<[f64; B]> {
        let terms = self.count();
        let blocks = self.len.div_ceil(B);
        let mut out = vec![[0.0; B]; blocks * terms];
        for h in 0..terms {
            let table = &self.values[h * self.len..(h + 1) * self.len];
            for (b, chunk) in table.chunks(B).enumerate() {
                out[b * terms + h][..chunk.len()].copy_from_slice(chunk);
            }
        }
        out
    }
}

/// Rows and columns of the block of the grid that the inner loop keeps in registers.
const ROWS: usize = 4;
const COLS: usize = 8;

/// For each of F fields given as (offset, x-tables), offset + sum_h x_h(x_i) y_h(y_j) on the
/// grid, row-major. All fields share the y-tables (one per term).
fn products<const F: usize>(fields: [(f64, &Tables); F], y: &Tables) -> [Vec<f64>; F] {
    let y_packed = y.packed::<ROWS>();
    fields.map(|(offset, x)| {
        let x_packed = x.packed::<COLS>();
        let grid = Dims {
            nx: x.len,
            ny: y.len,
            terms: x.count(),
        };
        // zeroed memory comes fresh from the allocator: no pass to fill it
        let mut out = vec![0.0; grid.nx * grid.ny];
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")
        {
            // SAFETY: the processor has AVX2 and FMA (checked just above).
            unsafe { accumulate_avx2(offset, grid, &x_packed, &y_packed, &mut out) };
            return out;
        }
        accumulate::<false>(offset, grid, &x_packed, &y_packed, &mut out);
        out
    })
}

/// The output grid's size (nx columns, ny rows) and the number of terms.
#[derive(Clone, Copy)]
struct Dims {
    nx: usize,
    ny: usize,
    terms: usize,
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn accumulate_avx2(offset: f64, g: Dims, x: &[[f64; COLS]], y: &[[f64; ROWS]], out: &mut [f64]) {
    accumulate::<true>(offset, g, x, y, out)
}

/// out[j nx + i] = offset + sum_h y_h[j] x_h[i] from packed tables, by blocks of ROWS x COLS kept
/// in registers while every term adds to them (a small matrix-product kernel). FUSED: with fused
/// multiply-adds (only where the processor has them: a software fma would be slow).
#[inline(always)]
fn accumulate<const FUSED: bool>(
    offset: f64,
    g: Dims,
    x: &[[f64; COLS]],
    y: &[[f64; ROWS]],
    out: &mut [f64],
) {
    if g.terms == 0 {
        out.fill(offset);
        return;
    }
    for (jb, y_block) in y.chunks_exact(g.terms).enumerate() {
        for (ib, x_block) in x.chunks_exact(g.terms).enumerate() {
            let mut acc = [[offset; COLS]; ROWS];
            for (xv, yv) in x_block.iter().zip(y_block) {
                for (row, &s) in acc.iter_mut().zip(yv) {
                    for (a, v) in row.iter_mut().zip(xv) {
                        *a = if FUSED { s.mul_add(*v, *a) } else { *a + s * v };
                    }
                }
            }
            let (i0, j0) = (ib * COLS, jb * ROWS);
            for (r, row) in acc.iter().enumerate().take(g.ny - j0) {
                let start = (j0 + r) * g.nx + i0;
                if i0 + COLS <= g.nx {
                    // a fixed-size copy: no call to memmove per block
                    let dst: &mut [f64; COLS] = (&mut out[start..start + COLS])
                        .try_into()
                        .expect("COLS long");
                    *dst = *row;
                } else {
                    out[start..start + g.nx - i0].copy_from_slice(&row[..g.nx - i0]);
                }
            }
        }
    }
}

/// The pressure terms of a solution: (A/M) sin(wx x + rho_x + phi) sin(wy y + rho_y).
pub(crate) fn pressure_terms(sol: &SpatialSolution) -> Vec<Term> {
    sol.harmonics
        .iter()
        .map(|h| Term {
            c: h.state.amplitude / h.evolution.m,
            wx: h.initial.wavenumber_x,
            px: h.state.phase_x + h.evolution.phase_lead,
            wy: h.initial.wavenumber_y,
            py: h.state.phase_y,
        })
        .collect()
}

/// Fields on a grid over the cell (cell-centred points: x_i = (i + 1/2) lx/n): n x n points, or
/// n x 1 for a shape constant along y (every wy = 0), whose fields do not vary along y.
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    /// Points along x (and along y, unless the shape is constant along y).
    pub n: usize,
    /// Grid x [m].
    pub x: Vec<f64>,
    /// Grid y [m]: one point, y = ly/2, for a shape constant along y.
    pub y: Vec<f64>,
    /// p [Pa], row-major: index j n + i for (x_i, y_j).
    pub pressure: Vec<f64>,
    /// U [m].
    pub shape: Vec<f64>,
    /// W = g(0) - g(t) [m].
    pub wear: Vec<f64>,
}

/// The fields of a solution on the grid over `cell`: n x n, or n x 1 for a shape constant along
/// y (a 4096-point 1-D grid would otherwise fill 3 x 4096^2 values, 400 MB).
pub fn field(sol: &SpatialSolution, cell: &Cell, n: usize) -> Field {
    let centred = |extent: f64, count: usize| Grid {
        first: 0.5 * extent / count as f64,
        step: extent / count as f64,
        count,
    };
    let rows = if cell.period_y == Period::Constant {
        1
    } else {
        n
    };
    let (gx, gy) = (centred(cell.lx, n), centred(cell.ly, rows));
    let pressure = pressure_terms(sol);
    let x_tables = |c: &dyn Fn(&HarmonicSolution) -> (f64, f64)| {
        Tables::from_rows(sol.harmonics.iter().map(|h| {
            let (amplitude, phase) = c(h);
            gx.sines(amplitude, h.initial.wavenumber_x, phase)
        }))
    };
    let shape = x_tables(&|h| (h.state.amplitude, h.state.phase_x));
    // W = mean wear + U(0) - U(t): per harmonic, the x-table of U(0) minus that of U(t)
    let initial = x_tables(&|h| (h.initial.amplitude, h.initial.phase_x));
    let wear = Tables {
        len: n,
        values: (initial.values.iter().zip(&shape.values))
            .map(|(u0, u)| u0 - u)
            .collect(),
    };
    let [pressure, shape, wear] = products(
        [
            (
                sol.inputs.mean_pressure,
                &Tables::from_rows(pressure.iter().map(|t| gx.sines(t.c, t.wx, t.px))),
            ),
            (0.0, &shape),
            (sol.mean_wear(), &wear),
        ],
        &Tables::from_rows(pressure.iter().map(|t| gy.sines(1.0, t.wy, t.py))),
    );
    let (xs, ys) = (gx.points(), gy.points());
    Field {
        n,
        x: xs,
        y: ys,
        pressure,
        shape,
        wear,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::spatial::harmonic::Harmonic;
    use crate::physics::spatial::{SpatialInputs, solve};
    use crate::physics::{Friction, Material};

    /// Five harmonics in several directions, worn for a while (phases and amplitudes moved).
    fn solution() -> SpatialSolution {
        let w = 2.0 * std::f64::consts::PI / 1e-3;
        let harmonics = [(1, 0), (2, 1), (3, 2), (1, 3), (4, 4)]
            .iter()
            .enumerate()
            .map(|(n, &(mx, my))| Harmonic {
                amplitude: 1e-7 / (n + 1) as f64,
                wavenumber_x: w * mx as f64,
                wavenumber_y: w * my as f64,
                phase_x: 0.4 * n as f64,
                phase_y: 1.3 - 0.1 * n as f64,
            })
            .collect();
        let inputs = SpatialInputs {
            material: Material {
                youngs_modulus: 1e8,
                poisson_ratio: 0.4,
                thickness: 2e-4,
            },
            friction: Friction {
                coefficient: 0.6,
                adhesion: 0.0,
            },
            wear: 1e-11,
            sliding_speed: 0.5,
            mean_pressure: 3e6,
            harmonics,
        };
        solve(&inputs, 2.0).expect("valid inputs")
    }

    #[test]
    fn the_grid_equals_the_pointwise_closed_form() {
        // Independent route: SpatialSolution::pressure/shape/wear evaluate every harmonic's sines
        // directly at each point; the field uses rotated sine tables and the blocked kernel. Grid
        // sizes both multiples of the 4 x 8 block and not (edge blocks).
        let sol = solution();
        let cell = Cell::of(&sol.inputs.harmonics);
        let amplitude: f64 = sol.harmonics.iter().map(|h| h.initial.amplitude).sum();
        for n in [8, 37, 64] {
            let f = field(&sol, &cell, n);
            for (j, &y) in f.y.iter().enumerate() {
                for (i, &x) in f.x.iter().enumerate() {
                    let k = j * n + i;
                    let p = sol.pressure(x, y);
                    assert!(
                        (f.pressure[k] - p).abs() < 1e-12 * p.abs(),
                        "n {n} p at {i},{j}"
                    );
                    assert!((f.shape[k] - sol.shape(x, y)).abs() < 1e-13 * amplitude);
                    assert!((f.wear[k] - sol.wear(x, y)).abs() < 1e-13 * amplitude);
                }
            }
        }
    }

    #[test]
    fn a_shape_constant_along_y_has_one_row() {
        // Independent route: the pointwise closed form at any y (every wy = 0: nothing varies
        // along y), on the longest 1-D grid, which as n x n would hold 3 x 4096^2 values.
        let mut sol = solution();
        sol.harmonics.truncate(1);
        sol.inputs.harmonics.truncate(1);
        assert_eq!(sol.inputs.harmonics[0].wavenumber_y, 0.0);
        let cell = Cell::of(&sol.inputs.harmonics);
        let f = field(&sol, &cell, 4096);
        assert_eq!((f.x.len(), f.y.len(), f.pressure.len()), (4096, 1, 4096));
        assert_eq!(f.y[0], 0.5 * cell.ly);
        for (i, &x) in f.x.iter().enumerate().step_by(97) {
            let p = sol.pressure(x, 0.3 * cell.ly);
            assert!((f.pressure[i] - p).abs() < 1e-12 * p.abs(), "{i}");
        }
    }

    #[test]
    fn the_portable_kernel_equals_the_dispatched_one() {
        let sol = solution();
        let cell = Cell::of(&sol.inputs.harmonics);
        let reference = field(&sol, &cell, 45);
        let terms = pressure_terms(&sol);
        let x = Tables::new(&terms, |t| t.x_table(&reference.x));
        let y = Tables::new(&terms, |t| t.y_table(&reference.y));
        let mut out = vec![0.0; 45 * 45];
        let g = Dims {
            nx: 45,
            ny: 45,
            terms: terms.len(),
        };
        accumulate::<false>(
            sol.inputs.mean_pressure,
            g,
            &x.packed::<COLS>(),
            &y.packed::<ROWS>(),
            &mut out,
        );
        for (a, b) in out.iter().zip(&reference.pressure) {
            assert!((a - b).abs() < 1e-12 * b.abs());
        }
    }

    #[test]
    fn rotated_sine_tables_stay_within_round_off() {
        // Against sin() at every point of the longest grid (4096 points over a 1 mm cell) for the
        // 31st harmonic of the cell: arguments up to 31 * 2 pi, about 0.05 rad per step.
        let grid = Grid {
            first: 0.5e-3 / 4096.0,
            step: 1e-3 / 4096.0,
            count: 4096,
        };
        let (w, p) = (31.0 * 2.0 * std::f64::consts::PI / 1e-3, -0.7);
        let table = grid.sines(1.0, w, p);
        for (i, v) in table.iter().enumerate() {
            let direct = (w * (grid.first + i as f64 * grid.step) + p).sin();
            assert!((v - direct).abs() < 1e-13, "{i}: {v} vs {direct}");
        }
    }
}
