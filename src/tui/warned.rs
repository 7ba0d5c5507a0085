//! The plausibility warnings of the preset open (`preset::warnings`: a value that looks like a
//! unit mistake, a harmonic that vanishes): said in the message line when the preset opens, and
//! listed whole by `i` while they hold.

use crate::preset::{self, Preset};

/// What the message line says of a preset's warnings when it opens: the first one (the line
/// may cut it; `i` lists them whole); None without warnings.
pub fn said(preset: &Preset) -> Option<String> {
    let all = preset::warnings(preset);
    let first = all.first()?;
    Some(match all.len() {
        1 => format!("warning (i repeats it): {first}"),
        n => format!("{n} warnings (i lists them): {first}"),
    })
}
