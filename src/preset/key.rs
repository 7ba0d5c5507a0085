//! Addressing the parameters of `params::PARAMS` in a preset: `Key` (a parameter, and which
//! harmonic), parsed from and shown as its preset key (`spatial.harmonics.0.amplitude`), and the
//! getter and the checked setters on `Preset` that the command line (`--set`, `--vary`), the
//! `[explore]` section and the explorer's form use.

use std::fmt;

use crate::physics::SweepRange;
use crate::physics::limits;
use crate::physics::spatial::partial::grid::check_side;
use crate::physics::spatial::{validate_grid, validate_harmonics};
use crate::preset::params::{Access, PARAMS, Param};
use crate::preset::surface_set::{SURFACE_PREFIX, grid_beside_map};
use crate::preset::{Preset, Problem};
use crate::preset::{law_rules, shape_rows, surface_rows};
use crate::units::parse_si;

const HARMONIC_PREFIX: &str = "spatial.harmonics.";

/// The keys of a problem (or all), separated by commas; harmonic keys with `N`.
fn list(problem: Option<Problem>) -> String {
    PARAMS
        .iter()
        .filter(|p| problem.is_none_or(|problem| p.applies_to(problem)))
        .map(|p| p.key)
        .collect::<Vec<_>>()
        .join(", ")
}

/// A parameter of a preset: an entry of `PARAMS`, and for a harmonic's parameter which harmonic
/// (0-based).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Key {
    index: usize,
    harmonic: Option<usize>,
}

impl Key {
    /// The key of a parameter that is not a harmonic's (None for an unknown or harmonic key).
    pub fn of(key: &str) -> Option<Key> {
        PARAMS
            .iter()
            .position(|p| p.key == key && !matches!(p.access, Access::Harmonic { .. }))
            .map(|index| Key {
                index,
                harmonic: None,
            })
    }

    /// The key of harmonic `n`'s parameter `field` ("amplitude", "wavenumber_x", ...).
    pub fn harmonic(n: usize, field: &str) -> Option<Key> {
        PARAMS
            .iter()
            .position(|p| p.key.strip_prefix("spatial.harmonics.N.") == Some(field))
            .map(|index| Key {
                index,
                harmonic: Some(n),
            })
    }

    /// Parses a preset key; Err says what is wrong and lists the keys.
    pub fn parse(text: &str) -> Result<Key, String> {
        let text = text.trim();
        let harmonic = text.strip_prefix(HARMONIC_PREFIX).and_then(|rest| {
            let (n, field) = rest.split_once('.')?;
            Key::harmonic(n.parse().ok()?, field)
        });
        harmonic
            .or_else(|| Key::of(text))
            .ok_or_else(|| format!("unknown key '{text}': the keys are {}", list(None)))
    }

    /// The parameter.
    pub fn param(self) -> &'static Param {
        &PARAMS[self.index]
    }

    /// The harmonic (0-based) of a harmonic's parameter.
    pub fn harmonic_index(self) -> Option<usize> {
        self.harmonic
    }

    /// The symbol, with the harmonic's number (1-based, as the explorer shows it) for a
    /// harmonic's parameter: "A1", "E".
    pub fn symbol(self) -> String {
        match self.harmonic {
            Some(n) => format!("{}{}", self.param().symbol, n + 1),
            None => self.param().symbol.to_string(),
        }
    }

    /// Every key of the preset's problem, in file order, the harmonics' last.
    pub fn all(preset: &Preset) -> Vec<Key> {
        let mut keys: Vec<Key> = Vec::new();
        for (index, p) in PARAMS.iter().enumerate() {
            if !p.applies_to(preset.problem) || !shown(p, preset) {
                continue;
            }
            match p.access {
                Access::Harmonic { .. } => {}
                _ => keys.push(Key {
                    index,
                    harmonic: None,
                }),
            }
        }
        if preset.problem == Problem::Spatial {
            for n in 0..preset.spatial.harmonics.len() {
                keys.extend(PARAMS.iter().enumerate().filter_map(|(index, p)| {
                    matches!(p.access, Access::Harmonic { .. }).then_some(Key {
                        index,
                        harmonic: Some(n),
                    })
                }));
            }
        }
        keys
    }
}

/// Whether the form shows the parameter: the shear cap, the yield strength and the hardness in
/// the plane problem (the spatial one takes friction without a cap and has no yield check), the
/// wear exponent in the plane problem and where a spatial preset gives one, the reference
/// pressure where the wear law is not linear, a shape's parameters for that kind of punch.
fn shown(p: &Param, preset: &Preset) -> bool {
    let plane = preset.problem == Problem::Plane;
    match p.key {
        // in the spatial form only where the preset gives one (its closed form is the linear law's)
        "wear.exponent" => plane || preset.wear_exponent != 1.0,
        "friction.shear_strength" => plane,
        "wear.reference_pressure" => preset.wear_exponent != 1.0,
        // "none" until given: a student enters a hardness to have the yield checked
        "material.yield_strength" | "material.hardness" => plane,
        "wear.archard_coefficient" => preset.strength.hardness.is_some(),
        // a height map is solved on its own grid
        "spatial.grid" => preset.spatial.surface.is_none(),
        _ if p.surface_name().is_some() => {
            surface_rows::applies(preset, p.surface_name().unwrap_or_default()).is_ok()
        }
        key => shape_rows::applies(preset, key).is_ok(),
    }
}

