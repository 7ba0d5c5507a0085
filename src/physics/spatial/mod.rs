//! The spatial problem (the wavy-punch paper, `docs/references.md`; the derivation in `docs/physics/spatial.md`): a rigid wavy punch of
//! N harmonics in complete contact with an elastic layer bonded to a rigid base; the layer slides
//! in -x at speed V under Coulomb friction tau = mu p + tau0 (1.1); the punch wears,
//! dg/dt = -k_w p with k_w = k V (1.2).
//!
//! Frame: x along the sliding line (the friction force on the layer points in +x), y across it,
//! z up out of the layer. Shape g = gbar(t) + U(x, y, t) (1.6).

pub mod at_times;
pub mod checks;
pub mod contact;
pub mod field;
pub mod groups;
pub mod harmonic;
pub mod history;
pub mod partial;
pub mod pipeline;
mod product;
pub mod result;
mod separable;
pub mod state;
pub mod surface;
mod wear_law;

use std::f64::consts::PI;
use std::sync::Arc;

use crate::physics::spatial::harmonic::{Evolution, Harmonic, HarmonicState, evolution};
use crate::physics::spatial::surface::{Surface, SurfaceShape};
use crate::physics::{Friction, Material, SolveError, limits, validate_common};

pub use state::{SpatialState, StateAt, state_at};

/// The inputs of the spatial problem.
#[derive(Clone, Debug, PartialEq)]
pub struct SpatialInputs {
    /// The layer (h = inf: half-space).
    pub material: Material,
    /// Friction law tau = mu p + tau0.
    pub friction: Friction,
    /// Wear coefficient k [1/Pa] (the same k as the plane problem).
    pub wear: f64,
    /// Exponent n of the wear law W' = -k V p (p/p0)^(n-1) (dimensionless, in [1, 4]); 1 is the
    /// paper's linear law (1.2).
    pub wear_exponent: f64,
    /// Reference pressure p0 [Pa] of the wear law, > 0; plays no part when n = 1.
    pub reference_pressure: f64,
    /// Sliding speed V [m/s], >= 0.
    pub sliding_speed: f64,
    /// Mean pressure pbar [Pa] (load per unit area), > 0.
    pub mean_pressure: f64,
    /// The punch's shape at t = 0.
    pub shape: PunchShape,
}

/// The punch's shape at t = 0: harmonics (1.6), or a periodic height map
/// (docs/physics/spatial-surface.md) solved on its own grid.
#[derive(Clone, Debug, PartialEq)]
pub enum PunchShape {
    /// A sum of harmonics A sin(wx x + rho_x) sin(wy y + rho_y).
    Harmonics(Vec<Harmonic>),
    /// A height map and its source (shared: a map is up to 1024 x 1024 heights).
    Surface(Arc<SurfaceShape>),
}

impl SpatialInputs {
    /// k_w = k V [m/(Pa s)]: punch wear depth per unit time per unit pressure.
    pub fn wear_rate(&self) -> f64 {
        self.wear * self.sliding_speed
    }

    /// The harmonics of the shape (none for a height map).
    pub fn harmonics(&self) -> &[Harmonic] {
        match &self.shape {
            PunchShape::Harmonics(h) => h,
            PunchShape::Surface(_) => &[],
        }
    }

    /// The height map of the shape (None for harmonics).
    pub fn surface(&self) -> Option<&Surface> {
        match &self.shape {
            PunchShape::Harmonics(_) => None,
            PunchShape::Surface(s) => Some(&s.surface),
        }
    }

    /// Checks every field (see `physics::limits`); a height map was checked when it was made
    /// (`Surface::new`).
    pub fn validate(&self) -> Result<(), SolveError> {
        validate_common(&self.material, &self.friction, self.wear)?;
        self.wear_law().validate()?;
        limits::check_all(&[
            (&limits::SPEED, "sliding_speed", self.sliding_speed),
            (&limits::MEAN_PRESSURE, "mean_pressure", self.mean_pressure),
        ])
        .map_err(SolveError::InvalidInput)?;
        match &self.shape {
            PunchShape::Harmonics(h) => validate_harmonics(h),
            PunchShape::Surface(_) => Ok(()),
        }
    }
}

