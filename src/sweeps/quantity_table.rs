//! The table of quantities, plane first, then spatial, and what one entry holds (`Quantity`). The formulas are
//! those of `docs/physics/plane.md` and `docs/physics/spatial.md`; the values are read from the
//! solution the solvers return, never recomputed here.

use crate::physics::plane::Model;
use crate::physics::plane::energy::Energy;
use crate::physics::plane::groups as plane_groups;
use crate::physics::spatial::groups as spatial_groups;
use crate::physics::spatial::result::HarmonicResult;
use crate::preset::{Preset, Problem};
use crate::sweeps::point::{PlanePoint, SpatialPoint};

/// How a quantity is computed from a point.
#[derive(Clone, Copy, Debug)]
pub enum Eval {
    /// From a plane point.
    Plane(fn(&PlanePoint) -> Result<f64, String>),
    /// From a spatial point.
    Spatial(fn(&SpatialPoint) -> Result<f64, String>),
    /// From one harmonic (0-based) of a spatial point.
    Harmonic(fn(&SpatialPoint, usize) -> Result<f64, String>),
}

/// Where a quantity comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Origin {
    /// A key of `wearlab solve`'s JSON report.
    Report,
    /// Derived from the solution (the explorer's sweep chart offers it).
    Derived,
}

/// One quantity.
#[derive(Clone, Copy, Debug)]
pub struct Quantity {
    /// The name in `--output`, in CSV headers and JSON keys; `N` stands for a harmonic's index.
    pub name: &'static str,
    /// The symbol on charts ("mu*", "a+b", "1/beta").
    pub symbol: &'static str,
    /// The SI unit ("" for dimensionless).
    pub unit: &'static str,
    /// What it is, in words (its sign convention where it has one).
    pub description: &'static str,
    /// The problem it belongs to.
    pub problem: Problem,
    /// A key of the solve report, or derived.
    pub origin: Origin,
    /// One of the problem's dimensionless groups (the explorer's dimensionless view).
    pub group: bool,
    /// A yes/no answer, 1 or 0 (written true/false).
    pub flag: bool,
    /// The plane models that have it (None: all).
    pub models: Option<&'static [Model]>,
    /// How it is computed.
    pub eval: Eval,
}

impl Quantity {
    /// Why the preset's model has no such quantity (theta for the narrow model), if it has none.
    pub fn missing_in(&self, preset: &Preset) -> Option<String> {
        let model = preset.plane.model;
        match self.models {
            Some(models) if preset.problem == Problem::Plane && !models.contains(&model) => {
                Some(format!("the {} model has no {}", model.name(), self.symbol))
            }
            _ => None,
        }
    }
}

const fn entry(
    name: &'static str,
    symbol: &'static str,
    unit: &'static str,
    description: &'static str,
    problem: Problem,
    eval: Eval,
) -> Quantity {
    Quantity {
        name,
        symbol,
        unit,
        description,
        problem,
        origin: Origin::Report,
        group: false,
        flag: false,
        models: None,
        eval,
    }
}

const fn plane(
    name: &'static str,
    symbol: &'static str,
    unit: &'static str,
    description: &'static str,
    eval: fn(&PlanePoint) -> Result<f64, String>,
) -> Quantity {
    entry(
        name,
        symbol,
        unit,
        description,
        Problem::Plane,
        Eval::Plane(eval),
    )
}

const fn spatial(
    name: &'static str,
    symbol: &'static str,
    unit: &'static str,
    description: &'static str,
    eval: fn(&SpatialPoint) -> Result<f64, String>,
) -> Quantity {
    entry(
        name,
        symbol,
        unit,
        description,
        Problem::Spatial,
        Eval::Spatial(eval),
    )
}

const fn harmonic(
    name: &'static str,
    symbol: &'static str,
    unit: &'static str,
    description: &'static str,
    eval: fn(&SpatialPoint, usize) -> Result<f64, String>,
) -> Quantity {
    entry(
        name,
        symbol,
        unit,
        description,
        Problem::Spatial,
        Eval::Harmonic(eval),
    )
}

impl Quantity {
    const fn derived(self) -> Quantity {
        Quantity {
            origin: Origin::Derived,
            ..self
        }
    }
    const fn group(self) -> Quantity {
        Quantity {
            group: true,
            ..self
        }
    }
    const fn flag(self) -> Quantity {
        Quantity { flag: true, ..self }
    }
    const fn only(self, models: &'static [Model]) -> Quantity {
        Quantity {
            models: Some(models),
            ..self
        }
    }
}

