//! How far the wide and narrow models are from the strip model of any thickness, as formulas
//! derived from a study against it (`tests/plane/plane_validity.rs` reruns it coarsely in
//! `cargo test`; `examples/validity_study.rs` reruns it in full).
//!
//! The study: the strip model (docs/physics/plane.md section 6, exact to 1e-10) at contact widths
//! (a+b)/h = Lambda from 0.05 to 1.45 (steps of 3 %) and at 10, 14, 20, ..., 240, for nu in
//! {0, 0.1, 0.2, 0.25, 0.3, 0.35, 0.4, 0.42, 0.44, ..., 0.49, 0.495, 0.499}, mu in {0, 0.1, 0.3,
//! 0.6, 1}, k m in {0, 0.01, 0.05, 0.2, 0.5, 1, 3}, tau0 = 0; at each width the wide and narrow
//! models solved at the strip's load. Errors, both dimensionless and independent of h/R (checked):
//! - contact width: |L_model/L_strip - 1|, tolerance 2 %;
//! - mu* - mu: |mu*_model - mu*_strip| / max(|mu*_strip - mu|, 0.01 (a+b)/R), tolerance 5 %. The
//!   floor: mu* - mu is of order theta (a+b)/R (eq. 4.9); below 0.01 (a+b)/R it is a near
//!   cancellation of the friction and wear parts (theta ~ 0), where a relative error means nothing.
//!
//! Between the study's grid points the tables are read conservatively: the worse of the two
//! neighbours (larger error coefficient, smaller width limit), never an interpolation.

/// Contact-width tolerance (relative).
pub const WIDTH_TOLERANCE: f64 = 0.02;
/// Tolerance on mu* - mu (relative, with the floor below).
pub const MU_STAR_TOLERANCE: f64 = 0.05;
/// mu* - mu is measured against max(|mu*_strip - mu|, MU_STAR_FLOOR (a+b)/R).
pub const MU_STAR_FLOOR: f64 = 0.01;

/// The ranges the study covered; outside them no model is said to hold.
pub const STUDIED_NU: f64 = 0.499;
/// Largest friction coefficient studied.
pub const STUDIED_MU: f64 = 1.0;
/// Largest k m studied.
pub const STUDIED_KM: f64 = 3.0;

/// The study's Poisson ratios.
const NU: [f64; 17] = [
    0.0, 0.1, 0.2, 0.25, 0.3, 0.35, 0.4, 0.42, 0.44, 0.45, 0.46, 0.47, 0.48, 0.485, 0.49, 0.495,
    0.499,
];
/// The study's friction coefficients.
const MU: [f64; 5] = [0.0, 0.1, 0.3, 0.6, 1.0];
/// The study's k m.
const KM: [f64; 7] = [0.0, 0.01, 0.05, 0.2, 0.5, 1.0, 3.0];

/// The two grid points around x (the same twice at or beyond an end).
fn neighbours(grid: &[f64], x: f64) -> (usize, usize) {
    match grid.iter().position(|&g| g >= x) {
        Some(0) => (0, 0),
        Some(i) if grid[i] == x => (i, i),
        Some(i) => (i - 1, i),
        None => (grid.len() - 1, grid.len() - 1),
    }
}

/// The worse (larger) of the table's values at the grid points around nu.
fn larger_in_nu(table: &[f64; 17], nu: f64) -> f64 {
    let (i, j) = neighbours(&NU, nu);
    table[i].max(table[j])
}

/// The wide model's contact width error: A(nu) Lambda^2, A(nu) = 0.072 + 0.05 nu + 0.13 nu^2,
/// an upper bound of the study's largest e_L/Lambda^2 over Lambda <= 0.5 and every mu, k m
/// (study: 0.072 at nu = 0, 0.089 at 0.3, 0.114 at 0.45, 0.128 at 0.499; e_L/Lambda^2 falls
/// beyond Lambda = 0.5). It holds within 2 % for Lambda up to 0.53 (nu = 0) .. 0.39 (nu = 0.499).
pub fn wide_width_error(nu: f64, lambda: f64) -> f64 {
    (0.072 + 0.05 * nu + 0.13 * nu * nu) * lambda * lambda
}

