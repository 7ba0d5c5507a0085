//! A preset the picker offers, and which of them a typed text finds.

use std::path::PathBuf;

use crate::preset::Preset;

/// A preset the picker offers.
#[derive(Clone, Debug, PartialEq)]
pub struct PickerEntry {
    /// What the list shows.
    pub title: String,
    /// Where it comes from ("bundled: x.toml" or a path).
    pub source: String,
    /// Its file, for a user's preset.
    pub path: Option<PathBuf>,
    /// The preset, or why it could not be read.
    pub preset: Result<Preset, String>,
    /// The heading it is listed under: where it comes from ("bundled with wearlab", a folder).
    pub folder: String,
}

impl PickerEntry {
    /// Whether every word of `filter` is in its title or its source, in any case.
    pub fn matches(&self, filter: &str) -> bool {
        let text = format!("{} {}", self.title, self.source).to_lowercase();
        filter
            .to_lowercase()
            .split_whitespace()
            .all(|word| text.contains(word))
    }
}

/// The entries `filter` matches, as indices of `entries`.
pub fn found(entries: &[PickerEntry], filter: &str) -> Vec<usize> {
    (0..entries.len())
        .filter(|&i| entries[i].matches(filter))
        .collect()
}
