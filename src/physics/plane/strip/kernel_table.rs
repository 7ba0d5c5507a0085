//! Space-domain kernels of the strip (docs/physics/plane.md section 2, Soldatenkov (2007) eq. (3.5)-(3.7)), tabulated once
//! per Poisson ratio for the strip of any thickness:
//!   R_j(z)   = A_j(z) - 1/z,  A_j(z) = pi/(2 sh(pi z/2)) + int_0^inf L_j(X) sin(zX) dX,
//!   chi B12(z) = int_0^inf chi L12(X) cos(zX) dX,   chi l12(z) = int_0^inf chi L12(X) sin(zX)/X dX,
//! with L_j = K_j - th X and L12 = K12 - 1 (the corrected forms). L_j and chi L12 decay like
//! X^2 e^{-2X}, so the integrals stop at X = 24. Their odd/even extensions are analytic in the
//! strip |Im X| < d(nu), d the distance of the nearest zero of D(X) (0.74 at nu = 1/2, 0.91 at
//! 0.3, 1.19 at 0; D's zeros nearest the axis lie on it), so the integrands are even analytic
//! functions of X and the trapezoid rule with step dX converges like exp(-d (2 pi/dX - z)): with
//! dX = 1/20 that is below 1e-20 up to z = 60 for every nu (the table is built this way, 480
//! nodes, the sines by rotation re-seeded every 64 rows). R_j and B12 decay like exp(-d z).
//! `direct` evaluates the same integrals by panels of Gauss–Legendre (an independent route for
//! the tests). The table has step 0.025 and six-point Lagrange interpolation, stored per interval
//! as the interpolating polynomial's coefficients (one Horner evaluation per kernel value):
//! measured against direct quadrature off the grid, the error is below 3e-10 (worst for chi B12
//! near z = 0).

use std::f64::consts::PI;

use crate::physics::elastic::{chi, kappa};
use crate::physics::quadrature::gauss_legendre;

/// Tabulated range of z = (s - x)/h; beyond it the kernels take their asymptotic forms.
pub const Z_MAX: f64 = 60.0;
/// Table step in z, and its inverse (exact).
const DZ: f64 = 0.025;
const PER_DZ: f64 = 40.0;

/// L1, L2 and chi L12 at X (all decaying; e-scaled like `strip_transfer`).
pub fn decaying_parts(nu: f64, x: f64) -> [f64; 3] {
    let kap = kappa(nu);
    let e = (-2.0 * x).exp();
    let sech = 2.0 * e / (1.0 + e * e);
    let th = x.tanh();
    let d = 2.0 * kap + (4.0 * x * x + 1.0 + kap * kap) * sech;
    let a = (4.0 * x * x + (kap - 1.0) * (kap - 1.0)) * th * sech;
    [
        -(a - 4.0 * x * sech) / d,
        -(a + 4.0 * x * sech) / d,
        -(4.0 * x * x + kap * kap - 1.0) * sech / d,
    ]
}

/// pi/(2 sh(pi z/2)) - 1/z, without cancellation near 0 (odd in z).
fn csch_minus_inverse(z: f64) -> f64 {
    let w = 0.5 * PI * z;
    if w.abs() < 0.05 {
        let w2 = w * w;
        // 1/sh w - 1/w = -w/6 + 7 w^3/360 - 31 w^5/15120 + ...
        0.5 * PI * w * (-1.0 / 6.0 + w2 * (7.0 / 360.0 - w2 * 31.0 / 15120.0))
    } else {
        0.5 * PI / w.sinh() - 1.0 / z
    }
}

/// The four kernels at one z by direct quadrature (what the table is built from).
pub fn direct(nu: f64, z: f64) -> [f64; 4] {
    let nodes = Nodes::new(nu);
    nodes.at(z)
}

/// Quadrature nodes in X with the decaying parts and weights folded in.
struct Nodes {
    x: Vec<f64>,
    w_l1: Vec<f64>,
    w_l2: Vec<f64>,
    w_l12: Vec<f64>,
    w_l12_over_x: Vec<f64>,
}

