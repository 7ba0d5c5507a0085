//! Which effect dominates at a plane operating point, read from the solution itself. Friction
//! tilts the pressure towards the trailing edge (a > b, psi < 0, so mu* < mu), wear towards the
//! leading edge (a < b, psi > 0, so mu* > mu): Soldatenkov (2007) eqs. (3.13), (4.5) and (4.7).
//! On a half-plane without adhesion the sign of theta decides both signs ((4.5): a - b =
//! 2 theta L; (4.7): psi = -(4/3) theta L Q2/R); on a strip of finite thickness the thickness
//! term of (4.5) shifts the pressure forwards even without wear (mu* > mu at h = 0.1 mm with
//! k = 0 on `polymer-coating.toml`), and adhesion or a measured profile shifts it too, so the
//! solution's own signs are read and the effect is named only where the inputs have it. A flat
//! punch with sharp corners touches along its face at every load (a = b, psi = 0, mu* = mu):
//! there theta says which corner's pressure singularity is the stronger, q2 ~ r^(-1/2-theta) at
//! the trailing corner and r^(-1/2+theta) at the leading one (Galin; Soldatenkov (2007) (4.5)).

use crate::phrase::Phrase;
use crate::physics::plane::{PlaneSolution, Shape};
use crate::units::format_si;

/// |mu* - mu| at or below which mu* counts as equal to mu (dimensionless). Symmetric inputs
/// (mu = 0 and k = 0) give |mu* - mu| below 1e-16 in every model; a real lean at the smallest
/// bundled load (P = 100 N/m) is above 1e-6.
pub const EVEN_MU: f64 = 1e-9;

/// |a - b| / (a + b) at or below which the contact counts as centred (dimensionless); symmetric
/// inputs give below 1e-15.
pub const EVEN_WIDTH: f64 = 1e-9;

/// Where the pressure leans, by the signs of mu* - mu and a - b.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lean {
    /// mu* > mu and a < b (or one of them even): the way wear tilts it.
    Forwards,
    /// mu* < mu and a > b (or one of them even): the way friction tilts it.
    Backwards,
    /// mu* = mu and a = b within `EVEN_MU` and `EVEN_WIDTH`.
    Even,
    /// The two signs disagree.
    Split,
}

/// The signs that say which effect dominates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dominance {
    /// mu* - mu (dimensionless): > 0 where the deformation component adds to friction.
    pub mu_star_minus_mu: f64,
    /// a - b [m]: > 0 where the contact reaches further behind the punch tip than ahead.
    pub a_minus_b: f64,
    /// |a - b| within `EVEN_WIDTH` of a + b: the contact is centred on the tip.
    pub centred: bool,
    /// Where the pressure leans.
    pub lean: Lean,
    /// k > 0: the wear law wears.
    pub wear: bool,
    /// mu > 0 or tau0 > 0: there is friction.
    pub friction: bool,
    /// A flat punch with sharp corners: its contact is the face at every load.
    pub sharp_corners: bool,
    /// theta (dimensionless) of the wide and strip models: > 0 where the trailing corner's
    /// singularity is the stronger; None for the narrow model, whose pressure stays finite.
    pub theta: Option<f64>,
}

impl Dominance {
    /// The signs of `s`.
    pub fn of(s: &PlaneSolution) -> Dominance {
        let mu = s.inputs.friction.coefficient;
        let excess = s.mu_star - mu;
        let shift = s.a - s.b;
        let sign = |value: f64, even: f64| {
            if value.abs() <= even {
                0
            } else {
                value.signum() as i8
            }
        };
        let by_mu = sign(excess, EVEN_MU);
        let by_width = -sign(shift, EVEN_WIDTH * (s.a + s.b));
        let lean = match (by_mu, by_width) {
            (0, 0) => Lean::Even,
            (1, 0 | 1) | (0, 1) => Lean::Forwards,
            (-1, 0 | -1) | (0, -1) => Lean::Backwards,
            _ => Lean::Split,
        };
        Dominance {
            mu_star_minus_mu: excess,
            a_minus_b: shift,
            centred: by_width == 0,
            lean,
            wear: s.inputs.wear.coefficient > 0.0,
            friction: mu > 0.0 || s.inputs.friction.adhesion > 0.0,
            sharp_corners: matches!(
                &s.inputs.shape,
                Shape::Flat { edge_radius, .. } if *edge_radius == 0.0
            ),
            theta: s.theta,
        }
    }

