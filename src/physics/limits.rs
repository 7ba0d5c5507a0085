//! The allowed range of every parameter, in one place: the solvers, the preset files and the
//! explorer's form all check against these and quote `allowed` when a value is rejected.
//!
//! The ranges cover every real contact by orders of magnitude and are chosen so that no formula
//! of the solvers overflows or divides by zero (`docs/presets.md` states them too).
//! The largest products:
//! - plane modulus m = pi E/(2 (1 - nu^2)) in [1.6e2, 2.1e13] Pa; the Hertz width sqrt(8 R P/m)
//!   in [6e-16, 2.3e8] m, and the wide model's search spans 1e-4 .. 1e6 times it, so L^4 (the
//!   Winkler psi) stays below 1e58;
//! - m k <= 2.1e12 keeps the exponent shift theta = arctan(m gamma/pi)/pi at least 1e-13 away
//!   from +-1/2 (1 - 4 theta^2 > 0, (4.6));
//! - the Winkler compliance beta = (1 - 2nu)(1 + nu) h/((1 - nu) E) lies in [3e-38, 10] m/Pa and
//!   lambda = k/beta below 1e37 1/m (the Winkler forms use exponentials of negative arguments);
//! - G k <= 7e22 Pa/m (k = |(wx, wy)|) and the layer's normal compliance (1 - nu) K2/(G k) >=
//!   1e-38 m/Pa (K2 is evaluated without cancellation, `elastic::strip_transfer`), so
//!   1/M <= 1e38 Pa/m, the Hessian bound sum k^2 A/M <= 1e60 Pa/m^2 (64 harmonics) and the decay
//!   rate k V/M <= 1e40 1/s (exp(-beta t) underflows to 0, never NaN); phases stay below 1e53 rad
//!   (sin is finite);
//! - a sweep's max/min is at most the ratio of its parameter's bounds (1e21), so its logarithm is
//!   finite.

/// One parameter's range: [min, max] (max excluded when `max_excluded`), plus 0 and +inf where
/// allowed.
#[derive(Clone, Copy, Debug)]
pub struct Limit {
    /// What is allowed, in words, with the unit.
    pub allowed: &'static str,
    /// Smallest allowed value (apart from 0 when `zero`).
    pub min: f64,
    /// Largest allowed value (excluded when `max_excluded`).
    pub max: f64,
    max_excluded: bool,
    zero: bool,
    infinite: bool,
    whole: bool,
}

const fn range(allowed: &'static str, min: f64, max: f64) -> Limit {
    Limit {
        allowed,
        min,
        max,
        max_excluded: false,
        zero: false,
        infinite: false,
        whole: false,
    }
}

impl Limit {
    const fn or_zero(self) -> Limit {
        Limit { zero: true, ..self }
    }
    const fn or_infinite(self) -> Limit {
        Limit {
            infinite: true,
            ..self
        }
    }
    const fn whole(self) -> Limit {
        Limit {
            whole: true,
            ..self
        }
    }
    const fn below_max(self) -> Limit {
        Limit {
            max_excluded: true,
            ..self
        }
    }

    /// True when only whole numbers are allowed (counts: points, grid, harmonics).
    pub fn is_whole(&self) -> bool {
        self.whole
    }

    /// Whether `value` is allowed.
    pub fn accepts(&self, value: f64) -> bool {
        if (value == 0.0 && self.zero) || (value == f64::INFINITY && self.infinite) {
            return true;
        }
        if self.whole && value.fract() != 0.0 {
            return false;
        }
        let below_max = if self.max_excluded {
            value < self.max
        } else {
            value <= self.max
        };
        value >= self.min && below_max
    }

    /// Err with "`name` = value is out of range: allowed ..." when `value` is not allowed.
    pub fn check(&self, name: &str, value: f64) -> Result<(), String> {
        if self.accepts(value) {
            Ok(())
        } else {
            Err(format!(
                "{name} = {} is out of range: allowed {}",
                show(value),
                self.allowed
            ))
        }
    }
}

