//! The bundled height-map presets show what their descriptions say.

use wearlab::physics::spatial::partial::Setup;
use wearlab::physics::spatial::pipeline;
use wearlab::preset;

/// Within half a unit of the last digit of `said`, given as its number of decimals.
fn quoted(value: f64, said: f64, decimals: i32) -> bool {
    (value - said).abs() <= 0.5 * 10f64.powi(-decimals) * (1.0 + 1e-9)
}

/// (a, b) agree to `rel` of b.
fn near(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs()
}

#[test]
fn the_thin_layer_wears_every_mode_at_one_rate_as_its_description_says() {
    let p = preset::bundled("rough-thin-layer.toml").unwrap().unwrap();
    let inputs = p.spatial_inputs();
    let solve = |t: f64| {
        let mut at = p.spatial_state_at();
        at.time = t;
        pipeline::solve(&inputs, &at, &[], false).unwrap()
    };
    let start = solve(0.0);
    assert!(start.contact.complete);
    assert!(near(start.contact.min_pressure, 22e6, 0.01));
    assert!(near(start.max_pressure, 109e6, 0.005));
    // the Winkler limit of docs/physics/spatial.md section 3: beta = k V (lambda + 2G)/h
    let m = p.material;
    let g = m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio));
    let lambda = 2.0 * g * m.poisson_ratio / (1.0 - 2.0 * m.poisson_ratio);
    let beta = p.wear * p.spatial.sliding_speed * (lambda + 2.0 * g) / m.thickness;
    assert!(near(beta, 6.73, 0.001));
    let r = solve(p.spatial.time);
    let (s0, s) = (start.surface.unwrap(), r.surface.unwrap());
    println!(
        "t = {}: rms {:.5e} m (Winkler {:.5e}), slope/rms {:.5e} -> {:.5e} 1/m, p_min {:.4e}",
        r.time,
        s.rms_height,
        s0.rms_height * (-beta * r.time).exp(),
        s0.rms_slope / s0.rms_height,
        s.rms_slope / s.rms_height,
        r.contact.min_pressure
    );
    assert!(near(s.rms_height, 5.21e-9, 0.001));
    assert!(near(
        s.rms_height,
        s0.rms_height * (-beta * r.time).exp(),
        0.001
    ));
    // "every mode decays at nearly the same rate": each Fourier mode's closed-form rate
    // (docs/physics/spatial.md section 3, friction included) lies between the quoted 6.71 1/s
    // of the shortest wave and the Winkler rate of the longest
    let rates = Setup::new(&inputs, 8).unwrap().decay_rates();
    let slowest = rates.iter().copied().fold(f64::INFINITY, f64::min);
    let fastest = rates.iter().copied().fold(0.0, f64::max);
    println!(
        "{} modes decay at {slowest:.4} to {fastest:.4} 1/s",
        rates.len()
    );
    assert!(quoted(slowest, 6.71, 2) && quoted(fastest, 6.73, 2));
    // so the PSD falls as a whole: every bin of the band keeps e^(-2 beta t) = 0.068 of its
    // power (the bins above the cutoff hold only the transform's round-off)
    let cutoff = 2.0 * std::f64::consts::PI / 60e-6;
    let winkler = (-2.0 * beta * r.time).exp();
    assert!(quoted(winkler, 0.068, 3));
    let band: Vec<f64> = (s0.psd.wavenumber.iter().zip(&s0.psd.psd))
        .zip(&s.psd.psd)
        .filter(|((q, _), _)| **q < cutoff)
        .map(|((_, c0), c)| c / c0)
        .collect();
    println!("PSD kept per bin of the band, longest waves first: {band:.4?}");
    assert!(band.len() >= 16);
    assert!(
        band.iter().all(|kept| near(*kept, winkler, 0.01)),
        "{band:?}"
    );
    let ratio = |s: wearlab::physics::spatial::result::SurfaceResult| s.rms_slope / s.rms_height;
    assert!(near(ratio(s), 2.56e4, 0.002) && near(ratio(s0), 2.56e4, 0.002));
    assert!(near(r.contact.min_pressure, 50e6, 0.003));
}

#[test]
fn the_ground_profile_loses_its_short_waves_first_as_its_description_says() {
    let p = preset::bundled("ground-profile.toml").unwrap().unwrap();
    let inputs = p.spatial_inputs();
    let solve = |t: f64| {
        let mut at = p.spatial_state_at();
        at.time = t;
        pipeline::solve(&inputs, &at, &[], false).unwrap()
    };
    let (start, end) = (solve(0.0), solve(p.spatial.time));
    let (s0, s) = (start.surface.unwrap(), end.surface.unwrap());
    let psd_ratio = |bin: usize| s0.psd.psd[bin] / s.psd.psd[bin];
    let last = s.psd.psd.len() - 1;
    println!(
        "t = 0: fraction {:.4}, p_max {:.4e}, skewness {:.3}, complete from {:?} s; t = {}: rms \
         {:.4e} m, slope {:.4e}, PSD first bin / {:.2}, last / {:.1e}",
        start.contact.fraction,
        start.max_pressure,
        s0.skewness,
        start.contact.time_to_complete,
        end.time,
        s.rms_height,
        s.rms_slope,
        psd_ratio(0),
        psd_ratio(last)
    );
    assert!(near(start.contact.fraction, 0.86, 0.005));
    assert!(near(start.max_pressure, 149e6, 0.005));
    assert!(near(s0.rms_height, 0.25e-6, 0.005));
    assert!(near(s0.skewness, -0.35, 0.01));
    assert!(near(start.contact.time_to_complete.unwrap(), 0.88, 0.005));
    assert!(end.contact.complete);
    // a third of the height, a tenth of the slope: the short waves went first
    assert!(near(s.rms_height, 79e-9, 0.005));
    assert!(near(s.rms_slope, 1.8e-3, 0.02));
    assert!(near(psd_ratio(0), 6.5, 0.01));
    assert!((24.0..25.5).contains(&psd_ratio(last).log10()));
}
