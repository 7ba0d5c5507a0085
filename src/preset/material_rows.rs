//! The form's and `--set`'s rows that the materials table and Archard's law add: `material.name`
//! (a choice of the table's entries; choosing one sets E, nu and the strengths) and
//! `wear.archard_coefficient` (Archard's K = k H, shown where the hardness is known).

use crate::materials::{self, MATERIALS};
use crate::preset::Preset;

/// The index into `materials::CHOICES` of the material whose values the preset has, 0
/// ("custom") when none has them all.
pub fn name_index(p: &Preset) -> usize {
    materials::matching(
        p.material.youngs_modulus,
        p.material.poisson_ratio,
        p.strength,
    )
    .map_or(0, |i| i + 1)
}

/// Takes the elastic constants and strengths of the table's entry `index - 1`.
pub fn set_name(p: &mut Preset, index: usize) -> Result<(), String> {
    let Some(entry) = index.checked_sub(1).and_then(|i| MATERIALS.get(i)) else {
        return Err(format!(
            "material.name: \"custom\" is what typing E, nu, Y or H on their rows gives; here \
             choose one of the table's materials: {}",
            materials::names()
        ));
    };
    p.material.youngs_modulus = entry.youngs_modulus;
    p.material.poisson_ratio = entry.poisson_ratio;
    p.strength = entry.strength;
    Ok(())
}

/// Archard's wear coefficient K = k H [-] (0 without a hardness: the row is not shown then).
pub fn archard(p: &Preset) -> f64 {
    p.strength.hardness.map_or(0.0, |h| p.wear * h)
}

/// Sets k = K/H [1/Pa] (unchanged without a hardness: the row is not shown then).
pub fn set_archard(p: &mut Preset, k_archard: f64) {
    if let Some(h) = p.strength.hardness {
        p.wear = k_archard / h;
    }
}
