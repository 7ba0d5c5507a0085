//! The legend of a plot: where it goes (never on data while there is room elsewhere) and how
//! its entries are written.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;

use crate::tui::view::raster::Raster;

/// One legend line: a sample of how the thing is drawn, and its name.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// Two columns showing the curve's look ("──" in its colour, "**", "11", "●").
    pub sample: String,
    /// The sample's style.
    pub style: Style,
    /// What it is.
    pub text: String,
}

impl Entry {
    /// Columns taken: sample, space, text.
    pub fn width(&self) -> usize {
        self.sample.chars().count() + 1 + self.text.chars().count()
    }

    /// Writes the entry at (x, y), at most `width` columns.
    pub fn render(&self, buf: &mut Buffer, x: u16, y: u16, width: u16) {
        let text = format!(" {}", self.text);
        let (end, _) = buf.set_stringn(x, y, &self.sample, width as usize, self.style);
        let used = end.saturating_sub(x);
        buf.set_stringn(
            end,
            y,
            &text,
            width.saturating_sub(used) as usize,
            Style::default(),
        );
    }
}

/// Where a plot's legend goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// In the header row, right of the y axis title.
    Header,
    /// Beside the title in the header row and in rows of its own above the plot: this many.
    Rows(u16),
    /// Inside the plot area at this corner (column, row of the plot area).
    Corner(u16, u16),
    /// Inside the plot area as packed lines across its width: from this row, this many rows.
    Band(u16, u16),
}

/// The columns the entries take in one line, two spaces apart.
pub fn line_width(entries: &[Entry]) -> usize {
    entries.iter().map(|e| e.width() + 2).sum::<usize>()
}

/// The key that lists a folded legend in full (the `i` box).
pub const IN_FULL_KEY: char = 'i';

/// Lines that the entries take when packed whole, two spaces apart: the first line `first`
/// columns wide (beside the y title), the others `width`.
pub fn lines_needed(entries: &[Entry], first: usize, width: usize) -> u16 {
    packed(entries, first, width).len() as u16
}

/// The entries that `lines` packed lines (`lines_needed`' widths) show whole: all of them when
/// they fit; else as many as fit in order with "+N more: i" after them, counting what is left
/// out (an entry wider than its line is left out rather than cut).
pub fn fold(entries: &[Entry], first: usize, width: usize, lines: u16) -> Vec<Entry> {
    let whole = |e: &Entry| e.width() <= width;
    if lines_needed(entries, first, width) <= lines && entries.iter().all(whole) {
        return entries.to_vec();
    }
    let shown: Vec<&Entry> = entries.iter().filter(|e| whole(e)).collect();
    (0..=shown.len())
        .rev()
        .map(|keep| {
            let mut kept: Vec<Entry> = shown[..keep].iter().map(|e| (*e).clone()).collect();
            kept.push(more(entries.len() - keep));
            kept
        })
        .find(|kept| lines_needed(kept, first, width) <= lines)
        .unwrap_or_else(|| vec![more(entries.len())])
}

/// The entry that counts the entries a folded legend leaves out ("+3 more: i").
fn more(n: usize) -> Entry {
    Entry {
        sample: String::new(),
        style: Style::default(),
        text: format!("+{n} more: {IN_FULL_KEY}"),
    }
}

/// The legend box's size inside the plot: the widest entry (and a column apart), one row each.
pub fn box_size(entries: &[Entry]) -> (u16, u16) {
    let w = entries.iter().map(Entry::width).max().unwrap_or(0) + 1;
    (w as u16, entries.len() as u16)
}

/// The corner of the plot area where the legend box covers no data cell: top right, top left,
/// bottom right, bottom left, in that order of preference. With `fallback`, the corner covering
/// the fewest when none is empty.
pub fn corner(raster: &Raster, plot: Rect, entries: &[Entry], fallback: bool) -> Option<Place> {
    let (w, h) = box_size(entries);
    if w > plot.width || h > plot.height {
        return None;
    }
    let (right, bottom) = (plot.width - w, plot.height - h);
    let corners = [(right, 0), (0, 0), (right, bottom), (0, bottom)];
    let covered = |&(x, y): &(u16, u16)| {
        raster.count(Rect {
            x,
            y,
            width: w,
            height: h,
        })
    };
    match corners.iter().find(|c| covered(c) == 0) {
        Some(&(x, y)) => Some(Place::Corner(x, y)),
        None if fallback => corners
            .iter()
            .min_by_key(|c| covered(c))
            .map(|&(x, y)| Place::Corner(x, y)),
        None => None,
    }
}

