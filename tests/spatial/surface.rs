//! Height maps and generated self-affine surfaces: the spectrum of a generated surface against
//! its definition, statistics against harmonics sampled on the grid, and refused files.

use std::f64::consts::PI;
use std::path::PathBuf;

use wearlab::physics::spatial::surface::{
    Amplitude, SelfAffine, Surface, generate, periodicity, radial_psd, read_csv, read_xyz,
    statistics,
};

fn self_affine(seed: u64, length_y: f64) -> SelfAffine {
    SelfAffine {
        hurst: 0.8,
        amplitude: Amplitude::RmsHeight(1e-6),
        rolloff_wavelength: 2.5e-4,
        cutoff_wavelength: 2.5e-5,
        length_x: 1e-3,
        length_y,
        grid: 64,
        seed,
    }
}

/// Least-squares slope of log C against log q over the PSD points in [q_r, q_s].
fn psd_slope(surface: &Surface, p: &SelfAffine) -> f64 {
    let (q_r, q_s) = (
        2.0 * PI / p.rolloff_wavelength,
        2.0 * PI / p.cutoff_wavelength,
    );
    let points: Vec<(f64, f64)> = radial_psd(surface, 24)
        .into_iter()
        .filter(|pt| pt.wavenumber >= q_r && pt.wavenumber <= q_s)
        .map(|pt| (pt.wavenumber.ln(), pt.psd.ln()))
        .collect();
    assert!(points.len() >= 6, "{} PSD points in the band", points.len());
    let n = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
    let sxy: f64 = points.iter().map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = points.iter().map(|(x, _)| (x - mx) * (x - mx)).sum();
    sxy / sxx
}

/// Over 8 seeds the fitted PSD slope is -2(1 + H) for a map and -(1 + 2H) for a profile. The
/// amplitudes are exactly sqrt(C(q)), so the seeds scatter the slope only through round-off; the
/// bias left is the log bins' averaging of a power law (under 2 %).
#[test]
fn psd_slope_is_the_hurst_exponents_across_seeds() {
    for (length_y, expected) in [(1e-3, -2.0 * 1.8), (0.0, -(1.0 + 1.6))] {
        let slopes: Vec<f64> = (1..=8)
            .map(|seed| {
                let p = self_affine(seed, length_y);
                psd_slope(&generate(&p).unwrap(), &p)
            })
            .collect();
        let (lo, hi) = slopes
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), s| {
                (a.min(*s), b.max(*s))
            });
        eprintln!("length_y = {length_y}: slopes {lo} .. {hi}, expected {expected}");
        assert!(hi - lo < 1e-9, "scatter over seeds {}", hi - lo);
        assert!(
            ((lo - expected) / expected).abs() < 0.02,
            "slope {lo} vs {expected}"
        );
    }
}

#[test]
fn generated_surface_has_the_rms_exactly_and_zero_mean() {
    for length_y in [1e-3, 0.0] {
        let p = self_affine(7, length_y);
        let s = generate(&p).unwrap();
        let stats = statistics(&s);
        assert!((stats.rms_height - 1e-6).abs() < 1e-6 * 1e-13);
        let mean = s.heights.iter().sum::<f64>() / s.heights.len() as f64;
        assert!(mean.abs() < 1e-6 * 1e-13, "mean {mean}");
        let by_slope = generate(&SelfAffine {
            amplitude: Amplitude::RmsSlope(0.05),
            ..p
        })
        .unwrap();
        assert!((statistics(&by_slope).rms_slope - 0.05).abs() < 0.05 * 1e-13);
    }
}

#[test]
fn the_same_seed_gives_the_same_bits() {
    let a = generate(&self_affine(42, 1e-3)).unwrap();
    let b = generate(&self_affine(42, 1e-3)).unwrap();
    let c = generate(&self_affine(43, 1e-3)).unwrap();
    let bits = |s: &Surface| s.heights.iter().map(|h| h.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits(&a), bits(&b));
    assert_ne!(bits(&a), bits(&c));
}

