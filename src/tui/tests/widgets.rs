//! The ranges charts are drawn over, the status panel's packing and scrolling, and wrapping.

use crate::phrase::Phrase;
use crate::tui::charts::range::{bounds, frames};
use crate::tui::charts::{Axis, Plot, Scale, Series};
use crate::tui::view::status_values::visible;
use crate::tui::view::wrap;
use crate::tui::view::wrapping::pack;

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

/// The plane pressure chart with a < 0 (default preset, h = 10 um): the mark "-a" lies right of
/// the tip. Each label covers its own mark's column, or is left out.
#[test]
fn mark_labels_sit_over_their_marks_or_are_left_out() {
    use crate::tui::charts::Mark;
    use crate::tui::view::axis::mark_labels;
    let mark = |at: f64, label: &str| Mark {
        at,
        label: label.into(),
    };
    let mut plot = Plot::new(
        axis("m", Scale::Linear),
        axis("Pa", Scale::Linear),
        vec![series(&[(0.0, 1.0), (1.0, 2.0)])],
    );
    let area = ratatui::layout::Rect::new(0, 0, 40, 5);
    let labels = |plot: &Plot| -> Vec<(u16, String)> {
        mark_labels(&frames(std::slice::from_ref(plot), &[], false)[0], area)
    };
    let owned = |l: &[(u16, &str)]| -> Vec<(u16, String)> {
        l.iter().map(|&(s, t)| (s, t.to_string())).collect()
    };
    // columns: round(f * 39): 0.5 -> 20, 0.52 -> 20, 0.7 -> 27
    plot.x_marks = vec![mark(0.7, "-a"), mark(0.5, "tip")];
    assert_eq!(labels(&plot), owned(&[(19, "tip"), (26, "-a")]));
    // on the same column: both named in one label over it (neither left out nor drawn apart
    // from its mark)
    plot.x_marks = vec![mark(0.52, "-a"), mark(0.5, "tip")];
    assert_eq!(labels(&plot), owned(&[(17, "-a/tip")]));
    // a column apart: one label covering both, the left mark's first (two marks a column apart
    // both labelled); columns 0.5 -> 20, 0.54 -> 21
    plot.x_marks = vec![mark(0.54, "complete"), mark(0.5, "now")];
    assert_eq!(labels(&plot), owned(&[(14, "now/complete")]));
    // at the right end: shifted left to end with the plot, still over its mark
    plot.x_marks = vec![mark(1.0, "complete")];
    assert_eq!(labels(&plot), owned(&[(32, "complete")]));
    // "now" three columns right of a validity mark: both named, "now" not left out (as on
    // thin-strip-winkler's sweep at 80x24); columns 0.4 -> 16, 0.48 -> 19
    plot.x_marks = vec![mark(0.4, "narrow ok>"), mark(0.48, "now")];
    assert_eq!(labels(&plot), owned(&[(7, "narrow ok>"), (18, "now")]));
}

/// Spatial chart 4 of the default preset: the curve's legend text carries a remark with its own
/// "=", and mu* - mu is 1e-7. The readout names the curve alone and gives the digits the axis
/// "mu* - 0.3 (x1e-7)" resolves (it read "mu*, contact complete from pbar = 428 kPa = 0.3").
#[test]
fn the_readout_names_the_curve_alone_with_the_digits_of_its_axis() {
    use crate::tui::charts::readout::{readout, value};
    let mut s = series(&[(1.0, 0.3 - 1e-7), (2.0, 0.3 - 3e-8)]);
    s.name = "mu*, contact complete from pbar = 428 kPa".into();
    let plot = Plot::new(axis("Pa", Scale::Linear), axis("", Scale::Linear), vec![s]);
    let f = frames(std::slice::from_ref(&plot), &[], false);
    // the span 7e-8: a hundredth of it is 7e-10, ten decimals
    assert_eq!(readout(&f, 1.0)[1], "mu* = 0.2999999700");
    assert_eq!(readout(&f, 0.0)[1], "mu* = 0.2999999000");
    // a wide axis keeps six significant digits
    assert_eq!(value(0.31234567, "", Some(0.05)), "0.312346");
    assert_eq!(value(0.31234567, "", None), "0.312346");
}

