//! The strip of any thickness (docs/physics/plane.md section 6): the wear-contact equation with the exact
//! kernels (3.7),
//!   gamma q2 + (1/m) p.v. int q2/(s-x) ds + (1/(m h)) int q2(s) [R2(z) + mu chi B12(z)] ds
//!     = -x/R - (tau0/m) [pi chi + chi l12((b-x)/h) + chi l12((a+x)/h)],    z = (s-x)/h,
//! solved by Gauss–Jacobi collocation: q2 = w(t) phi(t) with w = (1-t)^(1/2+theta) (1+t)^(1/2-theta)
//! on s = c + (L/2) t, unknowns phi at the zeros of P_N^(1/2+theta, 1/2-theta), collocation at the
//! zeros of P_{N+1}^(-1/2-theta, -1/2+theta), where (1/pi) sum W_i phi_i/(t_i - xi_k) is exactly
//! tan(pi theta) q2 + (1/pi) p.v. int q2/(t - xi). For a fixed L the shift c = (b-a)/2 enters as
//! the constant -c/R, so it is one more unknown: one linear solve per L (Householder QR: LU
//! breaks down for narrow strips with strong wear), then Brent on L for the load.

use std::collections::HashMap;
use std::f64::consts::PI;
use std::sync::{Arc, Mutex, OnceLock};

use nalgebra::{DMatrix, DVector};

use crate::physics::SolveError;
use crate::physics::elastic::chi_c12;
use crate::physics::plane::kernels::StripKernels;
use crate::physics::plane::{
    Model, PlaneInputs, PlaneSolution, PressureLaw, exponent, total_friction,
};
use crate::physics::quadrature::{GaussRule, gauss_jacobi, jacobi_zeros};
use crate::physics::roots::{bracket, brent_to};

/// The regular kernels the solver uses (the exact strip, or the wide limit for checks).
pub trait Kernels {
    /// R2(z) = A2(z) - 1/z.
    fn r2(&self, z: f64) -> f64;
    /// chi B12(z).
    fn chi_b12(&self, z: f64) -> f64;
    /// chi l12(z).
    fn chi_l12(&self, z: f64) -> f64;
    /// R2(z) + mu chi B12(z).
    fn regular(&self, z: f64, mu: f64) -> f64 {
        self.r2(z) + mu * self.chi_b12(z)
    }
}

impl Kernels for StripKernels {
    fn r2(&self, z: f64) -> f64 {
        StripKernels::r2(self, z)
    }
    fn chi_b12(&self, z: f64) -> f64 {
        StripKernels::chi_b12(self, z)
    }
    fn chi_l12(&self, z: f64) -> f64 {
        StripKernels::chi_l12(self, z)
    }
    fn regular(&self, z: f64, mu: f64) -> f64 {
        StripKernels::regular(self, z, mu)
    }
}

/// The wide-strip limit of the kernels: R2 -> 0, chi B12 -> chi c12, chi l12(z) -> chi c12 z
/// (section 4's kernel (4.1)); with it the solver must reproduce the wide closed form.
pub struct WideLimit {
    /// chi c12(nu).
    pub chi_c12: f64,
}

impl Kernels for WideLimit {
    fn r2(&self, _: f64) -> f64 {
        0.0
    }
    fn chi_b12(&self, _: f64) -> f64 {
        self.chi_c12
    }
    fn chi_l12(&self, z: f64) -> f64 {
        self.chi_c12 * z
    }
}

impl WideLimit {
    /// The limit for a Poisson ratio.
    pub fn new(nu: f64) -> WideLimit {
        WideLimit {
            chi_c12: chi_c12(nu),
        }
    }
}

/// The kernel table for nu, built once per nu and kept (a few tables at most).
pub fn kernels_for(nu: f64) -> Arc<StripKernels> {
    static CACHE: OnceLock<Mutex<HashMap<u64, Arc<StripKernels>>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
    let mut map = cache
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    if let Some(k) = map.get(&nu.to_bits()) {
        return Arc::clone(k);
    }
    if map.len() >= 4 {
        map.clear();
    }
    let k = Arc::new(StripKernels::new(nu));
    map.insert(nu.to_bits(), Arc::clone(&k));
    k
}

