//! The preset picker (`o`): the presets in a list, and under it the highlighted preset's source
//! and whole description, wrapped at spaces; a list longer than its rows says which it shows
//! and where more are; a description longer than its pane scrolls (PgUp/PgDn), the window's
//! border saying when more is below.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Clear, Paragraph};

use crate::tui::app::PickerEntry;
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

/// The largest scroll of the highlighted entry's description on `screen` (0 when it fits).
pub fn last(entries: &[PickerEntry], selected: usize, screen: Rect) -> u16 {
    let (_, _, desc) = areas(screen, entries.len());
    let text = Block::default().borders(Borders::TOP).inner(desc);
    let n = entries
        .get(selected)
        .map_or(0, |e| lines(e, text.width as usize).len());
    u16::try_from(n.saturating_sub(text.height as usize)).unwrap_or(u16::MAX)
}

/// Where the list stands when it does not show every preset, on the border under it: " presets
/// 1-9 of 14 (more below) "; "" when all are shown. In words: an arrow's ASCII form ("v more")
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
    format!(" presets {}-{last} of {count} (more {more}) ", offset + 1)
}

/// Draws the picker, the description scrolled by `scroll` lines.
pub fn draw(
    entries: &[PickerEntry],
    selected: usize,
    scroll: u16,
    style: RenderOptions,
    frame: &mut Frame,
    area: Rect,
) {
    let (rect, list, desc) = areas(area, entries.len());
    // the screen under it is cleared whole: no border of it beside the window's own
    frame.render_widget(
        Clear,
        Rect {
            height: area.height.saturating_sub(2),
            ..area
        },
    );
    let last = last(entries, selected, area);
    let more = match (scroll.min(last), last) {
        (0, 0) => "",
        (0, _) => " PgDn: more below ",
        (s, l) if s < l => " PgUp PgDn: more above and below ",
        _ => " PgUp: the start ",
    };
    let block = Block::default()
        .borders(Borders::ALL)
        .title(" open a preset (Enter opens, Esc closes) ")
        .title_bottom(Line::from(more).right_aligned());
    frame.render_widget(block, rect);
    let offset = selected.saturating_sub(list.height.saturating_sub(1) as usize);
    let names: Vec<Line> = entries
        .iter()
        .enumerate()
        .map(|(i, e)| {
            let mark = if e.preset.is_err() { "!" } else { " " };
            let text = format!("{mark}{}", e.title);
            if i == selected {
                Line::styled(text, style.selected())
            } else {
                Line::from(text)
            }
        })
        .collect();
    frame.render_widget(Paragraph::new(names).scroll((offset as u16, 0)), list);
    let Some(entry) = entries.get(selected) else {
        return;
    };
    let pane = Block::default()
        .borders(Borders::TOP)
        .title(Line::from(position(offset, list.height as usize, entries.len())).right_aligned());
    let width = pane.inner(desc).width as usize;
    frame.render_widget(
        Paragraph::new(lines(entry, width))
            .block(pane)
            .scroll((scroll.min(last), 0)),
        desc,
    );
}
