//! The spatial presets of harmonics whose descriptions were not yet checked say what the
//! closed form finds: each number a description quotes is recomputed here, within half a unit
//! of its last quoted digit (the description rounds). The running-in presets are checked in
//! tests/explorer/engine.rs, the height maps in tests/presets/surfaces.rs.

use std::f64::consts::PI;

use wearlab::physics::elastic::strip_transfer;
use wearlab::physics::roots::brent;
use wearlab::physics::spatial::harmonic::{Evolution, Harmonic, evolution};
use wearlab::physics::spatial::history::dispersion;
use wearlab::physics::spatial::{self, evolutions};
use wearlab::preset::{self, Preset};

fn preset(file: &str) -> Preset {
    preset::bundled(file).unwrap().unwrap()
}

/// Within half a unit of the last digit of `said`, given as its number of decimals.
fn quoted(value: f64, said: f64, decimals: i32) -> bool {
    (value - said).abs() <= 0.5 * 10f64.powi(-decimals) * (1.0 + 1e-9)
}

/// X*(nu): where the strip's coupling chi K12 changes sign (docs/physics/spatial.md section 2).
fn x_star(nu: f64) -> f64 {
    brent(0.01, 20.0, |x| strip_transfer(nu, x).chi_k12).unwrap()
}

fn kh(p: &Preset) -> Vec<f64> {
    let h = p.material.thickness;
    p.spatial
        .harmonics
        .iter()
        .map(|w| w.wavenumber() * h)
        .collect()
}

#[test]
fn the_egg_box_is_johnson_greenwood_and_higginsons() {
    let p = preset("jgh-egg-box.toml");
    let e = evolutions(&p.spatial_inputs())[0];
    let delta = p.spatial.harmonics[0].amplitude;
    // "sqrt(2) pi E* Delta/l = 97.6 MPa", E* = E/(1 - nu^2) against a rigid punch, l = 1 mm
    let e_star = p.material.youngs_modulus / (1.0 - p.material.poisson_ratio.powi(2));
    let jgh = 2f64.sqrt() * PI * e_star * delta / 1e-3;
    let amplitude = e.pressure_per_amplitude() * delta;
    assert!((amplitude - jgh).abs() < 1e-9 * jgh);
    assert!(quoted(amplitude / 1e6, 97.6, 1), "{amplitude}");
    // "mean pressure (200 MPa)"; "p_min = 200 - 97.6 = 102.4 MPa"
    let s = spatial::solve(&p.spatial_inputs(), 0.0).unwrap();
    let contact = spatial::contact::check(&s, &spatial::Cell::of(p.spatial_inputs().harmonics()));
    assert!(contact.complete && quoted(contact.min_pressure / 1e6, 102.4, 1));
    // "1/beta = 10 s"; "a tenfold in about 24 s": ln(10)/beta
    assert!(
        quoted(1.0 / e.decay_rate, 10.0, 0),
        "{}",
        1.0 / e.decay_rate
    );
    assert!(quoted(10f64.ln() / e.decay_rate, 24.0, 0));
    // "no drift, phase lead 0, mu* = mu = 0"
    assert_eq!((e.drift_velocity, e.phase_lead, s.mu_star), (0.0, 0.0, 0.0));
}

