//! Where a sliding line contact first yields: the stresses that the contact's pressure q2 and
//! shear q1 cause in an elastic half-plane, Flamant's line-load solutions superposed (Johnson
//! (1985) sections 2.1-2.4) in plane strain, and the largest von Mises equivalent stress, at the
//! surface or beneath it (Johnson (1985) sections 7.2 and 9.2: with friction the largest stress
//! moves from below the surface to the surface at the trailing edge).
//!
//! The field is the half-plane's: exact for the wide model, an estimate on a strip of finite
//! thickness, whose bonded base changes the field once h is not large against a + b.
//!
//! Axes as the solution's: x along the sliding direction (the leading edge b at +x, q1 > 0 acting
//! on the strip in +x), z into the strip. Stresses in Pa, tension positive.

use std::f64::consts::PI;

use crate::physics::plane::PlaneSolution;
use crate::physics::quadrature::{GaussRule, gauss_legendre, tanh_sinh};

/// The in-plane stresses at a point [Pa], tension positive; the out-of-plane stress of plane
/// strain is nu (sx + sz).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stress {
    /// sigma_xx [Pa].
    pub sx: f64,
    /// sigma_zz [Pa].
    pub sz: f64,
    /// tau_xz [Pa].
    pub txz: f64,
}

impl Stress {
    /// The von Mises equivalent stress [Pa] in plane strain with Poisson's ratio `nu`.
    pub fn von_mises(self, nu: f64) -> f64 {
        let sy = nu * (self.sx + self.sz);
        let d = (self.sx - sy).powi(2) + (sy - self.sz).powi(2) + (self.sz - self.sx).powi(2);
        (0.5 * d + 3.0 * self.txz * self.txz).sqrt()
    }
}

/// The largest von Mises stress of a contact and where it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peak {
    /// The von Mises equivalent stress [Pa].
    pub stress: f64,
    /// Its x [m] (moving frame of the solution).
    pub x: f64,
    /// Its depth z >= 0 [m] below the strip's surface; 0 at the surface.
    pub depth: f64,
}

/// Why a contact has no largest stress: its pressure is unbounded at a sharp corner of the punch,
/// so the strip yields there under any load.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Unbounded;

/// Depths below which the surface formula serves, as a fraction of the contact width.
const SURFACE: f64 = 1e-9;
/// Quadrature segments over the contact at most (each at most half the depth long).
const MOST_SEGMENTS: usize = 512;
/// Grid of the search: x points over the contact and beyond, depths below the surface.
const X_POINTS: usize = 61;
const DEPTHS: usize = 30;
/// Steps of the local search after the grid; each halves the step when it finds nothing better.
const REFINE_STEPS: usize = 60;

/// The stresses at (x, z) [m], z >= 0.
pub fn stress(sol: &PlaneSolution, x: f64, z: f64) -> Stress {
    let width = sol.contact_width();
    if z <= SURFACE * width {
        return surface(sol, x);
    }
    let (lo, hi) = (-sol.a, sol.b);
    let n = ((width / (0.5 * z)).ceil() as usize).clamp(4, MOST_SEGMENTS);
    let step = width / n as f64;
    let (interior, edge) = (gauss_legendre(8), tanh_sinh(1.0 / 8.0));
    let mut s = Stress {
        sx: 0.0,
        sz: 0.0,
        txz: 0.0,
    };
    for i in 0..n {
        let (s0, s1) = (lo + step * i as f64, (lo + step * (i + 1) as f64).min(hi));
        let rule: &GaussRule = if i == 0 || i == n - 1 {
            &edge
        } else {
            &interior
        };
        // Flamant: a line load p (compressive) and q (in +x) at t, dx = x - t, r^2 = dx^2 + z^2:
        // normal  sx = -2p dx^2 z/(pi r^4), sz = -2p z^3/(pi r^4), txz = -2p dx z^2/(pi r^4);
        // tangent sx = -2q dx^3/(pi r^4),   sz = -2q dx z^2/(pi r^4), txz = -2q dx^2 z/(pi r^4)
        let (half, mid) = (0.5 * (s1 - s0), 0.5 * (s1 + s0));
        for (u, w) in rule.nodes.iter().zip(&rule.weights) {
            let t = mid + half * u;
            let (p, q, dx) = (sol.pressure(t), sol.shear(t), x - t);
            let weight = half * w / (dx * dx + z * z).powi(2);
            s.sx += weight * dx * dx * (p * z + q * dx);
            s.sz += weight * z * z * (p * z + q * dx);
            s.txz += weight * dx * z * (p * z + q * dx);
        }
    }
    let c = -2.0 / PI;
    Stress {
        sx: c * s.sx,
        sz: c * s.sz,
        txz: c * s.txz,
    }
}