/// The largest Lambda (on the study's 3 % steps) up to which the wide model's mu* - mu stays
/// within 5 % of the strip's for every mu <= 1 and k m <= 3 of the study, per nu (the error grows
/// about like Lambda^2 below it; the worst cases mix friction and wear).
const WIDE_MU_STAR_LIMIT: [f64; 17] = [
    0.433, 0.362, 0.233, 0.313, 0.362, 0.262, 0.295, 0.262, 0.213, 0.262, 0.226, 0.207, 0.207,
    0.213, 0.362, 0.408, 0.446,
];

/// The wide model's error in mu* - mu, estimated as 5 % (Lambda/Lambda_max(nu))^2.
pub fn wide_mu_star_error(nu: f64, lambda: f64) -> f64 {
    let (i, j) = neighbours(&NU, nu);
    let limit = WIDE_MU_STAR_LIMIT[i].min(WIDE_MU_STAR_LIMIT[j]);
    MU_STAR_TOLERANCE * (lambda / limit).powi(2)
}

/// The width limit of the wide model for mu* - mu (the smaller neighbour's).
pub fn wide_mu_star_limit(nu: f64) -> f64 {
    let (i, j) = neighbours(&NU, nu);
    WIDE_MU_STAR_LIMIT[i].min(WIDE_MU_STAR_LIMIT[j])
}

