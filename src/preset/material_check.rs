//! Reading `[material]` and the wear coefficient of a preset file: the values written, or those
//! of the bundled material the file names (`material.name`; a value written beside the name
//! overrides the table's), and the wear coefficient as k or as Archard's K with the hardness.

use toml::Spanned;

use crate::materials::{self, MaterialEntry};
use crate::physics::Material;
use crate::physics::limits::{self, Limit};
use crate::physics::plane::yield_onset::Strength;
use crate::preset::PresetError;
use crate::preset::check::Checker;
use crate::preset::file::{FileMaterial, FileWear};
use crate::preset::written::Written;

impl Checker<'_> {
    /// The strip's elastic constants, thickness and strengths.
    pub(super) fn material(
        &self,
        section: &Spanned<FileMaterial>,
    ) -> Result<(Material, Strength), PresetError> {
        let mat = section.get_ref();
        let entry: Option<&MaterialEntry> = match &mat.name {
            Some(name) => Some(materials::named(name.get_ref()).ok_or_else(|| {
                self.error(
                    Some(name.span()),
                    format!(
                        "material.name = \"{}\" is not in the materials table; it has {}",
                        name.get_ref(),
                        materials::names()
                    ),
                )
            })?),
            None => None,
        };
        let number = |v: &Option<Spanned<Written>>,
                      key: &str,
                      limit: &Limit,
                      table: Option<f64>| match (v, table) {
            (Some(v), _) => self.value(v, key, limit).map(Some),
            (None, table) => Ok(table),
        };
        let required = |v, key: &str, limit, table| {
            number(v, key, limit, table)?.ok_or_else(|| {
                self.error(
                    Some(section.span()),
                    format!(
                        "[material] needs {key} (or a material.name from the table: {})",
                        materials::names()
                    ),
                )
            })
        };
        let material = Material {
            youngs_modulus: required(
                &mat.youngs_modulus,
                "material.youngs_modulus",
                &limits::YOUNGS_MODULUS,
                entry.map(|e| e.youngs_modulus),
            )?,
            poisson_ratio: required(
                &mat.poisson_ratio,
                "material.poisson_ratio",
                &limits::POISSON_RATIO,
                entry.map(|e| e.poisson_ratio),
            )?,
            thickness: self.value(&mat.thickness, "material.thickness", &limits::THICKNESS)?,
        };
        // a strength written replaces both of the table's: Y and H are one fact (Tabor (1951))
        let written = mat.yield_strength.is_some() || mat.hardness.is_some();
        let table = entry.filter(|_| !written).map(|e| e.strength);
        let strength = Strength {
            yield_strength: number(
                &mat.yield_strength,
                "material.yield_strength",
                &limits::YIELD_STRENGTH,
                table.and_then(|s| s.yield_strength),
            )?,
            hardness: number(
                &mat.hardness,
                "material.hardness",
                &limits::HARDNESS,
                table.and_then(|s| s.hardness),
            )?,
        };
        Ok((material, strength))
    }

    /// The wear coefficient k [1/Pa]: `wear.coefficient`, or `wear.archard_coefficient` K over
    /// the hardness H (k = K/H, Archard (1953)); 0 without a `[wear]` section.
    pub(super) fn wear_coefficient(
        &self,
        wear: Option<&FileWear>,
        strength: Strength,
    ) -> Result<f64, PresetError> {
        let Some(w) = wear else { return Ok(0.0) };
        match (&w.coefficient, &w.archard_coefficient) {
            (Some(_), Some(k)) => Err(self.error(
                Some(k.span()),
                "give the wear coefficient once: wear.coefficient (k) or \
                 wear.archard_coefficient (K = k H), not both",
            )),
            (Some(k), None) => self.value(k, "wear.coefficient", &limits::WEAR),
            (None, Some(k)) => {
                let archard = self.value(k, "wear.archard_coefficient", &limits::ARCHARD)?;
                let hardness = strength.hardness.ok_or_else(|| {
                    self.error(
                        Some(k.span()),
                        "wear.archard_coefficient is K = k H: it needs material.hardness (or a \
                         material.name with a hardness)",
                    )
                })?;
                Ok(archard / hardness)
            }
            (None, None) => Ok(0.0),
        }
    }
}
