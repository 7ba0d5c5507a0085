//! The save prompt (`s`) at its edges: a name that is a folder, a hidden file, a Tab, a long
//! reason, a folder that cannot be written; and the picker (`o`) over a preset folder with broken
//! files. Every refusal is said on screen, and the user's edits are never lost.

use std::path::{Path, PathBuf};

use ratatui::crossterm::event::KeyCode;

use super::update::message;
use super::*;
use crate::tui::app::Mode;
use crate::tui::text_field::TextField;

/// The screen's rows, each with its trailing blanks (and the test backend's quotes) removed.
fn rows(app: &App) -> Vec<String> {
    screen(app, 80, 24, PLAIN)
        .lines()
        .map(|l| l.trim_matches('"').trim_end().to_string())
        .collect()
}

/// The `n` rows over the keys' row as one text without blanks (a wrapped message joined again,
/// wherever its lines were broken).
fn bottom(app: &App, n: usize) -> String {
    let rows = rows(app);
    squeezed(&rows[rows.len() - 1 - n..rows.len() - 1].concat())
}

fn squeezed(text: &str) -> String {
    text.split_whitespace().collect()
}

/// An app with an unsaved edit, its save prompt open.
fn prompting() -> App {
    let mut app = app("polymer-coating.toml");
    app.places.presets = Some("/data/presets".into());
    select(&mut app, "E", None);
    press(&mut app, KeyCode::Right);
    press(&mut app, KeyCode::Char('s'));
    app
}

#[test]
fn a_name_that_is_a_folder_or_a_hidden_file_is_refused_on_screen() {
    let cases = [
        (
            "..",
            "'..' is a folder ('..' is the folder above): type a file name, e.g. ../lab.toml",
        ),
        (
            ".",
            "'.' is a folder ('.' is the folder itself): type a file name, e.g. lab.toml",
        ),
        (
            "labs/",
            "'labs/' is a folder (it ends in /): type a file name, e.g. labs/lab.toml",
        ),
        (
            ".toml",
            "'.toml' has no name before .toml (the file would be hidden): type one, e.g. lab.toml",
        ),
    ];
    for (typed, why) in cases {
        let mut app = prompting();
        let edited = app.doc.preset.clone();
        type_text(&mut app, typed);
        assert!(press(&mut app, KeyCode::Enter).is_empty(), "{typed}");
        assert_eq!(app.ui.mode, Mode::SaveAs(typed.into()), "the prompt stays");
        assert_eq!(message(&app), why);
        // the reason over the prompt, which keeps the text for a correction
        let shown = bottom(&app, 3);
        assert!(shown.contains(&squeezed(why)), "{typed}: {shown}");
        assert!(
            shown.contains(&squeezed(&format!("save as: {typed}_"))),
            "{shown}"
        );
        // a correction: the reason goes
        press(&mut app, KeyCode::Backspace);
        assert!(!bottom(&app, 3).contains(&squeezed(why)));
        assert_eq!(app.doc.preset, edited);
        assert!(app.doc.dirty);
    }
}

#[test]
fn a_tab_in_a_name_or_a_value_is_not_dropped_unsaid() {
    let mut app = prompting();
    type_text(&mut app, "lab");
    press(&mut app, KeyCode::Tab);
    assert_eq!(app.ui.mode, Mode::SaveAs("lab".into()));
    let why = "Tab is not typed: a file name holds no tabs, and wearlab does not complete \
               names: type the whole name";
    assert_eq!(message(&app), why);
    assert!(bottom(&app, 3).contains(&squeezed(why)));
    // a value's prompt says it on the message line
    let mut app = super::app("polymer-coating.toml");
    select(&mut app, "E", None);
    press(&mut app, KeyCode::Enter);
    press(&mut app, KeyCode::Tab);
    assert_eq!(message(&app), "Tab is not typed: a value holds no tabs");
    assert!(matches!(app.ui.mode, Mode::Editing(_)));
}

#[test]
fn a_long_reason_wraps_instead_of_being_cut() {
    // a path wider than the screen, then the reason after it
    let long = format!("/nowhere/{}/", "a-long-folder-name".repeat(4));
    let mut app = prompting();
    type_text(&mut app, &long);
    press(&mut app, KeyCode::Enter);
    let shown = bottom(&app, 5);
    let why = format!("'{long}' is a folder (it ends in /): type a file name");
    assert!(shown.contains(&squeezed(&why)), "{shown}");
    // a failed save's message: the file and the reason over two rows
    let mut app = super::app("polymer-coating.toml");
    let file = format!("/nowhere/{}.toml", "a-long-file-name".repeat(4));
    let target = crate::preset::SaveTarget {
        path: file.clone().into(),
        create_folder: false,
    };
    let why = format!("{file}: cannot write in the folder /nowhere: permission denied");
    let preset = Box::new(app.doc.preset.clone());
    update(&mut app, Msg::Saved(target, preset, Err(why.clone())));
    assert_eq!(bottom(&app, 2), squeezed(&format!("not saved: {why}")));
}

