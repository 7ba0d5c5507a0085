//! Generated self-affine surfaces (docs/physics/spatial-surface.md section 4): an isotropic power
//! spectrum with random phases and amplitudes exactly sqrt(C(q)) (Jacobs, Junge & Pastewka (2017)
//! section 2.4 give the same construction with random amplitudes), scaled to a given rms height
//! or rms slope.

use std::f64::consts::PI;

use super::spectrum::{C64, fft2, is_nyquist, wave_vector};
use super::statistics::statistics;
use super::{Surface, check_grid};

/// What the generated surface is scaled to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Amplitude {
    /// rms height [m], > 0.
    RmsHeight(f64),
    /// rms slope along x [-], > 0.
    RmsSlope(f64),
}

/// The parameters of a self-affine surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SelfAffine {
    /// Hurst exponent H [-], 0 < H <= 1.
    pub hurst: f64,
    /// rms height or rms slope.
    pub amplitude: Amplitude,
    /// Roll-off wavelength lambda_r [m]: C(q) is flat for q < q_r = 2 pi/lambda_r.
    pub rolloff_wavelength: f64,
    /// Short-wavelength cutoff lambda_s [m], <= lambda_r: C(q) = 0 above q_s = 2 pi/lambda_s.
    pub cutoff_wavelength: f64,
    /// Cell length along x [m], > 0.
    pub length_x: f64,
    /// Cell width along y [m]; 0 for a profile along x (grid N x 1).
    pub length_y: f64,
    /// Nodes per side N.
    pub grid: usize,
    /// Seed of the phases.
    pub seed: u64,
}

/// SplitMix64 (Steele, Lea & Flood (2014)): a 64-bit generator of integer arithmetic only, so the
/// same seed gives the same sequence on every machine.
#[derive(Clone, Copy, Debug)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    /// The generator started at `seed`.
    pub fn new(seed: u64) -> SplitMix64 {
        SplitMix64 { state: seed }
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform number in [0, 1) with 53 random bits.
    pub fn next_unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// The surface of these parameters. Refused when a parameter is out of range or when no mode of
/// the grid falls below the cutoff.
pub fn generate(p: &SelfAffine) -> Result<Surface, String> {
    validate(p)?;
    let profile = p.length_y == 0.0;
    let (nx, ny) = (p.grid, if profile { 1 } else { p.grid });
    check_grid(nx, ny)?;
    let shape = Surface {
        nx,
        ny,
        lx: p.length_x,
        ly: p.length_y,
        heights: Vec::new(),
    };
    let q_r = 2.0 * PI / p.rolloff_wavelength;
    let q_s = 2.0 * PI / p.cutoff_wavelength;
    // 2-D: C(q) ~ q^(-2(1+H)); profile: C1(q) ~ q^(-(1+2H)) (docs/physics/spatial-surface.md (4.1))
    let exponent = if profile {
        -(1.0 + 2.0 * p.hurst)
    } else {
        -2.0 * (1.0 + p.hurst)
    };
    let psd = |q: f64| {
        if q == 0.0 || q > q_s {
            0.0
        } else {
            q.max(q_r).powf(exponent)
        }
    };
    let mut rng = SplitMix64::new(p.seed);
    let mut data = vec![C64::default(); nx * ny];
    for ky in 0..ny {
        for kx in 0..nx {
            let index = ky * nx + kx;
            let partner = ((ny - ky) % ny) * nx + (nx - kx) % nx;
            if partner <= index || is_nyquist(kx, nx) || is_nyquist(ky, ny) {
                continue;
            }
            let (qx, qy) = wave_vector(&shape, kx, ky);
            let phase = 2.0 * PI * rng.next_unit();
            let value = C64::from_polar(psd(qx.hypot(qy)).sqrt(), phase);
            data[index] = value;
            data[partner] = value.conj();
        }
    }
    if data.iter().all(|c| c.norm_sqr() == 0.0) {
        return Err(format!(
            "no wave of the {nx}-node grid over {} m is longer than the cutoff wavelength {} m",
            p.length_x, p.cutoff_wavelength
        ));
    }
    fft2(&mut data, nx, ny, true);
    let raw = Surface {
        heights: data.iter().map(|c| c.re).collect(),
        ..shape
    };
    let stats = statistics(&raw);
    let scale = match p.amplitude {
        Amplitude::RmsHeight(h) => h / stats.rms_height,
        Amplitude::RmsSlope(s) => s / stats.rms_slope,
    };
    if !scale.is_finite() {
        return Err("the band has no slope along x to scale to (every wave runs along y)".into());
    }
    let heights = raw.heights.iter().map(|h| h * scale).collect();
    Surface::new(nx, ny, p.length_x, p.length_y, heights)
}

/// What a parameter of the generator allows, in words, as `validate` and the grid check refuse
/// (by the preset key's last part: "hurst", "grid"); the explorer's form and `--set` quote it.
pub fn allowed(name: &str) -> &'static str {
    match name {
        "hurst" => "0 < H <= 1",
        "rms_height" => "> 0 (m)",
        "rms_slope" => "> 0",
        "rolloff_wavelength" => "> 0 (m), at least the cutoff wavelength",
        "cutoff_wavelength" => "> 0 (m), at most the roll-off wavelength",
        "length_x" => "> 0 (m)",
        "length_y" => ">= 0 (m), 0 for a profile along x",
        "grid" => "a whole number from 2 to 1024 (to 16384 for a profile)",
        _ => "a whole number >= 0",
    }
}

fn validate(p: &SelfAffine) -> Result<(), String> {
    let positive = |name: &str, v: f64| {
        if v.is_finite() && v > 0.0 {
            Ok(())
        } else {
            Err(format!("{name} = {v}: must be > 0"))
        }
    };
    if !(p.hurst > 0.0 && p.hurst <= 1.0) {
        return Err(format!("hurst = {}: must be in (0, 1]", p.hurst));
    }
    match p.amplitude {
        Amplitude::RmsHeight(h) => positive("rms_height", h)?,
        Amplitude::RmsSlope(s) => positive("rms_slope", s)?,
    }
    positive("rolloff_wavelength", p.rolloff_wavelength)?;
    positive("cutoff_wavelength", p.cutoff_wavelength)?;
    positive("length_x", p.length_x)?;
    if !(p.length_y.is_finite() && p.length_y >= 0.0) {
        return Err(format!(
            "length_y = {}: must be >= 0 (0 for a profile)",
            p.length_y
        ));
    }
    if p.cutoff_wavelength > p.rolloff_wavelength {
        return Err(format!(
            "cutoff_wavelength = {} m is longer than rolloff_wavelength = {} m",
            p.cutoff_wavelength, p.rolloff_wavelength
        ));
    }
    Ok(())
}