/// Rows of the plot area that can hold the entries packed as lines, right-aligned as
/// `render_lines` writes them, with no data cell under them: the top rows, else the bottom
/// ones, else the highest free ones; at least one row is left to the data.
pub fn band(raster: &Raster, plot: Rect, entries: &[Entry]) -> Option<Place> {
    let lines = packed(entries, plot.width as usize, plot.width as usize);
    let rows = lines.len() as u16;
    if rows == 0 || rows >= plot.height {
        return None;
    }
    let last = plot.height - rows;
    [0, last].into_iter().chain(1..last).find_map(|y| {
        let clear = lines.iter().enumerate().all(|(i, line)| {
            let width = line_span(line).min(plot.width as usize) as u16;
            let row = y + i as u16;
            raster.count(Rect::new(plot.width - width, row, width, 1)) == 0
        });
        clear.then_some(Place::Band(y, rows))
    })
}

/// The entries packed whole into lines, two spaces apart: the first `first` columns wide, the
/// others `width` (the first line stays empty when its first entry is wider than `first` and
/// narrower lines follow: the title's row keeps no half entry).
fn packed(entries: &[Entry], first: usize, width: usize) -> Vec<Vec<&Entry>> {
    if entries.is_empty() {
        return Vec::new();
    }
    let mut lines: Vec<Vec<&Entry>> = vec![Vec::new()];
    let mut used = 0;
    for e in entries {
        let line = lines.last().expect("one line at least");
        let room = if lines.len() == 1 { first } else { width };
        let gap = if line.is_empty() { 0 } else { 2 };
        let wider = lines.len() == 1 && first < width;
        if used + gap + e.width() > room && (!line.is_empty() || wider) {
            lines.push(Vec::new());
            used = 0;
        } else {
            used += gap;
        }
        used += e.width();
        lines.last_mut().expect("one line at least").push(e);
    }
    lines
}

/// The columns a packed line takes.
fn line_span(line: &[&Entry]) -> usize {
    line.iter().map(|e| e.width()).sum::<usize>() + 2 * line.len().saturating_sub(1)
}

/// Writes the entries as packed lines into `area` (header row or legend rows), right-aligned.
pub fn render_lines(entries: &[Entry], buf: &mut Buffer, area: Rect) {
    let lines = packed(entries, area.width as usize, area.width as usize);
    for (row, line) in lines.iter().enumerate().take(area.height as usize) {
        render_line(
            line,
            buf,
            Rect::new(area.x, area.y + row as u16, area.width, 1),
        );
    }
}

/// Writes the entries as packed lines, right-aligned: the first in `first` (the title's row
/// right of the title), the others in the rows of `below`.
pub fn render_beside_title(entries: &[Entry], buf: &mut Buffer, first: Rect, below: Rect) {
    let lines = packed(entries, first.width as usize, below.width as usize);
    for (row, line) in lines.iter().enumerate().take(below.height as usize + 1) {
        let area = match row {
            0 => first,
            _ => Rect::new(below.x, below.y + row as u16 - 1, below.width, 1),
        };
        render_line(line, buf, area);
    }
}

/// Writes one packed line right-aligned in the row `area`.
fn render_line(line: &[&Entry], buf: &mut Buffer, area: Rect) {
    let mut x = area.x + (area.width as usize).saturating_sub(line_span(line)) as u16;
    for e in line {
        e.render(buf, x, area.y, area.x + area.width - x);
        x += e.width() as u16 + 2;
    }
}

/// Writes the entries as a box at the top left corner (x, y), clearing it first.
pub fn render_box(entries: &[Entry], buf: &mut Buffer, x: u16, y: u16) {
    let (w, _) = box_size(entries);
    for (i, e) in entries.iter().enumerate() {
        let row = y + i as u16;
        buf.set_stringn(x, row, " ".repeat(w as usize), w as usize, Style::default());
        e.render(buf, x + 1, row, w - 1);
    }
}
