//! The tick generator: distinct labels on linear axes whose span is 1e-12 to 1e12 of the values,
//! negative ranges, log and symmetric-log ranges; and the labels read as a user would.

use crate::tui::charts::Scale;
use crate::tui::charts::ticks::{Ticks, ticks};

fn labels(t: &Ticks) -> Vec<&str> {
    t.ticks.iter().map(|(_, l)| l.as_str()).collect()
}

/// Labels all different, positions increasing inside the range, between 2 and `max` of them.
fn check(t: &Ticks, range: [f64; 2], max: usize, what: &str) {
    let l = labels(t);
    assert!(t.ticks.len() >= 2, "{what}: {t:?}");
    assert!(t.ticks.len() <= max.max(2), "{what}: {t:?}");
    for (i, a) in l.iter().enumerate() {
        assert!(!l[..i].contains(a), "{what}: {a} twice in {t:?}");
    }
    let tol = 1e-9 * (range[1] - range[0]);
    for w in t.ticks.windows(2) {
        assert!(w[0].0 < w[1].0, "{what}: {t:?}");
    }
    for (p, _) in &t.ticks {
        assert!(
            (range[0] - tol..=range[1] + tol).contains(p),
            "{what}: {p} outside {range:?}"
        );
    }
}

/// Linear labels are numbers in a fixed ratio to the positions (the title's scale and offset).
fn truthful(t: &Ticks, what: &str) {
    let v: Vec<f64> = labels(t).iter().map(|l| l.parse().unwrap()).collect();
    let p: Vec<f64> = t.ticks.iter().map(|(p, _)| *p).collect();
    let ratio = (v[1] - v[0]) / (p[1] - p[0]);
    for i in 2..v.len() {
        let r = (v[i] - v[0]) / (p[i] - p[0]);
        // the positions of ticks 1e-12 apart at 0.3 are known to a few 1e-4 of their spacing
        assert!((r / ratio - 1.0).abs() < 1e-2, "{what}: {t:?}");
    }
    assert!(
        labels(t).iter().all(|l| l.len() <= 7),
        "{what}: labels too long {t:?}"
    );
}

#[test]
fn linear_labels_are_distinct_for_spans_from_1e_minus_12_to_1e12_of_the_values() {
    for centre in [0.3, -0.3, 7.5e3, -2e9, 1e-9, 42.0, 1.0] {
        for e in -12..=12 {
            let span = f64::abs(centre) * 10f64.powi(e);
            let range = [centre - 0.37 * span, centre + 0.63 * span];
            for unit in ["", "Pa", "m", "1/Pa"] {
                for max in [2, 3, 5, 8] {
                    let what = format!("{range:?} {unit} max {max}");
                    let t = ticks(range, Scale::Linear, "v", unit, max);
                    check(&t, range, max, &what);
                    truthful(&t, &what);
                }
            }
        }
    }
}

#[test]
fn negative_ranges_read_like_positive_ones() {
    let t = ticks([-86.7e-6, -43e-6], Scale::Linear, "x", "m", 5);
    assert_eq!(t.title, "x [um]");
    assert_eq!(labels(&t), ["-80", "-70", "-60", "-50"]);
    let t = ticks([-43e-6, 86.7e-6], Scale::Linear, "x", "m", 5);
    assert_eq!(labels(&t), ["-25", "0", "25", "50", "75"]);
}

#[test]
fn a_tiny_span_gets_an_offset_in_the_title() {
    // mu* varying in the 5th digit: plain ticks would all read "0.3"
    let t = ticks([0.299_951, 0.300_012], Scale::Linear, "mu*", "", 8);
    assert_eq!(t.title, "mu* - 0.3 (x1e-5)");
    assert_eq!(labels(&t), ["-4", "-3", "-2", "-1", "0", "1"]);
    // four significant digits are still plain numbers
    let t = ticks([0.2995, 0.3], Scale::Linear, "mu*", "", 3);
    assert_eq!(t.title, "mu*");
    assert_eq!(labels(&t), ["0.2996", "0.2998", "0.3000"]);
    // a pressure of 20 MPa varying by a kilopascal
    let t = ticks([20e6 - 900.0, 20e6 + 1100.0], Scale::Linear, "p", "Pa", 5);
    assert_eq!(t.title, "p - 20 MPa [kPa]");
    assert_eq!(labels(&t), ["-0.5", "0", "0.5", "1.0"]);
}

#[test]
fn log_labels_are_distinct_for_any_number_of_decades() {
    for a in [-15.0, -3.3, 0.0, 2.0, 7.7] {
        for decades in [0.01, 0.1, 0.3, 1.0, 2.0, 5.0, 12.0, 40.0, 200.0] {
            let range = [a, a + decades];
            for unit in ["", "N/m", "1/Pa"] {
                for max in [2, 3, 5, 8] {
                    let what = format!("log {range:?} {unit} max {max}");
                    check(&ticks(range, Scale::Log, "v", unit, max), range, max, &what);
                }
            }
        }
    }
    let t = ticks([2.0, 5.0], Scale::Log, "P", "N/m", 8);
    assert_eq!(t.title, "P [N/m] (log)");
    assert_eq!(labels(&t), ["100", "1k", "10k", "100k"]);
    // less than a decade: 1-2-5 within it
    let t = ticks([0.1, 0.8], Scale::Log, "kh", "", 8);
    assert_eq!(labels(&t), ["2", "5"]);
}

