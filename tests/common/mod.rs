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
        sliding_speed: 1.0,
        mean_pressure: pbar,
        shape: wearlab::physics::spatial::PunchShape::Harmonics(harmonics),
    }
}
