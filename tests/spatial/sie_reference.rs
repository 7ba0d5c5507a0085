//! The reference for mu > 0 on the 1-D half-plane (docs/physics/spatial-partial.md section 6,
//! route 6): a singular integral equation for the contact pressure, solved here by Gauss–Jacobi collocation with Galin's edge exponents
//! and written without any of the solver's code (only the library's Gauss–Jacobi rule, tested on
//! its own in src/physics/quadrature.rs, and Brent's root finder).
//!
//! Periodic half-plane, punch U = Delta cos(2 pi x/l), tau = mu p in the contact (-a, b).
//! From u_z^ = -A p^ + i sx B tau^ with A = (1 - nu)/(G|k|), B = (1 - 2nu)/(2G|k|)
//! (docs/physics/spatial.md section 2), du_z/dx = ((1 - nu)/G) H[p] - mu (1 - 2nu)/(2G) (p - pbar),
//! where H[p](x) = (1/l) PV int p(xi) cot(pi (x - xi)/l) dxi (the periodic Hilbert transform,
//! multiplier -i sign k). In the contact the gap is 0, du_z/dx = -U', so
//!     H[p] - mu chi p = -G U'/(1 - nu) - mu chi pbar,   chi = (1 - 2nu)/(2(1 - nu)),
//! with p = w(t) psi(t), x = c + e t, w = (1 - t)^alpha (1 + t)^beta, alpha = 1/2 + theta at the
//! leading (+x) edge, beta = 1/2 - theta, tan(pi theta) = mu chi (Galin; the dominant equation
//! a phi + (b/pi) int phi/(t - s) with a = -mu chi, b = -1 has cot(pi alpha) = -a/b). The Cauchy
//! integral is taken by the rule of F. Erdogan, G. D. Gupta, T. S. Cook, "Numerical solution of
//! singular integral equations", in Mechanics of Fracture 1 (Noordhoff, 1973) 368–425: nodes t_i
//! the zeros of P_N^(alpha,beta), collocation points s_k the N + 1 zeros of
//! P_{N+1}^(-alpha,-beta) (index -1). For a given half-width e, the N + 1 equations in the N
//! values psi_i are consistent only for one centre c: the root of the last equation's residual.

use crate::common;

use std::f64::consts::PI;

use nalgebra::{DMatrix, DVector};
use wearlab::physics::quadrature::{gauss_jacobi, jacobi_zeros, tanh_sinh};
use wearlab::physics::roots::brent_to;
use wearlab::physics::spatial::partial::Setup;

/// cot z - 1/z, smooth for |z| < pi (series below 0.1: the next term, z^9/93555, is < 1e-14).
pub fn cot_minus_pole(z: f64) -> f64 {
    if z.abs() < 0.1 {
        let z2 = z * z;
        -z * (1.0 / 3.0 + z2 * (1.0 / 45.0 + z2 * (2.0 / 945.0 + z2 / 4725.0)))
    } else {
        1.0 / z.tan() - 1.0 / z
    }
}

/// The problem: half-plane (G, nu), friction mu, punch Delta cos(2 pi x/l).
pub struct Wave {
    pub g: f64,
    pub nu: f64,
    pub mu: f64,
    pub delta: f64,
    pub l: f64,
}

impl Wave {
    pub fn chi(&self) -> f64 {
        (1.0 - 2.0 * self.nu) / (2.0 * (1.0 - self.nu))
    }
    pub fn slope(&self, x: f64) -> f64 {
        -2.0 * PI * self.delta / self.l * (2.0 * PI * x / self.l).sin()
    }
}

/// The collocation solution for contact half-width e.
pub struct Sie {
    pub c: f64,
    pub e: f64,
    pub alpha: f64,
    pub beta: f64,
    pub t: Vec<f64>,
    pub w: Vec<f64>,
    pub psi: Vec<f64>,
    pub bary: Vec<f64>,
    pub pbar: f64,
}