/// The last part of a surface's key (`hurst`).
fn surface_name(key: Key) -> &'static str {
    key.param().surface_name().unwrap_or_default()
}

/// The refusal of a value that the preset file gives and nothing here sets.
fn fixed(key: Key) -> String {
    format!(
        "{key} is read from the preset file with the measured profile; edit the file, or choose \
         another plane.shape.kind"
    )
}

impl fmt::Display for Key {
    /// The preset key, with the harmonic's index: `spatial.harmonics.0.amplitude`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.harmonic {
            Some(n) => f.write_str(&self.param().key.replace(".N.", &format!(".{n}."))),
            None => f.write_str(self.param().key),
        }
    }
}

impl Preset {
    fn harmonic_of(&self, key: Key) -> Result<usize, String> {
        let n = key.harmonic.unwrap_or(0);
        let count = self.spatial.harmonics.len();
        match count.checked_sub(1) {
            Some(_) if n < count => Ok(n),
            Some(last) => Err(format!(
                "{key}: there is no harmonic {n} (the preset has {count}, numbered 0 to {last})"
            )),
            None => Err(format!(
                "{key}: the preset has no harmonics (its punch is a height map, spatial.surface)"
            )),
        }
    }

    /// The parameter's value (a choice's index as a number); Err when the harmonic does not exist.
    pub fn get(&self, key: Key) -> Result<f64, String> {
        Ok(match key.param().access {
            Access::Number { get, .. } => get(self),
            Access::Harmonic { get, .. } => get(&self.spatial.harmonics[self.harmonic_of(key)?]),
            Access::Choice { get, .. } => get(self) as f64,
            Access::Surface { .. } => surface_rows::value(self, surface_name(key))?,
            Access::Fixed { .. } => return Err(fixed(key)),
        })
    }

    /// The text of a value that is shown and not set (a measured profile's file and range, a
    /// height-map file's name, grid and lengths); None for a value the form sets.
    pub fn fixed_text(&self, key: Key) -> Option<String> {
        match key.param().access {
            Access::Fixed { show } => Some(show(self)),
            Access::Surface { .. } => surface_rows::text(self, surface_name(key)),
            _ => None,
        }
    }

    /// Writes one value checked against its own limit (a choice by index), without the rules
    /// between fields (`check_rules`). For several values, assign each, then check the rules once.
    pub fn assign(&mut self, key: Key, value: f64) -> Result<(), String> {
        match key.param().access {
            // the key's name is written only for a refusal (a fit assigns a value per row)
            Access::Number { limit, set, .. } => {
                if !limit.accepts(value) {
                    limit.check(&key.to_string(), value)?;
                }
                set(self, value);
            }
            Access::Harmonic { limit, set, .. } => {
                limit.check(&key.to_string(), value)?;
                let n = self.harmonic_of(key)?;
                set(&mut self.spatial.harmonics[n], value);
            }
            Access::Choice { names, set, .. } => {
                if !(value >= 0.0 && value.fract() == 0.0 && (value as usize) < names.len()) {
                    return Err(format!(
                        "{key} = {value} is not a choice: allowed one of {}",
                        names.join(", ")
                    ));
                }
                set(self, value as usize)?;
            }
            Access::Surface { .. } => surface_rows::set(self, surface_name(key), value)?,
            Access::Fixed { .. } => return Err(fixed(key)),
        }
        Ok(())
    }

    /// Parses text for the parameter (a number with an optional SI prefix and unit, "10um",
    /// "3 GPa"; a choice by its name; `none` for an optional key, which clears it) and assigns
    /// it as `assign` does.
    pub fn assign_text(&mut self, key: Key, text: &str) -> Result<(), String> {
        let param = key.param();
        if param.optional() && text.trim() == "none" {
            self.clear(key);
            return Ok(());
        }
        let value = match param.choices() {
            Some(names) => names
                .iter()
                .position(|n| *n == text.trim())
                .ok_or_else(|| {
                    format!(
                        "{key} = '{}' is not a choice: allowed one of {}",
                        text.trim(),
                        names.join(", ")
                    )
                })? as f64,
            None => parse_si(text, param.unit)
                .map_err(|why| format!("{key} = {why} (allowed {})", param.allowed()))?,
        };
        self.assign(key, value)
    }

