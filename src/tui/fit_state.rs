//! What the explorer keeps of a fit (`F`): the form that chooses the inputs to free, the fit
//! running on the fit thread, and the report shown once it is done.

use crate::preset::{Key, Preset};

/// An input the fit form offers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Offered {
    /// The input.
    pub key: Key,
    /// Chosen to be freed.
    pub free: bool,
    /// Locked by the preset's lesson: it cannot be freed.
    pub locked: bool,
}

/// The fit form: the numeric inputs a fit can free, mu and k first.
#[derive(Clone, Debug, PartialEq)]
pub struct FitForm {
    /// The inputs offered, in the order shown.
    pub offered: Vec<Offered>,
    /// The highlighted one.
    pub selected: usize,
}

impl FitForm {
    /// The inputs chosen, in the order shown.
    pub fn chosen(&self) -> Vec<Key> {
        (self.offered.iter())
            .filter(|o| o.free)
            .map(|o| o.key)
            .collect()
    }
}

/// A fit sent to the fit thread and not yet answered.
#[derive(Clone, Debug, PartialEq)]
pub struct Fitting {
    /// The generation it was submitted with.
    pub generation: u64,
    /// The inputs it started from: an edit since makes its answer another preset's.
    pub from: Preset,
    /// The data file it fits (its path as given).
    pub data: String,
}

/// A fit's result in words, for the window that shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct FitReport {
    /// The window's title.
    pub title: String,
    /// Its paragraphs, each wrapped to the window; a paragraph starting with spaces keeps them
    /// as the indent of its every line.
    pub paragraphs: Vec<String>,
}