/// Checks the harmonics: 1 to 64 (`limits::HARMONICS`); every amplitude, wavenumber and phase
/// in range; no zero wave vector; no wave vector twice.
pub fn validate_harmonics(harmonics: &[Harmonic]) -> Result<(), SolveError> {
    if harmonics.is_empty() {
        return Err(SolveError::InvalidInput(
            "the punch has no harmonics: add at least one (amplitude, wavenumbers, phases)".into(),
        ));
    }
    limits::HARMONICS
        .check("the number of harmonics", harmonics.len() as f64)
        .map_err(SolveError::InvalidInput)?;
    for (i, h) in harmonics.iter().enumerate() {
        let n = i + 1;
        let of_harmonic = |name: &str| format!("harmonic {n}: {name}");
        [
            (&limits::AMPLITUDE, "amplitude", h.amplitude),
            (&limits::WAVENUMBER, "wavenumber_x", h.wavenumber_x),
            (&limits::WAVENUMBER, "wavenumber_y", h.wavenumber_y),
            (&limits::PHASE, "phase_x", h.phase_x),
            (&limits::PHASE, "phase_y", h.phase_y),
        ]
        .iter()
        // the name is written only for a refusal: a fit checks every row's preset
        .filter(|(limit, _, value)| !limit.accepts(*value))
        .try_for_each(|(limit, name, value)| limit.check(&of_harmonic(name), *value))
        .map_err(SolveError::InvalidInput)?;
        if h.wavenumber() == 0.0 {
            return Err(SolveError::InvalidInput(format!(
                "harmonic {n}: the wave vector is zero (wavenumber_x = wavenumber_y = 0); a constant \
                 belongs in the mean pressure, not in a harmonic"
            )));
        }
        if let Some(j) = harmonics[..i]
            .iter()
            .position(|o| o.wavenumber_x == h.wavenumber_x && o.wavenumber_y == h.wavenumber_y)
        {
            return Err(SolveError::InvalidInput(format!(
                "harmonics {} and {n} have the same wave vector: give each wave vector once",
                j + 1
            )));
        }
    }
    Ok(())
}

/// Checks the grid side against the shape: `limits::GRID`, and `limits::GRID_2D` when the
/// harmonics vary along both x and y.
pub fn validate_grid(harmonics: &[Harmonic], grid: usize) -> Result<(), SolveError> {
    let varies = |w: fn(&Harmonic) -> f64| harmonics.iter().any(|h| w(h) != 0.0);
    let limit = if varies(|h| h.wavenumber_x) && varies(|h| h.wavenumber_y) {
        &limits::GRID_2D
    } else {
        &limits::GRID
    };
    limit
        .check("grid", grid as f64)
        .map_err(SolveError::InvalidInput)
}

/// One harmonic at the time of the solution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HarmonicSolution {
    /// The harmonic as given at t = 0.
    pub initial: Harmonic,
    /// Its rates.
    pub evolution: Evolution,
    /// Its amplitude and phases at time t.
    pub state: HarmonicState,
}

/// The spatial solution at one instant.
#[derive(Clone, Debug, PartialEq)]
pub struct SpatialSolution {
    /// The inputs.
    pub inputs: SpatialInputs,
    /// t [s].
    pub time: f64,
    /// Each harmonic.
    pub harmonics: Vec<HarmonicSolution>,
    /// D = <p g_x> [Pa], section 5; psi = -D.
    pub psi: f64,
    /// P = pbar - mu psi [Pa]: vertical force on the punch per unit area.
    pub load: f64,
    /// T = mu pbar + tau0 + psi [Pa]: holding force per unit area along x.
    pub tangential: f64,
    /// mu* = mu + (1 + mu^2) psi/P.
    pub mu_star: f64,
}