/// A folder this process cannot write in: a read-only one, or for a user the modes do not stop
/// (root), /sys; None where neither holds.
fn unwritable(dir: &Path) -> Option<PathBuf> {
    use std::os::unix::fs::PermissionsExt;
    let ro = dir.join("read-only");
    std::fs::create_dir(&ro).unwrap();
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o555)).unwrap();
    [ro, PathBuf::from("/sys")]
        .into_iter()
        .find(|d| d.is_dir() && std::fs::File::create(d.join("probe.toml")).is_err())
}

#[test]
fn a_folder_that_cannot_be_written_is_named_with_the_file_not_a_temporary_one() {
    let dir = tempfile::tempdir().unwrap();
    let Some(folder) = unwritable(dir.path()) else {
        eprintln!("skipped: every folder here can be written");
        return;
    };
    let path = folder.join("lab.toml");
    let target = crate::preset::SaveTarget {
        path: path.clone(),
        create_folder: false,
    };
    let preset = Box::new(bundled("polymer-coating.toml"));
    let Msg::Saved(_, _, Err(why)) = crate::tui::effects::save(target, preset, false, None, &[])
    else {
        panic!("saved in {}", folder.display())
    };
    assert_eq!(
        why,
        format!(
            "{}: cannot write in the folder {}: permission denied",
            path.display(),
            folder.display()
        )
    );
}

#[test]
fn broken_files_in_the_preset_folder_are_listed_with_their_errors_and_cost_no_edits() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("x.toml"), "schema = 1\nname = \"a\u{e9}=b\n").unwrap();
    std::fs::write(d.join("latin1.toml"), b"schema = 1\nname = \"caf\xe9\"\n").unwrap();
    std::fs::write(d.join("empty.toml"), "").unwrap();
    std::fs::create_dir(d.join("folder.toml")).unwrap();
    let fifo = std::ffi::CString::new(d.join("pipe.toml").to_str().unwrap()).unwrap();
    // SAFETY: mkfifo reads a valid C string
    assert_eq!(unsafe { libc::mkfifo(fifo.as_ptr(), 0o644) }, 0);
    std::fs::write(
        d.join("\u{e9}\u{1F600} lab.toml"),
        crate::preset::BUNDLED[1].text,
    )
    .unwrap();
    let mut app = app("polymer-coating.toml");
    app.places.presets = Some(d.to_path_buf());
    select(&mut app, "E", None);
    press(&mut app, KeyCode::Right);
    let edited = app.doc.preset.clone();
    let broken = [
        ("empty.toml", "missing key \"schema\""),
        ("folder.toml", "it is a folder"),
        ("latin1.toml", ":2: the file is not UTF-8 text"),
        ("pipe.toml", "a named pipe (FIFO)"),
        ("x.toml", ":2: a text in quotes is not closed"),
    ];
    for _ in 0..2 {
        assert_eq!(
            press(&mut app, KeyCode::Char('o')),
            vec![Command::ListPresets]
        );
        let listed = crate::tui::effects::list_presets(&app.places);
        update(&mut app, listed);
        let Mode::Picker { entries, .. } = app.ui.mode.clone() else {
            panic!("{:?}", app.ui.mode)
        };
        assert!(entries.iter().any(|e| {
            e.title
                .ends_with("lab.toml: Hertz check: frictionless, no wear, half-plane")
        }));
        for (file, why) in broken {
            let at = (entries.iter())
                .position(|e| e.path.as_deref() == Some(&d.join(file)))
                .unwrap_or_else(|| panic!("{file} not listed"));
            let Mode::Picker { selected, .. } = &mut app.ui.mode else {
                panic!()
            };
            *selected = at;
            let shown = rows(&app).join("\n");
            assert!(
                shown.contains(&format!("! {file}: (unreadable)")),
                "{shown}"
            );
            assert!(shown.contains("cannot be opened: "), "{shown}");
            let error = entries[at].preset.clone().unwrap_err();
            assert!(error.contains(why), "{file}: {error}");
            assert!(
                error.starts_with(&d.join(file).display().to_string()),
                "{error}"
            );
        }
        // opening a broken one says why and keeps the edits
        press(&mut app, KeyCode::Enter);
        assert_eq!(app.ui.mode, Mode::Normal);
        assert!(app.ui.message.as_ref().unwrap().error);
        assert!(message(&app).contains("a text in quotes is not closed"));
        assert_eq!(app.doc.preset, edited);
        assert!(app.doc.dirty);
    }
}