/// A value as typed: plain digits for ordinary magnitudes, an exponent for huge or tiny ones.
pub fn show(value: f64) -> String {
    let size = value.abs();
    if size != 0.0 && !(1e-6..1e9).contains(&size) {
        format!("{value:e}")
    } else {
        format!("{value}")
    }
}

/// Checks (limit, name, value) triples in order; the first refusal is the error.
pub fn check_all(checks: &[(&Limit, &str, f64)]) -> Result<(), String> {
    checks
        .iter()
        .try_for_each(|(limit, name, value)| limit.check(name, *value))
}

/// Young's modulus E [Pa]: soft gels (100 Pa) to ten times diamond.
pub const YOUNGS_MODULUS: Limit = range("1e2 <= E <= 1e13 (Pa)", 1e2, 1e13);
/// Poisson's ratio nu.
pub const POISSON_RATIO: Limit = range("0 <= nu < 0.5", 0.0, 0.5).below_max();
/// Thickness h [m]: a nanometre coating to a kilometre; inf is the half-plane / half-space.
pub const THICKNESS: Limit = range("1e-9 <= h <= 1e3 (m) or inf", 1e-9, 1e3).or_infinite();
/// Friction coefficient mu (measured values stay below about 5).
pub const FRICTION: Limit = range("0 <= mu <= 10", 0.0, 10.0);
/// Adhesive shear stress tau0 [Pa] (the ideal shear strength of the strongest solids is ~1e10).
pub const ADHESION: Limit = range("0 <= tau0 <= 1e10 (Pa)", 0.0, 1e10);
/// Wear coefficient k [1/Pa] (severe wear of the softest solids is ~1e-7).
pub const WEAR: Limit = range(
    "0 <= k <= 0.1 (1/Pa; or typed in mm3/Nm, 1 mm3/Nm = 1e-9 1/Pa)",
    0.0,
    0.1,
);
/// Punch radius R [m]: a nanometre tip to a nearly flat punch.
pub const RADIUS: Limit = range("1e-9 <= R <= 1e6 (m)", 1e-9, 1e6);
/// Exponent n of the power punch g = (R/n)(|x|/R)^n (n = 2 is the parabola; above 10 the punch is
/// a flat with a corner in all but name).
pub const POWER_EXPONENT: Limit = range("1 < n <= 10", 1.0 + f64::EPSILON, 10.0);
/// Half-width c [m] of a flat punch's face.
pub const HALF_WIDTH: Limit = range("1e-9 <= c <= 1e3 (m)", 1e-9, 1e3);
/// Edge radius r [m] of a flat punch: 0 is a sharp corner.
pub const EDGE_RADIUS: Limit = range("0, or 1e-9 <= r <= 1e6 (m)", 1e-9, 1e6).or_zero();
/// Exponent n of the wear law W' = -k q2 (q2/p0)^(n-1) (1 is Archard's linear law).
pub const WEAR_EXPONENT: Limit = range("1 <= n <= 4", 1.0, 4.0);
/// Reference pressure p0 [Pa] of a nonlinear wear law.
pub const REFERENCE_PRESSURE: Limit = range("1e-3 <= p0 <= 1e12 (Pa)", 1e-3, 1e12);
/// Shear strength tau_max [Pa] capping the friction stress; inf is no cap.
pub const SHEAR_STRENGTH: Limit =
    range("1e-3 <= tau_max <= 1e12 (Pa) or inf", 1e-3, 1e12).or_infinite();
