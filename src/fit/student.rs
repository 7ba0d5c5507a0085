//! The quantile of Student's t distribution that a 95 % interval needs when the noise is estimated
//! from the residuals (Seber & Wild (1989) chapter 5): the density of t with nu degrees of
//! freedom, Gamma((nu+1)/2) / (sqrt(nu pi) Gamma(nu/2)) (1 + t^2/nu)^(-(nu+1)/2), integrated by
//! tanh-sinh quadrature and inverted by bisection.

use crate::physics::quadrature::tanh_sinh;

/// P(0 <= T <= t) for t >= 0 with `nu` degrees of freedom.
fn central_mass(t: f64, nu: f64) -> f64 {
    let log_norm = libm::lgamma(0.5 * (nu + 1.0))
        - libm::lgamma(0.5 * nu)
        - 0.5 * (nu * std::f64::consts::PI).ln();
    let density = |u: f64| (log_norm - 0.5 * (nu + 1.0) * (u * u / nu).ln_1p()).exp();
    tanh_sinh(1.0 / 16.0).integrate(0.0, t, density)
}

/// The t with P(|T| <= t) = `level` (0 < level < 1) for `nu` >= 1 degrees of freedom: 12.706 for
/// nu = 1 and 95 %, 1.95996 as nu grows.
pub fn two_sided(level: f64, nu: f64) -> f64 {
    let half = 0.5 * level;
    let (mut lo, mut hi) = (0.0, 1.0);
    // the 97.5 % quantile is below 1e3 for nu >= 1 (12.7 at nu = 1); 60 doublings bound the search
    for _ in 0..60 {
        if central_mass(hi, nu) >= half {
            break;
        }
        hi *= 2.0;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if hi - lo <= 1e-12 * hi {
            break;
        }
        if central_mass(mid, nu) < half {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_the_tables() {
        // two-sided 95 % points of t, Abramowitz & Stegun (1964) table 26.10 (5 digits)
        for (nu, t) in [
            (1.0, 12.706),
            (2.0, 4.3027),
            (5.0, 2.5706),
            (10.0, 2.2281),
            (30.0, 2.0423),
        ] {
            let got = two_sided(0.95, nu);
            assert!((got - t).abs() < 1e-4 * t, "nu = {nu}: {got}, table {t}");
        }
        // nu = 1 is the Cauchy distribution: tan(0.475 pi) in closed form
        let cauchy = (0.475 * std::f64::consts::PI).tan();
        assert!((two_sided(0.95, 1.0) - cauchy).abs() < 1e-8 * cauchy);
        // the normal limit, 1.959964 (the 97.5 % point of the standard normal)
        assert!((two_sided(0.95, 1e7) - 1.959964).abs() < 1e-5);
    }
}
