//! Property tests: any valid plane input gives either a finite solution or an error in words,
//! never NaN, and never a panic.

use proptest::prelude::*;
use wearlab::physics::plane::energy::energy;
use wearlab::physics::plane::profile::profile;
use wearlab::physics::plane::{Model, PlaneInputs, solve};
use wearlab::physics::{Friction, Material};

fn inputs() -> impl Strategy<Value = PlaneInputs> {
    (
        (
            5.0f64..12.0,
            0.0f64..0.4999,
            prop_oneof![
                Just(f64::INFINITY),
                (-6.0f64..-1.0).prop_map(|e| 10f64.powf(e))
            ],
        ),
        (
            0.0f64..2.0,
            prop_oneof![Just(0.0), (2.0f64..8.0).prop_map(|e| 10f64.powf(e))],
        ),
        prop_oneof![Just(0.0), (-15.0f64..-7.0).prop_map(|e| 10f64.powf(e))],
        (-3.0f64..0.0, 0.0f64..7.0),
    )
        .prop_map(|((e, nu, h), (mu, tau0), k, (r, p))| PlaneInputs {
            material: Material {
                youngs_modulus: 10f64.powf(e),
                poisson_ratio: nu,
                thickness: h,
            },
            friction: Friction {
                coefficient: mu,
                adhesion: tau0,
            },
            wear: k,
            radius: 10f64.powf(r),
            load: 10f64.powf(p),
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]
    #[test]
    fn solutions_are_finite_or_explained(inp in inputs(), narrow in any::<bool>()) {
        let model = if narrow { Model::Narrow } else { Model::Wide };
        match solve(&inp, model) {
            Ok(sol) => {
                for v in [sol.a, sol.b, sol.normal_force, sol.psi, sol.delta_g, sol.mu_star, sol.tangential_force] {
                    prop_assert!(v.is_finite(), "{sol:?}");
                }
                prop_assert!(sol.contact_width() > 0.0);
                let prof = profile(&sol, 21);
                prop_assert!(prof.pressure.iter().chain(&prof.wear).all(|v| v.is_finite() && *v >= 0.0));
                let en = energy(&sol);
                prop_assert!(en.i.is_finite() && en.j.is_finite() && en.residual.is_finite());
            }
            Err(e) => prop_assert!(!e.to_string().is_empty()),
        }
    }
}
