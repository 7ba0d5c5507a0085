//! An edit of the preset: the one way a change reaches the document (locked lesson keys refused,
//! one undo step, a new solve asked), for the keys of the form and for a fit's result alike.

use crate::materials::CUSTOM;
use crate::preset::{Key, Preset};
use crate::tui::app::{App, Command, UNDO_DEPTH};
use crate::tui::form::{self, Change};
use crate::tui::lesson_keys;

/// Replaces the preset by an edited one (undo keeps the old) and asks for a solve.
pub fn apply(app: &mut App, next: Preset, change: Change) -> Vec<Command> {
    if next == app.doc.preset {
        return Vec::new();
    }
    if let Some(key) = app.doc.preset.locked_change(&next) {
        app.complain(lesson_keys::why_locked(app, key));
        return Vec::new();
    }
    let previous = std::mem::replace(&mut app.doc.preset, next);
    // a notice about an earlier step no longer applies
    app.ui.message = None;
    if let Some(left) = left_the_table(&previous, &app.doc.preset, &change) {
        app.say(left);
    } else if let Some(chosen) = chosen_from_the_table(&app.doc.preset, &change) {
        app.say(chosen);
    } else if app.ui.expanded {
        // the form is hidden: say what changed
        app.say(format!("{}: {} -> {}", change.name, change.from, change.to));
    }
    app.doc.undo.push((previous, change));
    if app.doc.undo.len() > UNDO_DEPTH {
        app.doc.undo.remove(0);
    }
    app.doc.dirty = app.doc.edited();
    app.fit();
    vec![app.request()]
}

/// Where the material row took a table entry: what it set, and the entry's typical friction and
/// wear against steel, which it leaves to the friction and wear rows (they belong to the pair,
/// not to the material).
fn chosen_from_the_table(after: &Preset, change: &Change) -> Option<String> {
    let row = Key::of("material.name")?;
    if change.name != row.symbol() {
        return None;
    }
    let entry = crate::materials::named(&form::show(after, &row))?;
    let strengths = [
        (entry.strength.yield_strength, ", Y"),
        (entry.strength.hardness, ", H"),
    ];
    let set: String = (strengths.iter())
        .filter(|(value, _)| value.is_some())
        .map(|(_, name)| *name)
        .collect();
    Some(format!(
        "{}: E, nu{set} set; typical against steel, dry: mu {}, k {} mm3/Nm (not set: type them \
         on the mu and k rows)",
        entry.name,
        crate::units::format_si(entry.friction, ""),
        crate::units::format_si(entry.wear_rate / crate::materials::MM3_PER_NM, ""),
    ))
}

/// Where a value typed over a table material's (E, nu, Y or H: each is the table's) makes the
/// material row read "custom": the change and why the row changed.
fn left_the_table(before: &Preset, after: &Preset, change: &Change) -> Option<String> {
    let row = Key::of("material.name")?;
    let (was, now) = (form::show(before, &row), form::show(after, &row));
    (was != now && now == CUSTOM && change.name != row.symbol()).then(|| {
        format!(
            "{}: {} -> {}, not the table's {was}: the material row reads {CUSTOM}",
            change.name, change.from, change.to
        )
    })
}
