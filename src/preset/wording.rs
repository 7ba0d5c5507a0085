//! The reasons of the TOML reader and of serde, said in the preset's own words: "expected a
//! number, found the text "3 GPa"" rather than "invalid type: string "3 GPa", expected f64", and
//! section names rather than Rust type names ("expected struct FileMaterial").

use serde::Deserialize;
use serde::de::DeserializeOwned;

use crate::physics::Spacing;
use crate::physics::plane::Model;
use crate::preset::{Problem, written};

/// The reason of a TOML or serde error in words. `before` is the file's text up to the start of
/// the error's span, so that the key whose value is wrong can be named.
pub(super) fn reason(message: &str, before: &str) -> String {
    let message = message.trim().replace('\n', " ");
    let key = key_before(before);
    let with_key = |text: String| match key {
        Some(k) => format!("{k}: {text}"),
        None => text,
    };
    let text = if let Some(rest) = message
        .strip_prefix("invalid type: ")
        .or_else(|| message.strip_prefix("invalid value: "))
    {
        match rest.split_once(", expected ") {
            Some((found, wanted)) => with_key(format!(
                "expected {}, found {}",
                expected(wanted, key, before),
                found_words(found)
            )),
            None => with_key(rest.to_string()),
        }
    } else if message == "wanted string or table" {
        with_key(format!("expected {}", choices_for(key)))
    } else if let Some(rest) = message.strip_prefix("unknown field ") {
        match rest.split_once(", expected ") {
            Some((field, allowed)) => format!("unknown key {field}; allowed here: {allowed}"),
            None => format!(
                "unknown key {}",
                rest.trim_end_matches(", there are no fields")
            ),
        }
    } else if let Some(field) = message.strip_prefix("missing field ") {
        format!("missing key {field}")
    } else if let Some(field) = message.strip_prefix("duplicate field ") {
        format!("the key {field} is given twice")
    } else if message == "invalid basic string, expected `\"`" {
        "a text in quotes is not closed: the closing \" is missing on this line".into()
    } else if message == "duplicate key" {
        "this key is given twice (each key once per section)".into()
    } else if let Some(rest) = message.strip_prefix("unknown variant ") {
        with_key(format!(
            "unknown name {}",
            rest.replace(", expected", "; expected")
        ))
    } else {
        message
    };
    text.replace('`', "\"")
}

/// The key assigned just before the error's position (`key = value`), if any.
fn key_before(before: &str) -> Option<&str> {
    let line = before.rsplit('\n').next().unwrap_or(before);
    let (left, _) = line.rsplit_once('=')?;
    let left = left.trim_end();
    // the key starts after the last character that cannot be in a bare key, whatever its width
    let start = left
        .char_indices()
        .rev()
        .find(|&(_, c)| !(c.is_ascii_alphanumeric() || c == '_' || c == '-'))
        .map_or(0, |(i, c)| i + c.len_utf8());
    Some(&left[start..]).filter(|k| !k.is_empty())
}

/// The text before byte `offset`, cut at the character boundary at or before it: a reader's
/// position may fall inside a multi-byte character of a malformed file.
pub(super) fn text_before(text: &str, offset: usize) -> &str {
    let end = (0..=offset.min(text.len()))
        .rev()
        .find(|&i| text.is_char_boundary(i))
        .unwrap_or(0);
    &text[..end]
}

fn found_words(found: &str) -> String {
    let found = &found.replace('`', "");
    if let Some(n) = found.strip_prefix("integer ") {
        match n.strip_suffix(" as i128") {
            Some(n) => format!("the whole number {n}, which is too large"),
            None => format!("the whole number {n}"),
        }
    } else if let Some(n) = found.strip_prefix("floating point ") {
        format!("the number {n}")
    } else if let Some(s) = found.strip_prefix("string ") {
        format!("the text {s}")
    } else if let Some(b) = found.strip_prefix("boolean ") {
        format!("the value {b}")
    } else if found == "sequence" {
        "a list".into()
    } else if found == "map" {
        "a table (or a date)".into()
    } else {
        found.into()
    }
}

fn expected(wanted: &str, key: Option<&str>, before: &str) -> String {
    match wanted {
        written::EXPECTING => {
            let example = key
                .and_then(|k| written::key_in_section(before, k))
                .map_or_else(
                    || "e.g. 2.0e-3 or \"2 mm\"".into(),
                    |p| written::example(p.key),
                );
            format!("{wanted} ({example})")
        }
        "f64" => "a number (SI units, e.g. 3.0e9)".into(),
        "i64" => "a whole number".into(),
        "a string" => "text in quotes".into(),
        "a sequence" => "a list".into(),
        _ => match wanted.strip_prefix("struct ") {
            Some(name) => table(name, key),
            None => choices_for(key),
        },
    }
}

