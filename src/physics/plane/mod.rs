//! The plane problem (Soldatenkov (2007), `docs/references.md`; verified formulas in `docs/physics/plane.md`):
//! a rigid parabolic punch g(x) = x^2/(2R) slides with Coulomb friction and adhesion over an
//! elastic strip bonded to a rigid base; the strip wears, W' = -k q2.
//!
//! Conventions (docs/physics/plane.md section 1): x along the surface, positive in the punch's direction of
//! motion, origin at the punch tip; contact zone [-a, b] with b the leading edge; q2 > 0 pressure;
//! q1 shear on the strip, positive in +x.

pub mod checks;
pub mod criteria;
pub mod dominance;
pub mod energy;
mod found;
pub mod general;
pub mod groups;
pub mod laws;
pub mod narrow;
pub mod narrow_ode;
pub mod operating_point;
pub mod profile;
pub mod scope;
pub mod shape;
pub mod shape_validity;
pub mod sharp;
pub mod sharp_strip;
pub mod spline;
pub mod strip;
pub mod strip_check;
pub mod sweep;
pub mod sweep_verdicts;
pub mod validity;
pub mod verdict_table;
pub mod wide;
pub mod yield_onset;
mod yield_phrase;

use serde::{Deserialize, Serialize};

use crate::physics::{Friction, Material, SolveError, limits, validate_common};

pub(crate) use found::Found;
pub use laws::{FrictionLaw, WearLaw};
pub use operating_point::{OperatingPoint, operating_point};
pub use shape::Shape;

/// Which asymptotic model of the strip to solve.
#[derive(
    Clone,
    Copy,
    Debug,
    PartialEq,
    Eq,
    Hash,
    Serialize,
    Deserialize,
    strum::VariantArray,
    strum::VariantNames,
    strum::IntoStaticStr,
)]
#[serde(rename_all = "lowercase")]
#[strum(serialize_all = "lowercase")]
pub enum Model {
    /// Wide strip, (a+b)/h -> 0: half-plane kernel plus the thickness correction c12 (section 4).
    Wide,
    /// Narrow strip, (a+b)/h -> inf: Winkler foundation (section 5).
    Narrow,
    /// Any thickness: the exact strip kernels (3.7), solved by collocation (docs/physics/plane.md section 6).
    Strip,
}

impl Model {
    /// Every model, in the order the explorer cycles through them (the order declared).
    pub const ALL: &'static [Model] = <Model as strum::VariantArray>::VARIANTS;

    /// Every model's name, in the order of `ALL`.
    pub const NAMES: &'static [&'static str] = <Model as strum::VariantNames>::VARIANTS;

    /// The name used in preset files and in JSON (the variant's, in lower case, as serde's).
    pub fn name(self) -> &'static str {
        self.into()
    }

    /// True for the models that need a finite thickness (all but the wide one, which is exact
    /// for the half-plane).
    pub fn needs_finite_thickness(self) -> bool {
        self != Model::Wide
    }
}

/// The inputs of one plane solve at one load.
#[derive(Clone, Debug, PartialEq)]
pub struct PlaneInputs {
    /// The elastic strip.
    pub material: Material,
    /// Friction law q1 = mu q2 + tau0 below the shear strength.
    pub friction: Friction,
    /// Shear strength tau_max [Pa] > tau0 capping the friction stress, q1 = min(mu q2 + tau0,
    /// tau_max); inf (the default) is no cap.
    pub shear_strength: f64,
    /// Wear law W' = -k q2 (q2/p0)^(n-1): wear depth per unit sliding distance.
    pub wear: WearLaw,
    /// The punch's shape g(x).
    pub shape: Shape,
    /// Normal load per unit length P [N/m], > 0.
    pub load: f64,
}

impl PlaneInputs {
    /// The paper's worked example: a parabolic punch of radius R [m], the linear wear law with
    /// coefficient k [1/Pa] and uncapped friction, at the load P [N/m].
    pub fn parabolic(
        material: Material,
        friction: Friction,
        wear: f64,
        radius: f64,
        load: f64,
    ) -> PlaneInputs {
        PlaneInputs {
            material,
            friction,
            shear_strength: f64::INFINITY,
            wear: WearLaw::linear(wear),
            shape: Shape::Parabola { radius },
            load,
        }
    }