    /// Leaves out an optional key (`Param::optional`; nothing for another).
    fn clear(&mut self, key: Key) {
        match key.param().key {
            "material.yield_strength" => self.strength.yield_strength = None,
            "material.hardness" => self.strength.hardness = None,
            "wear.reference_pressure" => self.reference_pressure = None,
            _ => {}
        }
    }

    /// Sets one parameter: its limit, then the rules between fields; on Err the preset is
    /// unchanged and the text says what is allowed.
    pub fn set(&mut self, key: Key, value: f64) -> Result<(), String> {
        let mut next = self.clone();
        next.assign(key, value)?;
        next.check_rules()?;
        *self = next;
        Ok(())
    }

    /// The rules between fields, the same as the preset file's: a model other than wide needs a
    /// finite thickness; each sweep's min < max; the harmonics' wave vectors are nonzero and
    /// distinct.
    pub fn check_rules(&self) -> Result<(), String> {
        let model = self.plane.model;
        if model.needs_finite_thickness() && self.material.is_half_space() {
            return Err(format!(
                "plane.model = {} needs a finite material.thickness (h = inf is the half-plane): \
                 set the thickness, or use plane.model = wide",
                model.name()
            ));
        }
        let order = |s: &SweepRange, names| s.check_order(names, limits::show);
        order(
            &self.plane.sweep,
            ["plane.sweep.load_min", "plane.sweep.load_max"],
        )?;
        order(
            &self.spatial.sweep,
            ["spatial.sweep.pressure_min", "spatial.sweep.pressure_max"],
        )?;
        law_rules::check(self)?;
        // a height map (spatial.surface) has no harmonics and solves on its own grid
        let harmonics = match self.spatial.surface {
            Some(_) => Ok(()),
            None => validate_harmonics(&self.spatial.harmonics),
        };
        (harmonics.and_then(|()| validate_grid(&self.spatial.harmonics, self.spatial.grid)))
            .and_then(|()| match self.spatial.surface {
                Some(_) => Ok(()),
                None => check_side(self.spatial.grid),
            })
            .map_err(|e| e.to_string().trim_start_matches("invalid input: ").into())
    }
}

impl Preset {
    /// Parses a key for this preset: known, of the preset's problem (the other problem's section
    /// is kept in the file but not solved), and naming a harmonic the preset has.
    pub fn key(&self, text: &str) -> Result<Key, String> {
        let key = Key::parse(text).map_err(|_| {
            format!(
                "unknown key '{}': the keys of a {} preset are {}",
                text.trim(),
                self.problem.name(),
                list(Some(self.problem))
            )
        })?;
        if let Some(problem) = key.param().problem().filter(|p| *p != self.problem) {
            return Err(format!(
                "{key} applies to {} presets only; this preset solves problem = \"{}\"",
                problem.name(),
                self.problem.name()
            ));
        }
        if key.harmonic.is_some() {
            self.harmonic_of(key)?;
        }
        if let (Some(shape), "plane.radius") = (&self.plane.shape, key.param().key) {
            return Err(format!(
                "plane.radius is the parabola's radius; this preset's punch is a {} shape \
                 (plane.shape in the file), which plane.radius does not change",
                shape.kind()
            ));
        }
        if let (Some(map), "spatial.grid") = (&self.spatial.surface, key.param().key) {
            return Err(grid_beside_map(&map.surface));
        }
        if key.param().key == "wear.archard_coefficient" && self.strength.hardness.is_none() {
            return Err(
                "wear.archard_coefficient is K = k H: give material.hardness (or a material.name \
                 with a hardness) first"
                    .into(),
            );
        }
        if let Some(name) = key.param().surface_name() {
            surface_rows::applies(self, name)?;
        }
        shape_rows::applies(self, key.param().key)?;
        Ok(key)
    }
}

impl Preset {
    /// The preset with `KEY=VALUE` settings applied in order (each checked against its limit,
    /// then the rules between fields once, so that e.g. both ends of a sweep can move). Err names
    /// the setting, the key, the value and what is allowed.
    pub fn with_settings<S: AsRef<str>>(&self, settings: &[S]) -> Result<Preset, String> {
        let mut next = self.clone();
        for setting in settings {
            let setting = setting.as_ref();
            let (key, value) = setting.split_once('=').ok_or_else(|| {
                format!("'{setting}' is not KEY=VALUE (e.g. material.thickness=10um)")
            })?;
            match key.trim().strip_prefix(SURFACE_PREFIX) {
                Some(name) => next.set_surface_key(name, value),
                None => next.key(key).and_then(|key| next.assign_text(key, value)),
            }
            .map_err(|why| format!("{setting}: {why}"))?;
        }
        next.check_rules()
            .map_err(|why| format!("the values set break a rule: {why}"))?;
        Ok(next)
    }
}
