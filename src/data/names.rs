//! The names a data file's columns may carry, one list for the reader, the fit and their messages:
//! the x column names a parameter the program can vary (a preset key such as `plane.load`, its
//! symbol `P`, or a word of the lab such as `load`), each measured column a quantity the program
//! computes (a name of `sweeps::quantity` such as `mu_star`, its symbol `mu*`, or a word such as
//! `mu` or `contact width`).

use crate::preset::{Key, Preset};
use crate::sweeps::QuantityKey;

/// Words of the lab for parameters, each with its preset key (those of the other problem are
/// skipped for a preset).
const PARAMETER_WORDS: &[(&str, &str)] = &[
    ("load", "plane.load"),
    ("normal load", "plane.load"),
    ("mean pressure", "spatial.mean_pressure"),
    ("nominal pressure", "spatial.mean_pressure"),
    ("time", "spatial.time"),
    ("sliding speed", "spatial.sliding_speed"),
    ("thickness", "material.thickness"),
    ("radius", "plane.radius"),
];

/// Words of the lab for quantities, each with its name in `sweeps::quantity`: a tribometer's
/// friction coefficient is the total one, mu*.
const QUANTITY_WORDS: &[(&str, &str)] = &[
    ("mu", "mu_star"),
    ("friction coefficient", "mu_star"),
    ("coefficient of friction", "mu_star"),
    ("contact width", "contact_width"),
    ("wear per pass", "tip_wear"),
    ("friction force", "tangential_force"),
    ("contact fraction", "contact.fraction"),
    ("max pressure", "max_pressure"),
];

/// `text` in lower case with `_` and runs of spaces as one space.
fn normal(text: &str) -> String {
    text.to_lowercase()
        .replace('_', " ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// The parameter an x column names, for this preset: a number of its problem that is not a count.
pub fn parameter(preset: &Preset, name: &str) -> Result<Key, String> {
    let wanted = normal(name);
    let by_word = PARAMETER_WORDS
        .iter()
        .find(|(word, _)| *word == wanted)
        .and_then(|(_, key)| preset.key(key).ok());
    let found = preset.key(name).ok().or(by_word).or_else(|| {
        Key::all(preset)
            .into_iter()
            .find(|k| k.symbol() == name.trim())
    });
    match found {
        Some(key) if key.param().limit().is_some() && !key.param().is_whole() => Ok(key),
        Some(key) => Err(format!(
            "the first column, '{name}', is {key}, which is not a number the program can vary"
        )),
        None => Err(format!(
            "the first column, '{name}', names no parameter the program can vary for a {} \
             preset: the first column is the x axis, one of {}",
            preset.problem.name(),
            parameter_list(preset)
        )),
    }
}

/// The quantity a measured column names, for this preset's problem and model.
pub fn quantity(preset: &Preset, name: &str) -> Result<QuantityKey, String> {
    let wanted = normal(name);
    let exact = QuantityKey::parse(name, preset)
        .or_else(|_| QuantityKey::parse(&wanted.replace(' ', "_"), preset))
        .ok();
    let by_word = || {
        QUANTITY_WORDS
            .iter()
            .find(|(word, _)| *word == wanted)
            .and_then(|(_, q)| QuantityKey::parse(q, preset).ok())
    };
    let by_symbol = || {
        QuantityKey::all(preset)
            .into_iter()
            .find(|q| q.symbol() == name.trim())
    };
    exact.or_else(by_word).or_else(by_symbol).ok_or_else(|| {
        format!(
            "'{name}' matches no quantity the program computes for this preset (a {} preset, \
             the {} model): a measured column is one of {}",
            preset.problem.name(),
            preset.plane.model.name(),
            quantity_list(preset)
        )
    })
}

/// The parameters an x column may name, in words and keys ("load (plane.load), ...").
pub fn parameter_list(preset: &Preset) -> String {
    let mut names: Vec<String> = PARAMETER_WORDS
        .iter()
        .filter(|(_, key)| preset.key(key).is_ok())
        .map(|(word, key)| format!("{word} ({key})"))
        .collect();
    names.extend(
        Key::all(preset)
            .into_iter()
            .filter(|k| k.param().limit().is_some() && !k.param().is_whole())
            .map(|k| k.to_string()),
    );
    names.join(", ")
}

/// The quantities a measured column may name, in words and names ("mu (mu_star), ...").
pub fn quantity_list(preset: &Preset) -> String {
    let mut names: Vec<String> = QUANTITY_WORDS
        .iter()
        .filter(|(_, q)| QuantityKey::parse(q, preset).is_ok())
        .map(|(word, q)| format!("{word} ({q})"))
        .collect();
    names.extend(QuantityKey::all(preset).into_iter().map(|q| q.to_string()));
    names.join(", ")
}
