//! A value as a preset's author wrote it: a number in SI units (`thickness = 2.0e-3`) or a text
//! with units, read by the explorer form's parser `units::parse_si` (`thickness = "2 mm"`,
//! `coefficient = "3e-5 mm3/Nm"`); and the examples of the right kind for a key that the
//! refusals give, from the parameter registry `params::PARAMS`.

use std::fmt;

use serde::de::{self, Deserializer, Visitor};
use serde::{Deserialize, Serialize, Serializer};

use crate::preset::params::{PARAMS, Param};
use crate::units::{format_si_exact, parse_si};

/// A number of the file, as written.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Written {
    /// A TOML number (integer or float), in SI units.
    Number(f64),
    /// A TOML text: a number with an optional SI prefix and unit.
    Text(String),
}

/// The phrase serde's error carries for a value of the wrong type ("expected ...").
pub(super) const EXPECTING: &str = "a number in SI units or a text with units";

impl<'de> Deserialize<'de> for Written {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Read;
        impl Visitor<'_> for Read {
            type Value = Written;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str(EXPECTING)
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Written, E> {
                Ok(Written::Number(v))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Written, E> {
                Ok(Written::Number(v as f64))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Written, E> {
                Ok(Written::Number(v as f64))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Written, E> {
                Ok(Written::Text(v.to_string()))
            }
        }
        d.deserialize_any(Read)
    }
}

impl Serialize for Written {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Written::Number(v) => s.serialize_f64(*v),
            Written::Text(t) => s.serialize_str(t),
        }
    }
}

impl Written {
    /// The value in SI units of the parameter with preset key `key` (its unit from the
    /// registry; none for a key outside it). Err: the text as written, why it cannot be read,
    /// and an example for the key.
    pub(super) fn si(&self, key: &str) -> Result<f64, String> {
        match self {
            Written::Number(v) => Ok(*v),
            Written::Text(text) => {
                let unit = param(key).map_or("", |p| p.unit);
                parse_si(text, unit)
                    .map_err(|why| format!("{} = \"{text}\": {why}; {}", short(key), example(key)))
            }
        }
    }
}

/// The last part of a preset key, as written in its section ("thickness").
fn short(key: &str) -> &str {
    key.rsplit('.').next().unwrap_or(key)
}

/// The registry's parameter of a preset key (a harmonic's with any index).
pub(super) fn param(key: &str) -> Option<&'static Param> {
    let generic = match key.strip_prefix("spatial.harmonics.") {
        Some(rest) => format!("spatial.harmonics.N.{}", short(rest)),
        None => key.to_string(),
    };
    PARAMS.iter().find(|p| p.key == generic)
}

/// An example of a right value for `key`, from its typical magnitude and unit in the registry:
/// `e.g. thickness = "1 mm" or 0.001`; `e.g. poisson_ratio = 0.3`.
pub(super) fn example(key: &str) -> String {
    let name = short(key);
    match param(key).and_then(|p| Some((p.typical()?, p.unit))) {
        Some((typical, "")) => format!("e.g. {name} = {typical}"),
        Some((typical, unit)) => format!(
            "e.g. {name} = \"{}\" or {typical:e}",
            format_si_exact(typical, unit)
        ),
        None => format!("e.g. {name} = 1.0e-6"),
    }
}

/// The preset key of `key` written in the section whose header comes last in `before` (the
/// file's text up to the value): `material.thickness`, `spatial.harmonics.N.phase_y`, and a key
/// of an inline table in the section (`plane.sweep.load_min` for `load_min` under `[plane]`).
pub(super) fn key_in_section(before: &str, key: &str) -> Option<&'static Param> {
    let section = before
        .lines()
        .rev()
        .map(str::trim)
        .find(|l| l.starts_with('['))
        .map(|l| l.trim_matches(['[', ']', ' ']))
        .unwrap_or("");
    let section = if section == "spatial.harmonics" {
        "spatial.harmonics.N"
    } else {
        section
    };
    let dotted = format!(".{key}");
    PARAMS
        .iter()
        .find(|p| p.key == format!("{section}{dotted}"))
        .or_else(|| {
            PARAMS
                .iter()
                .find(|p| p.key.starts_with(&format!("{section}.")) && p.key.ends_with(&dotted))
        })
}

/// The refusal of an unquoted value with units (`thickness = 2 mm`): how to write it, with the
/// value read as the form reads it (`write thickness = "2 mm" or 2e-3`); None when the form
/// cannot read it either.
pub(super) fn unquoted(line: &str, before: &str) -> Option<String> {
    let (left, right) = line.split_once('=')?;
    let key = left.trim();
    let value = right.split('#').next().unwrap_or("").trim();
    let p = key_in_section(before, key)?;
    p.limit()?;
    // a value the form cannot read either is a typo, said by the reader's own words
    let si = parse_si(value, p.unit).ok()?;
    Some(format!(
        "{key} = {value}: a value with units is written in quotes: write {key} = \"{value}\" or \
         {si:e}"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn examples_are_of_the_key_s_kind() {
        assert_eq!(
            example("material.thickness"),
            "e.g. thickness = \"1 mm\" or 1e-3"
        );
        assert_eq!(
            example("material.youngs_modulus"),
            "e.g. youngs_modulus = \"1 GPa\" or 1e9"
        );
        assert_eq!(
            example("material.poisson_ratio"),
            "e.g. poisson_ratio = 0.3"
        );
        assert_eq!(
            Written::Text("2 xx".into()).si("material.thickness"),
            Err(
                "thickness = \"2 xx\": '2 xx': unknown unit; write a plain number or a prefixed \
                 m (e.g. km, Mm); e.g. thickness = \"1 mm\" or 1e-3"
                    .into()
            )
        );
    }

    #[test]
    fn keys_are_found_in_their_section() {
        let key = |before, k| key_in_section(before, k).map(|p| p.key);
        assert_eq!(key("[wear]\n", "coefficient"), Some("wear.coefficient"));
        assert_eq!(
            key("[friction]\nx = 1\n", "coefficient"),
            Some("friction.coefficient")
        );
        assert_eq!(
            key("[[spatial.harmonics]]\n", "phase_y"),
            Some("spatial.harmonics.N.phase_y")
        );
        assert_eq!(key("[plane]\n", "load_min"), Some("plane.sweep.load_min"));
        assert_eq!(key("", "name"), None);
    }

    #[test]
    fn an_unquoted_value_with_units_says_how_to_write_it() {
        assert_eq!(
            unquoted("thickness = 2 mm  # the coating", "[material]\n").unwrap(),
            "thickness = 2 mm: a value with units is written in quotes: write thickness = \
             \"2 mm\" or 2e-3"
        );
        assert_eq!(unquoted("load = 1.0e4 +", "[plane]\n"), None);
        assert_eq!(unquoted("model = strip", "[plane]\n"), None);
    }
}