    /// The same inputs at another load.
    pub fn with_load(&self, load: f64) -> PlaneInputs {
        PlaneInputs {
            load,
            ..self.clone()
        }
    }

    /// The punch's radius R [m] (`Shape::radius`): the parabola's for the closed forms.
    pub fn radius(&self) -> f64 {
        self.shape.radius()
    }

    /// True when the closed forms and today's strip solver answer: a parabola, the linear wear
    /// law and no shear cap.
    pub fn is_classical(&self) -> bool {
        self.shape.parabola_radius().is_some()
            && self.wear.is_linear()
            && self.shear_strength == f64::INFINITY
    }

    /// The friction law q1 = min(mu q2 + tau0, tau_max) of these inputs.
    pub fn friction_law(&self) -> FrictionLaw {
        FrictionLaw {
            coulomb: self.friction,
            shear_strength: self.shear_strength,
        }
    }

    /// Pi(q) [Pa]: the shear stress at the pressure q [Pa] (`FrictionLaw::shear`).
    pub fn shear_at(&self, q: f64) -> f64 {
        self.friction_law().shear(q)
    }

    /// Checks every field against its allowed range (see `physics::limits`) and refuses the
    /// combinations without a steady solution: sharp corners with a nonlinear wear law (the
    /// wear at a corner's singular pressure outgrows every power), sharp corners with a finite
    /// shear strength (the cap holds at the corners, a case not derived here).
    pub fn validate(&self) -> Result<(), SolveError> {
        validate_common(&self.material, &self.friction, self.wear.coefficient)?;
        self.wear.validate()?;
        self.friction_law().validate()?;
        self.shape.validate()?;
        limits::check_all(&[(&limits::LINE_LOAD, "load", self.load)])
            .map_err(SolveError::InvalidInput)?;
        if self.shape.is_sharp() && self.wear.coefficient > 0.0 && !self.wear.is_linear() {
            return Err(SolveError::InvalidInput(
                "a flat punch with sharp corners has no steady solution with a nonlinear wear \
                 law (n > 1): the wear at the singular corner pressure cannot be balanced; use \
                 wear.exponent = 1, k = 0 or a rounded edge (edge_radius > 0)"
                    .into(),
            ));
        }
        if self.shape.is_sharp() && self.shear_strength.is_finite() {
            return Err(SolveError::InvalidInput(
                "a flat punch with sharp corners cannot take a finite shear_strength: the cap \
                 would hold at the corners, where the pressure is unbounded, a case wearlab does \
                 not solve; remove shear_strength or round the edges (edge_radius > 0)"
                    .into(),
            ));
        }
        Ok(())
    }
}

/// How q2(x) is evaluated for a solved operating point.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum PressureLaw {
    /// q2 = c (a + x)^{1/2 - theta} (b - x)^{1/2 + theta}, (4.4) with the corrected prefactor.
    Wide { c: f64, theta: f64 },
    /// The Winkler solution (5.7) in its stable form, see `narrow::pressure`.
    Narrow { lambda: f64, beta: f64 },
    /// The collocation solution of the strip: q2 = w(t) phi(t).
    Strip(std::sync::Arc<strip::Collocation>),
    /// The narrow model's shot for any shape and law: q2 interpolated between its nodes.
    Shooting(std::sync::Arc<narrow_ode::Nodes>),
    /// The general solver's collocation (`general`), with the distances [m] from the trailing
    /// edge where q2 or Pi(q2) has a kink (the punch's, the cap's), at which quadratures split.
    General {
        pressure: std::sync::Arc<general::pressure::Pressure>,
        kinks: std::sync::Arc<[f64]>,
    },
    /// Sharp corners on the half-plane or wide strip: q2 = Z (A + B u), u = x + a,
    /// Z = u^(-1/2-theta) (L-u)^(-1/2+theta) (`sharp`); A [Pa m], B [Pa], L [m].
    Corners {
        theta: f64,
        constant: f64,
        slope: f64,
        width: f64,
    },
    /// Sharp corners on the strip of any thickness: the collocation of `sharp_strip`.
    StripCorners(std::sync::Arc<sharp_strip::CornerPressure>),
    /// Sharp corners on the Winkler strip: q2 = q_b e^(-lambda (b - x)), q_b [Pa] at the leading
    /// corner, lambda = k/beta [1/m] (`sharp`).
    Face { leading: f64, lambda: f64 },
}

