//! The height map's group of the form: a generated surface's keys set with the checks of
//! `--set`, `r` for a new seed (one undo step), a measured surface's file, grid and lengths shown
//! and refused with the reason, and the panel's title saying which surface it is.

use ratatui::crossterm::event::KeyCode;

use super::*;
use crate::physics::spatial::surface::{Amplitude, SelfAffine, SurfaceSource};
use crate::tui::app::Mode;
use crate::tui::form;

/// The generator's parameters of the preset's surface.
fn generator(app: &App) -> SelfAffine {
    match &app.doc.preset.spatial.surface.as_ref().unwrap().source {
        SurfaceSource::SelfAffine(p) => *p,
        other => panic!("{other:?}"),
    }
}

/// The surface's rows: (heading, symbol, value as shown).
fn surface_rows(app: &App) -> Vec<(String, String, String)> {
    let preset = &app.doc.preset;
    app.rows()
        .iter()
        .filter(|r| r.param().key.starts_with("spatial.surface."))
        .map(|r| {
            (
                form::heading(preset, r),
                r.param().symbol.to_string(),
                form::show(preset, r),
            )
        })
        .collect()
}

fn refused(app: &App, words: &str) {
    let m = app.ui.message.as_ref().expect("a message");
    assert!(m.error && m.text.contains(words), "{}", m.text);
}

#[test]
fn a_generated_surface_is_a_group_of_its_keys_set_as_set_sets_them() {
    let mut app = solved("rough-thin-layer.toml");
    let rows = surface_rows(&app);
    let shown: Vec<(&str, &str)> = rows
        .iter()
        .map(|(_, s, v)| (s.as_str(), v.as_str()))
        .collect();
    // the preset's keys: H = 0.8, 20 nm, 250 um, 60 um, 1 mm x 1 mm, 64 nodes, seed 7
    assert_eq!(
        shown,
        [
            ("H", "0.8"),
            ("h rms", "20.0 nm"),
            ("lam_r", "250 um"),
            ("lam_s", "60.0 um"),
            ("Lx", "1.00 mm"),
            ("Ly", "1.00 mm"),
            ("grid", "64"),
            ("seed", "7"),
        ]
    );
    assert!(rows.iter().all(|(h, ..)| h == "generated rough surface"));
    // a height map solves on its own grid: no spatial.grid row
    assert!(!app.rows().iter().any(|r| r.param().key == "spatial.grid"));

    // a nudge generates the surface again (one undo step)
    let before = app.doc.preset.clone();
    select(&mut app, "H", None);
    press(&mut app, KeyCode::Right);
    assert_eq!(generator(&app).hurst, 0.85);
    assert_ne!(app.doc.preset.spatial.surface, before.spatial.surface);
    press(&mut app, KeyCode::Char('u'));
    assert_eq!(app.doc.preset, before);

    // typed values meet the refusals of --set spatial.surface.hurst=1.5 (tests/cli)
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "1.5");
    press(&mut app, KeyCode::Enter);
    refused(&app, "hurst = 1.5: must be in (0, 1]");
    press(&mut app, KeyCode::Esc);
    assert_eq!(app.doc.preset, before);
    select(&mut app, "lam_s", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "300 um");
    press(&mut app, KeyCode::Enter);
    refused(&app, "is longer than rolloff_wavelength");
    press(&mut app, KeyCode::Esc);
    assert_eq!(app.doc.preset, before);
    select(&mut app, "grid", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "2048");
    press(&mut app, KeyCode::Enter);
    refused(&app, "more than the 1024 x 1024");
    press(&mut app, KeyCode::Esc);
    assert_eq!(app.doc.preset, before);
    // the same value through --set gives the same surface
    select(&mut app, "h rms", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "30 nm");
    press(&mut app, KeyCode::Enter);
    let set = before
        .with_settings(&["spatial.surface.rms_height=30nm"])
        .unwrap();
    assert_eq!(app.doc.preset.spatial.surface, set.spatial.surface);
    assert_eq!(generator(&app).amplitude, Amplitude::RmsHeight(30e-9));
}

