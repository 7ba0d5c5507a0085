//! The outputs of one contact state (docs/physics/spatial-partial.md section 4). All forces are
//! per unit area of the cell; averages <.> are means over the nodes.

use serde::Serialize;

use crate::physics::Friction;
use crate::physics::spatial::partial::active_set::ContactSolution;
use crate::physics::spatial::partial::grid::Grid;
use crate::physics::spatial::partial::operator::Operator;

/// The global outputs of a contact state.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Outputs {
    /// True when min over the nodes of p_cc >= 0 (then p = p_cc, the closed form).
    pub complete: bool,
    /// Fraction of the nodes in contact (p > 0); 1 in complete contact.
    pub contact_fraction: f64,
    /// max p over the nodes [Pa].
    pub max_pressure: f64,
    /// min over the nodes of the complete-contact pressure p_cc [Pa] (negative in partial contact).
    pub min_pressure_complete: f64,
    /// The node [x, y] [m] of that minimum.
    pub min_pressure_complete_at: [f64; 2],
    /// psi = -<p g_x> [Pa]: the deformation part of the friction force (negative when the pressure
    /// sits on the trailing, -x, side of the bumps).
    pub psi: f64,
    /// Delta = -<1_C g_x>: the mean punch slope over the contact, per cell area (0 in complete
    /// contact).
    pub delta: f64,
    /// P = pbar - mu psi - tau0 Delta [Pa]: the vertical force on the punch, positive pressing.
    pub normal_force: f64,
    /// T = mu pbar + tau0 fraction + psi [Pa]: the holding force along +x.
    pub holding_force: f64,
    /// mu* = (T - tau0 fraction)/P.
    pub mu_star: f64,
    /// <gap> = d [m] >= 0: the mean gap between punch and layer (0 in complete contact).
    pub mean_gap: f64,
}

/// A contact state on the grid: the fields and their outputs.
#[derive(Clone, Debug, PartialEq)]
pub struct State {
    /// The grid of the fields.
    pub grid: Grid,
    /// t [s].
    pub time: f64,
    /// U [m] at the nodes (row-major, x fastest).
    pub shape: Vec<f64>,
    /// p [Pa] at the nodes, >= 0.
    pub pressure: Vec<f64>,
    /// gap [m] at the nodes, >= 0 (0 in contact).
    pub gap: Vec<f64>,
    /// Punch wear W = g(0) - g(t) [m] at the nodes, >= 0.
    pub wear: Vec<f64>,
    /// The global outputs.
    pub outputs: Outputs,
    /// What the contact solver did.
    pub work: Work,
}

/// What the contact solver did for one state.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Work {
    /// Active-set iterations (0: complete contact, the closed form).
    pub iterations: usize,
    /// GMRES products.
    pub linear_iterations: usize,
    /// True when the active set cycled among a few edge nodes (tau0 > 0 on fine grids, section 3
    /// of docs/physics/spatial-partial.md) and the best state of the cycle was kept.
    pub cycled: bool,
    /// True when the sets cycled or stalled and the update was then limited to the ends of the
    /// contact zones (section 3 of docs/physics/spatial-partial.md, `zone_ends`).
    pub damped: bool,
}

impl Work {
    /// The work of one solution.
    pub fn of(sol: &ContactSolution) -> Work {
        Work {
            iterations: sol.iterations,
            linear_iterations: sol.linear_iterations,
            cycled: sol.cycled,
            damped: sol.damped,
        }
    }
}

impl State {
    /// The contact set: p > 0 (every node in complete contact).
    pub fn contact(&self) -> Vec<bool> {
        self.pressure
            .iter()
            .map(|p| self.outputs.complete || *p > 0.0)
            .collect()
    }

    /// tau = (mu p + tau0) 1_C [Pa] on the layer, along +x, at the nodes.
    pub fn shear(&self, friction: &Friction) -> Vec<f64> {
        self.pressure
            .iter()
            .zip(self.contact())
            .map(|(p, on)| {
                if on {
                    friction.coefficient * p + friction.adhesion
                } else {
                    0.0
                }
            })
            .collect()
    }

    /// p [Pa] at the node nearest to (x, y) [m].
    pub fn pressure_at(&self, x: f64, y: f64) -> f64 {
        self.pressure[self.grid.nearest(x, y)]
    }
}

/// The outputs and the gap of the solution `sol` for shape `shape` [m] under mean pressure
/// `pbar` [Pa] and `friction`, with mean gap `mean_gap` [m] (the solution's offset plus c pbar
/// when it came from a wear step).
pub fn evaluate(
    op: &mut Operator,
    shape: &[f64],
    pbar: f64,
    friction: &Friction,
    sol: &ContactSolution,
    mean_gap: f64,
) -> (Outputs, Vec<f64>) {
    let n = shape.len();
    let nodes = n as f64;
    let (mu, tau0) = (friction.coefficient, friction.adhesion);
    let mut work = vec![0.0; n];
    op.inverse(shape, &mut work, 0.0);
    let lowest = (0..n)
        .min_by(|a, b| work[*a].total_cmp(&work[*b]))
        .expect("a grid has nodes");
    let min_pressure_complete = pbar + work[lowest];
    let grid = op.grid();
    let min_pressure_complete_at = [grid.x(lowest % grid.nx), grid.y(lowest / grid.nx)];
    let complete = sol.complete || min_pressure_complete >= 0.0;
    let contact: Vec<bool> = sol.pressure.iter().map(|p| complete || *p > 0.0).collect();
    let mut slope = vec![0.0; n];
    op.derivative_x(shape, &mut slope);
    let psi = -sol
        .pressure
        .iter()
        .zip(&slope)
        .map(|(p, g)| p * g)
        .sum::<f64>()
        / nodes;
    let delta = if complete {
        0.0
    } else {
        -contact
            .iter()
            .zip(&slope)
            .filter(|(on, _)| **on)
            .map(|(_, g)| g)
            .sum::<f64>()
            / nodes
    };
    let fraction = contact.iter().filter(|on| **on).count() as f64 / nodes;
    // gap = d - U + K p - tau0 T[1_C]
    let mut gap = vec![0.0; n];
    op.apply(&sol.pressure, &mut gap, 0.0);
    if tau0 > 0.0 && !complete {
        let ones: Vec<f64> = contact.iter().map(|&on| f64::from(u8::from(on))).collect();
        op.shear(&ones, &mut work);
        gap.iter_mut().zip(&work).for_each(|(g, t)| *g -= tau0 * t);
    }
    gap.iter_mut()
        .zip(shape)
        .for_each(|(g, u)| *g += mean_gap - u);
    let normal_force = pbar - mu * psi - tau0 * delta;
    let holding_force = mu * pbar + tau0 * fraction + psi;
    let outputs = Outputs {
        complete,
        contact_fraction: fraction,
        max_pressure: sol.pressure.iter().copied().fold(0.0, f64::max),
        min_pressure_complete,
        min_pressure_complete_at,
        psi,
        delta,
        normal_force,
        holding_force,
        mu_star: (holding_force - tau0 * fraction) / normal_force,
        mean_gap,
    };
    (outputs, gap)
}
