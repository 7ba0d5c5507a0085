//! Which model answers which inputs: the closed forms (wide, narrow) and the strip collocation
//! solve the paper's worked example - a parabolic punch, the linear wear law, friction without a
//! shear cap; the narrow model also solves every other shape and law (`narrow_ode`), the wide
//! model every punch with smooth edges and the strip model those without a shear cap (the
//! general solver, `plane::general`); every model solves sharp corners (`plane::sharp`); what is
//! left is refused by name, never answered with a wrong number.

use crate::physics::SolveError;
use crate::physics::plane::{Model, PlaneInputs};

/// Ok when `model` solves `inputs`, else why not (exit 2 on the command line).
pub fn check(inputs: &PlaneInputs, model: Model) -> Result<(), SolveError> {
    let solves = match model {
        Model::Narrow | Model::Wide => return Ok(()),
        Model::Strip if inputs.shear_strength == f64::INFINITY => return Ok(()),
        _ if inputs.is_classical() => return Ok(()),
        Model::Strip => {
            "punches with no shear_strength only (the wide and narrow models take a \
             shear_strength)"
        }
    };
    Err(SolveError::InvalidInput(format!(
        "the {} model solves {solves}; these inputs have {}",
        model.name(),
        departures(inputs)
    )))
}

/// What sets the inputs apart from the worked example, in words.
fn departures(inputs: &PlaneInputs) -> String {
    let mut out = Vec::new();
    if inputs.shape.parabola_radius().is_none() {
        out.push(format!("a {} punch", inputs.shape.kind()));
    }
    if !inputs.wear.is_linear() {
        out.push(format!("wear.exponent = {}", inputs.wear.exponent));
    }
    if inputs.shear_strength.is_finite() {
        out.push(format!("shear_strength = {} Pa", inputs.shear_strength));
    }
    out.join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::plane::{Shape, WearLaw};
    use crate::physics::{Friction, Material};

    /// A parabolic punch (R = 50 mm, P = 10 kN/m) on a 1 mm polymer coating, linear wear.
    fn polymer_coating() -> PlaneInputs {
        PlaneInputs::parabolic(
            Material {
                youngs_modulus: 1e9,
                poisson_ratio: 0.3,
                thickness: 1e-3,
            },
            Friction {
                coefficient: 0.3,
                adhesion: 0.0,
            },
            1e-12,
            0.05,
            1e4,
        )
    }

    #[test]
    fn sharp_corners_are_solved_by_every_model() {
        let mut inputs = polymer_coating();
        inputs.shape = Shape::Flat {
            half_width: 1e-3,
            edge_radius: 0.0,
        };
        assert!(Model::ALL.iter().all(|&m| check(&inputs, m).is_ok()));
    }

    #[test]
    fn other_shapes_and_laws_are_refused_by_name() {
        let mut inputs = polymer_coating();
        assert!(check(&inputs, Model::Wide).is_ok());
        inputs.shape = Shape::Power {
            radius: 0.05,
            exponent: 3.0,
        };
        inputs.wear = WearLaw {
            exponent: 2.0,
            reference_pressure: 1e6,
            ..inputs.wear
        };
        assert!(check(&inputs, Model::Wide).is_ok());
        assert!(check(&inputs, Model::Strip).is_ok());
        assert!(check(&inputs, Model::Narrow).is_ok());
        inputs.shear_strength = 1e6;
        let err = check(&inputs, Model::Strip).unwrap_err().to_string();
        assert!(
            err.contains("strip model")
                && err.contains("no shear_strength")
                && err.contains("a power punch, wear.exponent = 2"),
            "{err}"
        );
        inputs.shape = Shape::Flat {
            half_width: 1e-3,
            edge_radius: 0.0,
        };
        inputs.wear = WearLaw::linear(1e-12);
        let err = inputs.validate().unwrap_err().to_string();
        assert!(err.contains("cannot take a finite shear_strength"), "{err}");
    }
}
