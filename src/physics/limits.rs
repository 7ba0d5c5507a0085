//! The allowed range of every parameter, in one place: the solvers, the preset files and the
//! explorer's form all check against these and quote `allowed` when a value is rejected.

/// One parameter's range.
#[derive(Clone, Copy, Debug)]
pub struct Limit {
    /// What is allowed, in words, with the unit.
    pub allowed: &'static str,
    ok: fn(f64) -> bool,
}

impl Limit {
    /// Whether `value` is allowed.
    pub fn accepts(&self, value: f64) -> bool {
        (self.ok)(value)
    }

    /// Err with "`name` = value is out of range: allowed ..." when `value` is not allowed.
    pub fn check(&self, name: &str, value: f64) -> Result<(), String> {
        if self.accepts(value) {
            Ok(())
        } else {
            Err(format!(
                "{name} = {value} is out of range: allowed {}",
                self.allowed
            ))
        }
    }
}

/// Checks (limit, name, value) triples in order; the first refusal is the error.
pub fn check_all(checks: &[(&Limit, &str, f64)]) -> Result<(), String> {
    checks
        .iter()
        .try_for_each(|(limit, name, value)| limit.check(name, *value))
}

fn positive_finite(v: f64) -> bool {
    v > 0.0 && v.is_finite()
}

fn non_negative_finite(v: f64) -> bool {
    v >= 0.0 && v.is_finite()
}

/// Young's modulus E [Pa].
pub const YOUNGS_MODULUS: Limit = Limit {
    allowed: "0 < E < inf (Pa)",
    ok: positive_finite,
};
/// Poisson's ratio nu.
pub const POISSON_RATIO: Limit = Limit {
    allowed: "0 <= nu < 0.5",
    ok: |v| (0.0..0.5).contains(&v),
};
/// Thickness h [m]; inf is the half-plane / half-space.
pub const THICKNESS: Limit = Limit {
    allowed: "h > 0 (m), or inf for a half-plane",
    ok: |v| v > 0.0,
};
/// Friction coefficient mu.
pub const FRICTION: Limit = Limit {
    allowed: "0 <= mu < inf",
    ok: non_negative_finite,
};
/// Adhesive shear stress tau0 [Pa].
pub const ADHESION: Limit = Limit {
    allowed: "0 <= tau0 < inf (Pa)",
    ok: non_negative_finite,
};
/// Wear coefficient k [1/Pa].
pub const WEAR: Limit = Limit {
    allowed: "0 <= k < inf (1/Pa)",
    ok: non_negative_finite,
};
/// Punch radius R [m].
pub const RADIUS: Limit = Limit {
    allowed: "0 < R < inf (m)",
    ok: positive_finite,
};
/// Load per unit length P [N/m].
pub const LINE_LOAD: Limit = Limit {
    allowed: "0 < P < inf (N/m)",
    ok: positive_finite,
};
/// Number of sweep points.
pub const SWEEP_POINTS: Limit = Limit {
    allowed: "a whole number from 2 to 2000",
    ok: |v| (2.0..=2000.0).contains(&v) && v.fract() == 0.0,
};
/// Sliding speed V [m/s].
pub const SPEED: Limit = Limit {
    allowed: "0 <= V < inf (m/s)",
    ok: non_negative_finite,
};
/// Mean pressure pbar [Pa].
pub const MEAN_PRESSURE: Limit = Limit {
    allowed: "0 < pbar < inf (Pa)",
    ok: positive_finite,
};
/// Harmonic amplitude A [m].
pub const AMPLITUDE: Limit = Limit {
    allowed: "0 <= A < inf (m)",
    ok: non_negative_finite,
};
/// Wavenumber [rad/m].
pub const WAVENUMBER: Limit = Limit {
    allowed: "0 <= w < inf (rad/m)",
    ok: non_negative_finite,
};
/// Phase [rad].
pub const PHASE: Limit = Limit {
    allowed: "a finite angle (rad)",
    ok: f64::is_finite,
};
/// Time t [s].
pub const TIME: Limit = Limit {
    allowed: "0 <= t < inf (s)",
    ok: non_negative_finite,
};
/// Duration of the time charts [s].
pub const DURATION: Limit = Limit {
    allowed: "0 < duration < inf (s)",
    ok: positive_finite,
};
/// Points per side of the field grid.
pub const GRID: Limit = Limit {
    allowed: "a whole number from 8 to 512",
    ok: |v| (8.0..=512.0).contains(&v) && v.fract() == 0.0,
};
