//! Where a sliding line contact first yields: the stresses that the contact's pressure q2 and
//! shear q1 cause in an elastic half-plane, Flamant's line-load solutions superposed (Johnson
//! (1985) sections 2.1-2.4) in plane strain, and the largest von Mises equivalent stress, at the
//! surface or beneath it (Johnson (1985) sections 7.2 and 9.2: with friction the largest stress
//! moves from below the surface to the surface at the trailing edge).
//!
//! The field is the half-plane's: exact for the wide model on a half-plane, an estimate on a
//! strip of finite thickness, whose bonded base changes the field once h is not large against
//! a + b; not given under the narrow model, whose thin bonded layer is nothing like a half-plane.
//!
//! Axes as the solution's: x along the sliding direction (the leading edge b at +x, q1 > 0 acting
//! on the strip in +x), z into the strip. Stresses in Pa, tension positive.

use std::f64::consts::PI;

use serde::Serialize;

use crate::physics::plane::{Model, PlaneSolution};
use crate::physics::quadrature::gauss_legendre;
use crate::units::format_si;

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

/// Why the largest stress of a contact is not given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NotJudged {
    /// The pressure is unbounded at a sharp corner of the punch: the strip yields there under
    /// any load.
    SharpCorners,
    /// The narrow (Winkler) model: a thin bonded layer, whose stresses are not a half-plane's.
    ThinLayer,
    /// The half-plane's largest stress lies deeper than the strip is thick, where the strip's
    /// rigid base is: the half-plane's field does not describe the bonded layer there.
    BelowLayer {
        /// Depth [m] of the half-plane's largest von Mises stress below the surface.
        depth: f64,
        /// The strip's thickness h [m].
        thickness: f64,
    },
}

impl NotJudged {
    /// Why, in words.
    pub fn reason(self) -> String {
        match self {
            NotJudged::SharpCorners => "the pressure is unbounded at the punch's sharp corners: \
                                        the strip yields there under any load"
                .into(),
            NotJudged::ThinLayer => "the narrow model's thin bonded layer is not a half-plane, \
                                     whose stresses this check computes"
                .into(),
            NotJudged::BelowLayer { depth, thickness } => format!(
                "the peak stress of a half-plane lies at depth {}, below the layer (h = {})",
                format_si(depth, "m"),
                format_si(thickness, "m")
            ),
        }
    }
}

/// A note in JSON: its reason in words.
impl Serialize for NotJudged {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(&self.reason())
    }
}

/// Panels of the 8-point Gauss rule in the angle phi, s = -a + w (1 - cos phi)/2, over which
/// the tractions are sampled once: the angle smooths their square-root ends.
const PANELS: usize = 128;
/// The shallowest depth of the field beneath the surface, in panel widths at the contact's
/// middle (the widest): shallower, the kernels are narrower than the panels. Above it the
/// surface stands for the layer.
const SHALLOWEST: f64 = 2.0;
/// Grid of the search: x points on the surface, x points and depths beneath it.
const SURFACE_POINTS: usize = 121;
const X_POINTS: usize = 61;
const DEPTHS: usize = 24;
/// Steps of the local search after the grid; each halves the step when it finds nothing better.
const REFINE_STEPS: usize = 60;

/// The contact's tractions at the nodes of a fixed rule over [-a, b].
struct Tractions {
    /// Node positions [m].
    s: Vec<f64>,
    /// Quadrature weights [m].
    w: Vec<f64>,
    /// q2 [Pa] at the nodes.
    p: Vec<f64>,
    /// q1 [Pa] at the nodes.
    q: Vec<f64>,
    /// The shallowest depth [m] at which the rule resolves the field.
    shallowest: f64,
}

impl Tractions {
    fn of(sol: &PlaneSolution) -> Tractions {
        let (lo, width) = (-sol.a, sol.contact_width());
        let rule = gauss_legendre(8);
        let dphi = PI / PANELS as f64;
        let mut t = Tractions {
            s: Vec::with_capacity(8 * PANELS),
            w: Vec::with_capacity(8 * PANELS),
            p: Vec::with_capacity(8 * PANELS),
            q: Vec::with_capacity(8 * PANELS),
            shallowest: SHALLOWEST * 0.5 * width * dphi,
        };
        for k in 0..PANELS {
            let mid = (k as f64 + 0.5) * dphi;
            for (u, weight) in rule.nodes.iter().zip(&rule.weights) {
                let phi = mid + 0.5 * dphi * u;
                let x = lo + 0.5 * width * (1.0 - phi.cos());
                t.s.push(x);
                t.w.push(0.5 * dphi * weight * 0.5 * width * phi.sin());
                t.p.push(sol.pressure(x));
                t.q.push(sol.shear(x));
            }
        }
        t
    }

