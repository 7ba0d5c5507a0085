//! Colours and styles, with the fallbacks for NO_COLOR and `--ascii`.

use std::borrow::Cow;

use ratatui::buffer::Buffer;
use ratatui::style::{Color, Modifier, Style};

use crate::tui::charts::palette;
use crate::tui::view::raster::Ink;

/// How to draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderOptions {
    /// ASCII only, on the whole screen: borders, ticks, arrows and marks (`ASCII_FORMS`), curves
    /// in characters instead of Braille, shades in characters.
    pub ascii: bool,
    /// Colours allowed (NO_COLOR unset).
    pub color: bool,
    /// 24-bit colour announced (COLORTERM=truecolor or 24bit); else the 256-colour palette.
    pub truecolor: bool,
}

const SERIES: [Color; 6] = [
    Color::Cyan,
    Color::Yellow,
    Color::Magenta,
    Color::Green,
    Color::Red,
    Color::Blue,
];

/// The characters of the curves in character mode, one per curve.
const GLYPHS: [char; 8] = ['*', '+', 'x', 'o', '#', '%', '&', '$'];

/// The characters of the dim parts of curves (where a model's check fails), one per curve as
/// `GLYPHS`: light marks, none of them a curve's or a mark line's (`:` with `--ascii`).
const DIM_GLYPHS: [char; 8] = ['.', ',', '\'', ';', '`', '~', '"', '^'];

/// The shades of the heatmap without colour, lightest first.
pub const SHADES: [char; 5] = [' ', '░', '▒', '▓', '█'];

/// The shades with `--ascii`, lightest first: the one ASCII ramp of every map and bar. No `+`
/// nor `-`, which read as a sign or a tick beside a value ("+ 0", "- -1"), and no `~`, `o`, `X`
/// or letter, which the maps draw over the shades (no contact, the preset's point, the cursor,
/// the regime map's lines).
pub const ASCII_SHADES: [char; 7] = [' ', '.', ':', '=', '*', '#', '@'];

/// The ASCII form of every non-ASCII character the explorer draws (`--ascii`): the one place
/// that decides it. Forms of one character replace a drawn cell; the longer ones (keys, "...")
/// replace text before it is laid out (`RenderOptions::text`). A character missing here is
/// drawn as `?`.
const ASCII_FORMS: [(char, &str); 32] = [
    ('─', "-"),
    ('│', "|"),
    ('┌', "+"),
    ('┐', "+"),
    ('└', "+"),
    ('┘', "+"),
    ('├', "+"),
    ('┤', "+"),
    ('┬', "+"),
    ('┴', "+"),
    ('┼', "+"),
    ('┊', ":"),
    ('┈', "-"),
    ('●', "@"),
    ('·', "."),
    ('◀', "<"),
    ('▶', ">"),
    ('↑', "^"),
    ('↓', "v"),
    ('←', "<"),
    ('→', ">"),
    ('–', "-"),
    ('—', "-"),
    ('ő', "o"),
    ('µ', "u"),
    ('░', "."),
    ('▒', ":"),
    ('▓', "#"),
    ('…', "..."),
    ('⏎', "Enter"),
    ('⌫', "Bksp"),
    ('⇧', "Shift"),
];

/// The ASCII form of `c` (`ASCII_FORMS`; `?` for a character it lacks).
fn ascii_form(c: char) -> &'static str {
    ASCII_FORMS
        .iter()
        .find(|(u, _)| *u == c)
        .map_or("?", |(_, a)| a)
}