    /// In one phrase, the evidence then the effect: "mu* - mu = -1.777e-4, a > b: friction
    /// dominates"; an effect the inputs lack is never named ("mu* - mu = +7.555e-5, a < b: not
    /// wear (k = 0)"); under a flat punch with sharp corners, which corner's singularity is the
    /// stronger ("mu* = mu, a = b: contact fixed by the corners; theta > 0: the trailing corner's
    /// singularity is the stronger").
    pub fn describe(&self) -> Phrase {
        let excess = format_si(self.mu_star_minus_mu, "");
        let excess = if self.mu_star_minus_mu > 0.0 {
            format!("+{excess}")
        } else {
            excess
        };
        let width = match (self.centred, self.a_minus_b > 0.0) {
            (true, _) => "a = b",
            (false, true) => "a > b",
            (false, false) => "a < b",
        };
        let evidence = |joint: &str| {
            Phrase::whole(format!("mu* - mu = {excess},")).then(format!("{joint}{width}:"))
        };
        let fixed = || Phrase::whole("mu* = mu, a = b:").then_words("contact fixed by the corners");
        match (self.lean, self.wear, self.friction) {
            (Lean::Even, ..) if self.sharp_corners => match self.theta {
                None => fixed(),
                Some(0.0) => fixed()
                    .ending(";")
                    .then("theta = 0:")
                    .then_words("the corners' singularities are alike"),
                Some(t) => {
                    let (sign, corner) = if t > 0.0 {
                        (">", "trailing")
                    } else {
                        ("<", "leading")
                    };
                    fixed()
                        .ending(";")
                        .then(format!("theta {sign} 0:"))
                        .then_words(&format!(
                            "the {corner} corner's singularity is the stronger"
                        ))
                }
            },
            (Lean::Even, ..) => Phrase::whole("mu* = mu, a = b:").then_words("neither dominates"),
            (Lean::Forwards, true, _) => evidence("").then_words("wear dominates"),
            (Lean::Forwards, false, _) => evidence("").then_words("not wear (k = 0)"),
            (Lean::Backwards, _, true) => evidence("").then_words("friction dominates"),
            (Lean::Backwards, _, false) => evidence("").then_words("not friction (mu = tau0 = 0)"),
            (Lean::Split, ..) => evidence("yet ").then_words("the two signs disagree"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Dominance, Lean};
    use crate::physics::plane::{Model, PlaneInputs, Shape, solve};
    use crate::physics::{Friction, Material};

    fn at(thickness: f64, mu: f64, k: f64, model: Model) -> Dominance {
        // polymer-coating.toml: E = 3 GPa, nu = 0.35, R = 50 mm, P = 5 kN/m
        let material = Material {
            youngs_modulus: 3.0e9,
            poisson_ratio: 0.35,
            thickness,
        };
        let friction = Friction {
            coefficient: mu,
            adhesion: 0.0,
        };
        let inputs = PlaneInputs::parabolic(material, friction, k, 0.05, 5.0e3);
        Dominance::of(&solve(&inputs, model).expect("solves"))
    }

    #[test]
    fn on_a_half_plane_the_words_follow_theta() {
        // theta = +0.0111 at k = 2e-11 (friction), -0.0323 at k = 1e-10 (wear): the status of
        // polymer-coating.toml with h = inf
        let friction = at(f64::INFINITY, 0.3, 2e-11, Model::Wide);
        assert_eq!(friction.lean, Lean::Backwards);
        assert!(
            friction
                .describe()
                .to_string()
                .ends_with("a > b: friction dominates")
        );
        let wear = at(f64::INFINITY, 0.3, 1e-10, Model::Wide);
        assert_eq!(wear.lean, Lean::Forwards);
        assert!(
            wear.describe()
                .to_string()
                .ends_with("a < b: wear dominates")
        );
    }

    #[test]
    fn a_thin_strip_leans_forwards_without_wear_and_is_not_said_to_wear() {
        // the strip model at h = 0.1 mm, k = 0: mu* = 0.3000755 > mu, a = 188 um < b = 194 um
        let d = at(1e-4, 0.3, 0.0, Model::Strip);
        assert_eq!(d.lean, Lean::Forwards);
        let text = d.describe().to_string();
        assert!(text.ends_with("a < b: not wear (k = 0)"), "{text}");
        // the point: h = 10 mm, k = 4e-11 has theta = +2.7e-4 yet mu* > mu and a < b
        let d = at(1e-2, 0.3, 4e-11, Model::Strip);
        assert_eq!(d.lean, Lean::Forwards);
        assert!(d.describe().to_string().ends_with("wear dominates"));
    }

    #[test]
    fn symmetric_inputs_are_even_in_every_model() {
        for model in [Model::Wide, Model::Strip, Model::Narrow] {
            let d = at(1e-2, 0.0, 0.0, model);
            assert_eq!(d.lean, Lean::Even, "{model:?}");
            assert_eq!(
                d.describe().to_string(),
                "mu* = mu, a = b: neither dominates"
            );
        }
        // the Winkler model has no friction-induced part: mu* = mu exactly, a = b
        assert_eq!(at(1e-2, 0.3, 0.0, Model::Narrow).lean, Lean::Even);
    }

    #[test]
    fn sharp_corners_name_the_stronger_corner_by_theta() {
        // sharp-flat-punch.toml: c = 1 mm on a half-plane, theta = +0.0111 at k = 2e-11 1/Pa
        // and -0.0323 at k = 1e-10 1/Pa (the parabola's theta above: theta depends on mu, k and
        // the material only, Soldatenkov (2007) (4.5))
        let flat = |k: f64, model: Model| {
            let material = Material {
                youngs_modulus: 3.0e9,
                poisson_ratio: 0.35,
                thickness: f64::INFINITY,
            };
            let friction = Friction {
                coefficient: 0.3,
                adhesion: 0.0,
            };
            let mut inputs = PlaneInputs::parabolic(material, friction, k, 0.05, 1.0e4);
            inputs.shape = Shape::Flat {
                half_width: 1e-3,
                edge_radius: 0.0,
            };
            Dominance::of(&solve(&inputs, model).expect("solves"))
        };
        let trailing = flat(2e-11, Model::Wide);
        assert_eq!(trailing.lean, Lean::Even);
        assert_eq!(
            trailing.describe().to_string(),
            "mu* = mu, a = b: contact fixed by the corners; theta > 0: the trailing corner's \
             singularity is the stronger"
        );
        assert!(
            flat(1e-10, Model::Wide)
                .describe()
                .to_string()
                .ends_with("theta < 0: the leading corner's singularity is the stronger")
        );
    }
}
