//! A save marks the edited copy in its name and description; the results on screen answer the
//! same inputs, so they stay current: not dimmed, not "solving…", not labelled by the old name.

use ratatui::crossterm::event::KeyCode;

use super::*;
use crate::tui::on_screen::{OnScreen, on_screen};

#[test]
fn the_results_stay_current_after_a_save_renames_the_edited_copy() {
    let dir = tempfile::tempdir().unwrap();
    let places = Places {
        presets: Some(dir.path().to_path_buf()),
        ..Places::default()
    };
    let mut app = App::new(bundled("polymer-coating.toml"), None, places);
    let cmds = app.start();
    settle(&mut app, cmds);
    select(&mut app, "mu", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "0.25");
    let cmds = press(&mut app, KeyCode::Enter);
    settle(&mut app, cmds);
    assert!(matches!(on_screen(&app), OnScreen::Current(_, false)));
    press(&mut app, KeyCode::Char('s'));
    let cmds = press(&mut app, KeyCode::Enter);
    assert!(
        matches!(cmds.as_slice(), [Command::Save { .. }]),
        "{cmds:?}"
    );
    assert!(app.doc.preset.name.ends_with("(edited)"));
    assert!(
        matches!(on_screen(&app), OnScreen::Current(_, false)),
        "{:?}",
        on_screen(&app)
    );
    let s = screen(&app, 120, 40, PLAIN);
    assert!(
        !s.contains("solving") && !s.contains("[\"Steel punch"),
        "{s}"
    );
}
