//! A preset saved under a typed name: the path the name resolves to, and an edited preset marked
//! as a copy (part of `update`: pure; the loop writes the file).

use crate::preset::resolve_save_path;
use crate::tui::app::{App, Command, Document, Mode};
use crate::tui::form;

/// The save prompt's text accepted: the file it names (`resolve_save_path`), and the edited
/// preset marked as a copy before it is saved; or why the name is refused.
pub fn accept(app: &mut App, buffer: String) -> Vec<Command> {
    let places = &app.places;
    match resolve_save_path(&buffer, places.home.as_deref(), places.presets.as_deref()) {
        Ok(target) => {
            app.ui.mode = Mode::Normal;
            with_provenance(&mut app.doc);
            vec![Command::Save {
                target,
                preset: Box::new(app.doc.preset.clone()),
                overwrite: false,
                origin: app.doc.origin(),
            }]
        }
        Err(why) => {
            app.complain(why);
            Vec::new()
        }
    }
}

/// Marks an edited preset before it is saved, so that a copy never passes for the original:
/// its description starts with what changed since it was opened (`Edited from "<name>": mu 0.1
/// -> 0.3.`) and that the text after it was written for the values as opened, and its name ends
/// in "(edited)".
fn with_provenance(doc: &mut Document) {
    let changed = form::differences(&doc.opened, &doc.preset);
    if changed.is_empty() {
        return;
    }
    let line = format!(
        "Edited from \"{}\": {}.\n{STALE}",
        doc.opened.name,
        changed.join(", ")
    );
    let p = &mut doc.preset;
    if !p.description.starts_with(&line) {
        p.description = format!("{line}\n{}", p.description);
    }
    if !p.name.ends_with(EDITED) {
        p.name = format!("{}{EDITED}", p.name);
    }
}

/// What an edited copy's description says of the text it keeps from the original.
pub const STALE: &str =
    "The notes below were written for the values as opened and may not hold for these.";

/// The end of an edited copy's name.
const EDITED: &str = " (edited)";
