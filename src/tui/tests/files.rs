//! `update` for the actions that reach files (open, save, export) and for quitting.

use crate::preset::SaveTarget;
use ratatui::crossterm::event::KeyCode;

use super::update::message;
use super::*;
use crate::tui::app::{Mode, PickerEntry};
use crate::tui::text_field::TextField;

#[test]
fn o_lists_the_presets_and_asks_before_dropping_unsaved_edits() {
    let mut app = app("polymer-coating.toml");
    assert_eq!(
        press(&mut app, KeyCode::Char('o')),
        vec![Command::ListPresets]
    );
    let Msg::PresetsListed(entries) = crate::tui::effects::list_presets(&Places::default()) else {
        panic!()
    };
    update(&mut app, Msg::PresetsListed(entries.clone()));
    press(&mut app, KeyCode::Down);
    assert_eq!(press(&mut app, KeyCode::Enter).len(), 1);
    assert_eq!(app.doc.preset, bundled("hertz-check.toml"));
    // with an unsaved edit, opening asks
    select(&mut app, "E", None);
    press(&mut app, KeyCode::Right);
    update(&mut app, Msg::PresetsListed(entries.clone()));
    assert!(press(&mut app, KeyCode::Enter).is_empty());
    assert!(matches!(app.ui.mode, Mode::ConfirmOpen(_)));
    press(&mut app, KeyCode::Char('n'));
    assert_eq!(message(&app), "not opened: your edits stay");
    assert!(app.doc.dirty);
    update(&mut app, Msg::PresetsListed(entries));
    press(&mut app, KeyCode::Enter);
    assert_eq!(press(&mut app, KeyCode::Char('y')).len(), 1);
    assert_eq!(app.doc.preset, bundled("polymer-coating.toml"));
    assert!(!app.doc.dirty);
}

#[test]
fn the_picker_opens_on_the_preset_shown() {
    // dispersion.toml opened: o highlighted the first bundled preset (polymer-coating)
    let Msg::PresetsListed(entries) = crate::tui::effects::list_presets(&Places::default()) else {
        panic!()
    };
    let mut app = app("dispersion.toml");
    update(&mut app, Msg::PresetsListed(entries.clone()));
    let Mode::Picker { selected, .. } = &app.ui.mode else {
        panic!()
    };
    assert_eq!(entries[*selected].source, "bundled: dispersion.toml");
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains("bundled: dispersion.toml"), "{s}");
}

#[test]
fn a_broken_preset_in_the_picker_shows_its_error_and_keeps_the_state() {
    let mut app = app("polymer-coating.toml");
    let before = app.doc.preset.clone();
    let broken = PickerEntry {
        title: "(unreadable)".into(),
        source: "lab/zz.toml".into(),
        path: Some("lab/zz.toml".into()),
        preset: Err("lab/zz.toml:3: missing field `poisson_ratio`".into()),
        folder: "lab".into(),
    };
    update(&mut app, Msg::PresetsListed(vec![broken]));
    assert!(press(&mut app, KeyCode::Enter).is_empty());
    assert!(app.ui.message.as_ref().unwrap().error);
    assert_eq!(
        message(&app),
        "lab/zz.toml:3: missing field `poisson_ratio`"
    );
    assert_eq!(app.doc.preset, before);
}

#[test]
fn s_proposes_the_files_name_and_never_overwrites_without_asking() {
    let mut app = app("polymer-coating.toml");
    app.places.presets = Some("/data/presets".into());
    app.doc.path = Some("/data/presets/my lab 1.toml".into());
    press(&mut app, KeyCode::Char('s'));
    assert_eq!(app.ui.mode, Mode::SaveAs(TextField::proposed("my lab 1")));
    // where it goes is said before anything is written
    let s = screen(&app, 120, 40, PLAIN);
    assert!(
        s.contains("save as: [my lab 1]_ -> /data/presets/my lab 1.toml"),
        "{s}"
    );
    // typing replaces the proposal, never appends to it
    type_text(&mut app, "my lab 1");
    let cmds = press(&mut app, KeyCode::Enter);
    let target = SaveTarget {
        path: "/data/presets/my lab 1.toml".into(),
        create_folder: true,
    };
    let [
        Command::Save {
            target: t,
            overwrite: false,
            ..
        },
    ] = cmds.as_slice()
    else {
        panic!("{cmds:?}")
    };
    assert_eq!(*t, target);
    update(&mut app, Msg::SaveExists(target.clone()));
    assert_eq!(app.ui.mode, Mode::ConfirmOverwrite(target.clone()));
    assert!(press(&mut app, KeyCode::Char('n')).is_empty());
    assert_eq!(message(&app), "not saved");
    update(&mut app, Msg::SaveExists(target.clone()));
    let cmds = press(&mut app, KeyCode::Char('y'));
    assert!(matches!(
        cmds.as_slice(),
        [Command::Save {
            overwrite: true,
            ..
        }]
    ));
    select(&mut app, "E", None);
    press(&mut app, KeyCode::Right);
    let saved = Box::new(app.doc.preset.clone());
    let said = "saved /data/presets/my lab 1.toml".to_string();
    update(&mut app, Msg::Saved(target.clone(), saved, Ok(said)));
    assert!(!app.doc.dirty);
    assert_eq!(message(&app), "saved /data/presets/my lab 1.toml");
    update(
        &mut app,
        Msg::Saved(
            target,
            Box::new(bundled("hertz-check.toml")),
            Err("disk full".into()),
        ),
    );
    assert_eq!(message(&app), "not saved: disk full");
}