/// The stresses on the surface: sz = -q2, txz = -q1 under the contact (0 beyond it), and
/// sx = -q2(x) - (2/pi) p.v. int q1(s)/(x - s) ds (Johnson (1985) section 2.4), the principal value as the regular integral of (q1(s) - q1(x))/(x - s) plus
/// q1(x) ln((x + a)/(b - x)).
fn surface(sol: &PlaneSolution, x: f64) -> Stress {
    let (lo, hi) = (-sol.a, sol.b);
    let inside = lo < x && x < hi;
    let (p, q) = if inside {
        (sol.pressure(x), sol.shear(x))
    } else {
        (0.0, 0.0)
    };
    let (interior, edge) = (gauss_legendre(8), tanh_sinh(1.0 / 8.0));
    let regular = |s: f64| (sol.shear(s) - q) / (x - s);
    let n = 64;
    let step = (hi - lo) / n as f64;
    let mut hilbert = 0.0;
    for i in 0..n {
        let (s0, s1) = (lo + step * i as f64, (lo + step * (i + 1) as f64).min(hi));
        // the ends carry the edge behaviour of q1, and so does the segment holding x
        let rule = if i == 0 || i == n - 1 || (s0..=s1).contains(&x) {
            &edge
        } else {
            &interior
        };
        hilbert += rule.integrate(s0, s1, regular);
    }
    if inside {
        hilbert += q * ((x - lo) / (hi - x)).ln();
    }
    Stress {
        sx: -p - 2.0 / PI * hilbert,
        sz: -p,
        txz: -q,
    }
}

/// The largest von Mises stress of the contact: a grid over x in [-a - w/5, b + w/5] (w = a + b)
/// and depths from the surface to 1.5 w, then a bounded compass search around the grid's best.
/// `Err(Unbounded)` for a punch with sharp corners.
pub fn peak(sol: &PlaneSolution) -> Result<Peak, Unbounded> {
    if sol.inputs.shape.is_sharp() {
        return Err(Unbounded);
    }
    let nu = sol.inputs.material.poisson_ratio;
    let w = sol.contact_width();
    let vm = |x: f64, z: f64| stress(sol, x, z.max(0.0)).von_mises(nu);
    let xs = (0..X_POINTS).map(|i| -sol.a - 0.2 * w + 1.4 * w * i as f64 / (X_POINTS - 1) as f64);
    // the surface, the edges, then depths in geometric steps from w/400 to 1.5 w
    let depths: Vec<f64> = std::iter::once(0.0)
        .chain((0..DEPTHS).map(|k| w / 400.0 * 600f64.powf(k as f64 / (DEPTHS - 1) as f64)))
        .collect();
    let mut best = Peak {
        stress: f64::NEG_INFINITY,
        x: 0.0,
        depth: 0.0,
    };
    let consider = |x: f64, z: f64, best: &mut Peak| {
        let v = vm(x, z);
        if v > best.stress {
            *best = Peak {
                stress: v,
                x,
                depth: z,
            };
        }
    };
    for x in xs.chain([-sol.a, sol.b]) {
        for &z in &depths {
            consider(x, z, &mut best);
        }
    }
    // compass search: the step starts at a grid spacing and halves where no neighbour is larger
    let mut h = 1.4 * w / (X_POINTS - 1) as f64;
    for _ in 0..REFINE_STEPS {
        let here = best;
        for (dx, dz) in [(h, 0.0), (-h, 0.0), (0.0, h), (0.0, -h)] {
            consider(here.x + dx, (here.depth + dz).max(0.0), &mut best);
        }
        if best == here {
            h *= 0.5;
        }
        if h < 1e-7 * w {
            break;
        }
    }
    Ok(best)
}