#[test]
fn an_edited_shared_or_bundled_preset_is_proposed_as_a_copy_in_your_folder() {
    // bundled, edited: "<file>-edited" in the user's folder
    let mut edited = prompting();
    edited.doc.source = Some("bundled: polymer-coating.toml".into());
    press(&mut edited, KeyCode::Esc);
    press(&mut edited, KeyCode::Char('s'));
    assert_eq!(
        edited.ui.mode,
        Mode::SaveAs(TextField::proposed("polymer-coating-edited"))
    );
    let s = screen(&edited, 120, 40, PLAIN);
    assert!(
        s.contains("-> /data/presets/polymer-coating-edited.toml"),
        "{s}"
    );
    // a shared file, unedited: its name, in the user's folder (not its own folder)
    let mut app = app("hertz-check.toml");
    app.places.presets = Some("/data/presets".into());
    app.doc.path = Some("/labs/shared/week3.toml".into());
    press(&mut app, KeyCode::Char('s'));
    assert_eq!(app.ui.mode, Mode::SaveAs(TextField::proposed("week3")));
    assert!(screen(&app, 120, 40, PLAIN).contains("-> /data/presets/week3.toml"));
}

#[test]
fn a_link_into_a_shared_folder_is_replaced_by_your_copy_and_the_original_stays() {
    let dir = tempfile::tempdir().unwrap();
    let (shared, mine) = (dir.path().join("shared"), dir.path().join("mine"));
    std::fs::create_dir_all(&shared).unwrap();
    std::fs::create_dir_all(&mine).unwrap();
    let original = shared.join("week3.toml");
    let text = crate::preset::BUNDLED[1].text;
    std::fs::write(&original, text).unwrap();
    let link = mine.join("week3.toml");
    std::os::unix::fs::symlink(&original, &link).unwrap();
    let target = crate::preset::SaveTarget {
        path: link.clone(),
        create_folder: true,
    };
    let preset = Box::new(bundled("polymer-coating.toml"));
    let saved =
        crate::tui::effects::save(target, preset, true, None, std::slice::from_ref(&shared));
    let Msg::Saved(_, _, Ok(said)) = saved else {
        panic!("{saved:?}")
    };
    assert!(said.contains("as your own copy"), "{said}");
    assert_eq!(std::fs::read_to_string(&original).unwrap(), text);
    assert!(!std::fs::symlink_metadata(&link).unwrap().is_symlink());
    assert_eq!(
        crate::preset::load(&link).unwrap().name,
        bundled("polymer-coating.toml").name
    );
}

#[test]
fn a_saved_edited_copy_says_what_was_edited_and_time_is_no_edit() {
    let mut spatial = app("contact-lost.toml");
    let mut app = app("polymer-coating.toml");
    let opened = app.doc.preset.clone();
    select(&mut app, "mu", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "0.4");
    press(&mut app, KeyCode::Enter);
    assert!(app.doc.dirty);
    // i says the description was written for other values
    press(&mut app, KeyCode::Char('i'));
    let about = screen(&app, 120, 40, PLAIN);
    assert!(
        about.contains("edited since opened (mu 0.3 -> 0.4)"),
        "{about}"
    );
    press(&mut app, KeyCode::Esc);
    press(&mut app, KeyCode::Char('s'));
    let cmds = press(&mut app, KeyCode::Enter);
    let [Command::Save { preset, .. }] = cmds.as_slice() else {
        panic!("{cmds:?}")
    };
    assert_eq!(preset.name, format!("{} (edited)", opened.name));
    let first = preset.description.lines().next().unwrap();
    assert_eq!(
        first,
        format!("Edited from \"{}\": mu 0.3 -> 0.4.", opened.name)
    );
    // the time of a spatial preset moves without an edit to save
    spatial.ui.playing = true;
    update(&mut spatial, Msg::Tick);
    assert!(spatial.doc.preset.spatial.time > 0.0 && !spatial.doc.dirty);
}
