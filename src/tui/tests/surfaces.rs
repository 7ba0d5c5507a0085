//! A height-map punch in the explorer: the generated 2-D surface and the measured-like profile
//! open, their screens read as a student would read them (the map, the status with the surface's
//! statistics, the spectrum before and after the running-in), and the harmonics' keys say why
//! they do nothing on a map.

use crate::engine::{Output, Progress};
use ratatui::crossterm::event::KeyCode;

use super::partial::on;
use super::*;
use crate::tui::charts::{Chart, Figure, SpatialChart};

/// (q, C) pairs of a spectrum curve.
type Points = Vec<(f64, f64)>;

/// The spectrum chart's curves: (as given, at t).
fn spectra(app: &App) -> (Points, Points) {
    let answer = app.solve.shown.as_ref().expect("solved");
    let Ok(Figure::Plots(plots)) = Chart::Spatial(SpatialChart::Spectrum).build(answer) else {
        panic!("no spectrum")
    };
    let s = &plots[0].series;
    (s[0].points.clone(), s[1].points.clone())
}

#[test]
fn a_generated_map_opens_with_its_statistics_and_its_spectrum() {
    let app = solved("rough-thin-layer.toml");
    let answer = app.solve.shown.as_ref().expect("solved");
    let Output::Surface(Ok(out)) = &answer.output else {
        panic!("{:?}", answer.output)
    };
    assert!(answer.complete);
    let c = out.cell.as_ref().unwrap();
    assert!(matches!(c.progress, Progress::Done { .. }));
    // the description's figures: 20 nm as given, 5.21 nm at t = 0.2 s (20 nm e^(-beta t) with
    // beta = 6.73 1/s on this thin layer)
    let s = screen(&app, 120, 40, PLAIN);
    assert!(s.contains("rms height = 5.21 nm (t = 0: 20.0 nm)"), "{s}");
    insta::assert_snapshot!("rough_map_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("rough_map_120x40", s);
    let spectrum = on(&app, SpatialChart::Spectrum);
    insta::assert_snapshot!("rough_spectrum_80x24", screen(&spectrum, 80, 24, PLAIN));
    insta::assert_snapshot!("rough_spectrum_120x40", screen(&spectrum, 120, 40, PLAIN));
    // on the thin layer every mode decays at nearly one rate: the rms falls to 5.21/20 = 0.26 and
    // the spectrum shifts down nearly as a whole (e^(-2 beta t) = 0.068 at beta = 6.73 1/s); the
    // shortest waves (kh up to 0.21, the bins past the cutoff's 1.05e5 rad/m from the grid's
    // diagonal) keep up to 0.24 of theirs
    let (given, at) = spectra(&spectrum);
    for ((q0, c0), (q, c)) in given.iter().zip(&at) {
        assert_eq!(q0, q);
        assert!((0.05..0.3).contains(&(c / c0)), "q = {q}: {}", c / c0);
    }
    // the dispersion chart says why it draws nothing
    let dispersion = on(&app, SpatialChart::Dispersion);
    assert!(screen(&dispersion, 120, 40, PLAIN).contains("wave vector at every node"));
}

#[test]
fn a_profile_runs_in_and_its_short_waves_go_first() {
    let app = on(&solved("ground-profile.toml"), SpatialChart::Spectrum);
    let s = screen(&app, 120, 40, PLAIN);
    // tests/presets/surfaces.rs: 249 nm as given (the description's 0.25 um), 79.2 nm at t = 2 s,
    // complete from 0.883 s
    assert!(s.contains("rms height = 79.2 nm (t = 0: 249 nm)"), "{s}");
    assert!(s.contains("complete after t = 883"), "{s}");
    insta::assert_snapshot!("profile_spectrum_120x40", s);
    insta::assert_snapshot!("profile_spectrum_80x24", screen(&app, 80, 24, PLAIN));
    // the first bin (the longest waves) falls 6.55-fold, the last (4 um waves) by 6.8e24
    let (given, at) = spectra(&app);
    let ratio = |i: usize| given[i].1 / at[i].1;
    assert!((ratio(0) / 6.55 - 1.0).abs() < 0.01, "{}", ratio(0));
    assert!(ratio(given.len() - 1) > 1e24, "{}", ratio(given.len() - 1));
    let history = on(&app, SpatialChart::History);
    insta::assert_snapshot!("profile_history_80x24", screen(&history, 80, 24, PLAIN));
}

#[test]
fn the_harmonics_keys_say_a_map_has_none() {
    let mut profile = app("ground-profile.toml");
    let kept = profile.doc.preset.clone();
    for key in ['+', '-'] {
        press(&mut profile, KeyCode::Char(key));
        let m = profile.ui.message.as_ref().unwrap();
        assert!(
            m.error && m.text.contains("no harmonics"),
            "{key}: {}",
            m.text
        );
        assert_eq!(profile.doc.preset, kept);
    }
}