/// A section or table of the file, by the name of the type that reads it.
fn table(type_name: &str, key: Option<&str>) -> String {
    match type_name {
        "FileMaterial" => {
            "the section [material] (youngs_modulus, poisson_ratio, thickness)".into()
        }
        "FileFriction" => "the section [friction] (coefficient, adhesion)".into(),
        "FileWear" => "the section [wear] (coefficient)".into(),
        "FilePlane" => "the section [plane] (model, radius, load, sweep)".into(),
        "FileSpatial" => "the section [spatial] (mean_pressure, sliding_speed, ...)".into(),
        "FileHarmonic" => "a [[spatial.harmonics]] table".into(),
        "FileLoadSweep" => "a table { load_min, load_max, points, scale }".into(),
        "FilePressureSweep" => "a table { pressure_min, pressure_max, points, scale }".into(),
        _ => match key {
            Some(k) => format!("a table for {k}"),
            None => "a table".into(),
        },
    }
}

/// The names a key allows, in quotes, read from the type's own list (the error it gives for an
/// unknown name).
fn choices<T: DeserializeOwned>() -> String {
    #[derive(Deserialize)]
    struct One<T> {
        #[allow(dead_code)]
        v: T,
    }
    let err = toml::from_str::<One<T>>("v = \"\"").err();
    let list = err
        .as_ref()
        .and_then(|e| e.message().split_once("expected ").map(|(_, l)| l.trim()));
    match list {
        Some(list) => list.replace('`', "\""),
        None => "a name in quotes".into(),
    }
}

fn choices_for(key: Option<&str>) -> String {
    match key {
        Some("problem") => choices::<Problem>(),
        Some("model") => choices::<Model>(),
        Some("scale") => choices::<Spacing>(),
        _ => "a name in quotes".into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serde_and_toml_reasons_in_words() {
        let cases = [
            (
                "invalid type: integer `3`, expected struct FileMaterial",
                "material = ",
                "material: expected the section [material] (youngs_modulus, poisson_ratio, \
                 thickness), found the whole number 3",
            ),
            (
                "invalid type: string \"3 GPa\", expected f64",
                "[material]\nyoungs_modulus = ",
                "youngs_modulus: expected a number (SI units, e.g. 3.0e9), found the text \"3 GPa\"",
            ),
            (
                "wanted string or table",
                "problem = ",
                "problem: expected \"plane\" or \"spatial\"",
            ),
            (
                "wanted string or table",
                "sweep = { load_min = 1, scale = ",
                "scale: expected \"log\" or \"linear\"",
            ),
            (
                "wanted string or table",
                "model =",
                "model: expected one of \"wide\", \"narrow\", \"strip\"",
            ),
            (
                "invalid type: floating point `1.5`, expected i64",
                "points = ",
                "points: expected a whole number, found the number 1.5",
            ),
            (
                "invalid type: integer `99999999999999999999` as i128, expected i64",
                "schema = ",
                "schema: expected a whole number, found the whole number 99999999999999999999, \
                 which is too large",
            ),
            (
                "unknown field `radiuss`, expected one of `model`, `radius`",
                "radiuss",
                "unknown key \"radiuss\"; allowed here: one of \"model\", \"radius\"",
            ),
            ("missing field `radius`", "", "missing key \"radius\""),
            (
                "invalid type: map, expected f64",
                "radius = ",
                "radius: expected a number (SI units, e.g. 3.0e9), found a table (or a date)",
            ),
        ];
        for (message, before, words) in cases {
            assert_eq!(reason(message, before), words);
        }
    }

    #[test]
    fn a_text_in_quotes_not_closed_is_said_in_words() {
        let err = crate::preset::parse("schema = 1\nname = \"a\u{e9}=b\n", "x.toml".as_ref());
        assert_eq!(
            err.unwrap_err().to_string(),
            "x.toml:2: a text in quotes is not closed: the closing \" is missing on this line"
        );
    }

    #[test]
    fn keys_and_positions_next_to_multibyte_characters() {
        assert_eq!(key_before("name = \"a\u{e9}="), None);
        assert_eq!(key_before("\u{e9}radius = "), Some("radius"));
        assert_eq!(key_before("x\u{1F600}load = "), Some("load"));
        let text = "a\u{20ac}b";
        assert_eq!(text_before(text, 2), "a");
        assert_eq!(text_before(text, 4), "a\u{20ac}");
        assert_eq!(text_before(text, 99), text);
    }
}
