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
    /// This curve (drawn over it: a lower index) covers it, or all but a tenth of it.
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
    let (shown, covered) = overlap(a, b, size);
    shown == 0 && covered > 0
}

/// The cells of `a` that are not cells of `b`, and those that are.
fn overlap(a: &Raster, b: &Raster, size: (u16, u16)) -> (usize, usize) {
    let all = (0..size.0).flat_map(|c| (0..size.1).map(move |r| (c, r)));
    all.filter(|&(c, r)| a.occupied(c, r))
        .fold((0, 0), |(s, v), (c, r)| {
            if b.occupied(c, r) {
                (s, v + 1)
            } else {
                (s + 1, v)
            }
        })
}

/// Whether `a` lies under `b`: at most a tenth of its cells show (polymer-coating's strip curve
/// showed one cell beside the wide model's, a 75-degree dispersion curve one of forty).
fn under(a: &Raster, b: &Raster, size: (u16, u16)) -> bool {
    let (shown, covered) = overlap(a, b, size);
    covered > 0 && shown * 10 <= shown + covered
}

/// For each horizontal reference line of the frame (drawn only on cells without data), the curve
/// it lies under where data covers its whole row in a plot area `size` (None: it shows).
pub fn marks_under(frame: &Frame, style: RenderOptions, size: (u16, u16)) -> Vec<Option<usize>> {
    let own: Vec<Raster> = (frame.plot.series.iter())
        .map(|s| cells(frame, style, size, &[&s.points]))
        .collect();
    crate::tui::view::axis::y_mark_rows(frame, size.1)
        .into_iter()
        .map(|r| {
            let covering = |j: usize| (0..size.0).filter(|&c| own[j].occupied(c, r)).count();
            let all = (0..size.0).all(|c| own.iter().any(|o| o.occupied(c, r)));
            all.then(|| (0..own.len()).max_by_key(|&j| covering(j)))
                .flatten()
        })
        .collect()
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
                .find(|&j| under(&own[i], &own[j], size))
                .map(Hidden::Under)
        })
        .collect()
}