/// Edge offset D(nu, mu, k m) = Lambda |L_Winkler/L_strip - 1|, the largest over the study's
/// Lambda >= 10, times 1.1: the Winkler contact width is off by at most D/Lambda (L_Winkler -
/// L_strip tends to a fixed multiple of h as Lambda grows). Near nu = 1/2 it is large: the layer is
/// then softer than Winkler's (the small-X expansion of K2 of docs/physics/plane.md section 2 is
/// K2 = (1-2nu) X/(2(1-nu)^2) + nu(4nu-1) X^3/(6(1-nu)^3) + ..., the cubic term checked to 1e-8 in
/// 40-digit arithmetic, and takes over as nu -> 1/2); friction adds to it and wear takes from it.
/// Indexed [nu][mu][k m] on the grids NU, MU, KM.
const NARROW_OFFSET: [[[f64; 7]; 5]; 17] = [
    // nu = 0.0
    [
        [0.405, 0.405, 0.405, 0.403, 0.396, 0.381, 0.299],
        [0.404, 0.428, 0.462, 0.458, 0.448, 0.426, 0.329],
        [0.393, 0.47, 0.573, 0.565, 0.548, 0.517, 0.39],
        [0.358, 0.516, 0.722, 0.709, 0.685, 0.647, 0.485],
        [0.28, 0.545, 0.888, 0.873, 0.845, 0.803, 0.61],
    ],
    // nu = 0.1
    [
        [0.419, 0.419, 0.418, 0.416, 0.405, 0.385, 0.297],
        [0.418, 0.437, 0.461, 0.456, 0.443, 0.419, 0.321],
        [0.411, 0.47, 0.546, 0.537, 0.52, 0.489, 0.37],
        [0.388, 0.508, 0.66, 0.649, 0.626, 0.59, 0.444],
        [0.337, 0.538, 0.792, 0.778, 0.752, 0.713, 0.545],
    ],
    // nu = 0.2
    [
        [0.395, 0.395, 0.395, 0.392, 0.382, 0.363, 0.281],
        [0.395, 0.404, 0.414, 0.41, 0.4, 0.382, 0.296],
        [0.391, 0.419, 0.452, 0.448, 0.439, 0.42, 0.327],
        [0.381, 0.437, 0.503, 0.501, 0.493, 0.476, 0.373],
        [0.357, 0.452, 0.561, 0.56, 0.556, 0.543, 0.435],
    ],
    // nu = 0.25
    [
        [0.354, 0.354, 0.354, 0.352, 0.347, 0.334, 0.263],
        [0.353, 0.354, 0.354, 0.356, 0.353, 0.342, 0.273],
        [0.352, 0.352, 0.354, 0.361, 0.366, 0.358, 0.291],
        [0.346, 0.347, 0.351, 0.365, 0.381, 0.381, 0.319],
        [0.332, 0.333, 0.34, 0.364, 0.396, 0.407, 0.356],
    ],
    // nu = 0.3
    [
        [0.273, 0.273, 0.273, 0.279, 0.287, 0.286, 0.235],
        [0.273, 0.273, 0.272, 0.271, 0.274, 0.279, 0.237],
        [0.271, 0.271, 0.268, 0.261, 0.258, 0.266, 0.24],
        [0.266, 0.265, 0.26, 0.244, 0.231, 0.246, 0.245],
        [0.255, 0.253, 0.244, 0.216, 0.192, 0.215, 0.251],
    ],
    // nu = 0.35
    [
        [0.118, 0.118, 0.118, 0.146, 0.183, 0.209, 0.195],
        [0.117, 0.116, 0.113, 0.112, 0.139, 0.182, 0.187],
        [0.113, 0.11, 0.118, 0.0741, 0.076, 0.127, 0.17],
        [0.0977, 0.202, 0.363, 0.234, 0.0843, 0.0475, 0.146],
        [0.0633, 0.441, 0.705, 0.496, 0.262, 0.0711, 0.114],
    ],
    // nu = 0.4
    [
        [0.245, 0.242, 0.225, 0.159, 0.0232, 0.087, 0.135],
        [0.249, 0.367, 0.371, 0.238, 0.101, 0.0293, 0.114],
        [0.279, 0.644, 0.722, 0.502, 0.266, 0.0978, 0.0725],
        [0.382, 1.11, 1.28, 0.903, 0.528, 0.255, 0.0114],
        [0.615, 1.81, 2.07, 1.44, 0.869, 0.469, 0.0752],
    ],
    // nu = 0.42
    [
        [0.501, 0.496, 0.464, 0.353, 0.137, 0.0194, 0.103],
        [0.508, 0.69, 0.66, 0.447, 0.242, 0.0859, 0.0757],
        [0.565, 1.13, 1.15, 0.789, 0.45, 0.219, 0.0224],
        [0.752, 1.87, 1.94, 1.31, 0.776, 0.415, 0.0684],
        [1.17, 3.0, 3.04, 2.01, 1.2, 0.675, 0.169],
    ],
    // nu = 0.44
    [
        [0.905, 0.894, 0.831, 0.626, 0.29, 0.118, 0.0644],
        [0.919, 1.21, 1.09, 0.735, 0.423, 0.202, 0.0308],
        [1.03, 1.95, 1.8, 1.18, 0.685, 0.367, 0.0549],
        [1.4, 3.21, 2.92, 1.85, 1.08, 0.607, 0.151],
        [2.17, 5.08, 4.46, 2.73, 1.59, 0.917, 0.275],
    ],
    // nu = 0.45
    [
        [1.21, 1.19, 1.09, 0.804, 0.384, 0.177, 0.0427],
        [1.23, 1.61, 1.4, 0.921, 0.533, 0.27, 0.0184],
        [1.4, 2.6, 2.26, 1.42, 0.826, 0.452, 0.0906],
        [1.92, 4.29, 3.6, 2.19, 1.26, 0.718, 0.197],
        [3.01, 6.75, 5.42, 3.17, 1.82, 1.06, 0.334],
    ],
    // nu = 0.46
    [
        [1.63, 1.6, 1.44, 1.02, 0.492, 0.243, 0.019],
        [1.66, 2.17, 1.8, 1.16, 0.659, 0.346, 0.0496],
        [1.92, 3.53, 2.86, 1.71, 0.986, 0.547, 0.129],
        [2.73, 5.83, 4.49, 2.58, 1.46, 0.838, 0.246],
        [4.31, 9.1, 6.62, 3.66, 2.07, 1.21, 0.397],
    ],
    // nu = 0.47
    [
        [2.27, 2.21, 1.92, 1.27, 0.618, 0.319, 0.0392],
        [2.33, 2.98, 2.34, 1.46, 0.804, 0.431, 0.0836],
        [2.77, 4.92, 3.65, 2.06, 1.17, 0.652, 0.171],
        [4.08, 8.11, 5.62, 3.02, 1.69, 0.971, 0.299],
        [6.53, 12.5, 8.13, 4.22, 2.35, 1.37, 0.465],
    ],
    // nu = 0.48
    [
        [3.37, 3.22, 2.67, 1.56, 0.763, 0.402, 0.0721],
        [3.49, 4.31, 3.11, 1.8, 0.971, 0.526, 0.121],
        [4.37, 7.14, 4.74, 2.49, 1.37, 0.769, 0.217],
        [6.81, 11.7, 7.1, 3.54, 1.95, 1.12, 0.357],
        [11.0, 17.5, 9.95, 4.85, 2.66, 1.55, 0.537],
    ],
    // nu = 0.485
    [
        [4.31, 4.03, 3.2, 1.69, 0.845, 0.448, 0.0898],
        [4.51, 5.38, 3.62, 1.98, 1.06, 0.578, 0.141],
        [5.9, 8.93, 5.42, 2.73, 1.49, 0.832, 0.241],
        [9.55, 14.3, 8.0, 3.84, 2.09, 1.2, 0.387],
        [15.5, 20.8, 11.0, 5.19, 2.83, 1.65, 0.576],
    ],
    // nu = 0.49
    [
        [5.92, 5.3, 3.89, 1.81, 0.934, 0.497, 0.108],
        [6.29, 6.95, 4.26, 2.17, 1.17, 0.634, 0.162],
        [8.85, 11.4, 6.23, 3.0, 1.61, 0.899, 0.266],
        [15.0, 17.8, 9.01, 4.17, 2.24, 1.28, 0.419],
        [24.4, 25.1, 12.2, 5.56, 3.01, 1.75, 0.615],
    ],
    // nu = 0.495
    [
        [9.58, 7.56, 4.73, 1.94, 1.03, 0.549, 0.128],
        [10.7, 9.41, 5.16, 2.41, 1.27, 0.692, 0.183],
        [17.3, 15.1, 7.23, 3.3, 1.74, 0.97, 0.293],
        [30.7, 22.3, 10.1, 4.52, 2.4, 1.36, 0.452],
        [47.8, 30.2, 13.5, 5.98, 3.2, 1.86, 0.656],
    ],
    // nu = 0.499
    [
        [25.1, 10.9, 5.58, 2.13, 1.11, 0.593, 0.144],
        [35.2, 12.6, 5.91, 2.63, 1.37, 0.742, 0.202],
        [68.5, 19.0, 8.18, 3.56, 1.85, 1.03, 0.315],
        [99.7, 26.8, 11.2, 4.83, 2.53, 1.44, 0.479],
        [1.23e+02, 35.0, 14.6, 6.33, 3.36, 1.94, 0.69],
    ],
];

