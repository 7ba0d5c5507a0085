//! Fields on a grid over the cell: pressure p, shape U and punch wear W, each a sum of separable
//! waves (`separable`: merged where wavenumbers repeat, then a blocked matrix-product kernel).

use crate::physics::spatial::separable::{Axis, Wave, sums};
use crate::physics::spatial::{Cell, Period, SpatialSolution};

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
    fn wave(&self) -> Wave {
        Wave::new(self.c, self.wx, self.px, self.wy, self.py)
    }
}

/// offset + sum of terms on the grid xs x ys, row-major (index j * xs.len() + i).
pub(crate) fn synthesize(terms: &[Term], offset: f64, xs: &[f64], ys: &[f64]) -> Vec<f64> {
    let waves: Vec<Wave> = terms.iter().map(Term::wave).collect();
    let mut out = Vec::new();
    sums(
        [(offset, &waves[..])],
        Axis::Points(xs),
        Axis::Points(ys),
        [&mut out],
    );
    out
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
    let mut out = Field {
        n,
        x: Vec::new(),
        y: Vec::new(),
        pressure: Vec::new(),
        shape: Vec::new(),
        wear: Vec::new(),
    };
    field_into(sol, cell, n, &mut out);
    out
}

/// `field` written into `out`'s buffers (no allocation when they already hold as many values).
pub fn field_into(sol: &SpatialSolution, cell: &Cell, n: usize, out: &mut Field) {
    let centred = |extent: f64, count: usize| Axis::Uniform {
        first: 0.5 * extent / count as f64,
        step: extent / count as f64,
        count,
    };
    let rows = if cell.period_y == Period::Constant {
        1
    } else {
        n
    };
    let pressure: Vec<Wave> = pressure_terms(sol).iter().map(Term::wave).collect();
    let (shape, wear): (Vec<Wave>, Vec<Wave>) = (sol.harmonics.iter())
        .map(|h| {
            let (wx, wy) = (h.initial.wavenumber_x, h.initial.wavenumber_y);
            let wave = |a: f64, px: f64| Wave::new(a, wx, px, wy, h.state.phase_y);
            let u = wave(h.state.amplitude, h.state.phase_x);
            // W = mean wear + U(0) - U(t)
            let u0 = wave(h.initial.amplitude, h.initial.phase_x);
            let x = [u0.x[0] - u.x[0], u0.x[1] - u.x[1]];
            (u, Wave { x, ..u })
        })
        .unzip();
    sums(
        [
            (sol.inputs.mean_pressure, &pressure[..]),
            (0.0, &shape[..]),
            (sol.mean_wear(), &wear[..]),
        ],
        centred(cell.lx, n),
        centred(cell.ly, rows),
        [&mut out.pressure, &mut out.shape, &mut out.wear],
    );
    let points = |extent: f64, count: usize| {
        (0..count).map(move |i| 0.5 * extent / count as f64 + i as f64 * extent / count as f64)
    };
    out.n = n;
    out.x.clear();
    out.x.extend(points(cell.lx, n));
    out.y.clear();
    out.y.extend(points(cell.ly, rows));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::spatial::harmonic::Harmonic;
    use crate::physics::spatial::{PunchShape, SpatialInputs, solve};
    use crate::physics::{Friction, Material};

    /// Eight harmonics in several directions, some sharing a wavenumber along y (merged) or x,
    /// worn for a while (phases and amplitudes moved).
    fn solution() -> SpatialSolution {
        let w = 2.0 * std::f64::consts::PI / 1e-3;
        let harmonics = [
            (1, 0),
            (2, 1),
            (3, 2),
            (1, 3),
            (4, 4),
            (2, 0),
            (3, 1),
            (1, 1),
        ]
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
            wear_exponent: 1.0,
            reference_pressure: 1.0,
            sliding_speed: 0.5,
            mean_pressure: 3e6,
            shape: PunchShape::Harmonics(harmonics),
        };
        solve(&inputs, 2.0).expect("valid inputs")
    }

    #[test]
    fn the_grid_equals_the_pointwise_closed_form() {
        // Independent route: SpatialSolution::pressure/shape/wear evaluate every harmonic's sines
        // directly at each point; the field merges the waves, uses rotated sine tables and the blocked
        // kernel. Grid
        // sizes both multiples of the 4 x 8 block and not (edge blocks).
        let sol = solution();
        let cell = Cell::of(sol.inputs.harmonics());
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
        sol.inputs.shape = PunchShape::Harmonics(sol.inputs.harmonics()[..1].to_vec());
        assert_eq!(sol.inputs.harmonics()[0].wavenumber_y, 0.0);
        let cell = Cell::of(sol.inputs.harmonics());
        let f = field(&sol, &cell, 4096);
        assert_eq!((f.x.len(), f.y.len(), f.pressure.len()), (4096, 1, 4096));
        assert_eq!(f.y[0], 0.5 * cell.ly);
        for (i, &x) in f.x.iter().enumerate().step_by(97) {
            let p = sol.pressure(x, 0.3 * cell.ly);
            assert!((f.pressure[i] - p).abs() < 1e-12 * p.abs(), "{i}");
        }
    }

    #[test]
    fn refilled_buffers_hold_the_fresh_fields() {
        // field_into over a field of another size, then of the same size: the fresh field's
        // numbers bit for bit.
        let sol = solution();
        let cell = Cell::of(sol.inputs.harmonics());
        let mut reused = field(&sol, &cell, 16);
        for n in [37, 37] {
            field_into(&sol, &cell, n, &mut reused);
            assert_eq!(reused, field(&sol, &cell, n));
        }
    }
}