/// The solution of the plane problem at one load. Serialised with the keys of `wearlab solve`'s
/// JSON (`docs/cli.md`): the inputs as their load P, without Q1 and the pressure law.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PlaneSolution {
    /// The model that produced it.
    pub model: Model,
    /// The inputs it solves (serialised as `load`, P [N/m]).
    #[serde(rename = "load", serialize_with = "load_of")]
    pub inputs: PlaneInputs,
    /// Q2 = integral of q2 [N/m], the total normal contact force.
    pub normal_force: f64,
    /// Q1 = mu Q2 + tau0 (a + b) [N/m], the total friction force.
    #[serde(skip)]
    pub friction_force: f64,
    /// T = Q1 + psi [N/m], the tangential force that drives the punch (3.11).
    pub tangential_force: f64,
    /// Trailing half-width a [m]: the contact zone is [-a, b].
    pub a: f64,
    /// Leading half-width b [m].
    pub b: f64,
    /// Exponent shift theta of the wide solution (4.5), in (-1/2, 1/2), from gamma of (4.3): > 0
    /// where friction shifts the edge exponents more than wear, < 0 where wear does. On the
    /// half-plane without adhesion its sign is which effect dominates (a > b and mu* < mu where
    /// it is positive); on a strip of finite thickness the thickness term moves the balance and
    /// the solution's signs say it (`dominance`).
    /// None for the narrow model.
    pub theta: Option<f64>,
    /// gamma = pi chi mu / m - k [1/Pa] of (4.3) (without k for a nonlinear wear law, which does
    /// not enter the edge exponents: docs/physics/plane-general.md section 3). None for the
    /// narrow model.
    pub gamma: Option<f64>,
    /// psi = integral of q2 g' [N/m], the deformation component of friction (2.2).
    pub psi: f64,
    /// phi = integral of q1 g' [N/m] (2.1), the friction's share of the load: P = Q2 - phi;
    /// mu psi + tau0 Delta_g without a shear cap.
    #[serde(skip)]
    pub phi: f64,
    /// Delta_g = g(b) - g(-a) [m] (3.11).
    pub delta_g: f64,
    /// Total friction coefficient mu* (3.13), dimensionless.
    pub mu_star: f64,
    #[serde(skip)]
    pub(crate) law: PressureLaw,
}

/// The inputs of a solution as the JSON shows them: their load P [N/m].
fn load_of<S: serde::Serializer>(inputs: &PlaneInputs, out: S) -> Result<S::Ok, S::Error> {
    out.serialize_f64(inputs.load)
}

impl PlaneSolution {
    /// Contact width L = a + b [m].
    pub fn contact_width(&self) -> f64 {
        self.a + self.b
    }

    /// Contact pressure q2(x) [Pa] at x [m] (moving frame); 0 outside [-a, b].
    pub fn pressure(&self, x: f64) -> f64 {
        if !(x > -self.a && x < self.b) {
            return 0.0;
        }
        self.pressure_from_trailing_edge(x + self.a)
    }

