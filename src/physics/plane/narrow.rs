//! Narrow strip ((a+b)/h -> inf), the Winkler foundation: Soldatenkov (2007) section 5, docs/physics/plane.md section 4.
//!
//! v = -beta (q2 - q2(0)), lambda = k/beta, q2' - lambda q2 = -g'/beta (5.3). With L = a + b,
//! y = lambda L and u = a + x in [0, L], everything is written in overflow-safe, cancellation-free
//! forms: Taylor series below y = 2 (Bernoulli numbers), exponentials of negative arguments above.

use crate::physics::SolveError;
use crate::physics::plane::{Found, Model, PlaneInputs, PlaneSolution, PressureLaw};
use crate::physics::roots::{BRENT_ITERATIONS, bracket_or_why, brent};

/// Winkler compliance of the normal displacement, beta = (1 - 2nu)(1 + nu) h / ((1 - nu) E) [m/Pa] (5.1).
pub fn winkler_beta(inputs: &PlaneInputs) -> f64 {
    let m = &inputs.material;
    let nu = m.poisson_ratio;
    (1.0 - 2.0 * nu) * (1.0 + nu) * m.thickness / ((1.0 - nu) * m.youngs_modulus)
}

/// Winkler compliance of the tangential displacement, alpha = 2 (1 + nu) h / E [m/Pa] (5.1).
pub fn winkler_alpha(inputs: &PlaneInputs) -> f64 {
    let m = &inputs.material;
    2.0 * (1.0 + m.poisson_ratio) * m.thickness / m.youngs_modulus
}

/// Bernoulli numbers B_2, B_4, ..., B_34 as (numerator, denominator)
/// (Abramowitz & Stegun, Table 23.2; DLMF Table 24.2.1).
const BERNOULLI: [(f64, f64); 17] = [
    (1.0, 6.0),
    (-1.0, 30.0),
    (1.0, 42.0),
    (-1.0, 30.0),
    (5.0, 66.0),
    (-691.0, 2730.0),
    (7.0, 6.0),
    (-3617.0, 510.0),
    (43867.0, 798.0),
    (-174611.0, 330.0),
    (854513.0, 138.0),
    (-236364091.0, 2730.0),
    (8553103.0, 6.0),
    (-23749461029.0, 870.0),
    (8615841276005.0, 14322.0),
    (-7709321041217.0, 510.0),
    (2577687858367.0, 6.0),
];

/// c_n = B_{2n}/(2n)!, n = 1..=17: 1/(e^y - 1) = 1/y - 1/2 + sum c_n y^{2n-1}.
fn taylor_c() -> [f64; 17] {
    let mut out = [0.0; 17];
    let mut fact = 1.0;
    for (n, (num, den)) in BERNOULLI.iter().enumerate() {
        let k = 2.0 * (n as f64 + 1.0);
        fact *= (k - 1.0) * k;
        out[n] = num / den / fact;
    }
    out
}

/// Below this y the Taylor series are used (their terms shrink like (y/2pi)^2 per order).
const SERIES_BELOW: f64 = 2.0;

/// The dimensionless shape functions of the Winkler solution at y = lambda L >= 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shape {
    /// hh(y) = 1/y - 1/(e^y - 1): a = L hh.
    pub hh: f64,
    /// G(y) = (1 - 2 hh)/y: Q2 = L^3 G/(2 R beta).
    pub g: f64,
    /// S(y) = [(2/3)(hh^3 + (1 - hh)^3) - (1 - 2 hh)/y]/y: psi = L^4 S/(2 beta R^2).
    pub s: f64,
}

