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

use crate::limits_strategy;

use limits_strategy::{across, poisson};
use wearlab::finite;
use wearlab::physics::limits;
use wearlab::physics::spatial::history::{dispersion, history};
use wearlab::physics::spatial::{PunchShape, SpatialInputs, StateAt, evolutions, solve, state_at};
use wearlab::physics::{Spacing, SweepRange};

fn harmonic() -> impl Strategy<Value = Harmonic> {
    (
        across(&limits::AMPLITUDE),
        across(&limits::WAVENUMBER),
        across(&limits::WAVENUMBER),
        across(&limits::PHASE),
        across(&limits::PHASE),
    )
        .prop_map(|(amplitude, wx, wy, px, py)| Harmonic {
            amplitude,
            wavenumber_x: wx,
            wavenumber_y: wy,
            phase_x: px,
            phase_y: py,
        })
}

/// Harmonics whose wavenumbers are whole multiples (0..6) of one base: the certified cell
/// minimum is searched for these.
fn commensurate_harmonics() -> impl Strategy<Value = Vec<Harmonic>> {
    let multiples =
        (0u32..6, 0u32..6, 1.0f64..2.0).prop_filter("a wave vector", |(nx, ny, _)| nx + ny > 0);
    (
        across(&limits::WAVENUMBER).prop_filter("nonzero", |w| *w > 0.0),
        proptest::collection::vec((harmonic(), multiples), 1..5),
    )
        .prop_map(|(base, waves)| {
            waves
                .into_iter()
                .map(|(h, (nx, ny, _))| Harmonic {
                    wavenumber_x: base * f64::from(nx),
                    wavenumber_y: base * f64::from(ny),
                    ..h
                })
                .collect()
        })
}

fn spatial_inputs() -> impl Strategy<Value = SpatialInputs> {
    (
        (
            across(&limits::YOUNGS_MODULUS),
            poisson(),
            across(&limits::THICKNESS),
        ),
        (
            across(&limits::FRICTION),
            across(&limits::ADHESION),
            across(&limits::WEAR),
        ),
        (across(&limits::SPEED), across(&limits::MEAN_PRESSURE)),
        prop_oneof![
            proptest::collection::vec(harmonic(), 1..5),
            commensurate_harmonics()
        ],
    )
        .prop_map(
            |((e, nu, h), (mu, tau0, k), (v, pbar), harmonics)| SpatialInputs {
                material: Material {
                    youngs_modulus: e,
                    poisson_ratio: nu,
                    thickness: h,
                },
                friction: Friction {
                    coefficient: mu,
                    adhesion: tau0,
                },
                wear: k,
                wear_exponent: 1.0,
                reference_pressure: 1.0,
                sliding_speed: v,
                mean_pressure: pbar,
                shape: PunchShape::Harmonics(harmonics),
            },
        )
}

fn cases(default: u32) -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

proptest! {
    // The whole allowed range (`physics::limits`, corners included): every result is finite or
    // an error in words. `cargo test` runs 300 cases; PROPTEST_CASES=20000 runs a deeper search.
    #![proptest_config(ProptestConfig::with_cases(cases(300)))]
    #[test]
    fn spatial_results_are_finite_or_explained(
        inp in spatial_inputs(),
        time in across(&limits::TIME),
        duration in across(&limits::DURATION),
    ) {
        match solve(&inp, time) {
            Ok(_) => {
                let ev = evolutions(&inp);
                let at = StateAt {
                    time,
                    grid: 8,
                    time_tolerance: 1e-6,
                    sweep: SweepRange {
                        min: inp.mean_pressure * 0.5,
                        max: inp.mean_pressure,
                        points: 5,
                        spacing: Spacing::Log,
                    },
                };
                let state = state_at(&inp, &ev, &at).map_err(|e| TestCaseError::fail(e.to_string()))?;
                let f = &state.field;
                prop_assert!(f.pressure.iter().chain(&f.shape).chain(&f.wear).all(|v| v.is_finite()));
                prop_assert!(state.cell.lx.is_finite() && state.cell.ly.is_finite());
                prop_assert_eq!(finite::check(&state.contact), Ok(()));
                prop_assert_eq!(finite::check(&state.sweep), Ok(()));
                prop_assert_eq!(finite::check(&history(&inp, &ev, duration, 4)), Ok(()));
                prop_assert_eq!(finite::check(&dispersion(&inp, 4)), Ok(()));
                let s = &state.solution;
                prop_assert!(s.load > 0.0 && s.mu_star.is_finite() && s.tangential.is_finite());
            }
            Err(e) => prop_assert!(e.to_string().len() > 20, "{e:?}"),
        }
    }
}
