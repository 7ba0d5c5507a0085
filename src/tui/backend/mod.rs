//! The explorer's terminal backend: ratatui's crossterm backend for everything but `draw`, whose
//! escape codes are shorter, for the map screens over SSH (`docs/performance.md`, "Bytes to
//! the terminal"). Per changed cell it writes only what changed in
//! ONE select-graphic-rendition code (foreground, background and attributes together, or a reset
//! and the new style when that is shorter), and moves the cursor by the shortest of a relative
//! move (`CSI n C` on the same row, `CR LF` or `CSI n B`/`CSI n A` to another row) and an
//! absolute `CSI r;c H`, or by writing again the few cells in between when that is shorter and
//! it knows what they hold: it keeps what it wrote (blank after a clear and at the start, in the
//! alternate screen just entered, as ratatui assumes too; unknown after a partial clear). It
//! starts every draw from a reset style and an unknown cursor, as ratatui's backend does; after
//! the last column (where a terminal holds the cursor until the next character) it moves by rows
//! from a carriage return only. tests/replay.rs replays its bytes through a terminal emulator.

use std::fmt::Write as _;
use std::io::{self, Write};

use ratatui::backend::{Backend, ClearType, CrosstermBackend, WindowSize};
use ratatui::buffer::Cell;
use ratatui::layout::{Position, Size};
use unicode_width::UnicodeWidthStr;

mod sgr;
pub use sgr::colour_bytes;
use sgr::{Pen, RESET, style};

/// ratatui's crossterm backend with a `draw` that writes fewer bytes.
pub struct Compact<W: Write> {
    inner: CrosstermBackend<W>,
    on_terminal: TerminalCells,
    /// The size to report instead of the terminal's (a replay in the tests).
    size: Option<Size>,
}

impl<W: Write> Compact<W> {
    /// A backend writing to `writer`, whose screen is blank.
    pub fn new(writer: W) -> Self {
        Compact {
            inner: CrosstermBackend::new(writer),
            on_terminal: TerminalCells::blank(),
            size: None,
        }
    }

    /// Reports `size` as the terminal's from now on (a replay through an emulator).
    #[cfg(test)]
    pub fn set_size(&mut self, size: Size) {
        self.size = Some(size);
    }
}

/// The most cells written again instead of a cursor motion (`CSI n C` is 3 bytes for one
/// column and 4 for up to 9, so more cells never write fewer bytes).
const REFILL: u16 = 3;

/// What the terminal shows, as far as this backend knows: the cells it wrote (None where it
/// does not know), and what is beyond them.
struct TerminalCells {
    rows: Vec<Vec<Option<Cell>>>,
    beyond: Option<Cell>,
}

impl TerminalCells {
    fn blank() -> TerminalCells {
        TerminalCells {
            rows: Vec::new(),
            beyond: Some(Cell::default()),
        }
    }

    fn unknown() -> TerminalCells {
        TerminalCells {
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
                match self.on_terminal.refill(cx, x, y, pen).filter(|_| cy == y) {
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
                self.on_terminal.set(x, y, Some(cell.clone()));
            } else {
                cursor = None;
                for k in 0..width.max(1) {
                    self.on_terminal.set(x.saturating_add(k), y, None);
                }
            }
        }
        if pen != RESET {
            out.push_str("\x1b[0m");
        }
        self.inner.write_all(out.as_bytes())
    }

    fn append_lines(&mut self, n: u16) -> io::Result<()> {
        self.on_terminal = TerminalCells::unknown();
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
        self.on_terminal = match clear_type {
            ClearType::All => TerminalCells::blank(),
            _ => TerminalCells::unknown(),
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
