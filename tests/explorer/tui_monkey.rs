//! A monkey in a pseudo-terminal: the real binary on every bundled preset, a bounded number of
//! random keys and window resizes (deterministic by seed, `TUI_MONKEY_SEED`), then SIGTERM. No
//! panic, and the terminal restored (the restore sequences last, out of raw mode) whether the
//! monkey's keys quit the explorer or the signal ends it. `src/tui/tests/monkey.rs` walks far
//! longer through `update` and `view`; this one goes through the event loop, the terminal and the
//! worker threads of the binary.
#![cfg(target_os = "linux")]

use std::path::Path;
use std::time::Duration;

use crate::tui_signals::{Explorer, LEAVE_ALTERNATE, SHOW_CURSOR};

/// Keys and resizes sent to each preset.
const ACTIONS: usize = 60;
/// The seed when `TUI_MONKEY_SEED` does not give one.
const SEED: u64 = 23;

/// The keys a user may type: arrows, Tab and Shift-Tab, Enter, Esc, Backspace, the explorer's
/// letters, digits, a multi-byte letter.
const KEYS: &[&[u8]] = &[
    b"\x1b[A",
    b"\x1b[B",
    b"\x1b[C",
    b"\x1b[D",
    b"\t",
    b"\x1b[Z",
    b"\r",
    b"\x1b",
    b"\x7f",
    b"+",
    b"-",
    b"0",
    b"1",
    b"5",
    b"e",
    b"9",
    b".",
    b"m",
    b"s",
    b"t",
    b"o",
    b"i",
    b"?",
    b"g",
    b"x",
    b"c",
    b"u",
    b"r",
    b"p",
    b"w",
    b"h",
    b"l",
    b" ",
    b"\xc3\xa9",
    b"/",
    b"q",
];

/// A xorshift generator: the same walk on every machine.
struct Rng(u64);

impl Rng {
    fn below(&mut self, n: usize) -> usize {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 % n as u64) as usize
    }
}

#[test]
fn a_monkey_in_a_pty_on_every_bundled_preset_breaks_nothing() {
    let seed = std::env::var("TUI_MONKEY_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(SEED);
    let mut rng = Rng(seed.max(1));
    // the presets (and their data files) copied, so that a save writes only in the copy
    let dir = tempfile::tempdir().unwrap();
    let presets = Path::new(env!("CARGO_MANIFEST_DIR")).join("presets");
    let mut names: Vec<String> = std::fs::read_dir(&presets)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    for name in &names {
        std::fs::copy(presets.join(name), dir.path().join(name)).unwrap();
    }
    for name in names.iter().filter(|n| n.ends_with(".toml")) {
        let mut explorer = Explorer::start(dir.path(), &[name]);
        for _ in 0..ACTIONS {
            if explorer.exited() {
                break;
            }
            if rng.below(8) == 0 {
                explorer.resize(1 + rng.below(200) as u16, 1 + rng.below(60) as u16);
            } else {
                explorer.type_bytes(KEYS[rng.below(KEYS.len())]);
            }
            std::thread::sleep(Duration::from_millis(5));
        }
        let (bytes, status, modes) = explorer.end(libc::SIGTERM);
        let text = String::from_utf8_lossy(&bytes);
        assert!(!text.contains("panicked"), "{name}, seed {seed}: {text}");
        assert!(
            matches!(status.code(), Some(0 | 143)),
            "{name}, seed {seed}: {status:?}"
        );
        assert!(
            bytes.ends_with(&[SHOW_CURSOR, LEAVE_ALTERNATE].concat()),
            "{name}, seed {seed}: the restore is not last: {:?}",
            String::from_utf8_lossy(&bytes[bytes.len().saturating_sub(200)..])
        );
        assert_eq!(
            modes & (libc::ICANON | libc::ECHO),
            libc::ICANON | libc::ECHO,
            "{name}, seed {seed}: left in raw mode"
        );
    }
}