#[test]
fn the_wave_on_a_thick_layer_leads_decays_and_drifts_as_said() {
    let p = preset("wave-thick-layer.toml");
    let e: Evolution = evolutions(&p.spatial_inputs())[0];
    let (mu, nu) = (p.friction.coefficient, p.material.poisson_ratio);
    // "kh = 63"; "phi = atan(mu (1 - 2nu)/(2(1 - nu))) = 0.086 rad" (the half-space's, to 1e-6
    // at kh = 63)
    assert!(quoted(kh(&p)[0], 63.0, 0));
    let phi = (mu * (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))).atan();
    assert!(
        (e.phase_lead - phi).abs() < 1e-6 && quoted(phi, 0.086, 3),
        "{phi}"
    );
    // "its crest sits 14 um (phi/wx) towards -x"; "236 and 250 um" (the shape's crest at a
    // quarter wavelength, l = 1 mm)
    let wx = p.spatial.harmonics[0].wavenumber_x;
    let lag = e.phase_lead / wx;
    assert!(quoted(lag * 1e6, 14.0, 0) && quoted((250e-6 - lag) * 1e6, 236.0, 0));
    assert!(quoted(2.0 * PI / wx / 4.0 * 1e6, 250.0, 0));
    // "1/beta = 49 s", "c = 0.28 um/s"
    assert!(
        quoted(1.0 / e.decay_rate, 49.0, 0),
        "{}",
        1.0 / e.decay_rate
    );
    assert!(
        quoted(e.drift_velocity * 1e6, 0.28, 2),
        "{}",
        e.drift_velocity
    );
    // "psi < 0 and mu* < mu"; "mu*(t) rising back to 0.3"
    let s = spatial::solve(&p.spatial_inputs(), 0.0).unwrap();
    let late = spatial::solve(&p.spatial_inputs(), 20.0 / e.decay_rate).unwrap();
    assert!(s.psi < 0.0 && s.mu_star < mu && s.mu_star < late.mu_star);
    assert!((late.mu_star - mu).abs() < 1e-9);
    // "oblique waves drift 0.4 and 0.7 % faster" (45 and 75 degrees, at the wave's kh)
    let d = dispersion(&p.spatial_inputs(), 41);
    let i = (0..d.k.len())
        .min_by(|&a, &b| {
            (d.k[a] - kh(&p)[0])
                .abs()
                .total_cmp(&(d.k[b] - kh(&p)[0]).abs())
        })
        .unwrap();
    let faster = |j: usize| 100.0 * (d.drift_velocity[j][i] / d.drift_velocity[0][i] - 1.0);
    assert!(
        quoted(faster(1), 0.4, 1) && quoted(faster(2), 0.7, 1),
        "{} {}",
        faster(1),
        faster(2)
    );
}

#[test]
fn the_rubber_wave_drifts_backwards() {
    let p = preset("rubber-backward-drift.toml");
    let e = evolutions(&p.spatial_inputs())[0];
    // "X*(0.49) = 4.02"; "kh = 1.26 < X*"; "phi = -0.66 rad"; "c < 0"; "psi > 0", "mu* above 1"
    assert_eq!(p.material.poisson_ratio, 0.49);
    assert!(quoted(x_star(0.49), 4.02, 2));
    assert!(quoted(kh(&p)[0], 1.26, 2) && kh(&p)[0] < x_star(0.49));
    assert!(quoted(e.phase_lead, -0.66, 2), "{}", e.phase_lead);
    let s = spatial::solve(&p.spatial_inputs(), 0.0).unwrap();
    assert!(e.drift_velocity < 0.0 && s.psi > 0.0 && s.mu_star > 1.0);
}

#[test]
fn the_four_harmonics_disperse() {
    let p = preset("dispersion.toml");
    let inputs = p.spatial_inputs();
    // "nu = 0.45, X* = 2.78", "mu = 0.8"; "kh = 1.6 and 2.2, below X*", "5.7 and 6.3"
    assert_eq!(
        (p.material.poisson_ratio, p.friction.coefficient),
        (0.45, 0.8)
    );
    assert!(quoted(x_star(0.45), 2.78, 2));
    let mut said = kh(&p);
    said.sort_by(f64::total_cmp);
    for (value, quote) in said.iter().zip([1.6, 2.2, 5.7, 6.3]) {
        assert!(quoted(*value, quote, 1), "{said:?}");
    }
    // "the long waves drift backwards, the short ones forwards" (two negative, two positive)
    for (w, e) in p.spatial.harmonics.iter().zip(evolutions(&inputs)) {
        let long = w.wavenumber() * p.material.thickness < x_star(0.45);
        assert_eq!(e.drift_velocity < 0.0, long, "{w:?}");
        // "the oblique ones drift faster than a wave along x of the same length"
        if w.wavenumber_y != 0.0 {
            let along_x = Harmonic {
                wavenumber_x: w.wavenumber(),
                wavenumber_y: 0.0,
                ..*w
            };
            let straight = evolution(
                &inputs.material,
                &inputs.friction,
                inputs.wear_rate(),
                &along_x,
            );
            assert!(
                e.drift_velocity.abs() > straight.drift_velocity.abs(),
                "{w:?}"
            );
        }
    }
}
