//! Transfer functions of an elastic strip (layer) bonded to a rigid base, shared by the plane and
//! the spatial problems.
//!
//! Plane strain, Soldatenkov (2007) eq. (3.2) with the corrections of `docs/physics/plane.md` section 2
//! (ch 2X in K12). Everything is evaluated with e = exp(-2X) after dividing the numerator and the
//! denominator by ch 2X, so no term overflows for any X >= 0, including X = +inf (half-plane).

use crate::physics::quadrature::gauss_legendre;

/// Plane-strain constant kappa = 3 - 4 nu (dimensionless).
pub fn kappa(nu: f64) -> f64 {
    3.0 - 4.0 * nu
}

/// chi = (1 - 2 nu) / (2 (1 - nu)) = (kappa - 1)/(kappa + 1) (dimensionless, 0 at nu = 1/2).
pub fn chi(nu: f64) -> f64 {
    (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))
}

/// m = pi E / (2 (1 - nu^2)) [Pa], the modulus of the plane problem (Soldatenkov (2007), after eq. (3.1)).
pub fn plane_modulus(youngs_modulus: f64, nu: f64) -> f64 {
    std::f64::consts::PI * youngs_modulus / (2.0 * (1.0 - nu * nu))
}

/// Beyond this X the strip functions equal their half-plane limits to better than 1e-18.
const X_HALF_PLANE: f64 = 30.0;

/// The strip transfer functions at one dimensionless wavenumber X = |k| h (all dimensionless).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StripTransfer {
    /// K1(X): u from q1; -> 1 for the half-plane, ~ 4X/(kappa+1) as X -> 0.
    pub k1: f64,
    /// K2(X): v from q2; -> 1 for the half-plane, ~ 4(kappa-1)X/(kappa+1)^2 as X -> 0.
    pub k2: f64,
    /// chi K12(X): the coupling of u with q2 and of v with q1; -> chi for the half-plane.
    /// Written with chi folded in so that it stays finite at nu = 1/2.
    pub chi_k12: f64,
    /// chi L12(X) = chi (K12 - 1), the part of the coupling that decays with X.
    pub chi_l12: f64,
}

/// D, K1, K2, chi K12 of (3.2) at X = |k| h >= 0 (X = +inf gives the half-plane values).
pub fn strip_transfer(nu: f64, x: f64) -> StripTransfer {
    let kap = kappa(nu);
    let chi = chi(nu);
    if x > X_HALF_PLANE {
        return StripTransfer {
            k1: 1.0,
            k2: 1.0,
            chi_k12: chi,
            chi_l12: 0.0,
        };
    }
    let e = (-2.0 * x).exp();
    let e2 = e * e;
    let sech = 2.0 * e / (1.0 + e2); // 1 / ch 2X
    // the differences from 1 come from expm1, so they keep full precision down to X = 1e-300
    let th = -(-4.0 * x).exp_m1() / (1.0 + e2); // th 2X = (1 - e^2)/(1 + e^2)
    let one_minus_sech = (-2.0 * x).exp_m1().powi(2) / (1.0 + e2); // (1 - e)^2/(1 + e^2)
    let x2 = x * x;
    let d = 2.0 * kap + (4.0 * x2 + 1.0 + kap * kap) * sech; // D / ch 2X
    // K2 D/ch 2X = 2 kappa th - 4X sech = 2 (kappa - 1) th + 2 (sh 2X - 2X)/ch 2X: both terms
    // positive, so K2 keeps its digits as kappa -> 1 (nu -> 1/2), where it is O(X^3)
    let kappa_minus_1 = 2.0 - 4.0 * nu;
    StripTransfer {
        k1: (2.0 * kap * th + 4.0 * x * sech) / d,
        k2: (2.0 * kappa_minus_1 * th + 2.0 * sinh_excess(2.0 * x) * sech) / d,
        chi_k12: (2.0 * kap * chi * one_minus_sech - 8.0 * x2 * sech / (kap + 1.0)) / d,
        chi_l12: -(4.0 * x2 + kap * kap - 1.0) * sech / d,
    }
}

/// sh y - y for 0 <= y <= 2 X_HALF_PLANE: the series sum y^(2n+1)/(2n+1)!, n >= 1, below y = 2
/// (its terms shrink by y^2/((2n+2)(2n+3)) <= 1/5, 24 terms reach 1e-17), else directly.
fn sinh_excess(y: f64) -> f64 {
    if y >= 2.0 {
        return y.sinh() - y;
    }
    let y2 = y * y;
    let mut term = y * y2 / 6.0;
    let mut sum = 0.0;
    for n in 1..=24 {
        sum += term;
        let k = 2.0 * n as f64;
        term *= y2 / ((k + 2.0) * (k + 3.0));
    }
    sum
}

