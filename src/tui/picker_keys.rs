//! The keys of the preset picker (`o`): typed text finds presets by their file, name or folder;
//! ↑↓ Home End choose among those found; PgUp PgDn scroll the description; Enter opens the
//! highlighted one, or the file a typed path names.

use std::path::PathBuf;

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use crate::tui::actions::open;
use crate::tui::app::{App, Command, Mode, PickerEntry, found};
use crate::tui::prompt_keys::{self, Prompt, PromptAction};
use crate::tui::view::windows_on_last_screen;

/// A key in the picker.
pub fn key(
    app: &mut App,
    key: KeyEvent,
    entries: Vec<PickerEntry>,
    selected: usize,
    scroll: u16,
    mut filter: String,
) -> Vec<Command> {
    let action = prompt_keys::prompt_action(Prompt::Picker, &key);
    let shown = found(&entries, &filter);
    let at = shown.iter().position(|&i| i == selected);
    let before = selected;
    let mut selected = selected;
    let mut scroll = scroll;
    match action {
        Some(PromptAction::Accept) => {
            app.ui.mode = Mode::Normal;
            if let Some(path) = typed_path(app, &filter, at.is_some()) {
                return vec![Command::ReadPreset(path)];
            }
            return match at.and_then(|_| entries.get(selected).cloned()) {
                Some(entry) => chosen(app, entry),
                None => {
                    app.complain(format!(
                        "no preset matches \"{filter}\": type less of its name, or a path to a \
                         .toml file (e.g. ~/labs/week3.toml)"
                    ));
                    Vec::new()
                }
            };
        }
        Some(PromptAction::Cancel) => {
            app.ui.mode = Mode::Normal;
            return Vec::new();
        }
        Some(PromptAction::PageUp | PromptAction::PageDown) => {
            // the description scrolls, stopping where its last line is at the bottom
            let last = crate::tui::view::picker::last(
                &entries,
                selected,
                &filter,
                windows_on_last_screen(app),
            );
            scroll = prompt_keys::scrolled(&key, scroll, last).unwrap_or(scroll);
        }
        Some(PromptAction::Up | PromptAction::Down | PromptAction::First | PromptAction::Last) => {
            let last = shown.len().saturating_sub(1);
            let to = match (action, at) {
                (Some(PromptAction::First), _) | (_, None) => 0,
                (Some(PromptAction::Last), _) => last,
                (Some(PromptAction::Up), Some(k)) => k.saturating_sub(1),
                (_, Some(k)) => (k + 1).min(last),
            };
            selected = shown.get(to).copied().unwrap_or(selected);
        }
        Some(PromptAction::Backspace) => {
            filter.pop();
        }
        _ => {
            let chord = key
                .modifiers
                .intersects(KeyModifiers::CONTROL | KeyModifiers::ALT);
            if let (KeyCode::Char(c), false) = (key.code, chord) {
                filter.push(c);
            }
        }
    }
    // the highlight stays on a preset the text still finds, else goes to the first it finds
    let now = found(&entries, &filter);
    if !now.contains(&selected) {
        selected = now.first().copied().unwrap_or(selected);
    }
    // another preset's description starts at its top
    if selected != before {
        scroll = 0;
    }
    app.ui.mode = Mode::Picker {
        entries,
        selected,
        scroll,
        filter,
    };
    Vec::new()
}

/// The file a typed text names: a path ("~/labs/week3.toml", "labs/x.toml"), `~` standing for
/// the home folder, or a file name ("week3.toml") that no listed preset matches; None for text
/// that finds presets.
fn typed_path(app: &App, filter: &str, found_one: bool) -> Option<PathBuf> {
    let typed = filter.trim();
    let path_like = typed.contains('/') || (typed.ends_with(".toml") && !found_one);
    if !path_like {
        return None;
    }
    match (typed.strip_prefix("~/"), &app.places.home) {
        (Some(rest), Some(home)) => Some(home.join(rest)),
        _ => Some(PathBuf::from(typed)),
    }
}

/// Opens a chosen entry: a file that cannot be read says why and keeps the state; unsaved edits
/// ask first.
pub fn chosen(app: &mut App, entry: PickerEntry) -> Vec<Command> {
    match &entry.preset {
        Err(why) => {
            app.complain(why.clone());
            Vec::new()
        }
        Ok(_) if app.doc.dirty => {
            app.ui.mode = Mode::ConfirmOpen(Box::new(entry));
            Vec::new()
        }
        Ok(_) => open(app, entry),
    }
}