/// Yield strength Y [Pa] of the strip in tension (the onset of plastic flow).
pub const YIELD_STRENGTH: Limit = range("1e3 <= Y <= 1e11 (Pa)", 1e3, 1e11);
/// Indentation hardness H [Pa] of the strip.
pub const HARDNESS: Limit = range("1e3 <= H <= 1e12 (Pa)", 1e3, 1e12);
/// Archard's wear coefficient K = k H [-]: a fraction of the contacts that make a wear particle
/// (Archard (1953) measured 1e-7 to 1e-2).
pub const ARCHARD: Limit = range("0 <= K <= 1", 0.0, 1.0);
/// Load per unit length P [N/m], also the ends of the load sweep.
pub const LINE_LOAD: Limit = range("1e-9 <= P <= 1e12 (N/m)", 1e-9, 1e12);
/// Number of sweep points.
pub const SWEEP_POINTS: Limit = range("a whole number from 2 to 2000", 2.0, 2000.0).whole();
/// Number of points of a plane profile (`wearlab solve --points`).
pub const PROFILE_POINTS: Limit = range("a whole number from 2 to 100000", 2.0, 100_000.0).whole();
/// Sliding speed V [m/s].
pub const SPEED: Limit = range("0 <= V <= 1e3 (m/s)", 0.0, 1e3);
/// Mean pressure pbar [Pa], also the ends of the mean-pressure sweep.
pub const MEAN_PRESSURE: Limit = range("1e-3 <= pbar <= 1e12 (Pa)", 1e-3, 1e12);
/// Harmonic amplitude A [m].
pub const AMPLITUDE: Limit = range("0 <= A <= 1 (m)", 0.0, 1.0);
/// Wavenumber [rad/m]: 0, or a wavelength from 0.6 nm to 6 km.
pub const WAVENUMBER: Limit = range("0, or 1e-3 <= w <= 1e10 (rad/m)", 1e-3, 1e10).or_zero();
/// Phase [rad].
pub const PHASE: Limit = range("-1e6 <= rho <= 1e6 (rad)", -1e6, 1e6);
/// Number of harmonics of the spatial punch.
pub const HARMONICS: Limit = range("a whole number from 1 to 64", 1.0, 64.0).whole();
/// Time t [s] (up to 30,000 years).
pub const TIME: Limit = range("0 <= t <= 1e12 (s)", 0.0, 1e12);
/// Time tolerance of the running-in: the local error allowed per time step, relative to the rms
/// of the shape at t = 0, per decay time 1/beta of the slowest harmonic (below 1e-8 the steps
/// would exceed the running-in's bound).
pub const TIME_TOLERANCE: Limit = range("1e-8 <= time tolerance <= 1e-2", 1e-8, 1e-2);
/// Duration of the time charts [s].
pub const DURATION: Limit = range("0 < duration <= 1e12 (s)", f64::MIN_POSITIVE, 1e12);
/// Points per side of the grid (fields and partial contact); at most `GRID_2D` for a shape that
/// varies along both x and y.
pub const GRID: Limit = range(
    "a whole number from 8 to 4096 (to 1024 for a shape that varies along x and y)",
    8.0,
    4096.0,
)
.whole();
/// Points per side of the grid for a shape that varies along both x and y.
pub const GRID_2D: Limit = range(
    "a whole number from 8 to 1024 for a shape that varies along x and y",
    8.0,
    1024.0,
)
.whole();
/// A probe coordinate x or y [m] (`wearlab solve --probe`).
pub const PROBE: Limit = range("-1e6 <= x, y <= 1e6 (m)", -1e6, 1e6);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_zero_infinity_and_whole_numbers() {
        assert!(POISSON_RATIO.accepts(0.0) && !POISSON_RATIO.accepts(0.5));
        assert!(THICKNESS.accepts(f64::INFINITY) && !THICKNESS.accepts(1e4));
        assert!(WAVENUMBER.accepts(0.0) && !WAVENUMBER.accepts(1e-4));
        assert!(!YOUNGS_MODULUS.accepts(f64::INFINITY) && !YOUNGS_MODULUS.accepts(1e308));
        assert!(!GRID.accepts(8.5) && GRID.accepts(4096.0) && !GRID_2D.accepts(2048.0));
        assert!(!DURATION.accepts(0.0));
        for limit in [YOUNGS_MODULUS, FRICTION, TIME, WAVENUMBER, THICKNESS] {
            assert!(!limit.accepts(f64::NAN) && !limit.accepts(-1.0));
        }
    }
}
