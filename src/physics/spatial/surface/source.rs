//! Where a punch surface comes from (the preset key `spatial.surface`, docs/presets.md): a
//! height-map file or the self-affine generator, kept beside the surface it gave so that a saved
//! preset names its source again.

use super::{SelfAffine, Surface};

/// The source of a surface.
#[derive(Clone, Debug, PartialEq)]
pub enum SurfaceSource {
    /// A height-map file: the CSV grid, or `x y z` columns when the name ends in `.xyz`.
    File {
        /// The file as the preset names it (relative to the preset's folder).
        file: String,
        /// Cell length along x [m] (the CSV grid's; an `x y z` file gives its own).
        length_x: f64,
        /// Cell width along y [m] (0 for a profile).
        length_y: f64,
    },
    /// The self-affine generator.
    SelfAffine(SelfAffine),
}

/// A surface and its source.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceShape {
    /// Where it came from.
    pub source: SurfaceSource,
    /// The height map at t = 0.
    pub surface: Surface,
}
