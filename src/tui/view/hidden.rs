//! Curves that cannot be seen on a plot: every cell of one lies under its own dim parts (its
//! model fails over the whole range) or under a curve drawn over it (the same values), so that
//! the legend says so instead of naming a sample that appears nowhere.

use crate::tui::charts::range::{Frame, plotted};
use crate::tui::view::raster::Raster;
use crate::tui::view::theme::RenderOptions;

/// Why a curve cannot be seen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hidden {
    /// Its dim parts (drawn over every curve) cover it: its model fails over the whole range.
    Fails,
    /// This curve (drawn over it: a lower index) covers it.
    Under(usize),
}

/// The cells of the curves `points` in a raster of the plot area `width` x `height`.
fn cells(
    frame: &Frame,
    style: RenderOptions,
    size: (u16, u16),
    curves: &[&[(f64, f64)]],
) -> Raster {
    let mut raster = Raster::new(size.0, size.1, style.braille());
    let (xs, ys) = (frame.plot.x.scale, frame.y_scale);
    let frac = |v: f64, [lo, hi]: [f64; 2]| (v - lo) / (hi - lo);
    for points in curves {
        let fitted: Vec<(f64, f64)> = plotted(points, xs, ys)
            .into_iter()
            .map(|(x, y)| (frac(x, frame.x), frac(y, frame.y)))
            .collect();
        raster.line(&fitted, style.series_ink(0));
    }
    raster
}

/// Whether every cell of `a` is a cell of `b` (and `a` has one).
fn within(a: &Raster, b: &Raster, size: (u16, u16)) -> bool {
    let all = (0..size.0).flat_map(|c| (0..size.1).map(move |r| (c, r)));
    let mut any = false;
    for (c, r) in all {
        if a.occupied(c, r) {
            if !b.occupied(c, r) {
                return false;
            }
            any = true;
        }
    }
    any
}

/// For each curve of the frame, why it cannot be seen in a plot area `size` (None: it shows).
pub fn hidden(frame: &Frame, style: RenderOptions, size: (u16, u16)) -> Vec<Option<Hidden>> {
    let series = &frame.plot.series;
    let own: Vec<Raster> = series
        .iter()
        .map(|s| cells(frame, style, size, &[&s.points]))
        .collect();
    (0..series.len())
        .map(|i| {
            let dims: Vec<&[(f64, f64)]> = (frame.plot.dim.iter())
                .filter(|(owner, _)| *owner == i)
                .map(|(_, d)| d.points.as_slice())
                .collect();
            if !dims.is_empty() && within(&own[i], &cells(frame, style, size, &dims), size) {
                return Some(Hidden::Fails);
            }
            (0..i)
                .find(|&j| within(&own[i], &own[j], size))
                .map(Hidden::Under)
        })
        .collect()
}