/// The models whose solution has the exponent shift theta (and gamma).
const EXPONENT: &[Model] = &[Model::Wide, Model::Strip];

fn exponent(value: Option<f64>) -> Result<f64, String> {
    value.ok_or_else(|| "the narrow model has no theta".into())
}

/// A quantity of the energy identity, or why it has no number (sharp corners).
fn balance(p: &PlanePoint, of: fn(&Energy) -> f64) -> Result<f64, String> {
    p.energy().map(|e| of(&e)).map_err(|u| u.note.to_string())
}

fn yes(flag: bool) -> Result<f64, String> {
    Ok(if flag { 1.0 } else { 0.0 })
}

fn wave(s: &SpatialPoint, n: usize) -> &HarmonicResult {
    &s.result.harmonics[n]
}

/// Every quantity.
#[rustfmt::skip]
pub(crate) const QUANTITIES: &[Quantity] = &[
    plane("load", "P", "N/m", "normal load per unit length (the input)", |p| Ok(p.solution.inputs.load)),
    plane("normal_force", "Q2", "N/m", "total normal contact force", |p| Ok(p.solution.normal_force)),
    plane("tangential_force", "T", "N/m", "tangential force that drives the punch, T = Q1 + psi (3.11)", |p| Ok(p.solution.tangential_force)),
    plane("a", "a", "m", "trailing half-width: the contact zone is [-a, b]", |p| Ok(p.solution.a)),
    plane("b", "b", "m", "leading half-width (b is the leading edge)", |p| Ok(p.solution.b)),
    plane("theta", "theta", "", "exponent shift of the pressure, q2 ~ (a+x)^(1/2-theta) (b-x)^(1/2+theta) (4.5), from gamma = pi chi mu/m - k: > 0 friction shifts the edges more than wear, < 0 wear does; which dominates the contact is the sign of mu* - mu (on a half-plane, the same as theta's)", |p| exponent(p.solution.theta)).only(EXPONENT).group(),
    plane("gamma", "gamma", "1/Pa", "gamma = pi chi mu/m - k of (4.3); theta has its sign", |p| exponent(p.solution.gamma)).only(EXPONENT),
    plane("psi", "psi", "N/m", "deformation component of friction, the integral of q2 g' (2.2)", |p| Ok(p.solution.psi)),
    plane("delta_g", "Delta_g", "m", "g(b) - g(-a) (3.11)", |p| Ok(p.solution.delta_g)),
    plane("mu_star", "mu*", "", "total friction coefficient (3.13)", |p| Ok(p.solution.mu_star)),
    plane("energy.I", "I", "N/m", "integral of q1 u', one side of the energy identity (2.9)", |p| balance(p, |e| e.i)),
    plane("energy.J", "J", "N/m", "integral of q2 v', the other side of (2.9)", |p| balance(p, |e| e.j)),
    plane("energy.residual", "I-J residual", "", "|I - J| relative to the gross work: how well (2.9) holds", |p| balance(p, |e| e.residual)),
    plane("energy.friction_loss", "friction loss", "N/m", "power dissipated by friction per unit sliding speed, Q1 + I (2.5)", |p| balance(p, |e| e.friction_loss)),
    plane("energy.wear_loss", "wear loss", "N/m", "power spent on wear per unit sliding speed, psi - J (2.7)", |p| p.energy().map_or_else(|u| u.wear_loss.ok_or_else(|| u.note.to_string()), |e| Ok(e.wear_loss))),
    plane("energy.external", "T", "N/m", "work of the tangential force per unit sliding distance: friction loss + wear loss when I = J (2.8)-(2.9)", |p| Ok(p.energy().map_or_else(|u| u.external, |e| e.external))),
    plane("energy.contact_residual", "contact residual", "", "|psi - J - k int q2^2| relative to T: how well the solution meets the contact condition", |p| balance(p, |e| e.contact_residual)),
    plane("energy.friction_share", "friction loss/T", "", "the friction loss's share of the external work T, (Q1 + I)/T (2.5)", |p| p.energy().map_err(|u| u.note.to_string()).and_then(|e| share(e.friction_share()))).derived(),
    plane("energy.wear_share", "wear loss/T", "", "the wear loss's share of the external work T, (psi - J)/T (2.7): 0 without wear, growing with k", wear_share).derived(),
    plane("validity.ok", "valid", "", "whether the model holds at this point (1 yes, 0 no): measured against the strip model where the study's estimate doubts it, as wearlab solve reports it", |p| yes(p.verdict().ok)).flag(),
    plane("validity.contact_width_over_thickness", "(a+b)/h", "", "contact width over the thickness, 0 for the half-plane: the wide model is the limit of small values, the narrow (Winkler) model of large ones", |p| Ok(p.validity.contact_width_over_thickness)).group(),
    plane("mu_star_minus_mu", "mu*-mu", "", "deformation part of friction: > 0 where the pressure leans forwards (wear dominates; a thin strip also leans so under friction alone), < 0 where friction dominates", |p| Ok(p.solution.mu_star - p.solution.inputs.friction.coefficient)).derived(),
    plane("contact_width", "a+b", "m", "contact width", |p| Ok(p.solution.contact_width())).derived(),
    plane("max_pressure", "max q2", "Pa", "largest contact pressure", |p| Ok(p.max_pressure())).derived(),
    plane("tip_wear", "tip wear", "m", "wear per pass at the punch tip: k times the integral of q2 from the tip to the leading edge", |p| Ok(p.tip_wear())).derived(),
    plane("width_over_radius", "(a+b)/R", "", "contact width over the punch radius: the small-slope theory needs it small (Hertz: sqrt(8 P/(m R)))", |p| Ok(plane_groups::width_over_radius(&p.solution))).derived().group(),
    plane("wear_number", "k m", "", "wear coefficient times the plane modulus m = pi E/(2(1 - nu^2)): how strongly wear shifts the pressure forwards", |p| Ok(plane_groups::wear_number(&p.solution.inputs))).derived().group(),
    plane("friction_number", "mu chi", "", "friction coefficient times chi = (1 - 2nu)/(2(1 - nu)): how strongly friction shifts the pressure backwards; theta = 0 where mu chi = k m/pi", |p| Ok(plane_groups::friction_number(&p.solution.inputs))).derived().group(),
    plane("load_number", "P/(m R)", "", "load over the plane modulus times the radius: the contact width over the radius grows like its square root", |p| Ok(plane_groups::load_number(&p.solution.inputs))).derived().group(),
    spatial("time", "t", "s", "the instant solved", |s| Ok(s.result.time)),
    spatial("mean_pressure", "pbar", "Pa", "mean contact pressure (the input)", |s| Ok(s.result.mean_pressure)),
    spatial("load", "P", "Pa", "vertical force on the punch per unit area, P = pbar - mu psi - tau0 Delta", |s| Ok(s.result.load)),
    spatial("tangential_force", "T", "Pa", "holding force per unit area along x, T = mu pbar + tau0 fraction + psi", |s| Ok(s.result.tangential_force)),
    spatial("mu_star", "mu*", "", "total friction coefficient, (T - tau0 fraction)/P", |s| Ok(s.result.mu_star)),
    spatial("psi", "psi", "Pa", "deformation component of friction, psi = -<p g_x>", |s| Ok(s.result.psi)),
    spatial("delta", "Delta", "", "-<1_C g_x>, the slope of the contact set (0 in complete contact)", |s| Ok(s.result.delta)),
    spatial("max_pressure", "p_max", "Pa", "largest contact pressure", |s| Ok(s.result.max_pressure)),
    spatial("mean_gap", "<gap>", "m", "mean gap over the cell (0 in complete contact)", |s| Ok(s.result.mean_gap)),
    spatial("contact.complete", "complete", "", "whether the contact is complete, p > 0 over the whole cell (1 yes, 0 no)", |s| yes(s.result.contact.complete)).flag(),
    spatial("contact.fraction", "fraction", "", "fraction of the cell in contact", |s| Ok(s.result.contact.fraction)),
    spatial("contact.time_to_complete", "t_complete", "s", "simulated time at which the running-in makes the contact complete", |s| s.result.contact.time_to_complete.ok_or_else(|| "complete from t = 0, or still partial at the end of the running-in".into())),
    spatial("contact.min_pressure", "p_min", "Pa", "smallest complete-contact pressure p_cc of the shape at t (certified over the cell, or the bound, or over the nodes once worn); negative where the contact is partial", |s| Ok(s.result.contact.min_pressure)),
    spatial("contact.lower_bound", "pbar-sum A/M", "Pa", "pbar - sum A/M with the closed-form amplitudes, a lower bound of p_cc", |s| Ok(s.result.contact.lower_bound)),
    spatial("mu_star_minus_mu", "mu*-mu", "", "deformation part of friction", |s| Ok(s.result.mu_star - s.inputs.friction.coefficient)).derived(),
    harmonic("harmonics.N.k", "k", "rad/m", "wavenumber |(wx, wy)| of the harmonic", |s, n| Ok(wave(s, n).k)),
    harmonic("harmonics.N.decay_rate", "beta", "1/s", "decay rate of the closed form: A(t) = A(0) e^(-beta t)", |s, n| Ok(wave(s, n).decay_rate)),
    harmonic("harmonics.N.drift_velocity", "c", "m/s", "drift velocity of the pattern, positive along +x (the friction force on the layer)", |s, n| Ok(wave(s, n).drift_velocity)),
    harmonic("harmonics.N.phase_rate", "Omega", "rad/s", "phase rate: rho_x(t) = rho_x(0) - Omega t", |s, n| Ok(wave(s, n).phase_rate)),
    harmonic("harmonics.N.phase_lead", "phi", "rad", "phase lead of the pressure over the shape: the friction coupling against the normal compliance, tan phi = mu sx B/A", |s, n| Ok(wave(s, n).phase_lead)).group(),
    harmonic("harmonics.N.pressure_per_amplitude", "1/M", "Pa/m", "pressure amplitude per unit shape amplitude", |s, n| Ok(wave(s, n).pressure_per_amplitude)),
    harmonic("harmonics.N.amplitude", "A", "m", "amplitude at time t (closed form)", |s, n| Ok(wave(s, n).amplitude)),
    harmonic("harmonics.N.phase_x", "rho_x", "rad", "phase along x at time t (closed form)", |s, n| Ok(wave(s, n).phase_x)),
    harmonic("harmonics.N.phase_y", "rho_y", "rad", "phase along y", |s, n| Ok(wave(s, n).phase_y)),
    harmonic("harmonics.N.decay_time", "1/beta", "s", "decay time: the amplitude falls by a factor e in 1/beta", |s, n| decay_time(wave(s, n))).derived(),
    harmonic("harmonics.N.kh", "kh", "", "wavenumber times thickness: below about 1 the layer is thin for this wave, above about 3 it acts as a half-space", kh).derived().group(),
    harmonic("harmonics.N.decay_exponent", "beta t", "", "decay exponent at time t, A(t)/A(0) = e^(-beta t); beta = k V A_c/M^2 with A_c the layer's normal compliance, so without friction beta t = k V t/A_c", |s, n| Ok(spatial_groups::decay_exponent(wave(s, n).decay_rate, s.result.time))).derived().group(),
    harmonic("harmonics.N.pressure_ratio", "A/(M pbar)", "", "the harmonic's pressure amplitude over the mean pressure (closed form): contact is surely complete while these sum below 1", |s, n| Ok(spatial_groups::pressure_ratio(wave(s, n).amplitude, wave(s, n).pressure_per_amplitude, s.result.mean_pressure))).derived().group(),
];

fn share(value: Option<f64>) -> Result<f64, String> {
    value.ok_or_else(|| "T = 0 (no friction, no wear): nothing is dissipated to share".into())
}

/// The wear loss's share of T, also where I and J have no number but the wear loss has one (the
/// Winkler face of a punch with sharp corners).
fn wear_share(p: &PlanePoint) -> Result<f64, String> {
    match p.energy() {
        Ok(e) => share(e.wear_share()),
        Err(u) if u.wear_loss.is_some() => share(u.wear_share()),
        Err(u) => Err(u.note.to_string()),
    }
}

fn decay_time(h: &HarmonicResult) -> Result<f64, String> {
    let beta = h.decay_rate;
    if beta > 0.0 {
        Ok(1.0 / beta)
    } else {
        Err("beta = 0 (no wear, or V = 0): the harmonic does not decay, 1/beta is infinite".into())
    }
}

fn kh(s: &SpatialPoint, n: usize) -> Result<f64, String> {
    let h = s.inputs.material.thickness;
    if h.is_finite() {
        Ok(spatial_groups::kh(wave(s, n).k, h))
    } else {
        Err("h = inf (half-space): kh is infinite".into())
    }
}
