//! Space-domain kernels of the strip (docs/physics/plane.md section 2, paper 001 (3.5)-(3.7)), tabulated once
//! per Poisson ratio for the strip of any thickness:
//!   R_j(z)   = A_j(z) - 1/z,  A_j(z) = pi/(2 sh(pi z/2)) + int_0^inf L_j(X) sin(zX) dX,
//!   chi B12(z) = int_0^inf chi L12(X) cos(zX) dX,   chi l12(z) = int_0^inf chi L12(X) sin(zX)/X dX,
//! with L_j = K_j - th X and L12 = K12 - 1 (the corrected forms). L_j and chi L12 decay like
//! X^2 e^{-2X}, so the integrals stop at X = 24; their odd/even extensions are analytic, so R_j
//! and B12 decay exponentially in z. The oscillation is resolved by panels of width 1/4 with 20
//! Gauss–Legendre nodes each (resolves z up to ~60); the sines are shared by all four kernels.
//! The table has step 0.025 and six-point Lagrange interpolation: measured against direct
//! quadrature off the grid, the error is below 3e-10 (worst for chi B12 near z = 0).

use std::f64::consts::PI;

use crate::physics::elastic::{chi, kappa};
use crate::physics::quadrature::gauss_legendre;

/// Tabulated range of z = (s - x)/h; beyond it the kernels take their asymptotic forms.
pub const Z_MAX: f64 = 60.0;
/// Table step in z.
const DZ: f64 = 0.025;

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

/// The kernel table for one Poisson ratio.
#[derive(Clone, Debug)]
pub struct StripKernels {
    /// Poisson's ratio it was built for.
    pub nu: f64,
    /// [R1, R2, chi B12, chi l12] at z = k DZ, k = 0..=Z_MAX/DZ.
    table: Vec<[f64; 4]>,
    /// chi l12(inf) = (pi/2) chi L12(0) = -(pi/2) chi.
    l12_inf: f64,
}

impl StripKernels {
    /// Builds the table (about 2400 values of four oscillatory integrals). On the uniform z grid
    /// sin(z_k X) and cos(z_k X) follow from one rotation per step, node by node.
    pub fn new(nu: f64) -> StripKernels {
        let nodes = Nodes::new(nu);
        let n = (Z_MAX / DZ).round() as usize;
        let mut table = vec![[0.0; 4]; n + 1];
        for i in 0..nodes.x.len() {
            let (step_s, step_c) = (DZ * nodes.x[i]).sin_cos();
            let (mut s, mut c) = (0.0, 1.0);
            for row in table.iter_mut() {
                row[0] += nodes.w_l1[i] * s;
                row[1] += nodes.w_l2[i] * s;
                row[2] += nodes.w_l12[i] * c;
                row[3] += nodes.w_l12_over_x[i] * s;
                (s, c) = (s * step_c + c * step_s, c * step_c - s * step_s);
            }
        }
        for (k, row) in table.iter_mut().enumerate().skip(1) {
            let base = csch_minus_inverse(k as f64 * DZ);
            row[0] += base;
            row[1] += base;
        }
        StripKernels {
            nu,
            table,
            l12_inf: -0.5 * PI * chi(nu),
        }
    }

    /// R2(z) + mu chi B12(z), the regular kernel of the strip equation, with one set of
    /// interpolation weights for both columns.
    pub fn regular(&self, z: f64, mu: f64) -> f64 {
        let a = z.abs();
        if a > Z_MAX {
            return -1.0 / z;
        }
        let sign = if z < 0.0 { -1.0 } else { 1.0 };
        let (i0, l) = self.stencil(a);
        let mut sum = 0.0;
        for (j, lj) in l.iter().enumerate() {
            let i = i0 + j as isize;
            let row = &self.table[i.unsigned_abs()];
            // R2 is odd, B12 even: reflect through z = 0
            let r2 = if i < 0 { -row[1] } else { row[1] };
            sum += lj * (sign * r2 + mu * row[2]);
        }
        sum
    }

    /// The first table index and the six Lagrange weights at z >= 0: on the uniform grid,
    /// l_j = D_j prod_k (u - u_k)/(u - u_j) with the constant D_j = 1/prod_{k != j} (j - k).
    fn stencil(&self, z: f64) -> (isize, [f64; 6]) {
        const D: [f64; 6] = [
            -1.0 / 120.0,
            1.0 / 24.0,
            -1.0 / 12.0,
            1.0 / 12.0,
            -1.0 / 24.0,
            1.0 / 120.0,
        ];
        let u = z / DZ;
        let last = self.table.len() as isize - 1;
        let i0 = (u.floor() as isize - 2).min(last - 5);
        let d: [f64; 6] = std::array::from_fn(|k| u - (i0 + k as isize) as f64);
        if let Some(j) = d.iter().position(|v| *v == 0.0) {
            let mut l = [0.0; 6];
            l[j] = 1.0;
            return (i0, l);
        }
        let all: f64 = d.iter().product();
        (i0, std::array::from_fn(|j| D[j] * all / d[j]))
    }

    /// Six-point Lagrange interpolation of column `col` at z in [0, Z_MAX]; near 0 the stencil
    /// reaches negative z through the kernel's parity (column 2 even, the others odd).
    fn interpolate(&self, col: usize, z: f64) -> f64 {
        let (i0, l) = self.stencil(z);
        let parity = if col == 2 { 1.0 } else { -1.0 };
        let value = |i: isize| {
            if i < 0 {
                parity * self.table[(-i) as usize][col]
            } else {
                self.table[i as usize][col]
            }
        };
        l.iter()
            .enumerate()
            .map(|(j, lj)| lj * value(i0 + j as isize))
            .sum()
    }

    fn odd(&self, col: usize, z: f64, beyond: f64) -> f64 {
        let a = z.abs();
        let v = if a > Z_MAX {
            beyond
        } else {
            self.interpolate(col, a)
        };
        if z < 0.0 { -v } else { v }
    }

    /// R1(z) = A1(z) - 1/z (odd; -1/z beyond the table).
    pub fn r1(&self, z: f64) -> f64 {
        self.odd(0, z, -1.0 / z.abs())
    }

    /// R2(z) = A2(z) - 1/z (odd; -1/z beyond the table).
    pub fn r2(&self, z: f64) -> f64 {
        self.odd(1, z, -1.0 / z.abs())
    }

    /// chi B12(z) (even; 0 beyond the table).
    pub fn chi_b12(&self, z: f64) -> f64 {
        let a = z.abs();
        if a > Z_MAX {
            0.0
        } else {
            self.interpolate(2, a)
        }
    }

    /// chi l12(z) (odd; its limit -(pi/2) chi beyond the table).
    pub fn chi_l12(&self, z: f64) -> f64 {
        self.odd(3, z, self.l12_inf)
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
        let k = StripKernels::new(0.35);
        for z in [0.013, 0.37, 1.234, 4.5678, 17.77, 43.21] {
            let d = direct(0.35, z);
            let got = [k.r1(z), k.r2(z), k.chi_b12(z), k.chi_l12(z)];
            for c in 0..4 {
                assert!(
                    (got[c] - d[c]).abs() < 5e-10,
                    "z = {z}, kernel {c}: {} vs {}",
                    got[c],
                    d[c]
                );
            }
            assert!(
                (k.r2(-z) + k.r2(z)).abs() < 1e-15 && (k.chi_b12(-z) - k.chi_b12(z)).abs() < 1e-15
            );
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