    /// The stresses at depth z >= `shallowest` beneath x: Flamant's line loads p (compressive)
    /// and q (in +x) at s, dx = x - s, r^2 = dx^2 + z^2:
    /// normal  sx = -2p dx^2 z/(pi r^4), sz = -2p z^3/(pi r^4), txz = -2p dx z^2/(pi r^4);
    /// tangent sx = -2q dx^3/(pi r^4),   sz = -2q dx z^2/(pi r^4), txz = -2q dx^2 z/(pi r^4).
    fn beneath(&self, x: f64, z: f64) -> Stress {
        let (mut sx, mut sz, mut txz) = (0.0, 0.0, 0.0);
        for i in 0..self.s.len() {
            let dx = x - self.s[i];
            let load = self.w[i] * (self.p[i] * z + self.q[i] * dx) / (dx * dx + z * z).powi(2);
            sx += load * dx * dx;
            sz += load * z * z;
            txz += load * dx * z;
        }
        let c = -2.0 / PI;
        Stress {
            sx: c * sx,
            sz: c * sz,
            txz: c * txz,
        }
    }

    /// The stresses on the surface: sz = -q2, txz = -q1 under the contact (0 beyond it), and
    /// sx = -q2(x) - (2/pi) p.v. int q1(s)/(x - s) ds (Johnson (1985) section 2.4), the
    /// principal value as the regular integral of (q1(s) - q1(x))/(x - s) plus
    /// q1(x) ln((x + a)/(b - x)).
    fn surface(&self, sol: &PlaneSolution, x: f64) -> Stress {
        let (lo, hi) = (-sol.a, sol.b);
        let inside = lo < x && x < hi;
        let (p, q) = if inside {
            (sol.pressure(x), sol.shear(x))
        } else {
            (0.0, 0.0)
        };
        let mut hilbert: f64 = (0..self.s.len())
            .filter(|&i| self.s[i] != x)
            .map(|i| self.w[i] * (self.q[i] - q) / (x - self.s[i]))
            .sum();
        if inside {
            hilbert += q * ((x - lo) / (hi - x)).ln();
        }
        Stress {
            sx: -p - 2.0 / PI * hilbert,
            sz: -p,
            txz: -q,
        }
    }
}

/// The stresses at (x, z) [m]: on the surface for z = 0, beneath it for z at least a small
/// fraction of the contact width (about w/40; shallower depths are taken at that depth).
pub fn stress(sol: &PlaneSolution, x: f64, z: f64) -> Stress {
    let t = Tractions::of(sol);
    if z <= 0.0 {
        t.surface(sol, x)
    } else {
        t.beneath(x, z.max(t.shallowest))
    }
}

/// The largest von Mises stress of the contact: the surface at x in [-a - w/5, b + w/5]
/// (w = a + b) and the edges, and beneath it from the shallowest depth resolved to 1.5 w; a
/// bounded compass search around the best of each. Not judged for a punch with sharp corners
/// or under the narrow model.
pub fn peak(sol: &PlaneSolution) -> Result<Peak, NotJudged> {
    if sol.inputs.shape.is_sharp() {
        return Err(NotJudged::SharpCorners);
    }
    if sol.model == Model::Narrow {
        return Err(NotJudged::ThinLayer);
    }
    let nu = sol.inputs.material.poisson_ratio;
    let t = Tractions::of(sol);
    let w = sol.contact_width();
    let across =
        |n: usize| (0..n).map(move |i| -sol.a - 0.2 * w + 1.4 * w * i as f64 / (n - 1) as f64);
    let surface = |x: f64| t.surface(sol, x).von_mises(nu);
    let beneath = |x: f64, z: f64| t.beneath(x, z.max(t.shallowest)).von_mises(nu);
    let better = |best: Peak, candidate: Peak| {
        if candidate.stress > best.stress {
            candidate
        } else {
            best
        }
    };
    let none = Peak {
        stress: f64::NEG_INFINITY,
        x: 0.0,
        depth: 0.0,
    };
    let mut top = across(SURFACE_POINTS)
        .chain([-sol.a, sol.b])
        .map(|x| Peak {
            stress: surface(x),
            x,
            depth: 0.0,
        })
        .fold(none, better);
    let depths: Vec<f64> = (0..DEPTHS)
        .map(|k| t.shallowest * (1.5 * w / t.shallowest).powf(k as f64 / (DEPTHS - 1) as f64))
        .collect();
    let mut deep = none;
    for x in across(X_POINTS) {
        for &depth in &depths {
            deep = better(
                deep,
                Peak {
                    stress: beneath(x, depth),
                    x,
                    depth,
                },
            );
        }
    }
    // compass searches: the step starts at a grid spacing and halves where no neighbour is
    // larger
    let mut h = 1.4 * w / (SURFACE_POINTS - 1) as f64;
    for _ in 0..REFINE_STEPS {
        let here = top;
        for x in [here.x - h, here.x + h] {
            top = better(
                top,
                Peak {
                    stress: surface(x),
                    x,
                    depth: 0.0,
                },
            );
        }
        if top == here {
            h *= 0.5;
        }
    }
    let mut h = 1.4 * w / (X_POINTS - 1) as f64;
    for _ in 0..REFINE_STEPS {
        let here = deep;
        for (dx, dz) in [(h, 0.0), (-h, 0.0), (0.0, h), (0.0, -h)] {
            let (x, depth) = (here.x + dx, (here.depth + dz).max(t.shallowest));
            deep = better(
                deep,
                Peak {
                    stress: beneath(x, depth),
                    x,
                    depth,
                },
            );
        }
        if deep == here {
            h *= 0.5;
        }
    }
    Ok(better(top, deep))
}