impl Nodes {
    fn new(nu: f64) -> Nodes {
        let rule = gauss_legendre(20);
        let width = 0.25;
        let panels = (24.0 / width) as usize;
        let mut n = Nodes {
            x: vec![],
            w_l1: vec![],
            w_l2: vec![],
            w_l12: vec![],
            w_l12_over_x: vec![],
        };
        for p in 0..panels {
            let lo = p as f64 * width;
            for (t, w) in rule.nodes.iter().zip(&rule.weights) {
                let x = lo + 0.5 * width * (1.0 + t);
                let w = 0.5 * width * w;
                let [l1, l2, l12] = decaying_parts(nu, x);
                n.x.push(x);
                n.w_l1.push(w * l1);
                n.w_l2.push(w * l2);
                n.w_l12.push(w * l12);
                n.w_l12_over_x.push(w * l12 / x);
            }
        }
        n
    }

    /// [R1, R2, chi B12, chi l12] at z >= 0.
    fn at(&self, z: f64) -> [f64; 4] {
        let (mut s1, mut s2, mut c12, mut l12) = (0.0, 0.0, 0.0, 0.0);
        for i in 0..self.x.len() {
            let (s, c) = (z * self.x[i]).sin_cos();
            s1 += self.w_l1[i] * s;
            s2 += self.w_l2[i] * s;
            c12 += self.w_l12[i] * c;
            l12 += self.w_l12_over_x[i] * s;
        }
        let base = if z == 0.0 { 0.0 } else { csch_minus_inverse(z) };
        [base + s1, base + s2, c12, l12]
    }
}

/// Number of table intervals of width DZ on [0, Z_MAX].
const INTERVALS: usize = 2400;
/// Trapezoid step and node count in X for the table (see the module note).
const DX: f64 = 0.05;
const X_NODES: usize = 480;

/// The kernel table for one Poisson ratio: on each interval [i DZ, (i+1) DZ] of z >= 0, the
/// coefficients of the six-point Lagrange interpolant in s = z/DZ - i, in powers of s.
#[derive(Clone, Debug)]
pub struct StripKernels {
    /// Poisson's ratio it was built for.
    pub nu: f64,
    /// [R2 c0..c5, chi B12 c0..c5] per interval (the columns of the collocation matrix).
    hot: Vec<[f64; 12]>,
    /// [R1 c0..c5, chi l12 c0..c5] per interval.
    cold: Vec<[f64; 12]>,
    /// chi l12(inf) = (pi/2) chi L12(0) = -(pi/2) chi.
    l12_inf: f64,
}

/// R2 + mu chi B12 for one mu: per interval the coefficients for z >= 0, then for z < 0 (where
/// the odd R2 changes sign and the even chi B12 does not).
pub struct Regular {
    table: Vec<[f64; 12]>,
}

impl Regular {
    /// The kernel at every z of `zs`, into `out`.
    pub fn column(&self, zs: &[f64], out: &mut [f64]) {
        for (o, &z) in out.iter_mut().zip(zs) {
            let a = z.abs();
            *o = if a > Z_MAX {
                -1.0 / z
            } else {
                let (i, s) = locate(a);
                let part = if z < 0.0 { 6 } else { 0 };
                horner(&self.table[i][part..part + 6], s)
            };
        }
    }
}

/// Horner's scheme for c0 + c1 s + ... + c5 s^5.
#[inline]
fn horner(c: &[f64], s: f64) -> f64 {
    ((((c[5] * s + c[4]) * s + c[3]) * s + c[2]) * s + c[1]) * s + c[0]
}

/// The interval of a >= 0 (the last one for a = Z_MAX) and s in [0, 1] within it.
#[inline]
fn locate(a: f64) -> (usize, f64) {
    let u = a * PER_DZ;
    // 0 <= u <= INTERVALS: the i32 conversion cannot saturate
    let i = (u as i32 as usize).min(INTERVALS - 1);
    (i, u - i as f64)
}