#[test]
fn wrapping_keeps_a_number_with_its_unit_and_a_key_pair_whole() {
    // contact-lost's description at 80 columns read "(5" / "MPa)", the help "[" / "] move"
    let text = "under a quarter of its mean pressure (5 MPa). at h = 1 um; chart, [ ] move it";
    let lines = wrap(text, 38);
    assert_eq!(lines[0], "under a quarter of its mean pressure");
    assert_eq!(lines[1], "(5 MPa). at h = 1 um; chart, [ ] move");
    // nor "name = value unit" (the spatial status read "after t" / "= 62.6 s")
    assert_eq!(wrap("to h = 1 um", 8), ["to", "h = 1 um"]);
    assert_eq!(
        wrap("complete after t = 62.6 s (simulated), then:", 16),
        ["complete after", "t = 62.6 s", "(simulated),", "then:"]
    );
    assert_eq!(
        wrap("I-J residual < 1e-14", 16),
        ["I-J", "residual < 1e-14"]
    );
    // a name of two symbols stays whole (the picker read "wear (k" / "m = 0.11)")
    assert_eq!(wrap("wear (k m = 0.11)", 12), ["wear", "(k m = 0.11)"]);
    assert_eq!(wrap("chart, [ ] move", 8), ["chart,", "[ ] move"]);
    // a word that is no unit, after a number, may start the next line
    assert_eq!(wrap("k = 2 is", 5), ["k = 2", "is"]);
}

#[test]
fn wrapping_keeps_a_group_name_and_a_short_parenthesis_whole() {
    // thin-strip-winkler's sweep cursor in groups at 80x24 read "(narrow: P = 10.0" / "kN/m):"
    let cursor = "cursor P/(m R) = 1.159e-3 (narrow: P = 10.0 kN/m):";
    assert_eq!(
        wrap(cursor, 48),
        ["cursor P/(m R) = 1.159e-3", "(narrow: P = 10.0 kN/m):"]
    );
    // in the status, the item too long for a line is wrapped between its pieces (as the sweep's
    // readout writes it), the rest packed after it
    let cursor = Phrase::whole("cursor P/(m R) = 1.159e-3").then("(narrow: P = 10.0 kN/m):");
    assert_eq!(
        pack(&[cursor, Phrase::from("mu* narrow = 0.303962")], 48, "  "),
        [
            "cursor P/(m R) = 1.159e-3",
            "  (narrow: P = 10.0 kN/m):",
            "  mu* narrow = 0.303962"
        ]
    );
    // the library's two-word group names (coating-thickness-sweep's notes read "mu" / "chi")
    assert_eq!(
        wrap("depends on mu chi and k m only", 13),
        ["depends on", "mu chi and", "k m only"]
    );
    // a parenthesis longer than half the line may break, never inside "name = value unit"
    assert_eq!(
        wrap("cursor (narrow: P = 10.0 kN/m):", 20),
        ["cursor (narrow:", "P = 10.0 kN/m):"]
    );
}

#[test]
fn a_parenthesis_of_prose_wraps_as_prose() {
    // rubber-running-in's notes: no line left half empty by an aside without a value
    assert_eq!(
        wrap("drawn apart (grey, or dots without colour); the", 24),
        ["drawn apart (grey, or", "dots without colour);", "the"]
    );
}

#[test]
fn a_text_longer_than_its_rows_ends_after_a_whole_clause_or_word() {
    use super::{ASCII, PLAIN};
    use crate::physics::plane::Model;
    use crate::physics::plane::strip_check::StripCheck;
    use crate::physics::plane::validity::Deviation;
    use crate::tui::view::wrap_within;
    use crate::tui::view::wrapping::lines_of;
    // polymer-coating's status in groups at 80x24 ended "..., mu* - mu" (its value cut away)
    let measured = Deviation {
        contact_width: 9e-4,
        mu_star_minus_mu: 9e-4,
    };
    let check = StripCheck::Measured(measured).describe(Model::Wide);
    assert_eq!(
        check.to_string(),
        "wide: contact width within 0.1 %, mu* - mu within 0.1 % of the exact strip solution"
    );
    assert_eq!(
        wrap_within(&check, 48, 1, PLAIN),
        ["wide: contact width within 0.1 %, …"]
    );
    assert_eq!(
        wrap_within(&check, 48, 1, ASCII),
        ["wide: contact width within 0.1 %, ..."]
    );
    assert_eq!(wrap_within(&check, 48, 2, PLAIN), lines_of(&check, 48));
    assert!(wrap_within(&check, 48, 0, PLAIN).is_empty());
    // no clause in the second half of the line: after the last whole word
    assert_eq!(
        wrap_within(&Phrase::words("one, two three four five six"), 20, 1, PLAIN),
        ["one, two three …"]
    );
    // a value is never cut from its unit: "0.1 %," is one piece
    assert_eq!(
        lines_of(&check, 31),
        [
            "wide: contact width within",
            "0.1 %, mu* - mu within 0.1 % of",
            "the exact strip solution"
        ]
    );
}