/// hh, G, S of docs/physics/plane.md section 4 at y >= 0.
///
/// With d = 1/2 - hh the identities hh^3 + (1 - hh)^3 = 1/4 + 3 d^2 and G = 2d/y give
/// S = (2 d^2 - (G - 1/6))/y, in which both terms are O(y) and of the same sign: no cancellation.
pub fn shape(y: f64) -> Shape {
    if y < SERIES_BELOW {
        let c = taylor_c();
        let y2 = y * y;
        // d/y = sum c_n y^{2n-2}; tail = sum_{n>=2} c_n y^{2n-3} (= (d/y - c_1)/y).
        let mut d_over_y = 0.0;
        let mut tail = 0.0;
        for (n, cn) in c.iter().enumerate().rev() {
            d_over_y = d_over_y * y2 + cn;
            if n >= 1 {
                tail = tail * y2 + cn;
            }
        }
        let tail = tail * y; // sum_{n>=2} c_n y^{2n-3}
        let d = y * d_over_y;
        Shape {
            hh: 0.5 - d,
            g: 2.0 * d_over_y,
            s: 2.0 * (y * d_over_y * d_over_y - tail),
        }
    } else {
        let hh = 1.0 / y - 1.0 / y.exp_m1();
        let d = 0.5 - hh;
        let g = 2.0 * d / y;
        Shape {
            hh,
            g,
            s: (2.0 * d * d - (g - 1.0 / 6.0)) / y,
        }
    }
}

/// q2 at u = a + x in [0, L] [Pa] for y = lambda L (5.7) in stable forms:
/// q2 = [u - L expm1(lambda u)/expm1(lambda L)]/(beta lambda R).
pub fn pressure(u: f64, l: f64, lambda: f64, beta: f64, radius: f64) -> f64 {
    let y = lambda * l;
    let s = (u / l).clamp(0.0, 1.0);
    if y < 1.0 {
        // [e1(lambda L) - e1(lambda u)]/lambda = L sum_{n>=1} y^{n-1} (1 - s^n)/(n+1)!,
        // with e1(z) = expm1(z)/z; q2 = u * that / (e1(lambda L) beta R).
        let mut sum = 0.0;
        let mut y_pow = 1.0;
        let mut s_pow = s;
        let mut fact = 2.0;
        for n in 1..=24 {
            sum += y_pow * (1.0 - s_pow) / fact;
            y_pow *= y;
            s_pow *= s;
            fact *= (n + 2) as f64;
        }
        let e1 = if y == 0.0 { 1.0 } else { y.exp_m1() / y };
        u * l * sum / (e1 * beta * radius)
    } else {
        // expm1(y s)/expm1(y) = e^{y(s-1)} (1 - e^{-ys})/(1 - e^{-y})
        let ratio = (y * (s - 1.0)).exp() * (-y * s).exp_m1() / (-y).exp_m1();
        ((u - l * ratio) / (beta * lambda * radius)).max(0.0)
    }
}

/// Everything at contact width L.
#[derive(Clone, Copy, Debug)]
struct NarrowState {
    a: f64,
    q2: f64,
    psi: f64,
    delta_g: f64,
    load: f64,
}

fn state(inputs: &PlaneInputs, beta: f64, lambda: f64, l: f64) -> NarrowState {
    let r = inputs.radius();
    let sh = shape(lambda * l);
    let q2 = l.powi(3) * sh.g / (2.0 * r * beta);
    let psi = l.powi(4) * sh.s / (2.0 * beta * r * r);
    let delta_g = inputs.wear.coefficient * q2; // (5.10)
    NarrowState {
        a: l * sh.hh,
        q2,
        psi,
        delta_g,
        load: q2 - inputs.friction.coefficient * psi - inputs.friction.adhesion * delta_g,
    }
}