/// psi = -D with D = sum A^2 wx sin(phi) Y/(2M), Y = 1/2 if wy != 0 else sin^2(rho_y) (section 5).
pub fn deformation_friction(harmonics: &[HarmonicSolution]) -> f64 {
    -harmonics
        .iter()
        .map(|h| {
            let y = if h.initial.wavenumber_y != 0.0 {
                0.5
            } else {
                h.state.phase_y.sin().powi(2)
            };
            h.state.amplitude.powi(2) * h.initial.wavenumber_x * h.evolution.phase_lead.sin() * y
                / (2.0 * h.evolution.m)
        })
        .sum::<f64>()
}

/// The evolutions of all harmonics (the costly, time-independent stage).
pub fn evolutions(inputs: &SpatialInputs) -> Vec<Evolution> {
    inputs
        .harmonics()
        .iter()
        .map(|h| evolution(&inputs.material, &inputs.friction, inputs.wear_rate(), h))
        .collect()
}

/// The solution at time t [s] from precomputed evolutions.
pub fn solve_with(inputs: &SpatialInputs, evolutions: &[Evolution], time: f64) -> SpatialSolution {
    let harmonics: Vec<HarmonicSolution> = inputs
        .harmonics()
        .iter()
        .zip(evolutions)
        .map(|(h, ev)| HarmonicSolution {
            initial: *h,
            evolution: *ev,
            state: harmonic::state_at(h, ev, time),
        })
        .collect();
    let psi = deformation_friction(&harmonics);
    let mu = inputs.friction.coefficient;
    let pbar = inputs.mean_pressure;
    let load = pbar - mu * psi;
    SpatialSolution {
        time,
        psi,
        load,
        tangential: mu * pbar + inputs.friction.adhesion + psi,
        mu_star: mu + (1.0 + mu * mu) * psi / load,
        harmonics,
        inputs: inputs.clone(),
    }
}

/// Validates and solves at time t [s] >= 0 by the closed form of the harmonics; the solution has
/// passed the physical checks (`spatial::checks`). A height map is refused: it has no harmonics,
/// and `pipeline::solve` answers it on its grid.
pub fn solve(inputs: &SpatialInputs, time: f64) -> Result<SpatialSolution, SolveError> {
    inputs.validate()?;
    if inputs.surface().is_some() {
        return Err(SolveError::InvalidInput(
            "a height-map punch has no closed form of harmonics: pipeline::solve answers it on \
             its grid"
                .into(),
        ));
    }
    limits::TIME
        .check("time", time)
        .map_err(SolveError::InvalidInput)?;
    let sol = solve_with(inputs, &evolutions(inputs), time);
    checks::check(&sol)?;
    Ok(sol)
}

impl SpatialSolution {
    /// Contact pressure p(x, y) [Pa] = pbar + sum (A/M) sin(wx x + rho_x + phi) sin(wy y + rho_y).
    pub fn pressure(&self, x: f64, y: f64) -> f64 {
        self.inputs.mean_pressure
            + self
                .harmonics
                .iter()
                .map(|h| {
                    h.state.amplitude / h.evolution.m
                        * (h.initial.wavenumber_x * x + h.state.phase_x + h.evolution.phase_lead)
                            .sin()
                        * (h.initial.wavenumber_y * y + h.state.phase_y).sin()
                })
                .sum::<f64>()
    }

    /// Shear stress tau = mu p + tau0 [Pa] on the layer, along +x.
    pub fn shear(&self, x: f64, y: f64) -> f64 {
        self.inputs.friction.coefficient * self.pressure(x, y) + self.inputs.friction.adhesion
    }

    /// The oscillating part of the shape U(x, y, t) [m] (1.6).
    pub fn shape(&self, x: f64, y: f64) -> f64 {
        self.harmonics
            .iter()
            .map(|h| {
                h.state.amplitude
                    * (h.initial.wavenumber_x * x + h.state.phase_x).sin()
                    * (h.initial.wavenumber_y * y + h.state.phase_y).sin()
            })
            .sum()
    }