/// chi c12(nu) = chi * integral_0^inf L12(X) dX (dimensionless, negative), the constant of the
/// wide-strip kernel (4.1). c12 alone diverges as nu -> 1/2; chi c12 stays finite.
///
/// chi L12 decays like X^2 e^{-2X}: composite Gauss–Legendre over [0, 40] in unit panels gives
/// the integral to about 1e-15. The quadrature (640 evaluations, ~35 us) is remembered for the
/// last nu on each thread, so sweeps at one nu (every wide solve calls it) pay it once.
pub fn chi_c12(nu: f64) -> f64 {
    thread_local! {
        static LAST: std::cell::Cell<Option<(u64, f64)>> = const { std::cell::Cell::new(None) };
    }
    if let Some((bits, value)) = LAST.get()
        && bits == nu.to_bits()
    {
        return value;
    }
    let rule = gauss_legendre(16);
    let value = (0..40)
        .map(|panel| {
            let x0 = panel as f64;
            rule.integrate(x0, x0 + 1.0, |x| strip_transfer(nu, x).chi_l12)
        })
        .sum();
    LAST.set(Some((nu.to_bits(), value)));
    value
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_plane_limits() {
        for nu in [0.0, 0.3, 0.5] {
            let t = strip_transfer(nu, f64::INFINITY);
            assert_eq!((t.k1, t.k2, t.chi_k12, t.chi_l12), (1.0, 1.0, chi(nu), 0.0));
            let t = strip_transfer(nu, 25.0);
            assert!((t.k1 - 1.0).abs() < 1e-15 && (t.chi_k12 - chi(nu)).abs() < 1e-15);
        }
    }

    #[test]
    fn small_x_limits_give_the_winkler_constants() {
        // docs/physics/plane.md section 2: K1 ~ 4X/(kappa+1), K2 ~ 4(kappa-1)X/(kappa+1)^2, K12 = O(X^2).
        let nu: f64 = 0.3;
        let kap = kappa(nu);
        let x = 1e-5;
        let t = strip_transfer(nu, x);
        assert!((t.k1 / x - 4.0 / (kap + 1.0)).abs() < 1e-8);
        assert!((t.k2 / x - 4.0 * (kap - 1.0) / ((kap + 1.0) * (kap + 1.0))).abs() < 1e-8);
        assert!(t.chi_k12.abs() < 1e-8);
    }

    #[test]
    fn direct_hyperbolic_form_agrees_at_moderate_x() {
        // (3.2) written with sh and ch directly, where nothing overflows yet.
        let nu: f64 = 0.27;
        let kap = kappa(nu);
        for x in [0.05f64, 0.7, 3.0, 9.0] {
            let d = 2.0 * kap * (2.0 * x).cosh() + 4.0 * x * x + 1.0 + kap * kap;
            let k1 = (2.0 * kap * (2.0 * x).sinh() + 4.0 * x) / d;
            let k2 = (2.0 * kap * (2.0 * x).sinh() - 4.0 * x) / d;
            let k12 = (2.0 * kap * ((2.0 * x).cosh() - 1.0) - 8.0 * x * x / (kap - 1.0)) / d;
            let t = strip_transfer(nu, x);
            assert!((t.k1 - k1).abs() < 1e-14);
            assert!((t.k2 - k2).abs() < 1e-14);
            assert!((t.chi_k12 - chi(nu) * k12).abs() < 1e-14);
            assert!((t.chi_l12 - chi(nu) * (k12 - 1.0)).abs() < 1e-14);
        }
    }

    #[test]
    fn accurate_for_thin_layers_and_nearly_incompressible_ones() {
        // (nu, X, K1, K2, chi K12): the hyperbolic form (3.2) in 50-digit arithmetic (mpmath,
        // mp.dps = 50: D = 2 kappa ch 2X + 4X^2 + 1 + kappa^2, K1 = (2 kappa sh 2X + 4X)/D,
        // K2 = (2 kappa sh 2X - 4X)/D, chi K12 = (2 kappa chi (ch 2X - 1) - 8X^2/(kappa+1))/D).
        let table = [
            (0.0, 1e-12, 1e-12, 5e-13, 2.5e-25),
            (0.0, 1e-06, 9.999999999995e-07, 5e-07, 2.49999999999875e-13),
            (
                0.0,
                0.7,
                0.5721128265187293,
                0.3469001987839227,
                0.09944325495737967,
            ),
            (
                0.3,
                1e-12,
                1.4285714285714285e-12,
                4.0816326530612245e-13,
                -1.0204081632653058e-25,
            ),
            (
                0.3,
                1e-06,
                1.42857142857e-06,
                4.081632653061516e-07,
                -1.0204081632629734e-13,
            ),
            (
                0.3,
                3.0,
                0.9631415408637378,
                0.9318269663800443,
                0.23581973037026735,
            ),
            (
                0.49999999999999994,
                1e-12,
                1.9999999999999996e-12,
                2.220446055916979e-28,
                -9.999999999999996e-25,
            ),
            (
                0.49999999999999994,
                1e-06,
                1.9999999999966664e-06,
                6.668887112703911e-19,
                -9.999999999979995e-13,
            ),
            (
                0.49999999999999994,
                0.7,
                0.7998989878675368,
                0.12208034297534824,
                -0.2372365257122659,
            ),
            (
                0.49999999999999994,
                3.0,
                0.9410894534677973,
                0.8867208540753091,
                -0.08155289908873216,
            ),
        ];
        let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
        for (nu, x, k1, k2, chi_k12) in table {
            let t = strip_transfer(nu, x);
            assert!(rel(t.k1, k1) < 1e-14, "K1 at nu={nu}, X={x}: {}", t.k1);
            assert!(rel(t.k2, k2) < 1e-13, "K2 at nu={nu}, X={x}: {}", t.k2);
            assert!(
                rel(t.chi_k12, chi_k12) < 1e-13,
                "chi K12 at nu={nu}, X={x}: {}",
                t.chi_k12
            );
        }
    }

    #[test]
    fn chi_c12_matches_the_reference_table() {
        // Values of docs/physics/plane.md section 2 (independent high-precision computation).
        let table = [
            (0.0, -0.749076675679),
            (0.2, -0.680127589496),
            (0.3, -0.649992028667),
            (0.4, -0.630273314782),
            (0.45, -0.628754393011),
            (0.5, -0.637734487685),
        ];
        for (nu, expected) in table {
            let got = chi_c12(nu);
            assert!(
                (got - expected).abs() < 1e-12,
                "nu={nu}: {got} vs {expected}"
            );
        }
    }
}
