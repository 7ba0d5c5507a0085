//! Fields on a grid over the cell: pressure p, shear tau, shape U and punch wear W.

use crate::physics::spatial::{Cell, SpatialSolution};

/// One term c sin(wx x + px) sin(wy y + py) of a separable sum.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Term {
    pub c: f64,
    pub wx: f64,
    pub px: f64,
    pub wy: f64,
    pub py: f64,
}

/// offset + sum of terms on the grid xs x ys, row-major (index j * xs.len() + i). Each term's
/// sines are computed once per row and column, so the cost is one multiply-add per term and point.
pub(crate) fn synthesize(terms: &[Term], offset: f64, xs: &[f64], ys: &[f64]) -> Vec<f64> {
    let mut out = vec![offset; xs.len() * ys.len()];
    for t in terms {
        let sx: Vec<f64> = xs.iter().map(|x| t.c * (t.wx * x + t.px).sin()).collect();
        for (j, y) in ys.iter().enumerate() {
            let sy = (t.wy * y + t.py).sin();
            for (o, s) in out[j * xs.len()..(j + 1) * xs.len()].iter_mut().zip(&sx) {
                *o += s * sy;
            }
        }
    }
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

/// Fields on an n x n grid over the cell (cell-centred points: x_i = (i + 1/2) lx/n).
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    /// Points per side.
    pub n: usize,
    /// Grid x [m].
    pub x: Vec<f64>,
    /// Grid y [m].
    pub y: Vec<f64>,
    /// p [Pa], row-major: index j n + i for (x_i, y_j).
    pub pressure: Vec<f64>,
    /// U [m].
    pub shape: Vec<f64>,
    /// W = g(0) - g(t) [m].
    pub wear: Vec<f64>,
}

impl Field {
    /// tau = mu p + tau0 [Pa] at every point.
    pub fn shear(&self, sol: &SpatialSolution) -> Vec<f64> {
        let f = &sol.inputs.friction;
        self.pressure
            .iter()
            .map(|p| f.coefficient * p + f.adhesion)
            .collect()
    }
}

/// The fields of a solution on an n x n grid over `cell`.
pub fn field(sol: &SpatialSolution, cell: &Cell, n: usize) -> Field {
    let xs: Vec<f64> = (0..n)
        .map(|i| (i as f64 + 0.5) * cell.lx / n as f64)
        .collect();
    let ys: Vec<f64> = (0..n)
        .map(|j| (j as f64 + 0.5) * cell.ly / n as f64)
        .collect();
    let shape_terms = |initial: bool| -> Vec<Term> {
        sol.harmonics
            .iter()
            .map(|h| Term {
                c: if initial {
                    h.initial.amplitude
                } else {
                    h.state.amplitude
                },
                wx: h.initial.wavenumber_x,
                px: if initial {
                    h.initial.phase_x
                } else {
                    h.state.phase_x
                },
                wy: h.initial.wavenumber_y,
                py: h.state.phase_y,
            })
            .collect()
    };
    let pressure = synthesize(&pressure_terms(sol), sol.inputs.mean_pressure, &xs, &ys);
    let shape = synthesize(&shape_terms(false), 0.0, &xs, &ys);
    let initial = synthesize(&shape_terms(true), sol.mean_wear(), &xs, &ys);
    let wear = initial.iter().zip(&shape).map(|(g0, u)| g0 - u).collect();
    Field {
        n,
        x: xs,
        y: ys,
        pressure,
        shape,
        wear,
    }
}
