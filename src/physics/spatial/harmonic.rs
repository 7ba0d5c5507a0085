//! One harmonic of the wavy punch: the layer's response to a surface wave (docs/physics/spatial.md section 2)
//! and the closed-form evolution under punch wear (section 3).

use crate::physics::elastic::strip_transfer;
use crate::physics::{Friction, Material};

/// The layer's compliances for a surface wave of wavenumber k (docs/physics/spatial.md section 2), all [m/Pa]:
///   u_z^ = -A p^ + i sx B tau^,  u_x^ = (sx^2 C + sy^2 Ct) tau^ + i sx B p^.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LayerResponse {
    /// A = (1 - nu) K2(kh)/(G k): normal compliance.
    pub a: f64,
    /// B = (1 - 2nu) K12(kh)/(2 G k): coupling of normal and tangential; negative for kh < X*(nu)
    /// when nu > 1/4.
    pub b: f64,
    /// C = (1 - nu) K1(kh)/(G k): in-plane compliance along the wave vector.
    pub c: f64,
    /// Ct = th(kh)/(G k): anti-plane compliance across the wave vector.
    pub ct: f64,
}

/// The response to a wave of wavenumber k = |(wx, wy)| > 0 [rad/m].
pub fn layer_response(material: &Material, k: f64) -> LayerResponse {
    let nu = material.poisson_ratio;
    let gk = material.shear_modulus() * k;
    let x = k * material.thickness; // inf for the half-space
    let t = strip_transfer(nu, x);
    LayerResponse {
        a: (1.0 - nu) * t.k2 / gk,
        // (1 - 2nu)/2 = chi (1 - nu): written with chi K12 so that it stays finite at nu = 1/2
        b: (1.0 - nu) * t.chi_k12 / gk,
        c: (1.0 - nu) * t.k1 / gk,
        ct: x.tanh() / gk,
    }
}

/// One harmonic A sin(wx x + rho_x) sin(wy y + rho_y) of the punch shape (1.6).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Harmonic {
    /// Amplitude A [m] at t = 0, >= 0.
    pub amplitude: f64,
    /// wx [rad/m], >= 0 (along the sliding line).
    pub wavenumber_x: f64,
    /// wy [rad/m], >= 0 (across it).
    pub wavenumber_y: f64,
    /// rho_x [rad] at t = 0.
    pub phase_x: f64,
    /// rho_y [rad] (constant in time).
    pub phase_y: f64,
}

impl Harmonic {
    /// |(wx, wy)| [rad/m].
    pub fn wavenumber(&self) -> f64 {
        self.wavenumber_x.hypot(self.wavenumber_y)
    }
}

/// How one harmonic evolves (docs/physics/spatial.md section 3). All rates use k_w = k V.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Evolution {
    /// Layer response at this wavenumber.
    pub response: LayerResponse,
    /// M = sqrt(A^2 + mu^2 sx^2 B^2) [m/Pa].
    pub m: f64,
    /// Decay rate beta = k_w A/M^2 [1/s]: A_n(t) = A_n(0) e^{-beta t}.
    pub decay_rate: f64,
    /// Phase rate Omega = k_w mu sx B/M^2 [rad/s]: rho_x(t) = rho_x(0) - Omega t.
    pub phase_rate: f64,
    /// Drift velocity c = Omega/wx [m/s] of the pattern, positive along +x (the direction of the
    /// friction force on the layer, against the layer's motion); 0 when wx = 0.
    pub drift_velocity: f64,
    /// Phase lead phi = atan2(mu sx B, A) [rad] of the pressure harmonic over the shape.
    pub phase_lead: f64,
}

impl Evolution {
    /// 1/M [Pa/m]: pressure amplitude per unit shape amplitude.
    pub fn pressure_per_amplitude(&self) -> f64 {
        1.0 / self.m
    }
}

/// The evolution of a harmonic of wave vector (wx, wy) under friction `mu` and wear rate
/// `k_w` = k V [m/(Pa s)].
pub fn evolution(material: &Material, friction: &Friction, k_w: f64, h: &Harmonic) -> Evolution {
    let k = h.wavenumber();
    let sx = h.wavenumber_x / k;
    let r = layer_response(material, k);
    let mu = friction.coefficient;
    let coupling = mu * sx * r.b;
    let m2 = r.a * r.a + coupling * coupling;
    let phase_rate = k_w * coupling / m2;
    Evolution {
        response: r,
        m: m2.sqrt(),
        decay_rate: k_w * r.a / m2,
        phase_rate,
        drift_velocity: if h.wavenumber_x > 0.0 {
            k_w * mu * r.b / (k * m2)
        } else {
            0.0
        },
        phase_lead: coupling.atan2(r.a),
    }
}

/// A harmonic's state at time t.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HarmonicState {
    /// A(t) [m].
    pub amplitude: f64,
    /// rho_x(t) [rad].
    pub phase_x: f64,
    /// rho_y [rad].
    pub phase_y: f64,
}

/// The state at time t [s]: A(t) = A(0) e^{-beta t}, rho_x(t) = rho_x(0) - Omega t.
pub fn state_at(h: &Harmonic, ev: &Evolution, t: f64) -> HarmonicState {
    HarmonicState {
        amplitude: h.amplitude * (-ev.decay_rate * t).exp(),
        phase_x: h.phase_x - ev.phase_rate * t,
        phase_y: h.phase_y,
    }
}