    /// Punch wear W(x, y, t) = g(x, y, 0) - g(x, y, t) [m]: the mean wear k_w pbar t plus the
    /// change of the oscillating part.
    pub fn wear(&self, x: f64, y: f64) -> f64 {
        let initial: f64 = self
            .harmonics
            .iter()
            .map(|h| {
                let w = &h.initial;
                w.amplitude
                    * (w.wavenumber_x * x + w.phase_x).sin()
                    * (w.wavenumber_y * y + w.phase_y).sin()
            })
            .sum();
        self.mean_wear() + initial - self.shape(x, y)
    }

    /// Mean wear depth k_w pbar t [m] (gbar(0) - gbar(t), section 3).
    pub fn mean_wear(&self) -> f64 {
        self.inputs.wear_rate() * self.inputs.mean_pressure * self.time
    }
}

/// How one axis of the pattern repeats.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Period {
    /// No harmonic varies along this axis.
    Constant,
    /// Every nonzero wavenumber is a whole multiple of `base` [rad/m] (to `COMMENSURATE_ULPS`);
    /// the period is 2 pi/base.
    Commensurate { base: f64 },
    /// The search found no common base (none of w_min/q, q <= `PERIOD_SEARCH`, makes every
    /// wavenumber a whole multiple): no period is known. This is not a proof that there is none.
    NotFound,
}

/// The largest denominator q the period search tries.
pub const PERIOD_SEARCH: usize = 64;
/// How close (in units of the last place of the ratio) w/base must be to a whole number. A
/// 17-digit number in a preset holds w to half an ulp, so a ratio the file means to be whole is
/// within a few ulps of it; anything farther (e.g. 1e-10 relative) beats over a finite length,
/// and the pattern has no period.
pub const COMMENSURATE_ULPS: f64 = 8.0;

/// The common base of wavenumbers, if one is found: the smallest nonzero one divided by
/// q <= `PERIOD_SEARCH` such that every wavenumber is a whole multiple to `COMMENSURATE_ULPS`.
pub fn period_of(wavenumbers: impl Iterator<Item = f64>) -> Period {
    let ws: Vec<f64> = wavenumbers.filter(|w| *w != 0.0).collect();
    let Some(w_min) = ws.iter().copied().reduce(f64::min) else {
        return Period::Constant;
    };
    (1..=PERIOD_SEARCH)
        .map(|q| w_min / q as f64)
        .find(|base| {
            ws.iter().all(|w| {
                let ratio = w / base;
                (ratio - ratio.round()).abs() <= COMMENSURATE_ULPS * f64::EPSILON * ratio
            })
        })
        .map_or(Period::NotFound, |base| Period::Commensurate { base })
}

/// The cell shown and searched: one period per axis, or (no period found, or a constant axis)
/// the longest wavelength present.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cell {
    /// Extent along x [m].
    pub lx: f64,
    /// Extent along y [m].
    pub ly: f64,
    /// Periodicity along x.
    pub period_x: Period,
    /// Periodicity along y.
    pub period_y: Period,
}

impl Cell {
    /// The cell of a set of harmonics.
    pub fn of(harmonics: &[Harmonic]) -> Cell {
        let k_min = harmonics
            .iter()
            .map(Harmonic::wavenumber)
            .fold(f64::INFINITY, f64::min);
        let longest = 2.0 * PI / k_min;
        let extent = |p: Period, ws: &mut dyn Iterator<Item = f64>| match p {
            Period::Commensurate { base } => 2.0 * PI / base,
            Period::NotFound => 2.0 * PI / ws.filter(|w| *w > 0.0).fold(f64::INFINITY, f64::min),
            Period::Constant => longest,
        };
        let period_x = period_of(harmonics.iter().map(|h| h.wavenumber_x));
        let period_y = period_of(harmonics.iter().map(|h| h.wavenumber_y));
        Cell {
            lx: extent(period_x, &mut harmonics.iter().map(|h| h.wavenumber_x)),
            ly: extent(period_y, &mut harmonics.iter().map(|h| h.wavenumber_y)),
            period_x,
            period_y,
        }
    }

    /// True when the pattern repeats in the cell along both axes.
    pub fn is_periodic(&self) -> bool {
        !matches!(self.period_x, Period::NotFound) && !matches!(self.period_y, Period::NotFound)
    }
}
