//! The product kernel of separable sums: out[j nx + i] = offset + sum_t x_t[i] y_t[j] from one
//! x-table and one y-table per term, by blocks of 4 x 8 grid points kept in registers while every
//! term adds to them (tables packed so that the kernel reads them contiguously, each output
//! written once), with AVX2 and fused multiply-adds where the processor has them.

/// One table per term (its values at the grid points), stored term after term.
pub(crate) struct Tables {
    len: usize,
    values: Vec<f64>,
}

impl Tables {
    pub fn new(len: usize) -> Tables {
        Tables {
            len,
            values: Vec::new(),
        }
    }

    pub fn push(&mut self, row: Vec<f64>) {
        self.values.extend(row);
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

/// out[j nx + i] = offset + sum_t x_t[i] y_t[j] (nx = x.len, ny = y.len).
pub(crate) fn product(offset: f64, x: &Tables, y: &Tables, out: &mut [f64]) {
    let grid = Dims {
        nx: x.len,
        ny: y.len,
        terms: x.count(),
    };
    let (x, y) = (x.packed::<COLS>(), y.packed::<ROWS>());
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma") {
        // SAFETY: the processor has AVX2 and FMA (checked just above).
        unsafe { accumulate_avx2(offset, grid, &x, &y, out) };
        return;
    }
    accumulate(offset, grid, &x, &y, out);
}

/// The output grid's size (nx columns, ny rows) and the number of terms.
#[derive(Clone, Copy)]
struct Dims {
    nx: usize,
    ny: usize,
    terms: usize,
}

/// `accumulate` with AVX2 fused multiply-adds: the block's 8 vectors of 4 stay in registers (the
/// portable loop, compiled for AVX2, kept them on the stack) and full blocks are stored straight
/// into `out`.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn accumulate_avx2(offset: f64, g: Dims, x: &[[f64; COLS]], y: &[[f64; ROWS]], out: &mut [f64]) {
    use std::arch::x86_64::_mm256_storeu_pd;
    use std::arch::x86_64::{__m256d, _mm256_fmadd_pd, _mm256_loadu_pd, _mm256_set1_pd};
    if g.terms == 0 {
        out.fill(offset);
        return;
    }
    for (jb, y_block) in y.chunks_exact(g.terms).enumerate() {
        for (ib, x_block) in x.chunks_exact(g.terms).enumerate() {
            let mut acc: [[__m256d; 2]; ROWS] = [[_mm256_set1_pd(offset); 2]; ROWS];
            for (xv, yv) in x_block.iter().zip(y_block) {
                // SAFETY: xv holds COLS = 8 values, read as two vectors of 4.
                let (lo, hi) = unsafe {
                    (
                        _mm256_loadu_pd(xv.as_ptr()),
                        _mm256_loadu_pd(xv.as_ptr().add(4)),
                    )
                };
                for (row, &s) in acc.iter_mut().zip(yv) {
                    let s = _mm256_set1_pd(s);
                    row[0] = _mm256_fmadd_pd(s, lo, row[0]);
                    row[1] = _mm256_fmadd_pd(s, hi, row[1]);
                }
            }
            let (i0, j0) = (ib * COLS, jb * ROWS);
            for (r, row) in acc.iter().enumerate().take(g.ny - j0) {
                let start = (j0 + r) * g.nx + i0;
                let mut values = [0.0; COLS];
                let dst = if i0 + COLS <= g.nx {
                    &mut out[start..start + COLS]
                } else {
                    &mut values[..]
                };
                // SAFETY: dst holds COLS = 8 values, written as two vectors of 4.
                unsafe {
                    _mm256_storeu_pd(dst.as_mut_ptr(), row[0]);
                    _mm256_storeu_pd(dst.as_mut_ptr().add(4), row[1]);
                }
                if i0 + COLS > g.nx {
                    out[start..start + g.nx - i0].copy_from_slice(&values[..g.nx - i0]);
                }
            }
        }
    }
}

/// out[j nx + i] = offset + sum_h y_h[j] x_h[i] from packed tables, by blocks of ROWS x COLS
/// while every term adds to them (a small matrix-product kernel), without fused multiply-adds (a
/// software fma would be slow).
fn accumulate(offset: f64, g: Dims, x: &[[f64; COLS]], y: &[[f64; ROWS]], out: &mut [f64]) {
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
                        *a += s * v;
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_portable_kernel_equals_the_dispatched_one() {
        let mut x = Tables::new(45);
        let mut y = Tables::new(37);
        for t in 0..5 {
            x.push(
                (0..45)
                    .map(|i| ((i * 7 + t * 3) % 11) as f64 - 5.0)
                    .collect(),
            );
            y.push((0..37).map(|j| ((j * 5 + t) % 13) as f64 * 0.25).collect());
        }
        let (mut a, mut b) = (vec![0.0; 45 * 37], vec![0.0; 45 * 37]);
        product(1.5, &x, &y, &mut a);
        let g = Dims {
            nx: 45,
            ny: 37,
            terms: 5,
        };
        accumulate(1.5, g, &x.packed::<COLS>(), &y.packed::<ROWS>(), &mut b);
        // small integers times quarters: every sum is exact either way
        assert_eq!(a, b);
        for j in 0..37 {
            for i in 0..45 {
                let sum: f64 = (0..5)
                    .map(|t| x.values[t * 45 + i] * y.values[t * 37 + j])
                    .sum();
                assert_eq!(a[j * 45 + i], 1.5 + sum);
            }
        }
    }
}
