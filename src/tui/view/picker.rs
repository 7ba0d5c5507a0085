//! The preset picker (`o`): the presets in a list, and under it the highlighted preset's source
//! and whole description, wrapped at spaces; a list longer than its rows says which it shows
//! and where more are; a description longer than its pane scrolls (PgUp/PgDn), the window's
//! border saying when more is below.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Clear, Paragraph};
use unicode_width::{UnicodeWidthChar, UnicodeWidthStr};

use crate::tui::app::{PickerEntry, found};
use crate::tui::view::popups::{help_rect, paragraphs};
use crate::tui::view::theme::RenderOptions;
use crate::tui::view::wrap;

/// The window, its list and its description pane (under a top border) on `screen`: the window
/// over everything but the message and key lines, up to 100 columns wide; the list at most
/// half of it, the description the rest.
fn areas(screen: Rect, entries: usize) -> (Rect, Rect, Rect) {
    let rect = help_rect(screen);
    let inner = Block::default().borders(Borders::ALL).inner(rect);
    let list_height = (entries as u16).min(inner.height.saturating_sub(1) / 2);
    let [list, desc] =
        Layout::vertical([Constraint::Length(list_height), Constraint::Min(3)]).areas(inner);
    (rect, list, desc)
}

/// The description pane's lines for an entry, `width` wide: its source, then its description
/// (or why it cannot be opened).
pub fn lines(entry: &PickerEntry, width: usize) -> Vec<Line<'static>> {
    let mut lines: Vec<Line> = wrap(&entry.source, width)
        .into_iter()
        .map(Line::from)
        .collect();
    match &entry.preset {
        Ok(p) => lines.extend(paragraphs(&p.description, width)),
        Err(why) => lines.extend(
            wrap(&format!("cannot be opened: {why}"), width)
                .into_iter()
                .map(Line::from),
        ),
    }
    lines
}

/// The largest scroll of the highlighted entry's description on `screen` (0 when it fits), the
/// list showing what `filter` finds.
pub fn last(entries: &[PickerEntry], selected: usize, filter: &str, screen: Rect) -> u16 {
    let shown = found(entries, filter);
    let (_, _, desc) = areas(screen, row_count(entries, &shown));
    let text = Block::default().borders(Borders::TOP).inner(desc);
    let n = entries
        .get(selected)
        .map_or(0, |e| lines(e, text.width as usize).len());
    u16::try_from(n.saturating_sub(text.height as usize)).unwrap_or(u16::MAX)
}

/// Where the list stands when it does not show all its rows (presets and their folders' headings),
/// on the border under it: " rows 1-9 of 16 (more below) "; "" when all are shown. In words: an arrow's ASCII form ("v more")
/// would read as a key.
fn position(offset: usize, rows: usize, count: usize) -> String {
    if rows == 0 || count <= rows {
        return String::new();
    }
    let last = (offset + rows).min(count);
    let more = match (offset > 0, last < count) {
        (true, true) => "above and below",
        (true, false) => "above",
        _ => "below",
    };
    format!(" rows {}-{last} of {count} (more {more}) ", offset + 1)
}

/// How many rows the list of `shown` takes: its entries and a heading for each folder.
fn row_count(entries: &[PickerEntry], shown: &[usize]) -> usize {
    let headings = (0..shown.len())
        .filter(|&k| k == 0 || entries[shown[k - 1]].folder != entries[shown[k]].folder)
        .count();
    shown.len() + headings
}

/// `text` in at most `width` columns, ended by "…" where it is cut.
fn fitted(text: &str, width: usize, style: RenderOptions) -> String {
    if text.width() <= width {
        return text.to_string();
    }
    let more = style.text("…");
    let mut out = String::new();
    for c in text.chars() {
        if out.width() + c.width().unwrap_or(0) + more.width() > width {
            break;
        }
        out.push(c);
    }
    out + &more
}

/// The list's rows: a heading where the folder changes, then each entry `shown` (indices of
/// `entries`); with the row of `selected` (None when it is not shown).
fn rows(
    entries: &[PickerEntry],
    shown: &[usize],
    selected: usize,
    style: RenderOptions,
    width: usize,
) -> (Vec<Line<'static>>, Option<usize>) {
    let mut lines = Vec::new();
    let mut at = None;
    let mut folder: Option<&str> = None;
    for &i in shown {
        let e = &entries[i];
        if folder != Some(e.folder.as_str()) {
            folder = Some(e.folder.as_str());
            lines.push(Line::styled(e.folder.clone(), style.heading()));
        }
        let mark = if e.preset.is_err() { "!" } else { " " };
        let text = fitted(&format!("{mark} {}", e.title), width, style);
        if i == selected {
            at = Some(lines.len());
            lines.push(Line::styled(text, style.selected()));
        } else {
            lines.push(Line::from(text));
        }
    }
    (lines, at)
}

/// Draws the picker: the presets `filter` finds under their folders, the description of
/// `selected` scrolled by `scroll` lines.
pub fn draw(
    entries: &[PickerEntry],
    selected: usize,
    scroll: u16,
    filter: &str,
    style: RenderOptions,
    frame: &mut Frame,
    area: Rect,
) {
    let shown = found(entries, filter);
    let (rect, list, desc) = areas(area, row_count(entries, &shown));
    let (names, at) = rows(entries, &shown, selected, style, list.width as usize);
    // the screen under it is cleared whole: no border of it beside the window's own
    frame.render_widget(
        Clear,
        Rect {
            height: area.height.saturating_sub(2),
            ..area
        },
    );
    let last = last(entries, selected, filter, area);
    let more = match (scroll.min(last), last) {
        (0, 0) => "",
        (0, _) => " PgDn: more below ",
        (s, l) if s < l => " PgUp PgDn: more above and below ",
        _ => " PgUp: the start ",
    };
    let title = if filter.is_empty() {
        " open a preset: type to find one, or a path ".to_string()
    } else {
        format!(" open a preset: {filter}_ ({} found) ", shown.len())
    };
    let block = Block::default()
        .borders(Borders::ALL)
        .title(title)
        .title_bottom(Line::from(more).right_aligned());
    frame.render_widget(block, rect);
    let offset = at
        .unwrap_or(0)
        .saturating_sub(list.height.saturating_sub(1) as usize);
    let count = names.len();
    frame.render_widget(Paragraph::new(names).scroll((offset as u16, 0)), list);
    let entry = at.and_then(|_| entries.get(selected));
    let pane = Block::default()
        .borders(Borders::TOP)
        .title(Line::from(position(offset, list.height as usize, count)).right_aligned());
    let width = pane.inner(desc).width as usize;
    let text = match entry {
        Some(entry) => lines(entry, width),
        None => wrap(
            &format!(
                "no preset found: Backspace to find more, or Enter to open \"{filter}\" as a \
                 file when it is a path"
            ),
            width,
        )
        .into_iter()
        .map(Line::from)
        .collect(),
    };
    frame.render_widget(
        Paragraph::new(text)
            .block(pane)
            .scroll((scroll.min(last), 0)),
        desc,
    );
}
