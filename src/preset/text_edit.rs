//! A preset's text as its author wrote it, with only the values that changed rewritten: the
//! comments, the order of the keys, the layout and the untouched values stay byte for byte
//! (`toml_edit`); a changed value keeps the unit its old value was written in (`as_written`),
//! a value without one is written in SI units as `to_toml` writes it.

use toml_edit::{ArrayOfTables, DocumentMut, Item, Table, TableLike, Value};

use crate::preset::as_written::in_unit_of;
use crate::preset::{Preset, to_toml};

/// `text` (which reads as `before`) with the values where `after` differs from `before`
/// rewritten, keys `after` has that the text lacks added, and keys `after` no longer has
/// removed; None when `text` is not TOML.
pub(super) fn edited(text: &str, before: &Preset, after: &Preset) -> Option<String> {
    let mut doc: DocumentMut = text.parse().ok()?;
    let old: DocumentMut = to_toml(before).parse().ok()?;
    let new: DocumentMut = to_toml(after).parse().ok()?;
    merge(doc.as_table_mut(), old.as_table(), new.as_table(), 0);
    Some(doc.to_string())
}

/// Carries the differences between `old` and `new` (both as `to_toml` writes them) into
/// `target`, the author's table that reads as `old`.
fn merge(target: &mut dyn TableLike, old: &dyn TableLike, new: &dyn TableLike, depth: usize) {
    for (key, item) in new.iter() {
        let was = old.get(key);
        if was.is_some_and(|w| same(w, item)) {
            continue;
        }
        match target.get_mut(key) {
            Some(at) => rewrite(at, was, item, depth),
            None => {
                target.insert(key, added(item, depth));
            }
        }
    }
    let gone: Vec<String> = (old.iter())
        .filter(|(key, _)| new.get(key).is_none())
        .map(|(key, _)| key.to_string())
        .collect();
    for key in gone {
        target.remove(&key);
    }
}

/// Rewrites the author's item `at` (which reads as `was`) to read as `new`.
fn rewrite(at: &mut Item, was: Option<&Item>, new: &Item, depth: usize) {
    let was_table = was.and_then(Item::as_table_like);
    if let (Some(target), Some(old), Some(fresh)) =
        (at.as_table_like_mut(), was_table, new.as_table_like())
    {
        return merge(target, old, fresh, depth + 1);
    }
    let was_array = was.and_then(Item::as_array_of_tables);
    if let (Some(target), Some(old), Some(fresh)) = (
        at.as_array_of_tables_mut(),
        was_array,
        new.as_array_of_tables(),
    ) {
        return merge_arrays(target, old, fresh);
    }
    let was_value = was.and_then(Item::as_value);
    match (at.as_value_mut(), new.as_value()) {
        (Some(target), Some(fresh)) => {
            let mut value = like(target, was_value, fresh);
            *value.decor_mut() = target.decor().clone();
            *target = value;
        }
        _ => *at = new.clone(),
    }
}

/// An array of tables (the harmonics) table by table; tables beyond the author's are added,
/// the author's beyond the new ones removed.
fn merge_arrays(target: &mut ArrayOfTables, old: &ArrayOfTables, new: &ArrayOfTables) {
    for (i, fresh) in new.iter().enumerate() {
        match (target.get_mut(i), old.get(i)) {
            (Some(at), Some(was)) => merge(at, was, fresh, 2),
            _ => target.push(fresh.clone()),
        }
    }
    while target.len() > new.len() {
        target.remove(target.len() - 1);
    }
}

/// The new value written like the author's: a number in the unit of the author's text when
/// there was one (`as_written`), else as `to_toml` writes it.
fn like(author: &Value, was: Option<&Value>, new: &Value) -> Value {
    let in_unit = match (
        author.as_str(),
        was.and_then(Value::as_float),
        new.as_float(),
    ) {
        (Some(text), Some(was), Some(value)) => in_unit_of(text, was, value),
        _ => None,
    };
    in_unit.map_or_else(|| new.clone(), Value::from)
}

/// A key the author's text lacks (left to its default), as added at `depth` (0: the top): a
/// table within a section is written inline, as the bundled presets write a sweep.
fn added(item: &Item, depth: usize) -> Item {
    match item {
        Item::Table(table) if depth > 0 => {
            Item::Value(Value::InlineTable(table.clone().into_inline_table()))
        }
        _ => item.clone(),
    }
}

/// Whether two items as `to_toml` writes them hold the same values.
fn same(a: &Item, b: &Item) -> bool {
    if let (Some(x), Some(y)) = (a.as_table_like(), b.as_table_like()) {
        return x.len() == y.len() && x.iter().all(|(k, v)| y.get(k).is_some_and(|w| same(v, w)));
    }
    if let (Some(x), Some(y)) = (a.as_array_of_tables(), b.as_array_of_tables()) {
        return x.len() == y.len() && x.iter().zip(y.iter()).all(|(s, t)| same_tables(s, t));
    }
    match (a.as_value(), b.as_value()) {
        (Some(x), Some(y)) => x.to_string().trim() == y.to_string().trim(),
        _ => false,
    }
}

fn same_tables(a: &Table, b: &Table) -> bool {
    a.len() == b.len() && a.iter().all(|(k, v)| b.get(k).is_some_and(|w| same(v, w)))
}
