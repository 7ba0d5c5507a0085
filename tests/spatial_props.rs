//! Property: the drift reverses sign across X*(nu) for nu > 1/4, and never for nu <= 1/4
//! (docs/physics/spatial.md section 2: the sign of B is the sign of K12).

use proptest::prelude::*;
use wearlab::physics::spatial::harmonic::{Harmonic, evolution};
use wearlab::physics::{Friction, Material};

fn drift_signs(nu: f64, angle: f64) -> Vec<bool> {
    let mat = Material {
        youngs_modulus: 1e7,
        poisson_ratio: nu,
        thickness: 1e-3,
    };
    let f = Friction {
        coefficient: 0.5,
        adhesion: 0.0,
    };
    (0..200)
        .map(|i| {
            let kh = 10f64.powf(-2.0 + 3.5 * i as f64 / 199.0);
            let k = kh / 1e-3;
            let h = Harmonic {
                amplitude: 1e-6,
                wavenumber_x: k * angle.cos(),
                wavenumber_y: k * angle.sin(),
                phase_x: 0.0,
                phase_y: 0.0,
            };
            evolution(&mat, &f, 1e-12, &h).drift_velocity > 0.0
        })
        .collect()
}

proptest! {
    #[test]
    fn never_reverses_for_nu_up_to_a_quarter(nu in 0.0f64..=0.25, angle in 0.0f64..1.5) {
        prop_assert!(drift_signs(nu, angle).iter().all(|&s| s));
    }

    #[test]
    fn reverses_once_for_nu_above_a_quarter(nu in 0.26f64..0.4999, angle in 0.0f64..1.5) {
        let signs = drift_signs(nu, angle);
        let changes = signs.windows(2).filter(|w| w[0] != w[1]).count();
        prop_assert_eq!(changes, 1);
        prop_assert!(!signs[0] && signs[199], "backwards for long waves, forwards for short");
    }
}
