//! The collocation of equation (E) at one contact width L (docs/physics/plane-general.md sections
//! 2-3), half-plane and wide strip:
//!   gamma0 q2 + (1/m) H[q2] + Nl(q2) + chi c12 Q1/(m h) + pi chi tau0/m + g'(x) = 0,
//!   Nl(q) = (pi chi/m) (Pi(q) - mu q - tau0) - (F(q) - k1 q),
//! gamma0 = pi chi mu/m - k1, k1 = k for the linear wear law and 0 otherwise. With q2 = w phi on
//! x = c + (L/2) t, unknowns phi_i at the zeros t_i of P_N^(1/2+theta, 1/2-theta) and collocation
//! at the zeros xi_k of P_{N+1}^(-1/2-theta, -1/2+theta), (1/pi) sum W_i phi_i/(t_i - xi_k) is
//! exactly tan(pi theta) q2 + (1/pi) p.v. int q2/(t - xi) for polynomial phi (Erdogan, Gupta & Cook
//! 1973), i.e. m/pi times the first two terms; q2 at xi_k is w(xi_k) times phi interpolated there.
//! The N + 1 equations fix the N values and the shift c: the end conditions q2(-a) = q2(b) = 0.
//!
//! Unknowns y_i = W_i phi_i/m (slopes, like g') and s = c/(L/2); Newton on them with the Jacobian
//! of the nonlinear terms (Pi and F are piecewise smooth), each row divided by its largest entry
//! before LU, steps halved while the residual grows.

use std::sync::{Arc, Mutex, OnceLock};

use nalgebra::{DMatrix, DVector};

use crate::physics::plane::general::pressure::Pressure;
use crate::physics::plane::general::projection::SlopeProjection;
use crate::physics::plane::general::{Problem, nonlinear};
use crate::physics::plane::strip::collocation::Rules;

/// Newton iterations at one width.
const NEWTON_STEPS: usize = 60;
/// Halvings of one Newton step.
const HALVINGS: usize = 30;
/// Newton stops when the step is below this, relative to the unknowns.
const NEWTON_TOLERANCE: f64 = 1e-14;
/// A step this small (relative) that lowers no residual is taken as converged: the residual is
/// at its round-off floor.
const ROUND_OFF_STEP: f64 = 1e-10;
/// Newton also stops after a step below `QUADRATIC_FROM` (relative) when quadratic convergence
/// puts the next one, size^3/previous^2, below `NEWTON_TOLERANCE` times `QUADRATIC_MARGIN`: that
/// step would only move the unknowns within their round-off (seen: steps 2.9e-3, 2.9e-8, then
/// 1.3e-14 and 6e-15 at the round-off floor).
const QUADRATIC_FROM: f64 = 1e-6;
const QUADRATIC_MARGIN: f64 = 1e-2;
/// Discretisations kept by `Discretisation::cached`: a load sweep asks for the same few (theta,
/// N) at every point.
const CACHED: usize = 4;

/// The matrices of one (theta, N): the Cauchy part 1/(t_i - xi_k) and the interpolation of phi
/// from the nodes to the collocation points times w(xi_k).
pub struct Discretisation {
    rules: Arc<Rules>,
    cauchy: DMatrix<f64>,
    /// w(xi_k) l_i(xi_k): q2 at xi_k is this times phi.
    to_points: DMatrix<f64>,
    /// The projection of a slope that is not a polynomial, built when first needed.
    projection: OnceLock<SlopeProjection>,
}

impl Discretisation {
    /// The discretisation with n nodes at exponent shift theta.
    pub fn new(theta: f64, n: usize) -> Discretisation {
        let rules = Rules::cached(theta, n);
        let (nodes, points, bary) = (rules.nodes(), rules.points(), rules.bary());
        let cauchy = DMatrix::from_fn(n + 1, n, |k, i| 1.0 / (nodes[i] - points[k]));
        let mut to_points = DMatrix::from_fn(n + 1, n, |k, i| bary[i] / (points[k] - nodes[i]));
        for (k, mut row) in to_points.row_iter_mut().enumerate() {
            let t = points[k];
            let weight = ((0.5 + theta) * (-t).ln_1p() + (0.5 - theta) * t.ln_1p()).exp();
            let sum = row.sum();
            row.scale_mut(weight / sum);
        }
        Discretisation {
            rules,
            cauchy,
            to_points,
            projection: OnceLock::new(),
        }
    }

