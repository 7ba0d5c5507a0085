//! The quantity registry: everything a sweep, a curve or a map can show, one entry each (name,
//! symbol, unit, description, how it is computed from a solved point). The names of quantities
//! that `wearlab solve` reports are its JSON keys (`mu_star`, `contact.min_pressure`,
//! `harmonics.N.decay_rate`); the others are derived (`mu_star_minus_mu`, `max_pressure`) or the
//! problem's dimensionless groups. The table itself, and what one entry holds, are in
//! `quantity_table`.

use std::fmt;

use crate::preset::{Preset, Problem};
use crate::sweeps::point::Point;
use crate::sweeps::quantity_table::QUANTITIES;

pub use crate::sweeps::quantity_table::{Eval, Origin, Quantity};

/// A quantity, and for a harmonic's quantity which harmonic (0-based).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct QuantityKey {
    index: usize,
    harmonic: Option<usize>,
}

const HARMONIC: &str = "harmonics.N.";

impl QuantityKey {
    /// The quantity.
    pub fn quantity(self) -> &'static Quantity {
        &QUANTITIES[self.index]
    }

    /// The harmonic (0-based) of a harmonic's quantity.
    pub fn harmonic(self) -> Option<usize> {
        self.harmonic
    }

    /// The symbol, with the harmonic's number (1-based, as the explorer shows it): "beta1".
    pub fn symbol(self) -> String {
        match self.harmonic {
            Some(n) => format!("{}{}", self.quantity().symbol, n + 1),
            None => self.quantity().symbol.to_string(),
        }
    }

    /// Every quantity of the preset's problem and model, the harmonics' for each harmonic.
    pub fn all(preset: &Preset) -> Vec<QuantityKey> {
        let mut keys = Vec::new();
        for (index, q) in QUANTITIES.iter().enumerate() {
            if q.problem != preset.problem || q.missing_in(preset).is_some() {
                continue;
            }
            match q.eval {
                Eval::Harmonic(_) => {
                    keys.extend((0..preset.spatial.harmonics.len()).map(|n| QuantityKey {
                        index,
                        harmonic: Some(n),
                    }))
                }
                _ => keys.push(QuantityKey {
                    index,
                    harmonic: None,
                }),
            }
        }
        keys
    }

    /// Parses a quantity's name for a preset: of its problem, defined for its model, naming a
    /// harmonic it has. Err says why and lists the names.
    pub fn parse(text: &str, preset: &Preset) -> Result<QuantityKey, String> {
        let text = text.trim();
        let harmonic = text.strip_prefix("harmonics.").and_then(|rest| {
            let (n, field) = rest.split_once('.')?;
            Some((n.parse::<usize>().ok()?, field))
        });
        let found = QUANTITIES.iter().enumerate().find(|(_, q)| {
            q.problem == preset.problem
                && match harmonic {
                    Some((_, field)) => q.name.strip_prefix(HARMONIC) == Some(field),
                    None => q.name == text,
                }
        });
        let Some((index, q)) = found else {
            let names: Vec<&str> = QUANTITIES
                .iter()
                .filter(|q| q.problem == preset.problem)
                .map(|q| q.name)
                .collect();
            return Err(format!(
                "unknown output '{text}': the outputs of a {} preset are {}",
                preset.problem.name(),
                names.join(", ")
            ));
        };
        if let Some(why) = q.missing_in(preset) {
            return Err(format!("output '{text}': {why}"));
        }
        let count = preset.spatial.harmonics.len();
        match harmonic {
            Some((n, _)) if n >= count => Err(format!(
                "output '{text}': there is no harmonic {n} (the preset has {count}, numbered 0 to {})",
                count - 1
            )),
            _ => Ok(QuantityKey {
                index,
                harmonic: harmonic.map(|(n, _)| n),
            }),
        }
    }

    /// The value at a solved point; Err says why it has none there.
    pub fn value(self, point: &Point) -> Result<f64, String> {
        let n = self.harmonic.unwrap_or(0);
        match (self.quantity().eval, point) {
            (Eval::Plane(f), Point::Plane(p)) => f(p),
            (Eval::Spatial(f), Point::Spatial(s)) => f(s),
            (Eval::Harmonic(f), Point::Spatial(s)) => f(s, n),
            _ => Err(format!("{self} belongs to the other problem")),
        }
    }
}

impl fmt::Display for QuantityKey {
    /// The name, with the harmonic's index: `harmonics.0.decay_rate`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.harmonic {
            Some(n) => f.write_str(&self.quantity().name.replace(".N.", &format!(".{n}."))),
            None => f.write_str(self.quantity().name),
        }
    }
}

/// The outputs of `wearlab sweep` without `--output`: the scalar keys of `wearlab solve`'s report
/// (the model's; the costly energy identity left out) and, for the spatial problem, each
/// harmonic's decay rate and drift velocity.
const DEFAULTS: &[&str] = &[
    "load",
    "normal_force",
    "tangential_force",
    "a",
    "b",
    "theta",
    "gamma",
    "psi",
    "delta_g",
    "mu_star",
    "validity.ok",
    "validity.contact_width_over_thickness",
    "time",
    "mean_pressure",
    "tangential_force",
    "contact.complete",
    "contact.fraction",
    "contact.min_pressure",
    "harmonics.N.decay_rate",
    "harmonics.N.drift_velocity",
];

/// The default outputs of a preset's problem and model.
pub fn defaults(preset: &Preset) -> Vec<QuantityKey> {
    QuantityKey::all(preset)
        .into_iter()
        .filter(|k| DEFAULTS.contains(&k.quantity().name))
        .collect()
}

/// The dimensionless groups of the preset's problem (the explorer's dimensionless view); each
/// quantity's `description` defines it in words.
pub fn groups(preset: &Preset) -> Vec<QuantityKey> {
    QuantityKey::all(preset)
        .into_iter()
        .filter(|k| k.quantity().group)
        .collect()
}

/// The dimensionless groups of a problem, each once (a harmonic's group stands for every
/// harmonic): the explorer's help defines them with their `description`.
pub fn problem_groups(problem: Problem) -> impl Iterator<Item = &'static Quantity> {
    QUANTITIES
        .iter()
        .filter(move |q| q.group && q.problem == problem)
}

/// The quantity of a problem with this name (`mu_star_minus_mu`; a harmonic's as
/// `harmonics.N.kh`).
pub fn by_name(problem: Problem, name: &str) -> Option<&'static Quantity> {
    QUANTITIES
        .iter()
        .find(|q| q.problem == problem && q.name == name)
}
