//! The explorer's terminal backend: ratatui's crossterm backend for everything but `draw`, whose
//! escape codes are shorter so that a full redraw of the map screen stays under 8 KB over SSH
//! (issue 10; README, "Bytes to the terminal"). Per changed cell it writes only what changed in
//! ONE select-graphic-rendition code (foreground, background and attributes together, or a reset
//! and the new style when that is shorter), and moves the cursor by the shortest of a relative
//! move (`CSI n C` on the same row, `CR LF` or `CSI n B`/`CSI n A` to another row) and an
//! absolute `CSI r;c H`, or by writing again the few cells in between when that is shorter and
//! it knows what they hold: it keeps what it wrote (blank after a clear and at the start, in the
//! alternate screen just entered, as ratatui assumes too; unknown after a partial clear). It
//! starts every draw from a reset style and an unknown cursor, as ratatui's backend does; after
//! the last column (where a terminal holds the cursor until the next character) it moves by rows
//! from a carriage return only. tests/backend.rs replays its bytes through a terminal emulator.

use std::fmt::Write as _;
use std::io::{self, Write};

use ratatui::backend::{Backend, ClearType, CrosstermBackend, WindowSize};
use ratatui::buffer::Cell;
use ratatui::layout::{Position, Size};
use ratatui::style::{Color, Modifier};
use unicode_width::UnicodeWidthStr;

/// ratatui's crossterm backend with a `draw` that writes fewer bytes.
pub struct Compact<W: Write> {
    inner: CrosstermBackend<W>,
    shown: Shown,
    /// The size to report instead of the terminal's (a replay in the tests).
    size: Option<Size>,
}

impl<W: Write> Compact<W> {
    /// A backend writing to `writer`, whose screen is blank.
    pub fn new(writer: W) -> Self {
        Compact {
            inner: CrosstermBackend::new(writer),
            shown: Shown::blank(),
            size: None,
        }
    }

    /// Reports `size` as the terminal's from now on (a replay through an emulator).
    #[cfg(test)]
    pub fn set_size(&mut self, size: Size) {
        self.size = Some(size);
    }
}

/// The most cells written again instead of a cursor motion (which is at most 7 bytes).
const REFILL: u16 = 6;

/// What the terminal shows, as far as this backend knows: the cells it wrote (None where it
/// does not know), and what is beyond them.
struct Shown {
    rows: Vec<Vec<Option<Cell>>>,
    beyond: Option<Cell>,
}

impl Shown {
    fn blank() -> Shown {
        Shown {
            rows: Vec::new(),
            beyond: Some(Cell::default()),
        }
    }

    fn unknown() -> Shown {
        Shown {
            rows: Vec::new(),
            beyond: None,
        }
    }

    fn get(&self, x: u16, y: u16) -> Option<&Cell> {
        match self
            .rows
            .get(usize::from(y))
            .and_then(|r| r.get(usize::from(x)))
        {
            Some(cell) => cell.as_ref(),
            None => self.beyond.as_ref(),
        }
    }

    fn set(&mut self, x: u16, y: u16, cell: Option<Cell>) {
        let (x, y) = (usize::from(x), usize::from(y));
        if self.rows.len() <= y {
            self.rows.resize(y + 1, Vec::new());
        }
        let row = &mut self.rows[y];
        if row.len() <= x {
            row.resize(x + 1, self.beyond.clone());
        }
        row[x] = cell;
    }

    /// The cells from column `from` to `to` (excluded) of row `y` written again starting with
    /// `pen`, and the pen after them; None unless each is known and one column wide.
    fn refill(&self, from: u16, to: u16, y: u16, mut pen: Pen) -> Option<(String, Pen)> {
        if to <= from || to - from > REFILL {
            return None;
        }
        let mut out = String::new();
        for x in from..to {
            let cell = self.get(x, y).filter(|c| c.symbol().width() == 1)?;
            let next = Pen::of(cell);
            out.push_str(&style(pen, next));
            out.push_str(cell.symbol());
            pen = next;
        }
        Some((out, pen))
    }
}

/// What a cell's text is drawn with.
#[derive(Clone, Copy, PartialEq, Eq)]
struct Pen {
    fg: Color,
    bg: Color,
    underline: Color,
    modifier: Modifier,
}

/// The style after a reset (`CSI 0 m`), with which every draw starts and ends.
const RESET: Pen = Pen {
    fg: Color::Reset,
    bg: Color::Reset,
    underline: Color::Reset,
    modifier: Modifier::empty(),
};