/// Two harmonics A sin(wx x + rx) sin(wy y + ry) sampled on a 32 x 16 grid: <h^2> = A^2/4 each,
/// <h_x^2> = A^2 wx^2/4, <h_xx^2> = A^2 wx^4/4; a profile's harmonic (wy = 0) has sin^2(ry)/2 in
/// place of 1/4 (the products' averages over the cell).
#[test]
fn a_map_sampled_from_harmonics_has_their_statistics() {
    let (lx, ly, nx, ny) = (2e-3, 1e-3, 32, 16);
    let waves = [(2.0e-6, 3.0, 1.0, 0.3, 1.1), (0.5e-6, 5.0, 2.0, -0.7, 0.4)];
    let mut heights = vec![0.0; nx * ny];
    for j in 0..ny {
        for i in 0..nx {
            let (x, y) = (i as f64 * lx / nx as f64, j as f64 * ly / ny as f64);
            heights[j * nx + i] = waves
                .iter()
                .map(|&(a, mx, my, rx, ry)| {
                    a * (2.0 * PI * mx * x / lx + rx).sin() * (2.0 * PI * my * y / ly + ry).sin()
                })
                .sum();
        }
    }
    let s = Surface::new(nx, ny, lx, ly, heights).unwrap();
    let stats = statistics(&s);
    let sum = |power: i32| -> f64 {
        waves
            .iter()
            .map(|&(a, mx, _, _, _)| a * a * (2.0 * PI * mx / lx).powi(power) / 4.0)
            .sum::<f64>()
            .sqrt()
    };
    assert!((stats.rms_height / sum(0) - 1.0).abs() < 1e-12);
    assert!((stats.rms_slope / sum(2) - 1.0).abs() < 1e-12);
    assert!((stats.rms_curvature / sum(4) - 1.0).abs() < 1e-12);
    assert!(stats.skewness.abs() < 1e-12);
    let p = periodicity(&s);
    assert!(p.edge_step_x < 2.0 * p.interior_step_x, "{}", p.message());

    let (a, ry): (f64, f64) = (1e-6, 0.9);
    let profile: Vec<f64> = (0..64)
        .map(|i| a * (2.0 * PI * 3.0 * i as f64 / 64.0).sin() * ry.sin())
        .collect();
    let s = Surface::new(64, 1, lx, 0.0, profile).unwrap();
    let expected = a * (2.0 * PI * 3.0 / lx) * (ry.sin().powi(2) / 2.0).sqrt();
    assert!((statistics(&s).rms_slope / expected - 1.0).abs() < 1e-12);
}

fn file(name: &str, text: &str) -> PathBuf {
    let path = std::env::temp_dir().join(format!("wearlab-surface-{}-{name}", std::process::id()));
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn csv_and_xyz_give_the_same_map() {
    let csv = file("grid.csv", "# two rows\n1e-6, 2e-6, 0\n\n0, -1e-6, 4e-6\n");
    let a = read_csv(&csv, 3e-3, 2e-3).unwrap();
    let xyz = file(
        "grid.xyz",
        "0.002 0.001 4e-6\n0 0 1e-6\n0.001 0 2e-6\n0.002 0 0\n0 0.001 0\n0.001 0.001 -1e-6\n",
    );
    let b = read_xyz(&xyz).unwrap();
    assert_eq!((a.nx, a.ny, b.nx, b.ny), (3, 2, 3, 2));
    assert!((b.lx - 3e-3).abs() < 1e-15 && (b.ly - 2e-3).abs() < 1e-15);
    for (x, y) in a.heights.iter().zip(&b.heights) {
        assert!((x - y).abs() < 1e-20);
    }
    assert!(a.heights.iter().sum::<f64>().abs() < 1e-20);
}

#[test]
fn bad_files_say_the_line_and_the_reason() {
    let csv = |name: &str, text: &str| {
        read_csv(&file(name, text), 1e-3, 1e-3)
            .unwrap_err()
            .to_string()
    };
    let wide = |n: usize| vec!["1e-6"; n].join(",");
    let cases = [
        (
            csv("ragged.csv", "1e-6,2e-6\n1e-6\n"),
            ":2: this row has 1 values",
        ),
        (csv("text.csv", "1e-6,abc\n"), ":1: 'abc' is not a number"),
        (
            csv("nan.csv", "# c\n1e-6,NaN\n"),
            ":2: NaN: NaN is not a height",
        ),
        (csv("empty.csv", ""), ": no heights"),
        (
            csv("one.csv", "1e-6\n"),
            ":1: a surface needs at least 2 nodes",
        ),
        (csv("km.csv", "1e-6,1000\n"), ":1: 1000: heights beyond"),
        (
            csv("huge.csv", &format!("{}\n{}\n", wide(4097), wide(4097))),
            ":2: a map larger than 1024 x 1024",
        ),
        (
            read_xyz(&file("ragged.xyz", "0 0 1e-6\n1 0\n"))
                .unwrap_err()
                .to_string(),
            ":2: 2 columns",
        ),
    ];
    for (message, expected) in cases {
        assert!(message.contains(expected), "{message:?} lacks {expected:?}");
    }
    let big = file("big.csv", "");
    std::fs::File::options()
        .write(true)
        .open(&big)
        .unwrap()
        .set_len(1 << 30)
        .unwrap();
    let message = read_csv(&big, 1e-3, 1e-3).unwrap_err().to_string();
    assert!(message.contains("1073741824 bytes"), "{message}");
    std::fs::remove_file(big).unwrap();
}