#[test]
fn r_draws_a_new_seed_in_one_undo_step() {
    let mut tui = solved("rough-thin-layer.toml");
    let before = tui.doc.preset.clone();
    let undo = tui.doc.undo.len();
    let commands = press(&mut tui, KeyCode::Char('r'));
    assert_eq!(commands.len(), 1, "a new solve");
    let seed = generator(&tui).seed;
    assert_ne!(seed, 7);
    assert!(seed < 1_000_000);
    assert_eq!(tui.doc.undo.len(), undo + 1);
    let m = tui.ui.message.as_ref().unwrap();
    assert!(
        m.text.starts_with(&format!("seed 7 -> {seed}")),
        "{}",
        m.text
    );
    // the same spectrum's parameters, another surface
    let now = generator(&tui);
    assert_eq!(SelfAffine { seed: 7, ..now }, generator_of(&before));
    assert_ne!(tui.doc.preset.spatial.surface, before.spatial.surface);
    // the same presses give the same seeds: the seed is drawn from the current one
    let mut again = app("rough-thin-layer.toml");
    press(&mut again, KeyCode::Char('r'));
    assert_eq!(generator(&again).seed, seed);
    press(&mut tui, KeyCode::Char('u'));
    assert_eq!(tui.doc.preset, before);
    assert_eq!(tui.doc.undo.len(), undo);
}

fn generator_of(preset: &crate::preset::Preset) -> SelfAffine {
    match &preset.spatial.surface.as_ref().unwrap().source {
        SurfaceSource::SelfAffine(p) => *p,
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_measured_surface_shows_its_file_grid_and_lengths_and_keeps_them() {
    let mut app = solved("ground-profile.toml");
    let rows = surface_rows(&app);
    let shown: Vec<(&str, &str)> = rows
        .iter()
        .map(|(_, s, v)| (s.as_str(), v.as_str()))
        .collect();
    // presets/ground-profile.toml: a 1024-point profile over 2 mm
    assert_eq!(
        shown,
        [
            ("file", "ground-profile.csv"),
            ("Lx", "2.00 mm"),
            ("Ly", "0 m"),
            ("grid", "1024 x 1"),
        ]
    );
    assert!(
        rows.iter()
            .all(|(h, ..)| h == "measured surface (from the file)")
    );
    let kept = app.doc.preset.clone();
    for label in ["file", "grid", "Lx", "Ly"] {
        select(&mut app, label, None);
        for code in [KeyCode::Enter, KeyCode::Right] {
            press(&mut app, code);
            refused(&app, "is from the file ground-profile.csv");
            assert_eq!(app.ui.mode, Mode::Normal);
            assert_eq!(app.doc.preset, kept);
        }
    }
    // r is the generated surface's
    press(&mut app, KeyCode::Char('r'));
    refused(&app, "is for a generated rough surface");
    assert_eq!(app.doc.preset, kept);
}

#[test]
fn the_surface_group_on_screen() {
    let mut rough = solved("rough-thin-layer.toml");
    select(&mut rough, "seed", None);
    let s = screen(&rough, 80, 24, PLAIN);
    assert!(s.contains("spatial: generated surface"), "{s}");
    assert!(s.contains("+/- r x"), "{s}");
    insta::assert_snapshot!("surface_group_generated_80x24", s);
    insta::assert_snapshot!(
        "surface_group_generated_120x40",
        screen(&rough, 120, 40, PLAIN)
    );
    let mut profile = solved("ground-profile.toml");
    select(&mut profile, "grid", None);
    let s = screen(&profile, 80, 24, PLAIN);
    assert!(s.contains("spatial: measured surface"), "{s}");
    assert!(s.contains("+/- x"), "{s}");
    insta::assert_snapshot!("surface_group_measured_80x24", s);
    insta::assert_snapshot!(
        "surface_group_measured_120x40",
        screen(&profile, 120, 40, PLAIN)
    );
}