/// The collocation solution at one contact width.
#[derive(Clone, Debug, PartialEq)]
pub struct Collocation {
    /// Contact width L [m].
    pub l: f64,
    /// Shift c = (b - a)/2 [m].
    pub c: f64,
    /// Exponent shift theta.
    pub theta: f64,
    /// Jacobi nodes t_i in (-1, 1).
    pub nodes: Vec<f64>,
    /// Quadrature weights W_i (with the Jacobi weight).
    pub weights: Vec<f64>,
    /// phi_i = q2/w at the nodes [Pa].
    pub phi: Vec<f64>,
    /// Q2 [N/m].
    pub q2: f64,
    /// psi [N/m].
    pub psi: f64,
    /// Delta_g [m].
    pub delta_g: f64,
    /// P [N/m] from (3.11).
    pub load: f64,
    /// Barycentric weights of the nodes (for phi between them).
    bary: Vec<f64>,
}

/// The number of nodes that resolves the strip: 40 + 4 L/h (docs/physics/plane.md suggests 60 + 5 L/h for
/// 1e-11; this keeps N against 1.5 N within 1e-8, tested).
pub fn nodes_for(l_over_h: f64) -> usize {
    (40.0 + 4.0 * l_over_h).ceil().min(400.0) as usize
}

/// Solves the collocation system at contact width `l` with `n` nodes.
pub fn collocate(inputs: &PlaneInputs, kernels: &dyn Kernels, l: f64, n: usize) -> Collocation {
    collocate_on(inputs, kernels, l, &Rules::new(inputs, n))
}

/// The Gauss–Jacobi nodes and weights and the collocation points for n unknowns: they depend on
/// theta and n only, so a sweep or a root search builds them once.
pub struct Rules {
    theta: f64,
    rule: GaussRule,
    xk: Vec<f64>,
}

impl Rules {
    /// The rules for these inputs' theta with n nodes.
    pub fn new(inputs: &PlaneInputs, n: usize) -> Rules {
        let (_, _, theta) = exponent(inputs);
        Rules {
            theta,
            rule: gauss_jacobi(n, 0.5 + theta, 0.5 - theta),
            xk: jacobi_zeros(n + 1, -0.5 - theta, -0.5 + theta),
        }
    }
}

/// As `collocate`, on prepared rules.
pub fn collocate_on(
    inputs: &PlaneInputs,
    kernels: &dyn Kernels,
    l: f64,
    rules: &Rules,
) -> Collocation {
    let (m, _, _) = exponent(inputs);
    let theta = rules.theta;
    let (rule, xk) = (&rules.rule, &rules.xk);
    let n = rule.nodes.len();
    let chi = inputs.material.chi();
    let (mu, tau0, r) = (
        inputs.friction.coefficient,
        inputs.friction.adhesion,
        inputs.radius,
    );
    let h = inputs.material.thickness;
    let half = 0.5 * l;
    let mut a = DMatrix::<f64>::zeros(n + 1, n + 1);
    let mut rhs = DVector::<f64>::zeros(n + 1);
    for (k, &xi) in xk.iter().enumerate() {
        for i in 0..n {
            let t = rule.nodes[i];
            let z = half * (t - xi) / h;
            let regular = kernels.regular(z, mu);
            a[(k, i)] = rule.weights[i] * (1.0 / (PI * (t - xi)) + half / (PI * h) * regular);
        }
        a[(k, n)] = m / PI;
        let ends = kernels.chi_l12(half * (1.0 - xi) / h) + kernels.chi_l12(half * (1.0 + xi) / h);
        rhs[k] = -(m / PI) * half * xi / r - tau0 / PI * (PI * chi + ends);
    }
    let sol = a
        .qr()
        .solve(&rhs)
        .unwrap_or_else(|| DVector::from_element(n + 1, f64::NAN));
    let phi: Vec<f64> = sol.iter().take(n).copied().collect();
    let c = sol[n] * r;
    let q2 = half * (0..n).map(|i| rule.weights[i] * phi[i]).sum::<f64>();
    let psi = half
        * (0..n)
            .map(|i| rule.weights[i] * phi[i] * (c + half * rule.nodes[i]) / r)
            .sum::<f64>();
    let delta_g = l * c / r;
    // barycentric weights 1/prod(t_j - t_k), each factor doubled so the products stay O(1)
    let bary = (0..n)
        .map(|j| {
            (0..n)
                .filter(|&k| k != j)
                .fold(1.0, |w, k| w / (2.0 * (rule.nodes[j] - rule.nodes[k])))
        })
        .collect();
    Collocation {
        bary,
        l,
        c,
        theta,
        nodes: rule.nodes.clone(),
        weights: rule.weights.clone(),
        phi,
        q2,
        psi,
        delta_g,
        load: q2 - mu * psi - tau0 * delta_g,
    }
}

