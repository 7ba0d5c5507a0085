//! The windows drawn over the main screen: the help (keys, the chart, the status symbols), the
//! preset picker and a choice row's list.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Clear, Paragraph, Wrap};

use crate::tui::app::{App, PickerEntry};
use crate::tui::view::layout::centered;
use crate::tui::view::theme::RenderOptions;
use crate::tui::view::wrap;
use crate::tui::{glossary, keys};

/// A two-column row: `left` padded to `indent` columns, `right` wrapped in the rest.
fn row(left: &str, right: &str, indent: usize, width: usize) -> Vec<Line<'static>> {
    wrap(right, width.saturating_sub(indent).max(10))
        .into_iter()
        .enumerate()
        .map(|(i, text)| {
            let left = if i == 0 { left } else { "" };
            Line::from(format!("{left:<indent$}{text}"))
        })
        .collect()
}

/// The help's lines for a text `width` wide.
pub fn help_lines(app: &App, style: RenderOptions, width: usize) -> Vec<Line<'static>> {
    let problem = app.doc.preset.problem;
    let heading = |t: String| Line::styled(t, style.heading());
    let mut lines = vec![heading("Keys".into())];
    for b in &keys::BINDINGS {
        let help = match b.only {
            Some(p) if p != problem => format!("{} (in the {} problem)", b.help, p.name()),
            _ => b.help.to_string(),
        };
        lines.extend(row(&format!("  {}", b.names), &help, 20, width));
    }
    let chart = app.ui.chart;
    let (i, n) = chart.position();
    lines.push(Line::from(""));
    lines.push(heading(format!("This chart ({i}/{n}): {}", chart.title())));
    lines.extend(
        wrap(chart.help(), width.saturating_sub(2))
            .into_iter()
            .map(|t| Line::from(format!("  {t}"))),
    );
    lines.push(Line::from(""));
    lines.push(heading("The status panel".into()));
    for (symbol, unit, meaning) in glossary::of(problem) {
        let left = match *unit {
            "" => format!("  {symbol}"),
            u => format!("  {symbol} [{u}]"),
        };
        lines.extend(row(&left, meaning, 20, width));
    }
    lines
}

/// The help window, scrolled by `scroll` lines.
pub fn help(app: &App, scroll: u16, style: RenderOptions, frame: &mut Frame, area: Rect) {
    // over everything but the message and key lines
    let above = Rect {
        height: area.height.saturating_sub(2),
        ..area
    };
    let rect = centered(above, 78, above.height);
    frame.render_widget(Clear, rect);
    let lines = help_lines(app, style, rect.width.saturating_sub(2) as usize);
    let last = lines
        .len()
        .saturating_sub(rect.height.saturating_sub(2) as usize) as u16;
    let more = if scroll < last { " ↓ more " } else { "" };
    let block = Block::default()
        .borders(Borders::ALL)
        .title(" help ")
        .title_bottom(Line::from(more).right_aligned());
    frame.render_widget(
        Paragraph::new(lines)
            .block(block)
            .scroll((scroll.min(last), 0)),
        rect,
    );
}

/// A preset description as paragraphs: its hard line breaks are joined, except before
/// "Look at:" and "Try:", which start lines of their own.
fn reflow(text: &str) -> String {
    let mut out = String::new();
    for line in text.trim().lines().map(str::trim) {
        if line.starts_with("Look at") || line.starts_with("Try") {
            out.push('\n');
        } else if !out.is_empty() {
            out.push(' ');
        }
        out.push_str(line);
    }
    out
}

/// The preset picker: the list, and the highlighted preset's source and description.
pub fn picker(
    entries: &[PickerEntry],
    selected: usize,
    style: RenderOptions,
    frame: &mut Frame,
    area: Rect,
) {
    let rect = centered(area, 78, 22);
    frame.render_widget(Clear, rect);
    let block = Block::default()
        .borders(Borders::ALL)
        .title(" open a preset (Enter opens, Esc closes) ");
    let inner = block.inner(rect);
    frame.render_widget(block, rect);
    let list_height = (entries.len() as u16).min(inner.height / 2);
    let [list, desc] =
        Layout::vertical([Constraint::Length(list_height), Constraint::Min(3)]).areas(inner);
    let offset = selected.saturating_sub(list_height.saturating_sub(1) as usize);
    let lines: Vec<Line> = entries
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
    frame.render_widget(Paragraph::new(lines).scroll((offset as u16, 0)), list);
    if let Some(e) = entries.get(selected) {
        let text = match &e.preset {
            Ok(p) => format!("{}\n{}", e.source, reflow(&p.description)),
            Err(why) => format!("{}\ncannot be opened: {why}", e.source),
        };
        frame.render_widget(
            Paragraph::new(text)
                .wrap(Wrap { trim: true })
                .block(Block::default().borders(Borders::TOP)),
            desc,
        );
    }
}

/// The list of a choice row, over the form.
pub fn choices(app: &App, selected: usize, style: RenderOptions, frame: &mut Frame, form: Rect) {
    let row = app.row();
    let names = row.param().choices().unwrap_or_default();
    let rect = centered(form, form.width.saturating_sub(4), names.len() as u16 + 2);
    frame.render_widget(Clear, rect);
    let lines: Vec<Line> = names
        .iter()
        .enumerate()
        .map(|(i, n)| {
            if i == selected {
                Line::styled(format!(" {n}"), style.selected())
            } else {
                Line::from(format!(" {n}"))
            }
        })
        .collect();
    let block = Block::default()
        .borders(Borders::ALL)
        .title(format!(" {} ", row.symbol()));
    frame.render_widget(Paragraph::new(lines).block(block), rect);
}
