//! Multi-byte text at every byte position of what a user types into a preset: the file (read from
//! disk), `--set KEY=VALUE`, `--vary KEY=FROM:TO[:N][:log]`, an output name and the explorer's
//! typed values (the same library calls the form and the sweep form make). Never a panic; a file
//! either loads or is refused as `path:line: reason`, a typed value either applies or says why.

use std::path::Path;
use std::time::Duration;

use assert_cmd::Command;
use wearlab::preset::{BUNDLED, Key, Preset, bundled, load, parse, resolve_save_path};
use wearlab::sweeps::axis::Axis;
use wearlab::sweeps::quantity::QuantityKey;
use wearlab::units::parse_si;

/// Two-, three- and four-byte characters, a combining mark alone and after a letter, a byte
/// order mark, and characters before `=` and a line's end (the reader's wording looks back from
/// where it stopped for `key =`, over the multi-byte character).
const INSERTS: [&str; 10] = [
    "é",
    "€",
    "😀",
    "\u{301}",
    "e\u{301}",
    "\u{feff}",
    "é=",
    "x€ = ",
    "é=\n",
    "a😀=b\n",
];

/// A preset of each kind: a plane one with a non-ASCII description ("—"), a spatial one, one
/// whose `[explore]` section is a map, one whose section is a sweep.
const FILES: [&str; 4] = [
    "wear-dominated.toml",
    "jgh-egg-box.toml",
    "friction-or-wear-map.toml",
    "coating-thickness-sweep.toml",
];

/// `bytes` with `insert` at byte `at` (which may fall inside a character of the file: the result
/// is then not UTF-8, as a file damaged on disk is not).
fn inserted(bytes: &[u8], at: usize, insert: &[u8]) -> Vec<u8> {
    [&bytes[..at], insert, &bytes[at..]].concat()
}

/// Reads the bytes as a preset: UTF-8 text as `load` parses it after reading, other bytes from a
/// file (where `load` refuses them). An error must be `path:line: reason` with a line of the file.
fn load_checked(path: &Path, bytes: &[u8], from_disk: bool) {
    let result = match std::str::from_utf8(bytes) {
        Ok(text) if !from_disk => parse(text, path),
        _ => {
            std::fs::write(path, bytes).unwrap();
            load(path)
        }
    };
    let Err(e) = result else {
        return;
    };
    let lines = 1 + bytes.iter().filter(|&&b| b == b'\n').count();
    let text = e.to_string();
    let context = || String::from_utf8_lossy(bytes).into_owned();
    let line = e
        .line
        .unwrap_or_else(|| panic!("{text}: no line\n{}", context()));
    assert!((1..=lines).contains(&line), "{text}\n{}", context());
    assert!(!e.reason.trim().is_empty(), "{text}\n{}", context());
    assert_eq!(text, format!("{}:{line}: {}", path.display(), e.reason));
}

#[test]
fn multibyte_text_at_every_byte_of_a_preset_file_loads_or_names_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("x.toml");
    let mut cases = 0;
    for file in FILES {
        let bytes = BUNDLED.iter().find(|b| b.file == file).unwrap().text;
        let bytes = bytes.as_bytes();
        // the file on disk for the preset with a multi-byte character of its own ("—")
        let from_disk = !bytes.is_ascii();
        for (n, insert) in INSERTS.iter().enumerate() {
            for at in 0..=bytes.len() {
                let mutated = inserted(bytes, at, insert.as_bytes());
                load_checked(&path, &mutated, from_disk && n == 0);
                cases += 1;
            }
        }
        if from_disk {
            // a character cut short: its first byte alone, also inside the file's own character
            for at in 0..=bytes.len() {
                load_checked(&path, &inserted(bytes, at, &[0xc3]), true);
            }
        }
    }
    assert!(cases > 40_000, "{cases}");
}

#[test]
fn the_reported_file_is_refused_with_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("x.toml");
    std::fs::write(&path, "schema = 1\nname = \"a\u{e9}=b\n").unwrap();
    let out = Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .timeout(Duration::from_secs(60))
        .arg("solve")
        .arg(&path)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains(&format!("{}:2: ", path.display())),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
}

/// Every text with each of `INSERTS` at each of its character boundaries (a typed text is UTF-8).
fn variants(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    for insert in INSERTS {
        for at in (0..=text.len()).filter(|&i| text.is_char_boundary(i)) {
            out.push(format!("{}{insert}{}", &text[..at], &text[at..]));
        }
    }
    out
}

fn presets() -> Vec<Preset> {
    FILES.iter().map(|f| bundled(f).unwrap().unwrap()).collect()
}

/// An error of a typed value says something in words.
fn refused(result: Result<impl Sized, String>, typed: &str) {
    if let Err(why) = result {
        assert!(!why.trim().is_empty(), "{typed:?}: empty reason");
    }
}

#[test]
fn multibyte_text_in_set_and_typed_values_applies_or_says_why() {
    for preset in presets() {
        for key in Key::all(&preset) {
            let param = key.param();
            let value = match param.choices() {
                Some(names) => names[0].to_string(),
                None => format!("{} {}", preset.get(key).unwrap(), param.unit),
            };
            let setting = format!("{key}={value}");
            for typed in variants(&setting) {
                refused(preset.with_settings(&[&typed]), &typed);
            }
            for typed in variants(&value) {
                refused(preset.clone().assign_text(key, &typed), &typed);
                refused(parse_si(&typed, param.unit), &typed);
            }
            for typed in variants(&key.to_string()) {
                refused(preset.key(&typed), &typed);
            }
        }
    }
}

#[test]
fn multibyte_text_in_vary_outputs_and_save_names_applies_or_says_why() {
    for preset in presets() {
        let Some(explore) = &preset.explore else {
            continue;
        };
        let a = &explore.axes[0];
        let vary = format!(
            "{}={} {unit}:{} {unit}:{}:log",
            a.key,
            a.range.min,
            a.range.max,
            a.range.points,
            unit = a.key.param().unit
        );
        for typed in variants(&vary) {
            refused(Axis::parse(&preset, &typed, 20), &typed);
        }
        for typed in variants(&explore.quantity.to_string()) {
            refused(QuantityKey::parse(&typed, &preset), &typed);
        }
    }
    let home = Path::new("/home/ana");
    for typed in variants("~/labs/my lab.toml") {
        refused(resolve_save_path(&typed, Some(home), Some(home)), &typed);
    }
}
