//! "Commensurate" means it: the cell minimum is certified only for wavenumbers
//! that are whole multiples of one base to within the precision of the numbers; otherwise, or
//! when the grid would be too fine, the check says it gave up and why.

use crate::common;

use std::f64::consts::{FRAC_PI_2, PI};

use common::{harmonic, layer, spatial};
use wearlab::physics::spatial::contact::{MAX_SIDE, NotCertified, check};
use wearlab::physics::spatial::{Cell, Period, period_of, solve};

/// Two waves along x of 1/M = G k/(1 - nu) each (half-space, no friction: docs/physics/spatial.md
/// section 2), equal pressure amplitudes c and opposite phases, on pbar = 10 MPa.
fn two_waves(w1: f64, w2: f64, c: f64) -> (f64, wearlab::physics::spatial::contact::Contact) {
    let mat = layer(1e9, 0.3, f64::INFINITY);
    let g = 1e9 / 2.6;
    let amplitude = |w: f64| c * 0.7 / (g * w);
    let inputs = spatial(
        mat,
        0.0,
        0.0,
        0.0,
        1e7,
        vec![
            harmonic(amplitude(w1), w1, 0.0, 0.0, FRAC_PI_2),
            harmonic(amplitude(w2), w2, 0.0, PI, FRAC_PI_2),
        ],
    );
    let sol = solve(&inputs, 0.0).unwrap();
    (1e7 - 2.0 * c, check(&sol, &Cell::of(inputs.harmonics())))
}

#[test]
fn waves_8e_11_apart_are_not_certified() {
    // They cancel over one cell (p = pbar there) and add half a beat away (p = pbar - 2c):
    // the infimum over the plane is the bound, which must not be hidden by a cell minimum.
    let (bound, c) = two_waves(1000.0, 1000.0 * (1.0 + 8e-11), 1.03e7);
    assert!(!c.exact && !c.complete, "{c:?}");
    assert_eq!(c.not_certified, Some(NotCertified::NoPeriod('x')));
    assert!((c.min_pressure - bound).abs() < 1e-6 * bound.abs());
    let why = c.failure().unwrap();
    assert!(why.starts_with("complete contact not certified"), "{why}");
    assert!(!why.contains("incommensurate"), "{why}");
    // Half a beat away, near x = pi/(w2 - w1), at a crest of the carrier, the two waves add
    // (independent route: the pointwise sum of the two sines)
    let (w1, w2) = (1000.0, 1000.0 * (1.0 + 8e-11));
    let crest = (PI / (w2 - w1) * 0.5 * (w1 + w2) / (2.0 * PI)).round();
    let x = 2.0 * PI * crest / (0.5 * (w1 + w2));
    let p = 1e7 + 1.03e7 * ((w1 * x).sin() - (w2 * x).sin());
    assert!(
        (p - bound).abs() < 1e-3 * bound.abs(),
        "p = {p} half a beat away"
    );
}

#[test]
fn multiples_written_to_17_digits_are_commensurate() {
    // 3 x 3141.592653589793 is 9424.777960769379; the decimal 9424.77796076938 differs in the last
    // place: the file means the multiple.
    assert_eq!(
        period_of([3141.592653589793, 9424.77796076938].into_iter()),
        Period::Commensurate {
            base: 3141.592653589793
        }
    );
    assert_eq!(
        period_of([3141.592653589793, 9424.7779607694].into_iter()),
        Period::NotFound,
        "2e-15 relative off: not a multiple"
    );
    assert_eq!(period_of([0.0, 0.0].into_iter()), Period::Constant);
    // the same cancelling pair at exactly equal wavenumbers is a real cancellation
    let (_, c) = two_waves(1000.0, 2000.0, 1e6);
    assert!(c.exact && c.complete, "{c:?}");
}

#[test]
fn a_grid_too_fine_to_decide_is_said() {
    // ratio 1000: 16 points per shortest wavelength need 16000 points per side
    let (_, c) = two_waves(10.0, 10_000.0, 1.03e7);
    assert!(!c.exact);
    assert_eq!(
        c.not_certified,
        Some(NotCertified::GridLimit { side: 16000.0 })
    );
    const { assert!(16000 > MAX_SIDE) };
    assert!(
        c.failure()
            .unwrap()
            .contains("needs a grid of 16000 points per side")
    );
}
