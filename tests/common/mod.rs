//! Helpers shared by the integration tests: input builders and independent quadratures.
#![allow(dead_code)]

use wearlab::physics::plane::PlaneInputs;
use wearlab::physics::{Friction, Material};

/// Plane inputs from the raw numbers, in the order the paper lists them (a builder struct would
/// only hide the symbols the tests quote).
#[allow(clippy::too_many_arguments)]
pub fn plane(e: f64, nu: f64, h: f64, mu: f64, tau0: f64, k: f64, r: f64, p: f64) -> PlaneInputs {
    PlaneInputs {
        material: Material {
            youngs_modulus: e,
            poisson_ratio: nu,
            thickness: h,
        },
        friction: Friction {
            coefficient: mu,
            adhesion: tau0,
        },
        shear_strength: f64::INFINITY,
        wear: wearlab::physics::plane::WearLaw::linear(k),
        shape: wearlab::physics::plane::Shape::Parabola { radius: r },
        load: p,
    }
}

/// Composite Gauss–Legendre in the angle phi, x = lo + (hi - lo)(1 - cos phi)/2, which smooths
/// square-root-type end behaviour. `panels` panels of the 20-point rule (hard-coded nodes are
/// avoided: the rule is the library's Legendre rule, whose exactness is tested separately).
pub fn integrate_cos(lo: f64, hi: f64, panels: usize, f: impl Fn(f64) -> f64) -> f64 {
    let rule = wearlab::physics::quadrature::gauss_legendre(20);
    let half = 0.5 * (hi - lo);
    let dphi = std::f64::consts::PI / panels as f64;
    (0..panels)
        .map(|k| {
            rule.integrate(k as f64 * dphi, (k + 1) as f64 * dphi, |phi| {
                f(lo + half * (1.0 - phi.cos())) * half * phi.sin()
            })
        })
        .sum()
}

/// p.v. integral of q(s)/(s - x) over [lo, hi] by singularity subtraction, with `integrate_cos`.
pub fn hilbert(lo: f64, hi: f64, x: f64, q: &impl Fn(f64) -> f64) -> f64 {
    let qx = q(x);
    let reg = |s: f64| if s == x { 0.0 } else { (q(s) - qx) / (s - x) };
    integrate_cos(lo, x, 200, reg)
        + integrate_cos(x, hi, 200, reg)
        + qx * ((hi - x) / (x - lo)).ln()
}

/// Relative difference |a - b| / max(|a|, |b|).
pub fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs()).max(f64::MIN_POSITIVE)
}

/// One harmonic a sin(wx x + px) sin(wy y + py) of a spatial punch.
pub fn harmonic(
    a: f64,
    wx: f64,
    wy: f64,
    px: f64,
    py: f64,
) -> wearlab::physics::spatial::harmonic::Harmonic {
    wearlab::physics::spatial::harmonic::Harmonic {
        amplitude: a,
        wavenumber_x: wx,
        wavenumber_y: wy,
        phase_x: px,
        phase_y: py,
    }
}

/// delta cos(2 pi x/l) along x (a 1-D shape).
pub fn cosine(delta: f64, l: f64) -> wearlab::physics::spatial::harmonic::Harmonic {
    let half_pi = std::f64::consts::FRAC_PI_2;
    harmonic(delta, 2.0 * std::f64::consts::PI / l, 0.0, half_pi, half_pi)
}

/// A layer of modulus e, Poisson ratio nu and thickness h (inf: half-space).
pub fn layer(e: f64, nu: f64, h: f64) -> Material {
    Material {
        youngs_modulus: e,
        poisson_ratio: nu,
        thickness: h,
    }
}

/// Spatial inputs with V = 1 m/s (so k_w = k).
pub fn spatial(
    material: Material,
    mu: f64,
    tau0: f64,
    k: f64,
    pbar: f64,
    harmonics: Vec<wearlab::physics::spatial::harmonic::Harmonic>,
) -> wearlab::physics::spatial::SpatialInputs {
    wearlab::physics::spatial::SpatialInputs {
        material,
        friction: Friction {
            coefficient: mu,
            adhesion: tau0,
        },
        wear: k,
        wear_exponent: 1.0,
        reference_pressure: 1.0,
        sliding_speed: 1.0,
        mean_pressure: pbar,
        shape: wearlab::physics::spatial::PunchShape::Harmonics(harmonics),
    }
}

/// The punch of 64 harmonics of `benches/partial_harmonics.rs`: wavenumbers (i, j) k0 for
/// i, j = 1..8 (k0 = 2 pi/1 mm, the egg-box's), amplitudes falling as 1/(i^2 + j^2) and scaled to
/// the egg-box's rms height (Delta = 0.1 um: sum A^2/4 = Delta^2/4), phases spread by the golden
/// ratio.
pub fn sixty_four_harmonics() -> Vec<wearlab::physics::spatial::harmonic::Harmonic> {
    use std::f64::consts::PI;
    let k0 = 2.0 * PI / 1e-3;
    let golden = 0.5 * (5f64.sqrt() - 1.0);
    let mut harmonics: Vec<_> = (1..=8)
        .flat_map(|i| (1..=8).map(move |j| (i, j)))
        .enumerate()
        .map(
            |(n, (i, j))| wearlab::physics::spatial::harmonic::Harmonic {
                amplitude: 1.0 / f64::from(i * i + j * j),
                wavenumber_x: f64::from(i) * k0,
                wavenumber_y: f64::from(j) * k0,
                phase_x: 2.0 * PI * ((2 * n + 1) as f64 * golden).fract(),
                phase_y: 2.0 * PI * ((2 * n + 2) as f64 * golden).fract(),
            },
        )
        .collect();
    let sum: f64 = harmonics.iter().map(|h| h.amplitude * h.amplitude).sum();
    harmonics
        .iter_mut()
        .for_each(|h| h.amplitude *= 1e-7 / sum.sqrt());
    harmonics
}

/// A preset of [`sixty_four_harmonics`] in partial contact on a 0.5 mm steel layer with friction
/// (the benchmark's: pbar = 25 MPa, mu = 0.3), worn from t = 0, on a `grid` x `grid` cell.
pub fn sixty_four_preset(grid: usize) -> String {
    let mut text = format!(
        "schema = 1\nproblem = \"spatial\"\n[material]\nyoungs_modulus = 2.0e11\n\
         poisson_ratio = 0.3\nthickness = 5.0e-4\n[friction]\ncoefficient = 0.3\n[wear]\n\
         coefficient = 1.0e-16\n[spatial]\nmean_pressure = 2.5e7\nsliding_speed = 1.0\n\
         time = 0.0\nduration = 50.0\ngrid = {grid}\n"
    );
    for h in sixty_four_harmonics() {
        text += &format!(
            "[[spatial.harmonics]]\namplitude = {:?}\nwavenumber_x = {:?}\nwavenumber_y = {:?}\n\
             phase_x = {:?}\nphase_y = {:?}\n",
            h.amplitude, h.wavenumber_x, h.wavenumber_y, h.phase_x, h.phase_y
        );
    }
    text
}
