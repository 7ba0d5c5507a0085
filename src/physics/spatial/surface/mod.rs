//! A rough punch surface given as a periodic height map (docs/physics/spatial-surface.md): the
//! shape g of docs/physics/spatial.md (1.6) sampled on an nx x ny grid over one period cell
//! lx x ly, heights measured from the punch toward the layer (the largest touch first), the mean
//! removed. A profile along the sliding line has ny = 1.

mod generate;
mod read;
mod source;
mod spectrum;
mod statistics;

pub use generate::{Amplitude, SelfAffine, SplitMix64, allowed, generate};
pub use read::{MAX_FILE_BYTES, ReadError, parse_csv, read_csv, read_xyz};
pub use source::{SurfaceShape, SurfaceSource};
pub use spectrum::{PsdPoint, mode_wave_vectors, radial_psd};
pub use statistics::{
    BearingPoint, Periodicity, Statistics, bearing_area, periodicity, statistics,
};

/// Largest 2-D grid side (nodes along x or y when ny > 1).
pub const MAX_SIDE_2D: usize = 1024;
/// Largest 1-D profile (nodes along x when ny = 1).
pub const MAX_SIDE_1D: usize = 16384;
/// Largest |height| [m] accepted: the model is the linear theory of a shallow punch, and a
/// height of a centimetre is far beyond any surface it describes.
pub const MAX_HEIGHT: f64 = 1e-2;

/// A periodic height map (see the module's doc).
#[derive(Clone, Debug, PartialEq)]
pub struct Surface {
    /// Nodes along x (the sliding line): x_i = i lx/nx.
    pub nx: usize,
    /// Nodes along y: y_j = j ly/ny; 1 for a profile.
    pub ny: usize,
    /// Cell extent along x [m], > 0.
    pub lx: f64,
    /// Cell extent along y [m], > 0 for a map; not used for a profile (ny = 1).
    pub ly: f64,
    /// Heights [m], row-major (index j nx + i), positive toward the layer, mean zero.
    pub heights: Vec<f64>,
}

impl Surface {
    /// The surface of these heights (row-major, j nx + i) with their mean removed. Refused when
    /// the grid is empty, has a single node along x, exceeds `MAX_SIDE_2D` (or `MAX_SIDE_1D` for
    /// a profile), when the lengths are not positive finite numbers, or when a height is not
    /// finite or exceeds `MAX_HEIGHT` in magnitude.
    pub fn new(
        nx: usize,
        ny: usize,
        lx: f64,
        ly: f64,
        mut heights: Vec<f64>,
    ) -> Result<Surface, String> {
        check_grid(nx, ny)?;
        if heights.len() != nx * ny {
            return Err(format!(
                "{} heights for an {nx} x {ny} grid (expected {})",
                heights.len(),
                nx * ny
            ));
        }
        if !(lx.is_finite() && lx > 0.0) {
            return Err(format!("length_x = {lx} m: the cell length must be > 0"));
        }
        if ny > 1 && !(ly.is_finite() && ly > 0.0) {
            return Err(format!(
                "length_y = {ly} m: a 2-D map needs a cell width > 0"
            ));
        }
        if let Some((index, h)) = heights
            .iter()
            .enumerate()
            .find(|(_, h)| !h.is_finite() || h.abs() > MAX_HEIGHT)
        {
            return Err(format!(
                "height {h} m at node (i = {}, j = {}): {}",
                index % nx,
                index / nx,
                height_reason(*h)
            ));
        }
        let mean = heights.iter().sum::<f64>() / heights.len() as f64;
        heights.iter_mut().for_each(|h| *h -= mean);
        Ok(Surface {
            nx,
            ny,
            lx,
            ly: if ny == 1 { 0.0 } else { ly },
            heights,
        })
    }

    /// True for a profile along the sliding line (ny = 1).
    pub fn is_profile(&self) -> bool {
        self.ny == 1
    }

    /// Height [m] at node (i, j).
    pub fn height(&self, i: usize, j: usize) -> f64 {
        self.heights[j * self.nx + i]
    }
}

/// Why a height is refused (not finite, or beyond `MAX_HEIGHT`).
pub(crate) fn height_reason(h: f64) -> String {
    if h.is_finite() {
        format!(
            "heights beyond {MAX_HEIGHT} m are not a surface the shallow-punch theory describes \
             (heights are in metres)"
        )
    } else {
        format!("{h} is not a height")
    }
}

/// Ok when an nx x ny grid is within the size limits.
pub(crate) fn check_grid(nx: usize, ny: usize) -> Result<(), String> {
    if nx == 0 || ny == 0 {
        return Err("the surface has no heights".into());
    }
    if nx < 2 {
        return Err(format!(
            "a surface needs at least 2 nodes along x (the sliding line), found {nx}"
        ));
    }
    if ny == 1 && nx > MAX_SIDE_1D {
        return Err(format!(
            "a profile of {nx} nodes is more than the {MAX_SIDE_1D} the solvers take"
        ));
    }
    if ny > 1 && (nx > MAX_SIDE_2D || ny > MAX_SIDE_2D) {
        return Err(format!(
            "a {nx} x {ny} map is more than the {MAX_SIDE_2D} x {MAX_SIDE_2D} the solvers take"
        ));
    }
    Ok(())
}
