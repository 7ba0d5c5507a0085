//! The result of the spatial problem at time t (`pipeline::solve`), serialised with the keys of
//! the command-line contract (`docs/cli.md`; the partial-contact keys of
//! docs/physics/spatial-partial.md section 7). All values SI.

use serde::Serialize;

use crate::physics::spatial::contact::NotCertified;
use crate::physics::spatial::surface::{Surface, bearing_area, radial_psd, statistics};

/// One harmonic at time t: its closed form (docs/physics/spatial.md section 3).
#[derive(Clone, Debug, Serialize)]
pub struct HarmonicResult {
    /// |(wx, wy)| [rad/m].
    pub k: f64,
    /// beta [1/s].
    pub decay_rate: f64,
    /// c [m/s], positive along +x.
    pub drift_velocity: f64,
    /// Omega [rad/s].
    pub phase_rate: f64,
    /// phi [rad].
    pub phase_lead: f64,
    /// 1/M [Pa/m].
    pub pressure_per_amplitude: f64,
    /// A(t) [m] of the closed form.
    pub amplitude: f64,
    /// rho_x(t) [rad] of the closed form.
    pub phase_x: f64,
    /// rho_y [rad].
    pub phase_y: f64,
}

/// The fields at one point.
#[derive(Clone, Debug, Serialize)]
pub struct Probe {
    /// x [m].
    pub x: f64,
    /// y [m].
    pub y: f64,
    /// p [Pa] (at the nearest node when the contact was partial at t = 0).
    pub pressure: f64,
    /// tau [Pa] on the layer, along +x (0 out of contact).
    pub shear: f64,
    /// U [m].
    pub shape: f64,
}

/// The contact at time t.
#[derive(Clone, Debug, Serialize)]
pub struct ContactResult {
    /// True when the contact is complete (p > 0 over the whole cell).
    pub complete: bool,
    /// Fraction of the cell in contact (p > 0).
    pub fraction: f64,
    /// The simulated time [s] at which the running-in makes the contact complete; null when it is
    /// complete at t = 0, or still partial at the end of the running-in (its bound:
    /// docs/models.md, "Time to complete contact").
    pub time_to_complete: Option<f64>,
    /// The estimated time-stepping error of the running-in at t: the sum of its steps' local
    /// error estimates, relative to the rms of the punch shape at t = 0 (it bounds the relative
    /// time-stepping error of max_pressure, mu_star and time_to_complete, and that of mean_gap
    /// relative to the shape's rms; `spatial.time_tolerance` sets it); null when nothing is
    /// stepped (complete at t = 0, no wear).
    pub time_error: Option<f64>,
    /// min of the complete-contact pressure p_cc [Pa] of the shape at t: negative when partial.
    pub min_pressure: f64,
    /// Where [x, y] [m] (null when only the bound is known).
    pub at: Option<[f64; 2]>,
    /// pbar - sum A_n(t)/M_n [Pa] with the closed-form amplitudes; for a wear law n != 1, whose
    /// amplitudes have no closed form, the nodal minimum of p_cc once the shape has worn.
    pub lower_bound: f64,
    /// True when `min_pressure` is the certified cell minimum; false for the bound or a minimum
    /// over the grid's nodes.
    pub exact: bool,
    /// Why the closed form's cell minimum was not certified (null when it was, or when
    /// `min_pressure` is over the grid's nodes).
    pub not_certified: Option<NotCertified>,
    /// The formal closed-form time [s] after which the bound guarantees complete contact (null
    /// without wear, and for a wear law n != 1, which has no closed form); not the running-in
    /// time, which is `time_to_complete`.
    pub complete_after: Option<f64>,
}

/// mu* against the mean pressure, for the punch as it is at time t.
#[derive(Clone, Debug, Serialize)]
pub struct SweepResult {
    /// pbar [Pa].
    pub mean_pressure: Vec<f64>,
    /// P [Pa].
    pub load: Vec<f64>,
    /// mu*; null where P <= 0, and, without a period cell (incommensurate wavenumbers), where the
    /// contact is partial.
    pub mu_star: Vec<Option<f64>>,
    /// Fraction of the cell in contact (null without a period cell).
    pub contact_fraction: Option<Vec<f64>>,
    /// The smallest pbar [Pa] with complete contact (null when unknown).
    pub complete_mean_pressure: Option<f64>,
}

/// The statistics of a height-map punch at time t (docs/physics/spatial-surface.md section 3).
#[derive(Clone, Debug, Serialize)]
pub struct SurfaceResult {
    /// rms height of the shape U at t [m].
    pub rms_height: f64,
    /// rms slope along x of U at t [-] (spectral, the x-Nyquist line dropped).
    pub rms_slope: f64,
    /// rms curvature along x of U at t [1/m] (spectral, the x-Nyquist line dropped).
    pub rms_curvature: f64,
    /// Skewness <U^3>/U_rms^3 [-] (positive: sharper peaks toward the layer).
    pub skewness: f64,
    /// Kurtosis <U^4>/U_rms^4 [-] (3 for Gaussian heights).
    pub kurtosis: f64,
    /// The bearing-area curve of U at t.
    pub bearing_area: BearingArea,
    /// The radially averaged power spectral density of U at t.
    pub psd: Psd,
    /// The cell lx, ly [m] (ly = 0 for a profile; not in the JSON: the height-map file's).
    #[serde(skip)]
    pub cell: [f64; 2],
}

