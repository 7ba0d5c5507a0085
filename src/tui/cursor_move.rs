//! The cursor keys' steps (`[ ] { }`): how far each moves a curve's cursor or a map's.

/// Where a cursor key moves a cursor: `[ ]` a short step back or forward (a data point along a
/// curve, a grid point along x on a map), `{ }` a long one (ten data points along a curve, a grid
/// point along y on a map).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CursorMove {
    /// `[`: a short step back.
    Back,
    /// `]`: a short step forward.
    Forward,
    /// `{`: a long step back.
    LongBack,
    /// `}`: a long step forward.
    LongForward,
}

impl CursorMove {
    /// The data points a curve's cursor moves (negative: left): 1 for `[ ]`, 10 for `{ }`.
    pub fn data_points(self) -> i32 {
        match self {
            CursorMove::Back => -1,
            CursorMove::Forward => 1,
            CursorMove::LongBack => -10,
            CursorMove::LongForward => 10,
        }
    }

    /// The grid points a map's cursor moves (columns, rows): `[ ]` along x, `{ }` along y.
    pub fn grid_step(self) -> (i32, i32) {
        match self {
            CursorMove::Back => (-1, 0),
            CursorMove::Forward => (1, 0),
            CursorMove::LongBack => (0, -1),
            CursorMove::LongForward => (0, 1),
        }
    }
}