pub fn system(
    wave: &Wave,
    e: f64,
    n: usize,
    c: f64,
) -> (DMatrix<f64>, DVector<f64>, Vec<f64>, Vec<f64>) {
    let theta = (wave.mu * wave.chi()).atan() / PI;
    let (alpha, beta) = (0.5 + theta, 0.5 - theta);
    let rule = gauss_jacobi(n, alpha, beta);
    let s = jacobi_zeros(n + 1, -alpha, -beta);
    let l = wave.l;
    let m = DMatrix::from_fn(n + 1, n, |k, i| {
        let (ti, sk) = (rule.nodes[i], s[k]);
        rule.weights[i]
            * (-1.0 / (PI * (ti - sk))
                + e / l * (cot_minus_pole(PI * e * (sk - ti) / l) + wave.mu * wave.chi()))
    });
    let rhs = DVector::from_fn(n + 1, |k, _| {
        -wave.g / (1.0 - wave.nu) * wave.slope(c + e * s[k])
    });
    (m, rhs, rule.nodes, rule.weights)
}

/// psi from the first N equations, and the residual of the last.
pub fn first_n(wave: &Wave, e: f64, n: usize, c: f64) -> (Vec<f64>, f64) {
    let (m, rhs, _, _) = system(wave, e, n, c);
    let psi = m
        .rows(0, n)
        .into_owned()
        .lu()
        .solve(&rhs.rows(0, n).into_owned())
        .expect("the collocation matrix is regular");
    let last = (m.row(n) * &psi)[0] - rhs[n];
    (psi.iter().copied().collect(), last)
}

pub fn solve_sie(wave: &Wave, e: f64, n: usize) -> Sie {
    // scan the centre over a quarter wavelength either side for the sign change nearest 0
    let l = wave.l;
    let residual = |c: f64| first_n(wave, e, n, c).1;
    let cs: Vec<f64> = (-40..=40).map(|i| i as f64 * l / 160.0).collect();
    let bracket = cs
        .windows(2)
        .filter(|p| residual(p[0]) * residual(p[1]) <= 0.0)
        .min_by(|a, b| a[0].abs().total_cmp(&b[0].abs()))
        .map(|p| (p[0], p[1]))
        .expect("a centre where the equations are consistent");
    // shifted by l so that Brent's relative tolerance is an absolute one of ~1e-15 l
    let c = brent_to(bracket.0 + l, bracket.1 + l, 1e-15, |c| residual(c - l)).unwrap() - l;
    let (psi, _) = first_n(wave, e, n, c);
    let (_, _, t, w) = system(wave, e, n, c);
    let bary: Vec<f64> = (0..n)
        .map(|i| {
            1.0 / (0..n)
                .filter(|&j| j != i)
                .map(|j| t[i] - t[j])
                .product::<f64>()
        })
        .collect();
    let theta = (wave.mu * wave.chi()).atan() / PI;
    let pbar = e / l * w.iter().zip(&psi).map(|(w, p)| w * p).sum::<f64>();
    Sie {
        c,
        e,
        alpha: 0.5 + theta,
        beta: 0.5 - theta,
        t,
        w,
        psi,
        bary,
        pbar,
    }
}

impl Sie {
    /// psi(z), the collocation polynomial, by the first barycentric form (stable also just outside).
    pub fn psi_at(&self, z: f64) -> f64 {
        if let Some(i) = self.t.iter().position(|t| *t == z) {
            return self.psi[i];
        }
        let ell: f64 = self.t.iter().map(|t| z - t).product();
        ell * (0..self.t.len())
            .map(|i| self.bary[i] * self.psi[i] / (z - self.t[i]))
            .sum::<f64>()
    }
    pub fn pressure(&self, x: f64) -> f64 {
        let t = (x - self.c) / self.e;
        (1.0 - t).powf(self.alpha) * (1.0 + t).powf(self.beta) * self.psi_at(t)
    }
    /// int w/(z - t) dt over [-1, 1] for |z| > 1, in closed form (alpha + beta = 1).
    pub fn cauchy_weight(&self, z: f64) -> f64 {
        let (a, b) = (self.alpha, self.beta);
        if z > 1.0 {
            PI / (PI * a).sin() * (z + b - a - (z - 1.0).powf(a) * (z + 1.0).powf(b))
        } else {
            let z = -z;
            -PI / (PI * b).sin() * (z + a - b - (z - 1.0).powf(b) * (z + 1.0).powf(a))
        }
    }
    /// int w psi/(z - t) dt for |z| > 1: psi(z) times the closed form plus an exact quadrature of
    /// the polynomial (psi(z) - psi(t))/(z - t).
    pub fn cauchy(&self, z: f64) -> f64 {
        let direct: f64 = (0..self.t.len())
            .map(|i| self.w[i] * self.psi[i] / (z - self.t[i]))
            .sum();
        if z.abs() > 1.4 {
            return direct;
        }
        let rule_part: f64 = self.w.iter().zip(&self.t).map(|(w, t)| w / (z - t)).sum();
        self.psi_at(z) * (self.cauchy_weight(z) - rule_part) + direct
    }