/// The bearing-area (Abbott-Firestone) curve: `BEARING_LEVELS` heights evenly spaced from the
/// highest node down to the lowest.
#[derive(Clone, Debug, Serialize)]
pub struct BearingArea {
    /// Height levels [m], positive toward the layer, from the mean (zero), decreasing.
    pub height: Vec<f64>,
    /// The fraction of the cell at or above each level [-] (1 at the lowest).
    pub fraction: Vec<f64>,
}

/// The radially averaged PSD over `PSD_BINS` logarithmic bins of |q| (empty bins left out).
#[derive(Clone, Debug, Serialize)]
pub struct Psd {
    /// Mean wavenumber |q| of each bin [rad/m], increasing.
    pub wavenumber: Vec<f64>,
    /// Mean C(q) of each bin: [m^4] for a map, [m^3] for a profile (docs/physics/spatial-surface.md
    /// section 2).
    pub psd: Vec<f64>,
}

/// The number of logarithmic bins of the reported PSD.
pub const PSD_BINS: usize = 32;
/// The number of levels of the reported bearing-area curve.
pub const BEARING_LEVELS: usize = 21;

impl SurfaceResult {
    /// The statistics, bearing-area curve and PSD of `surface`.
    pub fn of(surface: &Surface) -> SurfaceResult {
        let s = statistics(surface);
        let (height, fraction) = bearing_area(surface, BEARING_LEVELS)
            .into_iter()
            .map(|b| (b.height, b.fraction))
            .unzip();
        let (wavenumber, psd) = radial_psd(surface, PSD_BINS)
            .into_iter()
            .map(|p| (p.wavenumber, p.psd))
            .unzip();
        SurfaceResult {
            rms_height: s.rms_height,
            rms_slope: s.rms_slope,
            rms_curvature: s.rms_curvature,
            skewness: s.skewness,
            kurtosis: s.kurtosis,
            bearing_area: BearingArea { height, fraction },
            psd: Psd { wavenumber, psd },
            cell: [surface.lx, surface.ly],
        }
    }
}

/// The fields on a grid over the cell, row-major (x fastest).
#[derive(Clone, Debug, Default)]
pub struct FieldTable {
    /// x [m] of the columns.
    pub x: Vec<f64>,
    /// y [m] of the rows.
    pub y: Vec<f64>,
    /// p [Pa].
    pub pressure: Vec<f64>,
    /// tau [Pa].
    pub shear: Vec<f64>,
    /// U [m].
    pub shape: Vec<f64>,
    /// W [m].
    pub wear: Vec<f64>,
}

/// The spatial problem at time t: what `wearlab solve` reports (its JSON keys, `docs/cli.md`)
/// and what a sweep point reads.
#[derive(Clone, Debug, Serialize)]
pub struct SpatialResult {
    /// Always "spatial".
    pub problem: &'static str,
    /// t [s].
    pub time: f64,
    /// pbar [Pa].
    pub mean_pressure: f64,
    /// P = pbar - mu psi - tau0 Delta [Pa]: the vertical force per unit area.
    pub load: f64,
    /// T = mu pbar + tau0 fraction + psi [Pa]: the holding force per unit area along x.
    pub tangential_force: f64,
    /// mu* = (T - tau0 fraction)/P.
    pub mu_star: f64,
    /// psi = -<p g_x> [Pa].
    pub psi: f64,
    /// Delta = -<1_C g_x> (0 in complete contact).
    pub delta: f64,
    /// p_max [Pa].
    pub max_pressure: f64,
    /// The mean gap <gap> [m] (0 in complete contact).
    pub mean_gap: f64,
    /// When the per-harmonic closed form holds: "now", "after complete contact", or "for n = 1
    /// only" (a nonlinear wear law).
    pub harmonics_hold: &'static str,
    /// Why the running-in is simulated on the grid whatever the contact, in words (a nonlinear
    /// wear law; absent from the JSON for the linear one).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub running_in: Option<String>,
    /// Per harmonic.
    pub harmonics: Vec<HarmonicResult>,
    /// The contact.
    pub contact: ContactResult,
    /// Fields at the requested points.
    pub probes: Vec<Probe>,
    /// mu* against pbar (None when not asked for).
    pub sweep: Option<SweepResult>,
    /// The punch surface at t, for a height-map punch (absent from the JSON for harmonics).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface: Option<SurfaceResult>,
    /// The fields over the cell (not in the JSON; the CSV of `wearlab solve`).
    #[serde(skip)]
    pub field: FieldTable,
}