#[test]
fn a_preset_saved_after_a_nudge_holds_the_clean_value() {
    // polymer-coating.toml has E = 3.0e9; one nudge is x1.1 (form::STEPS), and 3e9 * 1.1 is
    // 3300000000.0000005 in f64: the file must say 3.3 GPa as the student reads it on the form
    let mut app = app("polymer-coating.toml");
    select(&mut app, "E", None);
    press(&mut app, KeyCode::Right);
    assert_eq!(app.doc.preset.material.youngs_modulus, 3.3e9);
    let dir = tempfile::tempdir().unwrap();
    let target = SaveTarget {
        path: dir.path().join("nudged.toml"),
        create_folder: false,
    };
    let saved =
        crate::tui::effects::save(target, Box::new(app.doc.preset.clone()), false, None, &[]);
    assert!(matches!(saved, Msg::Saved(_, _, Ok(_))), "{saved:?}");
    let text = std::fs::read_to_string(dir.path().join("nudged.toml")).unwrap();
    assert!(
        text.lines().any(|l| l == "youngs_modulus = 3300000000.0"),
        "{text}"
    );
}

#[test]
fn e_exports_the_visible_chart_and_reports_where() {
    let mut app = solved("polymer-coating.toml");
    let cmds = press(&mut app, KeyCode::Char('e'));
    let (path, text) = exported(&cmds);
    assert_eq!(path.to_str(), Some("wearlab-pressure-and-shear.csv"));
    assert!(text.contains("\npressure q2,"));
    update(&mut app, Msg::Exported(path.clone(), Ok(())));
    assert_eq!(
        message(&app),
        "exported the chart to wearlab-pressure-and-shear.csv"
    );
}

#[test]
fn an_export_never_overwrites_a_file_without_asking() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("wearlab-pressure-and-shear.svg");
    std::fs::write(&path, "mine").unwrap();
    let mut app = solved("polymer-coating.toml");
    let cmds = press(&mut app, KeyCode::Char('E'));
    let [Command::Export { text, .. }] = cmds.as_slice() else {
        panic!("{cmds:?}")
    };
    // the loop's I/O finds the file and asks
    let report = crate::tui::effects::export(path.clone(), text.clone(), false);
    update(&mut app, report);
    assert!(matches!(app.ui.mode, Mode::ConfirmExport(_)));
    let s = screen(&app, 80, 24, PLAIN);
    assert!(
        s.contains("wearlab-pressure-and-shear.svg exists: overwrite? y/n"),
        "{s}"
    );
    press(&mut app, KeyCode::Char('n'));
    assert_eq!(message(&app), "not exported: the file stays as it was");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "mine");
    // asked again, yes writes it
    update(
        &mut app,
        crate::tui::effects::export(path.clone(), text.clone(), false),
    );
    let cmds = press(&mut app, KeyCode::Char('y'));
    let [
        Command::Export {
            path: p,
            text: t,
            overwrite: true,
        },
    ] = cmds.as_slice()
    else {
        panic!("{cmds:?}")
    };
    update(
        &mut app,
        crate::tui::effects::export(p.clone(), t.clone(), true),
    );
    assert!(std::fs::read_to_string(&path).unwrap().starts_with("<svg"));
    assert!(message(&app).starts_with("exported the chart to"));
}

#[test]
fn q_quits_and_asks_when_there_are_unsaved_edits() {
    let mut app = app("polymer-coating.toml");
    assert_eq!(press(&mut app, KeyCode::Char('q')), vec![Command::Quit]);
    press(&mut app, KeyCode::Right);
    assert!(press(&mut app, KeyCode::Char('q')).is_empty());
    assert_eq!(app.ui.mode, Mode::ConfirmQuit(Box::new(Mode::Normal)));
    press(&mut app, KeyCode::Char('n'));
    assert_eq!(app.ui.mode, Mode::Normal);
    press(&mut app, KeyCode::Char('q'));
    assert_eq!(press(&mut app, KeyCode::Char('y')), vec![Command::Quit]);
}

#[test]
fn ctrl_c_quits_from_every_mode() {
    let target = SaveTarget {
        path: "x.toml".into(),
        create_folder: false,
    };
    let entry = PickerEntry {
        title: "t".into(),
        source: "s".into(),
        path: None,
        preset: Ok(bundled("hertz-check.toml")),
        folder: "lab".into(),
    };
    let modes = [
        Mode::Normal,
        Mode::Editing("3".into()),
        Mode::Choosing(0),
        Mode::Help(3),
        Mode::Picker {
            entries: vec![entry.clone()],
            selected: 0,
            scroll: 0,
            filter: String::new(),
        },
        Mode::SaveAs("my lab".into()),
        Mode::ConfirmOverwrite(target),
        Mode::ConfirmOpen(Box::new(entry)),
        Mode::ConfirmQuit(Box::new(Mode::Normal)),
    ];
    for mode in modes {
        let mut clean = app("polymer-coating.toml");
        clean.ui.mode = mode.clone();
        assert_eq!(ctrl(&mut clean, 'c'), vec![Command::Quit], "{mode:?}");
        // with unsaved edits it asks, and a second Ctrl-C quits
        let mut edited = app("polymer-coating.toml");
        edited.doc.dirty = true;
        edited.ui.mode = mode.clone();
        let first = ctrl(&mut edited, 'c');
        if !matches!(mode, Mode::ConfirmQuit(_)) {
            assert!(first.is_empty(), "{mode:?}");
            assert_eq!(edited.ui.mode, Mode::ConfirmQuit(Box::new(mode.clone())));
            // answering no goes back to what was being done, the typed text included
            press(&mut edited, KeyCode::Char('n'));
            assert_eq!(edited.ui.mode, mode, "no returns");
            ctrl(&mut edited, 'c');
        }
        assert_eq!(ctrl(&mut edited, 'c'), vec![Command::Quit], "{mode:?}");
    }
}