/// [R1, R2, chi B12, chi l12] at z = k DZ, k = 0..=INTERVALS, by the trapezoid rule in X.
fn trapezoid_table(nu: f64) -> Vec<[f64; 4]> {
    const RESEED: usize = 64;
    let mut table = vec![[0.0; 4]; INTERVALS + 1];
    // X = 0: L1 = L2 = 0 (odd), chi L12(0) = -chi; sin(zX)/X -> z
    let l12_0 = decaying_parts(nu, 0.0)[2];
    for (k, row) in table.iter_mut().enumerate() {
        row[2] = 0.5 * DX * l12_0;
        row[3] = 0.5 * DX * l12_0 * k as f64 * DZ;
    }
    for j in 1..=X_NODES {
        let x = j as f64 * DX;
        let [l1, l2, l12] = decaying_parts(nu, x).map(|v| DX * v);
        let l12_over_x = l12 / x;
        let (step_s, step_c) = (DZ * x).sin_cos();
        let (mut s, mut c) = (0.0, 1.0);
        for (k, row) in table.iter_mut().enumerate() {
            if k % RESEED == 0 {
                (s, c) = (k as f64 * DZ * x).sin_cos();
            }
            row[0] += l1 * s;
            row[1] += l2 * s;
            row[2] += l12 * c;
            row[3] += l12_over_x * s;
            (s, c) = (s * step_c + c * step_s, c * step_c - s * step_s);
        }
    }
    for (k, row) in table.iter_mut().enumerate().skip(1) {
        let base = csch_minus_inverse(k as f64 * DZ);
        row[0] += base;
        row[1] += base;
    }
    table
}

/// Coefficients in powers of s of the Lagrange basis polynomials on the grid offsets
/// first..first+5 (relative to the interval's left end).
fn lagrange_monomials(first: isize) -> [[f64; 6]; 6] {
    let offsets: [f64; 6] = std::array::from_fn(|j| (first + j as isize) as f64);
    std::array::from_fn(|j| {
        let mut poly = [0.0; 6];
        poly[0] = 1.0;
        let mut den = 1.0;
        for (k, &o) in offsets.iter().enumerate().filter(|&(k, _)| k != j) {
            for p in (1..6).rev() {
                poly[p] = poly[p - 1] - o * poly[p];
            }
            poly[0] *= -o;
            den *= offsets[j] - offsets[k];
        }
        poly.map(|c| c / den)
    })
}

impl StripKernels {
    /// Builds the table (2401 values of four oscillatory integrals, then the interpolants).
    pub fn new(nu: f64) -> StripKernels {
        let table = trapezoid_table(nu);
        let last = INTERVALS as isize;
        // the stencil of interval i is i-2..i+3, kept inside the table at its far end; below
        // z = 0 it reflects through the kernels' parity (chi B12 even, the others odd)
        let value = |k: isize, col: usize| {
            let v = table[k.unsigned_abs()][col];
            if k < 0 && col != 2 { -v } else { v }
        };
        // the stencil starts 2 below the interval, or 3 or 4 below at the table's far end
        let bases = [-2, -3, -4].map(lagrange_monomials);
        let coefficients = |i: usize, cols: [usize; 2]| {
            let first = (i as isize - 2).min(last - 5);
            let basis = &bases[(i as isize - first - 2) as usize];
            let mut c = [0.0; 12];
            for (half, col) in cols.into_iter().enumerate() {
                for (j, b) in basis.iter().enumerate() {
                    let y = value(first + j as isize, col);
                    for p in 0..6 {
                        c[6 * half + p] += y * b[p];
                    }
                }
            }
            c
        };
        StripKernels {
            nu,
            hot: (0..INTERVALS).map(|i| coefficients(i, [1, 2])).collect(),
            cold: (0..INTERVALS).map(|i| coefficients(i, [0, 3])).collect(),
            l12_inf: -0.5 * PI * chi(nu),
        }
    }

    /// R2(z) + mu chi B12(z), the regular kernel of the strip equation (-1/z beyond the table).
    pub fn regular(&self, z: f64, mu: f64) -> f64 {
        let a = z.abs();
        if a > Z_MAX {
            return -1.0 / z;
        }
        let (i, s) = locate(a);
        let c = &self.hot[i];
        let sign = if z < 0.0 { -1.0 } else { 1.0 };
        let combined: [f64; 6] = std::array::from_fn(|p| sign * c[p] + mu * c[6 + p]);
        horner(&combined, s)
    }

    /// R2 + mu chi B12 for one mu, its interpolants combined once (for a whole matrix).
    pub fn regular_for(&self, mu: f64) -> Regular {
        Regular {
            table: self
                .hot
                .iter()
                .map(|c| {
                    std::array::from_fn(|p| {
                        if p < 6 {
                            c[p] + mu * c[6 + p]
                        } else {
                            mu * c[p] - c[p - 6]
                        }
                    })
                })
                .collect(),
        }
    }

