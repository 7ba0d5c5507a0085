//! The chart widget's ranges and ticks, and the status panel's packing and scrolling.

use crate::tui::charts::{Axis, Plot, Series};
use crate::tui::view::chart::{bounds, ticks, x_bounds, y_bounds};
use crate::tui::view::status::{pack, visible};

fn axis(unit: &'static str, log: bool) -> Axis {
    Axis {
        label: "v".into(),
        unit,
        log,
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
fn overlays_do_not_set_the_y_range_but_markers_do() {
    let plot = Plot {
        x: axis("N/m", false),
        y: axis("", false),
        series: vec![
            series(&[(1.0, 0.2), (2.0, 0.3)]),
            series(&[(0.5, 50.0), (3.0, 60.0)]),
        ],
        focus: 1,
        markers: Some(series(&[(1.5, 0.1)])),
    };
    assert_eq!(x_bounds(&plot), [0.5, 3.0], "x spans the overlay too");
    assert_eq!(y_bounds(&plot), [0.1, 0.3]);
}

#[test]
fn a_log_axis_drops_values_at_or_below_zero_and_ticks_in_real_values() {
    let plot = Plot {
        x: axis("N/m", true),
        y: axis("m", false),
        series: vec![series(&[(0.0, 1.0), (100.0, 1e-6), (1e5, 2e-6)])],
        focus: 1,
        markers: None,
    };
    let xb = x_bounds(&plot);
    assert_eq!(xb, [2.0, 5.0]);
    assert_eq!(y_bounds(&plot), [1e-6, 2e-6]);
    // 10^2, 10^3.5, 10^5 N/m
    assert_eq!(ticks(xb, &plot.x), ["100 N/m", "3.16 kN/m", "100 kN/m"]);
    assert_eq!(
        ticks([1e-6, 2e-6], &plot.y),
        ["1.00 um", "1.50 um", "2.00 um"]
    );
}

#[test]
fn ticks_without_a_unit_are_plain_numbers() {
    assert_eq!(
        ticks([0.25, 0.35], &axis("", false)),
        ["0.25", "0.3", "0.35"]
    );
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