    /// The discretisation with n nodes at theta, built once and kept (the last few used).
    pub fn cached(theta: f64, n: usize) -> Arc<Discretisation> {
        static CACHE: OnceLock<Mutex<Vec<Arc<Discretisation>>>> = OnceLock::new();
        let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
        let mut list = cache.lock().unwrap_or_else(|p| p.into_inner());
        let hit = list
            .iter()
            .position(|d| d.rules.theta().to_bits() == theta.to_bits() && d.len() == n);
        let d = match hit {
            Some(i) => list.remove(i),
            None => Arc::new(Discretisation::new(theta, n)),
        };
        list.insert(0, Arc::clone(&d));
        list.truncate(CACHED);
        d
    }

    /// g' and dg'/ds at the collocation points for the shift s at width l: the values there, or
    /// where g' is not a polynomial its projection (`projection`), split at the punch's kinks.
    fn slopes(&self, problem: &Problem, s: f64, l: f64) -> [Vec<f64>; 2] {
        let (half, shape) = (0.5 * l, problem.shape);
        let at = |t: f64| {
            let x = (s + t) * half;
            [shape.slope(x), shape.curvature(x, 1e-7 * l) * half]
        };
        if shape.slope_is_polynomial() {
            let values: Vec<[f64; 2]> = self.rules.points().iter().map(|&t| at(t)).collect();
            return [0, 1].map(|j| values.iter().map(|v| v[j]).collect());
        }
        let kinks: Vec<f64> = shape.kinks().iter().map(|x| x / half - s).collect();
        self.projection().project(&kinks, at)
    }

    /// The number of nodes N.
    pub fn len(&self) -> usize {
        self.rules.len()
    }

    /// Never empty; here for clippy's len_without_is_empty.
    pub fn is_empty(&self) -> bool {
        self.rules.is_empty()
    }

    /// The rules.
    pub fn rules(&self) -> &Arc<Rules> {
        &self.rules
    }

    /// The projection onto the polynomials through the collocation points.
    pub fn projection(&self) -> &SlopeProjection {
        self.projection
            .get_or_init(|| SlopeProjection::new(self.rules.points(), self.rules.theta()))
    }
}

/// The unknowns at one width: y_i = W_i phi_i/m and s = c/(L/2).
#[derive(Clone, Debug, PartialEq)]
pub struct Unknowns {
    pub y: DVector<f64>,
    pub s: f64,
}

impl Unknowns {
    /// Zero pressure centred on the tip: Newton's first step from here solves the problem with
    /// the nonlinear terms linearised at q2 = 0.
    pub fn zero(n: usize) -> Unknowns {
        Unknowns {
            y: DVector::zeros(n),
            s: 0.0,
        }
    }

    /// The pressure they describe at width l.
    pub fn pressure(&self, d: &Discretisation, problem: &Problem, l: f64) -> Pressure {
        let m = problem.m();
        let phi = self
            .y
            .iter()
            .zip(d.rules.weights())
            .map(|(y, w)| m * y / w)
            .collect();
        Pressure::new(Arc::clone(&d.rules), l, self.s * 0.5 * l, phi)
    }
}

/// The parts of (E) that are linear in y at one width: the Cauchy matrix plus, on the strip of
/// any thickness, (L/(2h)) (R2 + mu chi B12)(z_ik), z_ik = (L/2)(t_i - xi_k)/h; and the constant
/// of each row: pi chi tau0/m plus, on the strip, (tau0/m) [chi l12((b-x)/h) + chi l12((a+x)/h)]
/// (docs/physics/plane.md section 6).
struct AtWidth {
    linear: DMatrix<f64>,
    constant: DVector<f64>,
}

impl AtWidth {
    fn new(d: &Discretisation, problem: &Problem, l: f64) -> AtWidth {
        let (n, m, half) = (d.len(), problem.m(), 0.5 * l);
        let tau0 = problem.friction.adhesion();
        let pi_chi_tau0 = std::f64::consts::PI * problem.material.chi() * tau0 / m;
        let mut linear = d.cauchy.clone();
        let mut constant = DVector::from_element(n + 1, pi_chi_tau0);
        if let Some(kernels) = problem.strip {
            let h = problem.material.thickness;
            let mu = problem.friction.coefficient();
            let (nodes, points) = (d.rules.nodes(), d.rules.points());
            for k in 0..=n {
                for i in 0..n {
                    linear[(k, i)] +=
                        half / h * kernels.regular(half * (nodes[i] - points[k]) / h, mu);
                }
                if tau0 != 0.0 {
                    let xi = points[k];
                    constant[k] += tau0 / m
                        * (kernels.chi_l12(half * (1.0 - xi) / h)
                            + kernels.chi_l12(half * (1.0 + xi) / h));
                }
            }
        }
        AtWidth { linear, constant }
    }
}