    /// An odd kernel from `part` (0: first six coefficients, 6: last six) of `cols`.
    fn odd(&self, cols: &[[f64; 12]], part: usize, z: f64, beyond: f64) -> f64 {
        let a = z.abs();
        let v = if a > Z_MAX {
            beyond
        } else {
            let (i, s) = locate(a);
            horner(&cols[i][part..part + 6], s)
        };
        if z < 0.0 { -v } else { v }
    }

    /// R1(z) = A1(z) - 1/z (odd; -1/z beyond the table).
    pub fn r1(&self, z: f64) -> f64 {
        self.odd(&self.cold, 0, z, -1.0 / z.abs())
    }

    /// R2(z) = A2(z) - 1/z (odd; -1/z beyond the table).
    pub fn r2(&self, z: f64) -> f64 {
        self.odd(&self.hot, 0, z, -1.0 / z.abs())
    }

    /// chi B12(z) (even; 0 beyond the table).
    pub fn chi_b12(&self, z: f64) -> f64 {
        let a = z.abs();
        if a > Z_MAX {
            return 0.0;
        }
        let (i, s) = locate(a);
        horner(&self.hot[i][6..], s)
    }

    /// chi l12(z) (odd; its limit -(pi/2) chi beyond the table).
    pub fn chi_l12(&self, z: f64) -> f64 {
        self.odd(&self.cold, 6, z, self.l12_inf)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::elastic::{chi_c12, strip_transfer};

    #[test]
    fn decaying_parts_are_the_transfer_functions_minus_their_limits() {
        for nu in [0.0, 0.3, 0.49] {
            for x in [0.01f64, 0.4, 2.0, 7.0] {
                let t = strip_transfer(nu, x);
                let [l1, l2, l12] = decaying_parts(nu, x);
                assert!((l1 - (t.k1 - x.tanh())).abs() < 1e-14, "L1 at {x}");
                assert!((l2 - (t.k2 - x.tanh())).abs() < 1e-14, "L2 at {x}");
                assert!((l12 - t.chi_l12).abs() < 1e-14, "L12 at {x}");
            }
        }
    }

    #[test]
    fn b12_at_zero_is_c12_and_l12_grows_like_c12_z() {
        let k = StripKernels::new(0.3);
        let c12 = chi_c12(0.3);
        assert!((k.chi_b12(0.0) - c12).abs() < 1e-12);
        // l12' = B12, so l12(z) ~ c12 z near 0
        assert!((k.chi_l12(1e-4) / 1e-4 - c12).abs() < 1e-6);
        assert_eq!(k.r2(0.0), 0.0);
    }

    #[test]
    fn table_interpolation_matches_direct_quadrature() {
        // the trapezoid table against Gauss–Legendre panels, off the grid, over nu's whole range
        for nu in [0.0, 0.35, 0.49, 0.499] {
            let k = StripKernels::new(nu);
            for z in [0.013, 0.37, 1.234, 4.5678, 17.77, 43.21, 59.987] {
                let d = direct(nu, z);
                let got = [k.r1(z), k.r2(z), k.chi_b12(z), k.chi_l12(z)];
                for c in 0..4 {
                    assert!(
                        (got[c] - d[c]).abs() < 5e-10,
                        "nu = {nu}, z = {z}, kernel {c}: {} vs {}",
                        got[c],
                        d[c]
                    );
                }
                assert!((k.regular(z, 0.3) - (d[1] + 0.3 * d[2])).abs() < 5e-10);
                let mut column = [0.0; 3];
                k.regular_for(0.3).column(&[z, -z, 70.0 + z], &mut column);
                assert!((column[0] - k.regular(z, 0.3)).abs() < 1e-15);
                assert!((column[1] - k.regular(-z, 0.3)).abs() < 1e-15);
                assert_eq!(column[2], -1.0 / (70.0 + z));
                assert!(
                    (k.r2(-z) + k.r2(z)).abs() < 1e-15
                        && (k.chi_b12(-z) - k.chi_b12(z)).abs() < 1e-15
                        && (k.regular(-z, 0.3) - (-k.r2(z) + 0.3 * k.chi_b12(z))).abs() < 1e-15
                );
            }
        }
    }

    #[test]
    fn kernels_decay_to_their_asymptotes() {
        let k = StripKernels::new(0.3);
        let z = 59.0;
        assert!((k.r2(z) + 1.0 / z).abs() < 1e-12);
        assert!(k.chi_b12(z).abs() < 1e-12);
        assert!((k.chi_l12(z) + 0.5 * PI * chi(0.3)).abs() < 1e-9);
    }
}