#[test]
fn symlog_labels_are_distinct_and_show_zero_and_both_signs() {
    for (lo, hi) in [
        (-1e-6, 1e-8),
        (-3e-9, 5e-3),
        (-1.0, 1.0),
        (2e-12, 7e-6),
        (-7e5, -3.0),
    ] {
        let Scale::SymLog(c) = Scale::symlog_for([lo, hi].into_iter()) else {
            panic!()
        };
        let scale = Scale::SymLog(c);
        let range = [scale.to_plot(lo).unwrap(), scale.to_plot(hi).unwrap()];
        for max in [2, 3, 4, 5, 8, 12] {
            let what = format!("symlog {lo}..{hi} c {c} max {max}");
            let t = ticks(range, scale, "c", "m/s", max);
            check(&t, range, max, &what);
            if lo < 0.0 && hi > 0.0 {
                assert!(labels(&t).contains(&"0"), "{what}: {t:?}");
            }
        }
    }
    // the drift velocity of rubber-backward-drift's kind: both branches labelled
    let scale = Scale::SymLog(1e-9);
    let range = [scale.to_plot(-1e-6).unwrap(), scale.to_plot(1e-7).unwrap()];
    let t = ticks(range, scale, "c", "m/s", 9);
    assert_eq!(t.title, "c [m/s] (symlog)");
    assert_eq!(labels(&t), ["-1u", "-100n", "-10n", "0", "10n", "100n"]);
    // dispersion.toml's drift velocity on 8 rows (at most 4 ticks): -275 nm/s to +45 nm/s with
    // c = 1 nm/s (symlog_for: a tenth of the smaller branch). The zero line is labelled 0 (not
    // on the -1n row) and the positive branch has a tick of its own
    let range = [scale.to_plot(-3e-7).unwrap(), scale.to_plot(5e-8).unwrap()];
    let t = ticks(range, scale, "c", "m/s", 4);
    assert_eq!(labels(&t), ["-100n", "0", "50n"]);
    // rubber-backward-drift's: -1 um/s to +0.5 nm/s, c = 0.1 nm/s: 1-2-5 where decades leave the
    // positive side bare
    let scale = Scale::SymLog(1e-10);
    let range = [scale.to_plot(-1e-6).unwrap(), scale.to_plot(5e-10).unwrap()];
    let t = ticks(range, scale, "c", "m/s", 4);
    assert_eq!(labels(&t), ["-1u", "-10n", "0", "500p"]);
}

#[test]
fn scales_map_back_and_forth() {
    for scale in [Scale::Linear, Scale::Log, Scale::SymLog(1e-9)] {
        for v in [3e-10, 2.5e-7, 1.0, 4e5] {
            let p = scale.to_plot(v).unwrap();
            assert!((scale.value_at(p) / v - 1.0).abs() < 1e-12, "{scale:?} {v}");
        }
    }
    assert_eq!(Scale::Log.to_plot(0.0), None);
    assert_eq!(Scale::Log.to_plot(-1.0), None);
    assert_eq!(Scale::SymLog(1.0).to_plot(0.0), Some(0.0));
    assert!(Scale::SymLog(1.0).to_plot(-5.0).unwrap() < 0.0);
}

#[test]
fn a_constant_curve_gets_one_tick_at_its_value_and_stays_linear_under_y() {
    use ratatui::crossterm::event::KeyCode;

    use super::{PLAIN, app, press, screen, settle};
    use crate::tui::charts::{Chart, SpatialChart};
    // jgh-egg-box has no friction: mu*(t) = 0 all along (and the line mu = 0 on it); it sat
    // between ticks -1 and 1, and y put it between -5 and 5 on a symmetric-log axis
    let mut history = app("jgh-egg-box.toml");
    history.ui.chart = Chart::Spatial(SpatialChart::History);
    let cmds = history.start();
    settle(&mut history, cmds);
    for toggled in [false, true] {
        let s = screen(&history, 80, 24, PLAIN);
        assert!(s.contains("  0┤●****") || s.contains("   0┤●****"), "{s}");
        assert!(!s.contains("-1┤") && !s.contains("-5┤"), "{s}");
        if !toggled {
            press(&mut history, KeyCode::Char('y'));
        }
    }
    let said = history.ui.message.clone().unwrap().text;
    assert!(
        said.contains("A logarithmic") && said.contains("mu* stays linear (one value, 0)"),
        "{said}"
    );
    // mu* against pbar through partial contact: the solver's mu* scatters by 1e-20 around 0
    // (round-off of a frictionless contact); drawn at 0 on a "0" tick, not on an axis
    // "mu* (x1e-20)" that makes the round-off look like physics
    let mut curve = app("jgh-egg-box.toml");
    curve.ui.chart = Chart::Spatial(SpatialChart::MuStar);
    let cmds = curve.start();
    settle(&mut curve, cmds);
    let s = screen(&curve, 80, 24, PLAIN);
    assert!(s.contains("0┤****") && !s.contains("(x1e-"), "{s}");
}
