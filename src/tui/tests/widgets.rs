//! The ranges charts are drawn over, and the status panel's packing and scrolling.

use crate::tui::charts::range::{bounds, frames};
use crate::tui::charts::{Axis, Plot, Scale, Series};
use crate::tui::view::status::{pack, visible};

fn axis(unit: &'static str, scale: Scale) -> Axis {
    Axis {
        label: "v".into(),
        unit,
        scale,
    }
}

fn series(points: &[(f64, f64)]) -> Series {
    Series {
        name: "s".into(),
        points: points.to_vec(),
    }
}

#[test]
fn bounds_span_the_finite_values_and_never_collapse() {
    assert_eq!(bounds([3.0, -1.0, f64::NAN, 2.0].into_iter()), [-1.0, 3.0]);
    assert_eq!(bounds(std::iter::empty()), [0.0, 1.0]);
    assert_eq!(bounds([f64::INFINITY].into_iter()), [0.0, 1.0]);
    // a flat curve: 5 % around the value, or 1 around 0
    assert_eq!(bounds([2.0, 2.0].into_iter()), [1.9, 2.1]);
    assert_eq!(bounds([0.0].into_iter()), [-1.0, 1.0]);
}

#[test]
fn overlays_do_not_set_the_y_range_but_markers_and_pins_do() {
    let mut plot = Plot::new(
        axis("N/m", Scale::Linear),
        axis("", Scale::Linear),
        vec![
            series(&[(1.0, 0.2), (2.0, 0.3)]),
            series(&[(0.5, 50.0), (3.0, 60.0)]),
        ],
    );
    plot.focus = 1;
    plot.markers = Some(series(&[(1.5, 0.1)]));
    let f = &frames(std::slice::from_ref(&plot), &[], false)[0];
    assert_eq!(f.x, [0.5, 3.0], "x spans the overlay too");
    assert_eq!(f.y, [0.1, 0.3]);
    let mut pin = plot.clone();
    pin.series[0].points = vec![(1.0, 0.4)];
    let pins = [std::slice::from_ref(&pin)];
    let f = &frames(std::slice::from_ref(&plot), &pins, false)[0];
    assert_eq!(f.y, [0.1, 0.4], "a pin stays in view");
}

#[test]
fn a_log_axis_drops_values_at_or_below_zero() {
    let plot = Plot::new(
        axis("N/m", Scale::Log),
        axis("m", Scale::Linear),
        vec![series(&[(0.0, 1.0), (100.0, 1e-6), (1e5, 2e-6)])],
    );
    let f = &frames(std::slice::from_ref(&plot), &[], false)[0];
    assert_eq!(f.x, [2.0, 5.0]);
    assert_eq!(f.y, [1e-6, 2e-6]);
}

#[test]
fn the_y_toggle_gives_log_for_positive_data_and_symlog_for_both_signs() {
    let positive = Plot::new(
        axis("s", Scale::Linear),
        axis("m", Scale::Linear),
        vec![series(&[(0.0, 1e-6), (1.0, 1e-9)])],
    );
    let f = &frames(std::slice::from_ref(&positive), &[], true)[0];
    assert_eq!(f.y_scale, Scale::Log);
    assert_eq!(f.y, [-9.0, -6.0]);
    // c from -1 um/s to +10 nm/s: linear within +-1 nm/s, a tenth of the smaller branch
    let both = Plot::new(
        axis("", Scale::Log),
        axis("m/s", Scale::Linear),
        vec![series(&[(1.0, -1e-6), (10.0, 1e-8)])],
    );
    let f = &frames(std::slice::from_ref(&both), &[], true)[0];
    assert_eq!(f.y_scale, Scale::SymLog(1e-9));
    // and back: a chart that is log by default toggles to linear
    let mut log = positive.clone();
    log.y.scale = Scale::Log;
    let f = &frames(std::slice::from_ref(&log), &[], true)[0];
    assert_eq!(f.y_scale, Scale::Linear);
}

fn items(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
}

#[test]
fn packing_never_splits_a_value() {
    let lines = pack(
        &items(&["a = 311 um", "b = 299 um", "Q2 = 5.00 kN/m"]),
        24,
        "",
    );
    assert_eq!(lines, ["a = 311 um  b = 299 um", "Q2 = 5.00 kN/m"]);
    let lines = pack(
        &items(&["1: kh 1.571", "1/beta 288 s", "c -275 nm/s"]),
        26,
        "   ",
    );
    assert_eq!(lines, ["1: kh 1.571  1/beta 288 s", "   c -275 nm/s"]);
}

#[test]
fn the_selected_harmonic_stays_in_view() {
    let blocks: Vec<Vec<String>> = (0..6).map(|n| vec![format!("{n}")]).collect();
    assert_eq!(visible(&blocks, None, 10), (0, 6));
    assert_eq!(visible(&blocks, None, 2), (0, 2));
    assert_eq!(visible(&blocks, Some(1), 2), (0, 2));
    assert_eq!(visible(&blocks, Some(4), 2), (3, 2));
    assert_eq!(visible(&blocks, Some(5), 2), (4, 2));
    assert_eq!(visible(&blocks, Some(5), 0), (5, 0));
}