impl Pen {
    fn of(cell: &Cell) -> Pen {
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
fn style(from: Pen, to: Pen) -> String {
    if from == to {
        String::new()
    } else {
        format!("\x1b[{}m", sgr(from, to))
    }
}

/// `CSI n <final>`, without n when it is 1.
fn csi(out: &mut String, n: u16, end: char) {
    match n {
        0 => {}
        1 => {
            let _ = write!(out, "\x1b[{end}");
        }
        _ => {
            let _ = write!(out, "\x1b[{n}{end}");
        }
    }
}

/// The shortest codes moving the cursor from `from` (None: unknown) to (x, y). A column of
/// `from` may be one past the last (after a character there): then only moves that start with a
/// carriage return, or that go down by `CSI n B` and right, are used.
fn motion(from: Option<(u16, u16)>, x: u16, y: u16) -> String {
    let mut best = String::from("\x1b[");
    match (x, y) {
        (0, 0) => {}
        (0, _) => {
            let _ = write!(best, "{}", y + 1);
        }
        _ => {
            let _ = write!(best, "{};{}", y + 1, x + 1);
        }
    }
    best.push('H');
    let Some((cx, cy)) = from else {
        return best;
    };
    let mut candidates = Vec::with_capacity(2);
    // from a carriage return: rows by line feeds or CSI n B / CSI n A, then right
    let mut cr = String::from("\r");
    if y > cy {
        let mut feeds = "\n".repeat(usize::from(y - cy));
        let mut down = String::new();
        csi(&mut down, y - cy, 'B');
        if down.len() < feeds.len() {
            feeds = down;
        }
        cr.push_str(&feeds);
    } else {
        csi(&mut cr, cy - y, 'A');
    }
    csi(&mut cr, x, 'C');
    candidates.push(cr);
    // or keep the column when the target is not left of it
    if x >= cx {
        let mut keep = String::new();
        if y > cy {
            csi(&mut keep, y - cy, 'B');
        } else {
            csi(&mut keep, cy - y, 'A');
        }
        csi(&mut keep, x - cx, 'C');
        candidates.push(keep);
    }
    for c in candidates {
        if c.len() < best.len() {
            best = c;
        }
    }
    best
}

impl<W: Write> Backend for Compact<W> {
    type Error = io::Error;

    fn draw<'a, I>(&mut self, content: I) -> io::Result<()>
    where
        I: Iterator<Item = (u16, u16, &'a Cell)>,
    {
        let mut out = String::new();
        let mut pen = RESET;
        let mut cursor: Option<(u16, u16)> = None;
        for (x, y, cell) in content {
            let next = Pen::of(cell);
            if let Some((cx, cy)) = cursor.filter(|&c| c != (x, y)) {
                let moved = motion(cursor, x, y);
                match self.shown.refill(cx, x, y, pen).filter(|_| cy == y) {
                    Some((text, after))
                        if text.len() + style(after, next).len()
                            < moved.len() + style(pen, next).len() =>
                    {
                        out.push_str(&text);
                        pen = after;
                    }
                    _ => out.push_str(&moved),
                }
            } else if cursor.is_none() {
                out.push_str(&motion(None, x, y));
            }
            out.push_str(&style(pen, next));
            pen = next;
            out.push_str(cell.symbol());
            // where the terminal's cursor is now is known only after a one-column symbol, and
            // what the columns under a wider one show is not
            let width = cell.symbol().width() as u16;
            if width == 1 {
                cursor = Some((x + 1, y));
                self.shown.set(x, y, Some(cell.clone()));
            } else {
                cursor = None;
                for k in 0..width.max(1) {
                    self.shown.set(x.saturating_add(k), y, None);
                }
            }
        }
        if pen != RESET {
            out.push_str("\x1b[0m");
        }
        self.inner.write_all(out.as_bytes())
    }

    fn append_lines(&mut self, n: u16) -> io::Result<()> {
        self.shown = Shown::unknown();
        self.inner.append_lines(n)
    }

    fn hide_cursor(&mut self) -> io::Result<()> {
        self.inner.hide_cursor()
    }

    fn show_cursor(&mut self) -> io::Result<()> {
        self.inner.show_cursor()
    }

    fn get_cursor_position(&mut self) -> io::Result<Position> {
        self.inner.get_cursor_position()
    }

    fn set_cursor_position<P: Into<Position>>(&mut self, position: P) -> io::Result<()> {
        self.inner.set_cursor_position(position)
    }

    fn clear(&mut self) -> io::Result<()> {
        self.clear_region(ClearType::All)
    }

    fn clear_region(&mut self, clear_type: ClearType) -> io::Result<()> {
        // the style is reset between draws, so a cleared cell is blank
        self.shown = match clear_type {
            ClearType::All => Shown::blank(),
            _ => Shown::unknown(),
        };
        self.inner.clear_region(clear_type)
    }

    fn size(&self) -> io::Result<Size> {
        match self.size {
            Some(size) => Ok(size),
            None => self.inner.size(),
        }
    }

    fn window_size(&mut self) -> io::Result<WindowSize> {
        self.inner.window_size()
    }

    fn flush(&mut self) -> io::Result<()> {
        Backend::flush(&mut self.inner)
    }
}