impl RenderOptions {
    /// `text` as drawn: with `--ascii` every non-ASCII character in its ASCII form.
    pub fn text<'a>(self, text: &'a str) -> Cow<'a, str> {
        if !self.ascii || text.is_ascii() {
            return Cow::Borrowed(text);
        }
        Cow::Owned(
            text.chars()
                .map(|c| {
                    if c.is_ascii() {
                        c.to_string()
                    } else {
                        ascii_form(c).to_string()
                    }
                })
                .collect(),
        )
    }

    /// With `--ascii`, every drawn cell in ASCII: each character whose form is one character
    /// replaced by it (blocks of the colour map by a space in their colour); text with longer
    /// forms was replaced before it was laid out (`text`), and stays as drawn.
    pub fn to_ascii(self, buf: &mut Buffer) {
        if !self.ascii {
            return;
        }
        for cell in &mut buf.content {
            let mut chars = cell.symbol().chars();
            let (Some(c), None) = (chars.next(), chars.next()) else {
                if !cell.symbol().is_ascii() {
                    cell.set_char('?');
                }
                continue;
            };
            match c {
                _ if c.is_ascii() => {}
                // a half block shows its background's half; a full block its foreground
                '▀' | '▄' => {
                    cell.set_char(' ');
                }
                '█' => {
                    let fg = cell.fg;
                    cell.set_char(' ').set_bg(fg);
                }
                _ => {
                    let form = ascii_form(c);
                    let mut one = form.chars();
                    if let (Some(a), None) = (one.next(), one.next()) {
                        cell.set_char(a);
                    }
                }
            }
        }
    }

    /// Errors and warnings: red, or bold without colour.
    pub fn error(self) -> Style {
        if self.color {
            Style::default().fg(Color::Red)
        } else {
            Style::default().add_modifier(Modifier::BOLD)
        }
    }

    /// A verdict that holds: green, or plain.
    pub fn ok(self) -> Style {
        if self.color {
            Style::default().fg(Color::Green)
        } else {
            Style::default()
        }
    }

    /// A result for other inputs than the form's (shown while the current one is solving).
    pub fn stale(self) -> Style {
        Style::default().add_modifier(Modifier::DIM)
    }

    /// The selected row or list entry.
    pub fn selected(self) -> Style {
        Style::default().add_modifier(Modifier::REVERSED)
    }

    /// A group heading.
    pub fn heading(self) -> Style {
        Style::default().add_modifier(Modifier::BOLD)
    }

    /// The footer's key list.
    pub fn footer(self) -> Style {
        Style::default().add_modifier(Modifier::DIM)
    }

    /// The i-th curve of a chart.
    pub fn series(self, i: usize) -> Style {
        if self.color {
            Style::default().fg(SERIES[i % SERIES.len()])
        } else {
            Style::default()
        }
    }

    /// Curves are drawn in Braille dots (in colour, not `--ascii`); else one character per
    /// cell, each curve its own.
    pub fn braille(self) -> bool {
        self.color && !self.ascii
    }

    /// How the i-th curve of a plot is drawn.
    pub fn series_ink(self, i: usize) -> Ink {
        Ink {
            glyph: GLYPHS[i % GLYPHS.len()],
            solid: false,
            second: None,
            style: self.series(i),
        }
    }

    /// How marked points are drawn.
    pub fn marker_ink(self) -> Ink {
        let style = if self.color {
            Style::default()
                .fg(Color::White)
                .add_modifier(Modifier::BOLD)
        } else {
            Style::default().add_modifier(Modifier::BOLD)
        };
        Ink {
            glyph: if self.ascii { '@' } else { '●' },
            solid: true,
            second: None,
            style,
        }
    }

    /// How measured points are drawn (an overlaid data file) and their error bars: a diamond
    /// (`O` with `--ascii`) and a vertical line in a colour no curve has, bold without colour.
    pub fn data_inks(self) -> (Ink, Ink) {
        let style = if self.color {
            Style::default()
                .fg(Color::LightRed)
                .add_modifier(Modifier::BOLD)
        } else {
            Style::default().add_modifier(Modifier::BOLD)
        };
        let point = Ink {
            glyph: if self.ascii { 'O' } else { '◆' },
            solid: true,
            second: None,
            style,
        };
        let bar = Ink {
            glyph: if self.ascii { '|' } else { '│' },
            solid: true,
            second: None,
            style: style.remove_modifier(Modifier::BOLD),
        };
        (point, bar)
    }

    /// How the i-th curve of pin `pin` (from 0) is drawn: the pin's number, dim, in the curve's
    /// colour; in character mode the number and the curve's own glyph in turn ("1+1+" for the
    /// second curve of pin 1), so that each pinned curve is told apart without colour.
    pub fn pin_ink(self, pin: usize, i: usize) -> Ink {
        Ink {
            glyph: char::from_digit(pin as u32 + 1, 10).unwrap_or('#'),
            solid: true,
            second: (!self.braille()).then_some(GLYPHS[i % GLYPHS.len()]),
            style: self.series(i).add_modifier(Modifier::DIM),
        }
    }

    /// How a dim part of the i-th curve is drawn (where its model fails its validity check):
    /// the curve's colour, dim; without colour a '.' for every curve.
    pub fn dim_ink(self, i: usize) -> Ink {
        Ink {
            glyph: DIM_GLYPHS[i % DIM_GLYPHS.len()],
            solid: false,
            second: None,
            style: self.series(i).add_modifier(Modifier::DIM),
        }
    }

    /// A legend sample of an ink: a short line in its colour, its two characters in turn, or
    /// its character twice.
    pub fn sample(self, ink: Ink) -> String {
        if let Some(second) = ink.second {
            format!("{}{second}", ink.glyph)
        } else if self.braille() && !ink.solid {
            "──".into()
        } else if ink.solid && !ink.glyph.is_ascii_digit() {
            ink.glyph.to_string()
        } else {
            ink.glyph.to_string().repeat(2)
        }
    }

    /// Reference lines (mu, c = 0, the contact edges).
    pub fn mark(self) -> Style {
        Style::default().add_modifier(Modifier::DIM)
    }

    /// The characters of vertical and horizontal reference lines.
    pub fn mark_glyphs(self) -> (char, char) {
        if self.ascii {
            (':', '-')
        } else {
            ('┊', '┈')
        }
    }

    /// Shaded ranges: a dark background, or a dotted fill without colour.
    pub fn shaded(self) -> (char, Style) {
        match (self.color, self.ascii) {
            (true, _) => (' ', Style::default().bg(Color::Indexed(236))),
            (false, false) => ('·', Style::default()),
            (false, true) => ('.', Style::default()),
        }
    }

    /// The cursor line.
    pub fn cursor(self) -> Style {
        if self.color {
            Style::default().fg(Color::Yellow)
        } else {
            Style::default().add_modifier(Modifier::BOLD)
        }
    }

    /// The tick beside a colour bar, before its value: with `--ascii` a space, as every ASCII
    /// tick would read as a shade of the bar or a sign ("++0", "-+-0.5").
    pub fn bar_tick(self) -> char {
        if self.ascii { ' ' } else { '┤' }
    }

    /// The cursor's character on cells without data.
    pub fn cursor_glyph(self) -> char {
        if self.ascii { '|' } else { '│' }
    }

    /// The regime map's colour of a level of the quantised viridis map: 24-bit, or the nearest
    /// of the 256-colour palette.
    pub fn heat(self, level: usize) -> Color {
        if self.truecolor {
            let (r, g, b) = palette::level_colour(level);
            Color::Rgb(r, g, b)
        } else {
            Color::Indexed(palette::level_256(level))
        }
    }

    /// The colours of `n` filled bands of the pressure map (`palette::band_colour`): 24-bit, or
    /// distinct colours of the 256-colour palette.
    pub fn bands(self, n: usize) -> Vec<Color> {
        if self.truecolor {
            (0..n)
                .map(|band| {
                    let (r, g, b) = palette::band_colour(band, n);
                    Color::Rgb(r, g, b)
                })
                .collect()
        } else {
            palette::bands_256(n)
                .into_iter()
                .map(Color::Indexed)
                .collect()
        }
    }

    /// How the heatmap draws an empty value (no contact), apart from every level and shade: its
    /// character without colour (`·`, or `~` with `--ascii`) and its colour (`palette::EMPTY`).
    pub fn empty(self) -> (char, Color) {
        let glyph = if self.ascii { '~' } else { '·' };
        let grey = if self.truecolor {
            let (r, g, b) = palette::EMPTY;
            Color::Rgb(r, g, b)
        } else {
            Color::Indexed(palette::EMPTY_256)
        };
        (glyph, grey)
    }

    /// The shade of t in [0, 1] without colour.
    pub fn shade(self, t: f64) -> char {
        let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
        let ramp: &[char] = if self.ascii { &ASCII_SHADES } else { &SHADES };
        ramp[(t * (ramp.len() - 1) as f64).round() as usize]
    }
}
