//! Statistics of a height map (docs/physics/spatial-surface.md section 3) and how far it is from
//! periodic.

use super::Surface;
use super::spectrum::{is_nyquist, spectrum, wave_vector};

/// The statistics of a surface. Derivatives are along x (the sliding line), spectral, with the
/// x-Nyquist line dropped: a map sampled from harmonics gives exactly the harmonics' values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Statistics {
    /// sqrt(<h^2>) [m] (the mean is zero).
    pub rms_height: f64,
    /// sqrt(<h_x^2>) [-]: rms slope along the sliding line.
    pub rms_slope: f64,
    /// sqrt(<h_xx^2>) [1/m]: rms curvature along the sliding line.
    pub rms_curvature: f64,
    /// <h^3>/h_rms^3 [-]: positive when the peaks (toward the layer) are sharper than the valleys;
    /// 0 for a flat surface.
    pub skewness: f64,
    /// <h^4>/h_rms^4 [-]: 3 for Gaussian heights, 1.5 for a single cosine; 0 for a flat surface.
    pub kurtosis: f64,
}

/// The statistics of `surface` (Parseval over its spectrum for the derivatives).
pub fn statistics(surface: &Surface) -> Statistics {
    let n = surface.heights.len() as f64;
    let mean_square = surface.heights.iter().map(|h| h * h).sum::<f64>() / n;
    let mean_cube = surface.heights.iter().map(|h| h * h * h).sum::<f64>() / n;
    let mean_fourth = surface.heights.iter().map(|h| (h * h).powi(2)).sum::<f64>() / n;
    let spectrum = spectrum(surface);
    let (mut slope, mut curvature) = (0.0, 0.0);
    for ky in 0..surface.ny {
        for kx in (0..surface.nx).filter(|&kx| !is_nyquist(kx, surface.nx)) {
            let (qx, _) = wave_vector(surface, kx, ky);
            let power = spectrum[ky * surface.nx + kx].norm_sqr() / (n * n);
            slope += power * qx * qx;
            curvature += power * qx.powi(4);
        }
    }
    let rms_height = mean_square.sqrt();
    Statistics {
        rms_height,
        rms_slope: slope.sqrt(),
        rms_curvature: curvature.sqrt(),
        skewness: if rms_height > 0.0 {
            mean_cube / rms_height.powi(3)
        } else {
            0.0
        },
        kurtosis: if rms_height > 0.0 {
            mean_fourth / mean_square.powi(2)
        } else {
            0.0
        },
    }
}

/// How far a map is from periodic: the steps across the cell's edges (from the last node to the
/// first, which the periodic cell makes neighbours) beside the steps between interior neighbours.
/// The surface is used as given: its grid is the period cell, so a large edge step is a real
/// feature of the cell (a ridge repeated every period), and the report says so rather than
/// altering the data with a taper.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Periodicity {
    /// rms over the rows of h(x_0) - h(x_{nx-1}) [m].
    pub edge_step_x: f64,
    /// rms of the steps between x-neighbours inside the cell [m].
    pub interior_step_x: f64,
    /// rms over the columns of h(y_0) - h(y_{ny-1}) [m]; 0 for a profile.
    pub edge_step_y: f64,
    /// rms of the steps between y-neighbours inside the cell [m]; 0 for a profile.
    pub interior_step_y: f64,
    /// rms height [m], the scale the steps are read against.
    pub rms_height: f64,
}

impl Periodicity {
    /// The larger of the two edge steps over the rms height [-]; 0 for a flat surface.
    pub fn edge_ratio(&self) -> f64 {
        if self.rms_height > 0.0 {
            self.edge_step_x.max(self.edge_step_y) / self.rms_height
        } else {
            0.0
        }
    }

    /// One sentence for the user: the edge steps against the rms height and what is done.
    pub fn message(&self) -> String {
        format!(
            "the step across the cell's x edges is {:.3e} m and across its y edges {:.3e} m \
             ({:.2} of the rms height {:.3e} m; interior neighbour steps {:.3e} m along x, \
             {:.3e} m along y): the surface is used as given, repeated periodically over the cell",
            self.edge_step_x,
            self.edge_step_y,
            self.edge_ratio(),
            self.rms_height,
            self.interior_step_x,
            self.interior_step_y
        )
    }
}

/// The periodicity report of `surface`.
pub fn periodicity(surface: &Surface) -> Periodicity {
    let (nx, ny) = (surface.nx, surface.ny);
    let h = |i: usize, j: usize| surface.height(i, j);
    let rms = |steps: Vec<f64>| {
        if steps.is_empty() {
            0.0
        } else {
            (steps.iter().map(|s| s * s).sum::<f64>() / steps.len() as f64).sqrt()
        }
    };
    let edge_x = (0..ny).map(|j| h(0, j) - h(nx - 1, j)).collect();
    let interior_x = (0..ny)
        .flat_map(|j| (1..nx).map(move |i| (i, j)))
        .map(|(i, j)| h(i, j) - h(i - 1, j))
        .collect();
    let (edge_y, interior_y) = if ny > 1 {
        (
            (0..nx).map(|i| h(i, 0) - h(i, ny - 1)).collect(),
            (1..ny)
                .flat_map(|j| (0..nx).map(move |i| (i, j)))
                .map(|(i, j)| h(i, j) - h(i, j - 1))
                .collect(),
        )
    } else {
        (Vec::new(), Vec::new())
    };
    let n = surface.heights.len() as f64;
    Periodicity {
        edge_step_x: rms(edge_x),
        interior_step_x: rms(interior_x),
        edge_step_y: rms(edge_y),
        interior_step_y: rms(interior_y),
        rms_height: (surface.heights.iter().map(|h| h * h).sum::<f64>() / n).sqrt(),
    }
}

/// One point of the bearing-area (Abbott-Firestone) curve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BearingPoint {
    /// A height level [m], positive toward the layer (the mean is zero).
    pub height: f64,
    /// The fraction of the cell's nodes at or above that level [-]: the area a flat plane at that
    /// height would cut through a rigid surface.
    pub fraction: f64,
}

/// The bearing-area curve at `levels` heights evenly spaced from the highest node (fraction
/// 1/(nx ny) or more) down to the lowest (fraction 1); a flat surface has one point, its common
/// height with fraction 1.
pub fn bearing_area(surface: &Surface, levels: usize) -> Vec<BearingPoint> {
    let mut sorted = surface.heights.clone();
    sorted.sort_by(|a, b| b.total_cmp(a));
    let (top, bottom) = (sorted[0], sorted[sorted.len() - 1]);
    let levels = if top > bottom { levels } else { levels.min(1) };
    let n = sorted.len() as f64;
    (0..levels)
        .map(|k| {
            // the last level is the lowest node itself, so that every node counts
            let height = if k + 1 == levels {
                bottom
            } else {
                top + (bottom - top) * k as f64 / (levels - 1) as f64
            };
            BearingPoint {
                height,
                fraction: sorted.partition_point(|&h| h >= height) as f64 / n,
            }
        })
        .collect()
}
