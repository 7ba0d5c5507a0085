//! Select graphic rendition (SGR) codes of the explorer's backend: the shortest parameters that
//! turn one style into another in one code.

use std::fmt::Write as _;

use ratatui::buffer::Cell;
use ratatui::style::{Color, Modifier};

/// What a cell's text is drawn with.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) struct Pen {
    fg: Color,
    bg: Color,
    underline: Color,
    modifier: Modifier,
}

/// The style after a reset (`CSI 0 m`), with which every draw starts and ends.
pub(super) const RESET: Pen = Pen {
    fg: Color::Reset,
    bg: Color::Reset,
    underline: Color::Reset,
    modifier: Modifier::empty(),
};

impl Pen {
    pub(super) fn of(cell: &Cell) -> Pen {
        Pen {
            fg: cell.fg,
            bg: cell.bg,
            underline: cell.underline_color,
            modifier: cell.modifier,
        }
    }
}

/// The SGR parameters that set an attribute, and the one that clears it (bold and dim share 22).
const ATTRIBUTES: [(Modifier, &str, &str); 9] = [
    (Modifier::BOLD, "1", "22"),
    (Modifier::DIM, "2", "22"),
    (Modifier::ITALIC, "3", "23"),
    (Modifier::UNDERLINED, "4", "24"),
    (Modifier::SLOW_BLINK, "5", "25"),
    (Modifier::RAPID_BLINK, "6", "25"),
    (Modifier::REVERSED, "7", "27"),
    (Modifier::HIDDEN, "8", "28"),
    (Modifier::CROSSED_OUT, "9", "29"),
];

/// Appends `;p` (or `p` first) to the parameters.
fn param(out: &mut String, p: impl std::fmt::Display) {
    if !out.is_empty() {
        out.push(';');
    }
    let _ = write!(out, "{p}");
}

/// The parameters of a colour, `base` 30 for the foreground, 40 for the background, 50 for the
/// underline: the codes crossterm writes (38;5;n for the 16 named colours as for the others).
fn colour(out: &mut String, base: u8, c: Color) {
    let index = match c {
        Color::Reset => return param(out, base + 9),
        Color::Rgb(r, g, b) => {
            return param(out, format_args!("{};2;{r};{g};{b}", base + 8));
        }
        Color::Indexed(i) => i,
        Color::Black => 0,
        Color::Red => 1,
        Color::Green => 2,
        Color::Yellow => 3,
        Color::Blue => 4,
        Color::Magenta => 5,
        Color::Cyan => 6,
        Color::Gray => 7,
        Color::DarkGray => 8,
        Color::LightRed => 9,
        Color::LightGreen => 10,
        Color::LightYellow => 11,
        Color::LightBlue => 12,
        Color::LightMagenta => 13,
        Color::LightCyan => 14,
        Color::White => 15,
    };
    param(out, format_args!("{};5;{index}", base + 8));
}

/// Bytes of the parameter that sets a foreground or background colour (`38;5;n`, `39`, ...),
/// by which the heatmap weighs its choice of glyphs.
pub fn colour_bytes(c: Color) -> u32 {
    let mut s = String::new();
    colour(&mut s, 30, c);
    s.len() as u32
}

/// The parameters of `to`'s colours that differ from `from`'s.
fn colours(out: &mut String, from: Pen, to: Pen) {
    for (base, a, b) in [
        (30, from.fg, to.fg),
        (40, from.bg, to.bg),
        (50, from.underline, to.underline),
    ] {
        if a != b {
            colour(out, base, b);
        }
    }
}

/// The shortest SGR parameters that turn `from` into `to`: the changes alone, or a reset and
/// everything `to` has.
fn sgr(from: Pen, to: Pen) -> String {
    let mut changes = String::new();
    let removed = from.modifier - to.modifier;
    let mut cleared = Modifier::empty();
    for (m, _, off) in ATTRIBUTES {
        if removed.contains(m) && !cleared.contains(m) {
            param(&mut changes, off);
            cleared |= match off {
                "22" => Modifier::BOLD | Modifier::DIM,
                "25" => Modifier::SLOW_BLINK | Modifier::RAPID_BLINK,
                _ => m,
            };
        }
    }
    // what a shared clearing code took away from `to` is set again with what it adds
    let added = to.modifier - (from.modifier - cleared);
    for (m, on, _) in ATTRIBUTES {
        if added.contains(m) {
            param(&mut changes, on);
        }
    }
    colours(&mut changes, from, to);
    let mut fresh = String::from("0");
    for (m, on, _) in ATTRIBUTES {
        if to.modifier.contains(m) {
            param(&mut fresh, on);
        }
    }
    colours(&mut fresh, RESET, to);
    if fresh.len() < changes.len() {
        fresh
    } else {
        changes
    }
}

/// The escape that turns `from` into `to` (none when they are the same).
pub(super) fn style(from: Pen, to: Pen) -> String {
    if from == to {
        String::new()
    } else {
        format!("\x1b[{}m", sgr(from, to))
    }
}