/// The Winkler model's contact width error D(nu, mu, k m)/Lambda.
pub fn narrow_width_error(nu: f64, mu: f64, km: f64, lambda: f64) -> f64 {
    narrow_offset(nu, mu, km) / lambda
}

/// The Lambda the Winkler model needs for its contact width within 2 %: D(nu, mu, k m)/0.02.
pub fn narrow_width_limit(nu: f64, mu: f64, km: f64) -> f64 {
    narrow_offset(nu, mu, km) / WIDTH_TOLERANCE
}

/// The worst of NARROW_OFFSET at the eight grid points around (nu, mu, k m).
fn narrow_offset(nu: f64, mu: f64, km: f64) -> f64 {
    let (i, j) = neighbours(&NU, nu);
    let (k, l) = neighbours(&MU, mu);
    let (m, n) = neighbours(&KM, km);
    let mut worst: f64 = 0.0;
    for a in [i, j] {
        for b in [k, l] {
            for c in [m, n] {
                worst = worst.max(NARROW_OFFSET[a][b][c]);
            }
        }
    }
    worst
}

/// f(nu): the friction-induced part of the strip's mu* - mu without wear is at most
/// f(nu) mu (1 + mu^2) h/R for Lambda >= 10 (study, k m = 0, the largest over mu and Lambda;
/// proportional to mu (1 + mu^2) to 1 % for nu <= 0.47, 12 % at 0.49); the Winkler model has no
/// such part. It changes sign near nu = 0.25 (negative below), hence the small value there.
const NARROW_FRICTION_PART: [f64; 17] = [
    0.496, 0.372, 0.166, 0.0455, 0.244, 0.653, 1.47, 2.08, 3.09, 3.9, 5.1, 7.1, 11.1, 15.0, 22.7,
    45.0, 188.0,
];

/// The Winkler model's error in mu* - mu: the friction-induced part F = f(nu) mu (1 + mu^2) h/R it
/// lacks, against what it has, |F| / max(|mu*_W - mu| - |F|, 0.01 (a+b)/R) (at most 100).
pub fn narrow_mu_star_error(
    nu: f64,
    mu: f64,
    h_over_r: f64,
    winkler_mu_star_minus_mu: f64,
    l_over_r: f64,
) -> f64 {
    let friction = larger_in_nu(&NARROW_FRICTION_PART, nu) * mu * (1.0 + mu * mu) * h_over_r;
    let against = (winkler_mu_star_minus_mu.abs() - friction).max(MU_STAR_FLOOR * l_over_r);
    (friction / against).min(100.0)
}
