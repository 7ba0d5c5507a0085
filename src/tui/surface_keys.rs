//! The keys of a height-map punch (`spatial.surface`): `r` draws a new seed for a generated
//! surface; the harmonics' keys say why they do nothing on a map.

use crate::physics::spatial::surface::SplitMix64;
use crate::preset::{Key, Preset};
use crate::tui::app::{App, Command};
use crate::tui::form::{self, Change};

/// Seeds drawn by `r` stay below this, so that the form shows them whole and they are typed
/// back easily.
const SEEDS: u64 = 1_000_000;

/// `+` or `-` on a height map: nothing to add to or remove.
pub fn no_harmonics(app: &mut App) -> Vec<Command> {
    app.complain(
        "the punch is a height map (spatial.surface): it has no harmonics to add or remove",
    );
    Vec::new()
}

/// `r` on a generated surface: the preset with the next seed (drawn from the current one, so
/// that the same presses give the same surfaces), set as the form sets it, with what changed and
/// the message to say; Err says why not.
pub fn new_seed(preset: &Preset) -> Result<(Preset, Change, String), String> {
    let row = Key::of("spatial.surface.seed").expect("the registry has the surface's seed");
    let now = form::get(preset, &row) as u64;
    let mut draw = SplitMix64::new(now);
    let seed = (0..8)
        .map(|_| draw.next_u64() % SEEDS)
        .find(|s| *s != now)
        .unwrap_or((now + 1) % SEEDS);
    let (next, change) = form::set(preset, &row, seed as f64)?;
    let said = format!(
        "seed {now} -> {seed}: the same spectrum and rms with other random phases (u undoes)"
    );
    Ok((next, change, said))
}
