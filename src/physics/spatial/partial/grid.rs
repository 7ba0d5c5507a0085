//! The nodes of the period cell (docs/physics/spatial-partial.md section 2) and the punch shape
//! sampled on them.

use std::f64::consts::PI;

use crate::physics::SolveError;
use crate::physics::spatial::field::{Term, synthesize};
use crate::physics::spatial::harmonic::Harmonic;
use crate::physics::spatial::surface::Surface;
use crate::physics::spatial::{Cell, Period};

/// Fewest nodes per wavelength of any harmonic, along each axis (section 2: "well below N/2: at
/// least 16 nodes per shortest shape wavelength").
pub const NODES_PER_WAVELENGTH: usize = 16;

/// Refuses a side of the grid below `NODES_PER_WAVELENGTH`: every harmonic has at least one
/// wavelength on the period cell, so no shape is solved in partial contact on it. A preset's
/// `spatial.grid` is held to this when it is read or set; the finer need of a shape's shortest
/// harmonic is the solver's (`Grid::new`), since the explorer adds harmonics on a fixed grid.
pub fn check_side(side: usize) -> Result<(), SolveError> {
    if side < NODES_PER_WAVELENGTH {
        return Err(SolveError::InvalidInput(format!(
            "grid = {side} is too coarse for partial contact: every harmonic needs at least \
             {NODES_PER_WAVELENGTH} nodes per wavelength, so grid >= {NODES_PER_WAVELENGTH}"
        )));
    }
    Ok(())
}

/// An nx x ny grid of nodes x_i = i lx/nx, y_j = j ly/ny over one period cell. An axis along
/// which no harmonic varies has one node (1-D shapes solve on N x 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// Nodes along x.
    pub nx: usize,
    /// Nodes along y.
    pub ny: usize,
    /// Cell extent along x [m].
    pub lx: f64,
    /// Cell extent along y [m].
    pub ly: f64,
}

impl Grid {
    /// The grid with `side` nodes along every axis on which the harmonics vary. Refused when the
    /// wavenumbers have no common period (no finite cell) or when a harmonic would get fewer than
    /// `NODES_PER_WAVELENGTH` nodes per wavelength.
    pub fn new(harmonics: &[Harmonic], side: usize) -> Result<Grid, SolveError> {
        let cell = Cell::of(harmonics);
        if !cell.is_periodic() {
            return Err(SolveError::NoSolution(
                "partial contact is solved on a period cell, and these wavenumbers have no common \
                 period: make every wavenumber along an axis an integer multiple of one base"
                    .into(),
            ));
        }
        let nodes = |p: Period| if p == Period::Constant { 1 } else { side };
        let grid = Grid {
            nx: nodes(cell.period_x),
            ny: nodes(cell.period_y),
            lx: cell.lx,
            ly: cell.ly,
        };
        let needed = harmonics
            .iter()
            .map(|h| {
                let mx = (h.wavenumber_x * grid.lx / (2.0 * PI)).round() as usize;
                let my = (h.wavenumber_y * grid.ly / (2.0 * PI)).round() as usize;
                NODES_PER_WAVELENGTH * mx.max(my)
            })
            .max()
            .unwrap_or(0);
        if needed > side {
            return Err(SolveError::InvalidInput(format!(
                "grid = {side} is too coarse for partial contact: the shortest harmonic needs at \
                 least {NODES_PER_WAVELENGTH} nodes per wavelength, so grid >= {needed}"
            )));
        }
        Ok(grid)
    }

    /// The grid of a height map: its own nodes over its cell. A profile (ny = 1) has no width;
    /// its one row gets ly = lx, which only sets y_0 = 0 (no wave varies along y).
    pub fn of_surface(surface: &Surface) -> Grid {
        Grid {
            nx: surface.nx,
            ny: surface.ny,
            lx: surface.lx,
            ly: if surface.is_profile() {
                surface.lx
            } else {
                surface.ly
            },
        }
    }

    /// Number of nodes nx ny.
    pub fn len(&self) -> usize {
        self.nx * self.ny
    }

    /// Never true (a grid has at least one node); for clippy's len convention.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// x_i = i lx/nx [m].
    pub fn x(&self, i: usize) -> f64 {
        i as f64 * self.lx / self.nx as f64
    }

    /// y_j = j ly/ny [m].
    pub fn y(&self, j: usize) -> f64 {
        j as f64 * self.ly / self.ny as f64
    }

    /// The node coordinates along x [m].
    pub fn xs(&self) -> Vec<f64> {
        (0..self.nx).map(|i| self.x(i)).collect()
    }

    /// The node coordinates along y [m].
    pub fn ys(&self) -> Vec<f64> {
        (0..self.ny).map(|j| self.y(j)).collect()
    }

    /// Index (row-major, x fastest: j nx + i) of the node nearest to (x, y) [m], periodically.
    pub fn nearest(&self, x: f64, y: f64) -> usize {
        let index =
            |v: f64, l: f64, n: usize| ((v.rem_euclid(l) / l * n as f64).round() as usize) % n;
        index(y, self.ly, self.ny) * self.nx + index(x, self.lx, self.nx)
    }

    /// The zero-mean shape U [m] of the harmonics (amplitude, phases at the instant) at the nodes.
    pub fn sample(&self, harmonics: &[Harmonic]) -> Vec<f64> {
        let terms: Vec<Term> = harmonics
            .iter()
            .map(|h| Term {
                c: h.amplitude,
                wx: h.wavenumber_x,
                px: h.phase_x,
                wy: h.wavenumber_y,
                py: h.phase_y,
            })
            .collect();
        synthesize(&terms, 0.0, &self.xs(), &self.ys())
    }
}