/// What the strip's yield stress is known from: its yield strength, else its hardness.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Strength {
    /// Yield strength Y [Pa] in tension, when given.
    pub yield_strength: Option<f64>,
    /// Indentation hardness H [Pa], when given.
    pub hardness: Option<f64>,
}

impl Strength {
    /// The yield stress [Pa] and where it comes from: Y when given, else H/3 (Tabor (1951): the
    /// hardness of a plastically rigid solid is about three times its yield stress); None when
    /// neither is given.
    pub fn yield_stress(self) -> Option<(f64, &'static str)> {
        match (self.yield_strength, self.hardness) {
            (Some(y), _) => Some((y, "yield_strength")),
            (None, Some(h)) => Some((h / 3.0, "hardness / 3")),
            (None, None) => None,
        }
    }
}

/// The yield check of a contact: its largest von Mises stress against the yield stress.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct YieldCheck {
    /// The yield stress Y [Pa] judged against.
    pub strength: f64,
    /// Where Y comes from: "yield_strength", or "hardness / 3".
    pub basis: &'static str,
    /// The hardness was given beside the yield strength and is not used: Y comes first.
    #[serde(skip)]
    pub hardness_unused: bool,
    /// The largest von Mises stress [Pa]; null where it is not judged (`note` says why).
    pub von_mises_max: Option<f64>,
    /// von_mises_max / Y (dimensionless); null where not judged.
    pub ratio: Option<f64>,
    /// x [m] of the largest stress (the solution's moving frame); null where not judged.
    pub x: Option<f64>,
    /// Depth [m] of the largest stress below the strip's surface (0: on it); null where not
    /// judged.
    pub depth: Option<f64>,
    /// Whether the strip yields: the largest stress reaches Y, or the pressure is unbounded at
    /// sharp corners; null under the narrow model and where the half-plane's largest stress
    /// lies below the layer.
    pub yields: Option<bool>,
    /// Why the largest stress is not given, where it is not (in JSON, in words).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<NotJudged>,
}

/// The half-plane's peak where it lies within the strip; where it lies deeper than the strip's
/// thickness h, the estimate does not hold (the strip is bonded to a rigid base at depth h).
fn within_layer(sol: &PlaneSolution, p: Peak) -> Result<Peak, NotJudged> {
    let thickness = sol.inputs.material.thickness;
    if p.depth > thickness {
        Err(NotJudged::BelowLayer {
            depth: p.depth,
            thickness,
        })
    } else {
        Ok(p)
    }
}

/// The yield check of a solution when the strength is known: not judged where `peak` is not
/// given or where the half-plane's peak lies below the layer.
pub fn judge(sol: &PlaneSolution, strength: Strength) -> Option<YieldCheck> {
    let (y, basis) = strength.yield_stress()?;
    let hardness_unused = strength.yield_strength.is_some() && strength.hardness.is_some();
    let check = match peak(sol).and_then(|p| within_layer(sol, p)) {
        Ok(p) => YieldCheck {
            strength: y,
            basis,
            hardness_unused,
            von_mises_max: Some(p.stress),
            ratio: Some(p.stress / y),
            x: Some(p.x),
            depth: Some(p.depth),
            yields: Some(p.stress >= y),
            note: None,
        },
        Err(why) => YieldCheck {
            strength: y,
            basis,
            hardness_unused,
            von_mises_max: None,
            ratio: None,
            x: None,
            depth: None,
            yields: (why == NotJudged::SharpCorners).then_some(true),
            note: Some(why),
        },
    };
    Some(check)
}