/// The residual of (E) at the collocation points and, when `jacobian` is given, its Jacobian in
/// (y, s).
fn residual(
    d: &Discretisation,
    problem: &Problem,
    (l, at): (f64, &AtWidth),
    u: &Unknowns,
    jacobian: Option<&mut DMatrix<f64>>,
) -> DVector<f64> {
    let n = d.len();
    let m = problem.m();
    let weights = d.rules.weights();
    let c12 = problem.c12_over_h();
    let capped = problem.friction.shear_strength.is_finite();
    // the pressure and its splits, found once for the cap's terms and the thickness correction
    let pressure = (c12 != 0.0 || capped).then(|| {
        let p = u.pressure(d, problem, l);
        let splits = problem.splits(&p);
        (p, splits)
    });
    let corrected = pressure.as_ref().filter(|_| c12 != 0.0);
    let q1 = corrected.map_or(0.0, |(p, splits)| problem.friction_force_split(p, splits));
    let constant = c12 * q1 / m;
    let [slope, slope_ds] = d.slopes(problem, u.s, l);
    let (nl, dnl) = match pressure.as_ref().filter(|_| capped) {
        Some((p, splits)) => {
            let parts = (d.rules.bary(), d.rules.weights());
            nonlinear::projected(problem, d.projection(), (p, splits), parts)
        }
        None => {
            let phi = u.y.iter().zip(weights).map(|(y, w)| m * y / w);
            let q = &d.to_points * DVector::from_iterator(n, phi);
            nonlinear::at_points(problem, &d.to_points, weights, &q)
        }
    };
    let mut r = &at.linear * &u.y + &at.constant;
    for k in 0..=n {
        r[k] += nl[k] + constant + slope[k];
    }
    if let Some(jac) = jacobian {
        jac.view_mut((0, 0), (n + 1, n)).copy_from(&at.linear);
        let dq1 = corrected.map(|(p, splits)| problem.friction_force_gradient(p, splits, d));
        for k in 0..=n {
            for i in 0..n {
                let mut entry = jac[(k, i)] + dnl[(k, i)];
                if let Some(g) = &dq1 {
                    entry += c12 / m * g[i];
                }
                jac[(k, i)] = entry;
            }
            jac[(k, n)] = slope_ds[k];
        }
    }
    r
}

/// Solves (E) at width l by Newton from `start`; None when it does not converge in
/// `NEWTON_STEPS` steps or the Jacobian is singular.
pub fn solve_at(
    d: &Discretisation,
    problem: &Problem,
    l: f64,
    start: &Unknowns,
) -> Option<Unknowns> {
    let n = d.len();
    let mut u = start.clone();
    let mut jac = DMatrix::zeros(n + 1, n + 1);
    let at = AtWidth::new(d, problem, l);
    let mut r = residual(d, problem, (l, &at), &u, Some(&mut jac));
    let mut last_size = f64::INFINITY;
    for _ in 0..NEWTON_STEPS {
        let mut rhs = -&r;
        for k in 0..=n {
            let big = jac.row(k).amax();
            if !(big > 0.0 && big.is_finite()) {
                return None;
            }
            jac.row_mut(k).scale_mut(1.0 / big);
            rhs[k] /= big;
        }
        let step = jac.clone().lu().solve(&rhs)?;
        let scale = u.y.amax().max(f64::MIN_POSITIVE);
        let size = (step.rows(0, n).amax() / scale).max(step[n].abs());
        let full = Unknowns {
            y: &u.y + step.rows(0, n),
            s: u.s + step[n],
        };
        let predicted = size.powi(3) / (last_size * last_size);
        if size <= NEWTON_TOLERANCE
            || (size <= QUADRATIC_FROM && predicted <= QUADRATIC_MARGIN * NEWTON_TOLERANCE)
        {
            return Some(full);
        }
        let norm = r.norm();
        let mut factor = 1.0;
        let mut next = None;
        for _ in 0..HALVINGS {
            let trial = Unknowns {
                y: &u.y + factor * step.rows(0, n),
                s: u.s + factor * step[n],
            };
            let r_trial = residual(d, problem, (l, &at), &trial, Some(&mut jac));
            if r_trial.iter().all(|v| v.is_finite()) && r_trial.norm() < norm {
                // a halved step says nothing of the convergence's order
                last_size = if factor == 1.0 { size } else { f64::INFINITY };
                next = Some((trial, r_trial));
                break;
            }
            factor *= 0.5;
        }
        match next {
            Some((trial, r_trial)) => (u, r) = (trial, r_trial),
            // the residual is at its round-off floor: no step lowers it
            None if size <= ROUND_OFF_STEP => return Some(full),
            None => return None,
        }
    }
    None
}
