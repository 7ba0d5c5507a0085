//! The keys `+` and `-` on a punch of harmonics: add a harmonic at the next free multiple of the
//! first one's wave vector, remove the selected one: the next preset, for `actions` to apply.

use crate::physics::spatial::harmonic::Harmonic;
use crate::preset::Preset;
use crate::tui::form::Change;

/// The most harmonics a punch has (`limits::HARMONICS`).
pub const MAX_HARMONICS: usize = crate::physics::limits::HARMONICS.max as usize;

/// A harmonic added at the first free multiple (2x, 3x, ...) of the first harmonic's wave
/// vector (the fundamental), with half the last one's amplitude: the preset, the change and
/// what to say; or why it cannot be.
pub fn added(preset: &Preset) -> Result<(Preset, Change, String), String> {
    let harmonics = &preset.spatial.harmonics;
    let n = harmonics.len();
    if n >= MAX_HARMONICS {
        return Err(format!(
            "the punch has {n} harmonics, the most + adds: remove one with - first"
        ));
    }
    let (Some(&first), Some(&last)) = (harmonics.first(), harmonics.last()) else {
        return Err("the punch has no harmonic to take a multiple of".into());
    };
    // fewer than MAX_HARMONICS wave vectors are taken, so one of MAX_HARMONICS multiples is
    // free unless out of range
    let next = (2..=MAX_HARMONICS as u32 + 1).find_map(|m| {
        let mut next = preset.clone();
        next.spatial.harmonics.push(Harmonic {
            amplitude: last.amplitude / 2.0,
            wavenumber_x: first.wavenumber_x * m as f64,
            wavenumber_y: first.wavenumber_y * m as f64,
            ..last
        });
        next.check_rules().ok().map(|()| next)
    });
    let next = next.ok_or(
        "cannot add a harmonic: every multiple of the first wave vector up to 65x is taken or out of range; edit wx, wy instead",
    )?;
    let change = Change {
        name: "harmonics".into(),
        from: n.to_string(),
        to: (n + 1).to_string(),
    };
    Ok((next, change, format!("added harmonic {}", n + 1)))
}

/// The harmonic `selected` (or the last one) removed: the preset, the change and what to say;
/// or why it cannot be.
pub fn removed(
    preset: &Preset,
    selected: Option<usize>,
) -> Result<(Preset, Change, String), String> {
    let n = preset.spatial.harmonics.len();
    if n <= 1 {
        return Err("the punch needs at least one harmonic".into());
    }
    let index = selected.unwrap_or(n - 1);
    let mut next = preset.clone();
    next.spatial.harmonics.remove(index);
    let change = Change {
        name: "harmonics".into(),
        from: n.to_string(),
        to: (n - 1).to_string(),
    };
    Ok((next, change, format!("removed harmonic {}", index + 1)))
}
