//! The keys of a height-map punch (`spatial.surface`): the harmonics' keys say why they do
//! nothing on a map.

use crate::tui::app::{App, Command};

/// `+` or `-` on a height map: nothing to add to or remove.
pub fn no_harmonics(app: &mut App) -> Vec<Command> {
    app.complain(
        "the punch is a height map (spatial.surface): it has no harmonics to add or remove",
    );
    Vec::new()
}