    /// The global outputs: (contact fraction, p_max, psi, mean gap, closure int gap' over the gap).
    pub fn outputs(&self, wave: &Wave) -> [f64; 5] {
        let l = wave.l;
        let fraction = 2.0 * self.e / l;
        // p_max: a fine scan, then golden-section refinement
        let xs: Vec<f64> = (1..2000)
            .map(|i| self.c + self.e * (i as f64 / 1000.0 - 1.0))
            .collect();
        let i = (0..xs.len())
            .max_by(|a, b| self.pressure(xs[*a]).total_cmp(&self.pressure(xs[*b])))
            .unwrap();
        let (mut lo, mut hi) = (xs[i.saturating_sub(1)], xs[(i + 1).min(xs.len() - 1)]);
        let golden = (5f64.sqrt() - 1.0) / 2.0;
        for _ in 0..100 {
            let (x1, x2) = (hi - golden * (hi - lo), lo + golden * (hi - lo));
            if self.pressure(x1) > self.pressure(x2) {
                hi = x2
            } else {
                lo = x1
            }
        }
        let p_max = self.pressure(0.5 * (lo + hi));
        let psi = -self.e / l
            * (0..self.t.len())
                .map(|i| self.w[i] * self.psi[i] * wave.slope(self.c + self.e * self.t[i]))
                .sum::<f64>();
        // gap' outside the contact, from b = c + e to the next contact's start c - e + l
        let (b, end) = (self.c + self.e, self.c - self.e + l);
        let regular = |u: f64| {
            let z = PI * u / l;
            if z <= PI / 2.0 {
                cot_minus_pole(z) - 1.0 / (z - PI)
            } else {
                cot_minus_pole(z - PI) - 1.0 / z
            }
        };
        let gap_slope = |eta: f64| {
            let h = (self.cauchy((eta - self.c) / self.e)
                + self.cauchy((eta - l - self.c) / self.e))
                / PI
                + self.e / l
                    * (0..self.t.len())
                        .map(|i| {
                            self.w[i] * self.psi[i] * regular(eta - self.c - self.e * self.t[i])
                        })
                        .sum::<f64>();
            -wave.slope(eta)
                - (1.0 - wave.nu) / wave.g * h
                - wave.mu * (1.0 - 2.0 * wave.nu) * self.pbar / (2.0 * wave.g)
        };
        let rule = tanh_sinh(1.0 / 32.0);
        let closure = rule.integrate(b, end, gap_slope);
        let mean_gap = rule.integrate(b, end, |eta| (end - eta) * gap_slope(eta)) / l;
        [fraction, p_max, psi, mean_gap, closure]
    }
}

pub fn wave(mu: f64) -> Wave {
    // a polymer-like half-plane under a 1 um, 1 mm wave (the numbers only set the scales)
    let (e, nu) = (3e9, 0.3);
    Wave {
        g: e / (2.0 * (1.0 + nu)),
        nu,
        mu,
        delta: 1e-6,
        l: 1e-3,
    }
}

/// The FFT solver's outputs for the same wave at the SIE's mean pressure on N nodes.
pub fn fft(wave: &Wave, pbar: f64, n: usize) -> [f64; 5] {
    let material = common::layer(2.0 * wave.g * (1.0 + wave.nu), wave.nu, f64::INFINITY);
    let harmonics = vec![common::cosine(wave.delta, wave.l)];
    let inputs = common::spatial(material, wave.mu, 0.0, 0.0, pbar, harmonics);
    let setup = Setup::new(&inputs, n).unwrap();
    let state = setup.initial_state().unwrap();
    let o = state.outputs;
    [
        o.contact_fraction,
        o.max_pressure,
        o.psi,
        o.mean_gap,
        o.mu_star,
    ]
}