/// Solves the Winkler problem at the inputs' load: P(L) is increasing; bracket around
/// L0 = (12 beta R P)^{1/3} (the frictionless, wearless width) and Brent. The parabola with the
/// linear law and no cap only (`plane::solve_narrow` sends the others to `narrow_ode`).
pub fn solve(inputs: &PlaneInputs) -> Result<PlaneSolution, SolveError> {
    if inputs.material.is_half_space() {
        return Err(SolveError::InvalidInput(
            "the narrow (Winkler) model needs a finite thickness h; a half-plane is a wide strip"
                .into(),
        ));
    }
    let beta = winkler_beta(inputs);
    let lambda = inputs.wear.coefficient / beta;
    let p = inputs.load;
    let f = |l: f64| state(inputs, beta, lambda, l).load - p;
    let l0 = (12.0 * beta * inputs.radius() * p).cbrt();
    let (lo, hi) = bracket_or_why(l0, (0.5, 60), (2.0, 200), f).map_err(|why| {
        SolveError::NoSolution(format!(
            "the narrow-strip model finds no contact width for P = {p:.4e} N/m: {why} \
             (friction and adhesion may leave no net normal load: check tau0 k < 1)"
        ))
    })?;
    let l = brent(lo, hi, f).ok_or_else(|| {
        SolveError::NoSolution(format!(
            "the contact width did not converge at P = {p:.4e} N/m \
             (Brent's method, {BRENT_ITERATIONS} iterations)"
        ))
    })?;
    let s = state(inputs, beta, lambda, l);
    Ok(PlaneSolution::assemble(
        Model::Narrow,
        inputs,
        Found {
            a: s.a,
            b: l - s.a,
            width: l,
            q2: s.q2,
            psi: s.psi,
            delta_g: s.delta_g,
            theta: None,
            gamma: None,
            friction_integrals: None,
        },
        PressureLaw::Narrow { lambda, beta },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn direct(y: f64) -> Shape {
        let hh = 1.0 / y - 1.0 / y.exp_m1();
        let g = (1.0 - 2.0 * hh) / y;
        let s = ((2.0 / 3.0) * (hh.powi(3) + (1.0 - hh).powi(3)) - (1.0 - 2.0 * hh) / y) / y;
        Shape { hh, g, s }
    }

    #[test]
    fn series_agree_with_the_direct_forms_where_both_are_accurate() {
        // The direct forms lose about log10(1/y^2) digits; at y = 1.5 .. 1.99 both are good to 1e-13.
        for y in [1.5, 1.8, 1.99] {
            let (a, b) = (shape(y), direct(y));
            assert!((a.hh - b.hh).abs() < 1e-14, "hh at {y}");
            assert!((a.g - b.g).abs() < 1e-14 * b.g, "G at {y}");
            assert!(
                (a.s - b.s).abs() < 1e-12 * b.s,
                "S at {y}: {} vs {}",
                a.s,
                b.s
            );
        }
        // Continuity across the switch at y = 2.
        let (below, above) = (shape(2.0 - 1e-12), shape(2.0 + 1e-12));
        assert!((below.s - above.s).abs() < 1e-13);
    }

    #[test]
    fn leading_terms_of_the_series() {
        // docs/physics/plane.md section 4: hh = 1/2 - y/12 + ..., G = 1/6 - y^2/360, S = y/60 - y^3/1890.
        let y = 1e-3;
        let s = shape(y);
        assert!((s.hh - (0.5 - y / 12.0 + y.powi(3) / 720.0)).abs() < 1e-18);
        assert!((s.g - (1.0 / 6.0 - y * y / 360.0)).abs() < 1e-14);
        assert!((s.s - (y / 60.0 - y.powi(3) / 1890.0)).abs() < 1e-17);
        assert_eq!(
            shape(0.0),
            Shape {
                hh: 0.5,
                g: 1.0 / 6.0,
                s: 0.0
            }
        );
    }

    #[test]
    fn large_y_stays_finite() {
        for y in [50.0, 800.0, 1e5] {
            let s = shape(y);
            assert!(s.hh.is_finite() && s.g.is_finite() && s.s.is_finite());
            assert!((s.hh - 1.0 / y).abs() < 1e-12);
            let q = pressure(0.3, 1.0, y, 1.0, 1.0);
            assert!(q.is_finite() && q > 0.0);
        }
    }
}