    /// Contact pressure [Pa] at distance u [m] from the trailing edge, u in [0, a + b]; 0 outside.
    /// Local coordinates keep full precision near both edges even when the contact zone lies far
    /// from the punch tip.
    pub fn pressure_from_trailing_edge(&self, u: f64) -> f64 {
        let l = self.contact_width();
        if !(u > 0.0 && u < l) {
            return 0.0;
        }
        match &self.law {
            &PressureLaw::Wide { c, theta } => c * u.powf(0.5 - theta) * (l - u).powf(0.5 + theta),
            &PressureLaw::Narrow { lambda, beta } => {
                narrow::pressure(u, l, lambda, beta, self.inputs.radius())
            }
            PressureLaw::Strip(col) => col.pressure_from_trailing_edge(u),
            PressureLaw::Shooting(nodes) => nodes.pressure(u - self.a),
            PressureLaw::General { pressure, .. } => pressure.pressure_from_trailing_edge(u),
            &PressureLaw::Corners {
                theta,
                constant,
                slope,
                width,
            } => sharp::corners_pressure(theta, constant, slope, width, u),
            PressureLaw::StripCorners(p) => p.pressure_from_trailing_edge(u),
            &PressureLaw::Face { leading, lambda } => sharp::face_pressure(leading, lambda, l - u),
        }
    }

    /// Shear stress q1(x) = min(mu q2 + tau0, tau_max) [Pa] on the strip, positive in +x; 0
    /// outside [-a, b].
    pub fn shear(&self, x: f64) -> f64 {
        if x < -self.a || x > self.b {
            return 0.0;
        }
        self.inputs.shear_at(self.pressure(x))
    }

    /// Wear rate F(q2(x)): wear depth per unit sliding distance (dimensionless).
    pub fn wear_rate(&self, x: f64) -> f64 {
        self.inputs.wear.rate(self.pressure(x))
    }
}

/// Solves the plane problem at the inputs' load with the chosen model; the solution has passed
/// the physical checks (`plane::checks`).
pub fn solve(inputs: &PlaneInputs, model: Model) -> Result<PlaneSolution, SolveError> {
    inputs.validate()?;
    scope::check(inputs, model)?;
    let sol = match (model, inputs.shape.sharp_half_width()) {
        (_, Some(c)) => sharp::solve(inputs, model, c),
        (Model::Wide, _) if inputs.is_classical() => wide::solve(inputs),
        (Model::Wide, _) => general::answer::solve(inputs, model),
        (Model::Narrow, _) => solve_narrow(inputs),
        (Model::Strip, _) if inputs.is_classical() => strip::solve(inputs),
        (Model::Strip, _) => general::answer::solve(inputs, model),
    }?;
    checks::check(&sol)?;
    Ok(sol)
}

/// The strip model's solution against which `strip_check` measures another model: as `solve`
/// gives it, for the parabola with the linear laws to the accuracy a measurement needs
/// (`strip::solve_to_check`).
pub(crate) fn solve_strip_to_check(inputs: &PlaneInputs) -> Result<PlaneSolution, SolveError> {
    if !inputs.is_classical() {
        return solve(inputs, Model::Strip);
    }
    inputs.validate()?;
    scope::check(inputs, Model::Strip)?;
    let sol = strip::solve_to_check(inputs)?;
    checks::check(&sol)?;
    Ok(sol)
}

/// The narrow model: the closed form (5.7) for the parabola with the linear law and no cap, the
/// shooting of `narrow_ode` for every other shape and law.
pub(crate) fn solve_narrow(inputs: &PlaneInputs) -> Result<PlaneSolution, SolveError> {
    if inputs.is_classical() {
        narrow::solve(inputs)
    } else {
        narrow_ode::solve(inputs)
    }
}

/// m [Pa], gamma [1/Pa] and theta of the dominant equation (4.3): gamma = pi chi mu/m - k,
/// theta = arctan(m gamma/pi)/pi (4.5). Shared by the wide and the strip models.
pub(crate) fn exponent(inputs: &PlaneInputs) -> (f64, f64, f64) {
    let m = inputs.material.plane_modulus();
    let gamma = std::f64::consts::PI * inputs.material.chi() * inputs.friction.coefficient / m
        - inputs.wear.coefficient;
    (
        m,
        gamma,
        (m * gamma / std::f64::consts::PI).atan() / std::f64::consts::PI,
    )
}
