//! The picker: every description shown whole, presets listed by folder and file, typed text
//! that finds presets or opens a typed path, and what opening one leaves of the last one.

use super::update::message;
use super::*;
use crate::tui::app::Mode;

#[test]
fn the_picker_shows_every_description_whole() {
    // every line of each bundled preset's wrapped description is on screen at one of the
    // scroll positions PgDn reaches; at 120x40 each fits without scrolling
    let Msg::PresetsListed(entries) = crate::tui::effects::list_presets(&Places::default()) else {
        panic!()
    };
    for (w, h) in [(80u16, 24u16), (120, 40)] {
        let mut app = app("polymer-coating.toml");
        app.ui.screen = ratatui::layout::Rect::new(0, 0, w, h);
        update(&mut app, Msg::PresetsListed(entries.clone()));
        for (i, entry) in entries.iter().enumerate() {
            let mut seen: Vec<String> = Vec::new();
            for _ in 0..20 {
                let s = screen(&app, w, h, PLAIN);
                seen.extend(
                    s.lines()
                        .map(|l| l.trim_matches('"').trim_matches(['│', ' ']).to_string()),
                );
                press(&mut app, KeyCode::PageDown);
            }
            let width = (w.min(100) - 2) as usize;
            for line in crate::tui::view::picker::lines(entry, width) {
                let line = line.to_string();
                assert!(
                    seen.iter().any(|s| s == line.trim_end()),
                    "{w}x{h} {}: not shown: {line}",
                    entry.source
                );
            }
            let last = crate::tui::view::picker::last(&entries, i, "", app.ui.screen);
            assert!(w < 120 || last == 0, "{}: scrolls at 120x40", entry.source);
            press(&mut app, KeyCode::Down);
            // the next preset's description starts at its top
            let next = matches!(app.ui.mode, Mode::Picker { scroll: 0, .. });
            assert!(next || i + 1 == entries.len());
        }
    }
}

#[test]
fn presets_are_listed_by_folder_and_by_their_file_and_name() {
    // a saved copy of a bundled preset keeps the bundled name: the list says which file it is
    let mine = tempfile::tempdir().unwrap();
    let shared = tempfile::tempdir().unwrap();
    let text = crate::preset::BUNDLED[1].text;
    std::fs::write(mine.path().join("my lab.toml"), text).unwrap();
    std::fs::write(mine.path().join("broken.toml"), "schema = ").unwrap();
    std::fs::write(shared.path().join("week3.toml"), text).unwrap();
    let places = Places {
        presets: Some(mine.path().to_path_buf()),
        // a folder named twice (and the personal one among the shared) is listed once
        shared: vec![
            shared.path().into(),
            shared.path().into(),
            mine.path().into(),
        ],
        ..Places::default()
    };
    let Msg::PresetsListed(entries) = crate::tui::effects::list_presets(&places) else {
        panic!()
    };
    let titled = |folder: &str| -> Vec<String> {
        (entries.iter())
            .filter(|e| e.folder.starts_with(folder))
            .map(|e| e.title.clone())
            .collect()
    };
    let name = bundled("hertz-check.toml").name;
    assert!(titled("bundled").contains(&format!("hertz-check.toml: {name}")));
    assert_eq!(titled("shared"), [format!("week3.toml: {name}")]);
    let shared_heading = format!("shared: {}", mine.path().display());
    assert!(!entries.iter().any(|e| e.folder == shared_heading));
    assert_eq!(
        titled("your presets"),
        [
            "broken.toml: (unreadable)".to_string(),
            format!("my lab.toml: {name}")
        ]
    );
}

#[test]
fn typed_text_finds_presets_and_a_typed_path_opens_its_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("week3.toml");
    std::fs::write(&path, crate::preset::BUNDLED[1].text).unwrap();
    let mut app = app("polymer-coating.toml");
    update(
        &mut app,
        crate::tui::effects::list_presets(&Places::default()),
    );
    for c in "STRIP-WINK".chars() {
        press(&mut app, KeyCode::Char(c));
    }
    let Mode::Picker {
        entries,
        selected,
        filter,
        ..
    } = &app.ui.mode
    else {
        panic!()
    };
    assert_eq!(filter, "STRIP-WINK");
    assert_eq!(
        entries[*selected].source,
        "bundled: thin-strip-winkler.toml"
    );
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains("open a preset: STRIP-WINK_ (1 found)"), "{s}");
    // End and Home move among those found only
    press(&mut app, KeyCode::End);
    press(&mut app, KeyCode::Home);
    let Mode::Picker {
        entries, selected, ..
    } = &app.ui.mode
    else {
        panic!()
    };
    assert_eq!(
        entries[*selected].source,
        "bundled: thin-strip-winkler.toml"
    );
    // a text that finds nothing says so, and Enter says what to type
    for c in "zz".chars() {
        press(&mut app, KeyCode::Char(c));
    }
    assert!(screen(&app, 80, 24, PLAIN).contains("no preset found"));
    assert!(press(&mut app, KeyCode::Enter).is_empty());
    assert!(
        message(&app).starts_with("no preset matches \"STRIP-WINKzz\""),
        "{}",
        message(&app)
    );
    // a path is read, then opened
    update(
        &mut app,
        crate::tui::effects::list_presets(&Places::default()),
    );
    for c in path.display().to_string().chars() {
        press(&mut app, KeyCode::Char(c));
    }
    assert_eq!(
        press(&mut app, KeyCode::Enter),
        [Command::ReadPreset(path.clone())]
    );
    update(&mut app, crate::tui::effects::read_preset(path.clone()));
    assert_eq!(app.doc.path.as_ref(), Some(&path));
    assert_eq!(app.doc.preset, bundled("hertz-check.toml"));
}

/// Opens the bundled preset whose file `file` names through the picker, its solve delivered.
fn open_bundled(app: &mut App, file: &str) {
    update(app, crate::tui::effects::list_presets(&Places::default()));
    type_text(app, file);
    let commands = press(app, KeyCode::Enter);
    assert_eq!(
        app.doc.source.as_deref(),
        Some(&*format!("bundled: {file}"))
    );
    settle(app, commands);
}

#[test]
fn opening_a_preset_turns_the_cursors_off_and_keeps_the_pins() {
    // the pressure map's cell cursor of a spatial preset
    let mut app = solved("dispersion.toml");
    press(&mut app, KeyCode::Char('x'));
    assert!(app.ui.map_cell.is_some());
    open_bundled(&mut app, "polymer-coating.toml");
    assert_eq!(app.ui.map_cell, None);
    // the chart cursor of a plane preset, with a pin on its chart
    let chart = app.ui.chart;
    press(&mut app, KeyCode::Char('x'));
    press(&mut app, KeyCode::Char('c'));
    assert!(app.ui.cursor.is_some());
    assert_eq!(app.ui.pins_of(chart).len(), 1);
    open_bundled(&mut app, "hertz-check.toml");
    assert_eq!(app.ui.cursor, None);
    assert_eq!(app.ui.pins_of(chart).len(), 1);
    // no readout of the last preset's chart is left in the status
    let s = screen(&app, 80, 24, PLAIN);
    assert!(!s.contains("cursor "), "{s}");
}