/// The contact width at which the load is `p`, by a bracket from the wide estimate and Brent.
pub(crate) fn width_for_load(
    inputs: &PlaneInputs,
    kernels: &dyn Kernels,
    p: f64,
    rtol: f64,
) -> Result<f64, SolveError> {
    let h = inputs.material.thickness;
    let rules = std::cell::RefCell::new(HashMap::<usize, Rules>::new());
    let f = |l: f64| {
        let n = nodes_for(l / h);
        let mut cache = rules.borrow_mut();
        let r = cache.entry(n).or_insert_with(|| Rules::new(inputs, n));
        collocate_on(inputs, kernels, l, r).load - p
    };
    let guess = (8.0 * inputs.radius * p / inputs.material.plane_modulus()).sqrt();
    let Some((lo, hi)) = bracket(guess, (0.5, 60), (1.5, 60), f) else {
        return Err(SolveError::NoSolution(format!(
            "the strip model finds no contact width for P = {p:.4e} N/m"
        )));
    };
    brent_to(lo, hi, rtol, f).ok_or_else(|| {
        SolveError::NoSolution(format!(
            "the contact width did not converge at P = {p:.4e} N/m"
        ))
    })
}

/// The solution from a converged collocation.
pub fn solution(inputs: &PlaneInputs, col: Collocation, model: Model) -> PlaneSolution {
    let mu = inputs.friction.coefficient;
    let tau0 = inputs.friction.adhesion;
    let (_, gamma, _) = exponent(inputs);
    PlaneSolution {
        model,
        inputs: *inputs,
        normal_force: col.q2,
        friction_force: mu * col.q2 + tau0 * col.l,
        tangential_force: mu * col.q2 + tau0 * col.l + col.psi,
        a: 0.5 * col.l - col.c,
        b: 0.5 * col.l + col.c,
        theta: Some(col.theta),
        gamma: Some(gamma),
        psi: col.psi,
        delta_g: col.delta_g,
        mu_star: total_friction(&inputs.friction, col.psi, col.delta_g, inputs.load),
        law: PressureLaw::Strip(Arc::new(col)),
    }
}

/// Solves the strip model at the inputs' load (finite thickness only).
pub fn solve(inputs: &PlaneInputs) -> Result<PlaneSolution, SolveError> {
    if inputs.material.is_half_space() {
        return Err(SolveError::InvalidInput(
            "the strip model needs a finite thickness h; for a half-plane use the wide model (it is exact there)".into(),
        ));
    }
    let kernels = kernels_for(inputs.material.poisson_ratio);
    solve_with(inputs, kernels.as_ref())
}

/// As `solve`, with the kernels given.
pub fn solve_with(
    inputs: &PlaneInputs,
    kernels: &dyn Kernels,
) -> Result<PlaneSolution, SolveError> {
    let l = width_for_load(inputs, kernels, inputs.load, 1e-15)?;
    let col = collocate(inputs, kernels, l, nodes_for(l / inputs.material.thickness));
    if col.phi.iter().any(|v| !v.is_finite()) {
        return Err(SolveError::NoSolution(
            "the strip collocation system is singular".into(),
        ));
    }
    Ok(solution(inputs, col, Model::Strip))
}

impl Collocation {
    /// phi at t by barycentric interpolation through the nodes.
    pub fn phi_at(&self, t: f64) -> f64 {
        let (mut num, mut den) = (0.0, 0.0);
        for j in 0..self.nodes.len() {
            let d = t - self.nodes[j];
            if d == 0.0 {
                return self.phi[j];
            }
            num += self.bary[j] / d * self.phi[j];
            den += self.bary[j] / d;
        }
        num / den
    }

    /// q2 at distance u from the trailing edge [Pa].
    pub fn pressure_from_trailing_edge(&self, u: f64) -> f64 {
        let t = (2.0 * u / self.l - 1.0).clamp(-1.0, 1.0);
        (1.0 - t).powf(0.5 + self.theta) * (1.0 + t).powf(0.5 - self.theta) * self.phi_at(t)
    }
}
