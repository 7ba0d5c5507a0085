//! The windows drawn over the main screen: the help (keys, the chart, the status symbols), the
//! preset's description (`i`) and a choice row's list (the preset picker is `picker`).

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Clear, Paragraph};

use crate::tui::app::App;
use crate::tui::keys::{Open, Scope};
use crate::tui::sweep_state::View;
use crate::tui::view::layout::centered;
use crate::tui::view::sweep;
use crate::tui::view::theme::RenderOptions;
use crate::tui::view::wrap;
use crate::tui::view::wrapping::pack;
use crate::tui::{glossary, keys};

/// A two-column row: `left` padded to `indent` columns, `right` wrapped in the rest; a `left`
/// too long for its column has a line of its own, the text starting under it.
fn row(left: &str, right: &str, indent: usize, width: usize) -> Vec<Line<'static>> {
    let own_line = left.chars().count() + 1 > indent;
    let texts = wrap(right, width.saturating_sub(indent).max(10));
    let head = own_line.then(|| Line::from(left.to_string()));
    let body = texts.into_iter().enumerate().map(move |(i, text)| {
        let left = if i == 0 && !own_line { left } else { "" };
        Line::from(format!("{left:<indent$}{text}"))
    });
    head.into_iter().chain(body).collect()
}

/// The help's lines for a text `width` wide.
pub fn help_lines(app: &App, style: RenderOptions, width: usize) -> Vec<Line<'static>> {
    let problem = app.doc.preset.problem;
    let open = Open::of(&app.doc.preset);
    let heading = |t: String| Line::styled(t, style.heading());
    let mut lines = vec![heading("Keys".into())];
    for b in &keys::BINDINGS {
        let help = match b.only {
            Scope::Problem(p) if p != problem => {
                format!("{} (in the {} problem)", b.help, p.name())
            }
            scope if !scope.applies(open) => {
                format!("{} (on {})", b.help, scope.place().unwrap_or_default())
            }
            _ => b.help.to_string(),
        };
        lines.extend(row(&format!("  {}", b.names), &help, 20, width));
    }
    let chart = app.ui.chart;
    let (i, n) = chart.position();
    // what the chart area shows: the sweep or the map over the charts when one is on
    let (title, text) = match app.explore.view {
        Some(View::Sweep) => ("This view: the sweep chart (v)".into(), sweep::SWEEP_HELP),
        Some(View::Map) => ("This view: the regime map (M)".into(), sweep::MAP_HELP),
        None => (
            format!("This chart ({i}/{n}): {}", chart.title()),
            chart.help(),
        ),
    };
    lines.push(Line::from(""));
    lines.push(heading(title));
    lines.extend(
        wrap(text, width.saturating_sub(2))
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

/// Where the help goes on a screen: over everything but the message and key lines, the whole
/// width up to 100 columns (so that no border of the screen under it shows beside it).
pub fn help_rect(screen: Rect) -> Rect {
    let above = Rect {
        height: screen.height.saturating_sub(2),
        ..screen
    };
    centered(above, 100, above.height)
}

/// A text window's lines (from `lines_of` a text width) on `screen`, and the largest scroll
/// that still fills it.
fn window_layout(
    lines_of: impl Fn(usize) -> Vec<Line<'static>>,
    screen: Rect,
) -> (Vec<Line<'static>>, u16) {
    let rect = help_rect(screen);
    let lines = lines_of(rect.width.saturating_sub(2) as usize);
    let last = lines
        .len()
        .saturating_sub(rect.height.saturating_sub(2) as usize);
    (lines, u16::try_from(last).unwrap_or(u16::MAX))
}

const PLAIN: RenderOptions = RenderOptions {
    ascii: false,
    color: false,
    truecolor: false,
};

/// The largest scroll of the help on `screen`: scrolling stops there.
pub fn help_last(app: &App, screen: Rect) -> u16 {
    window_layout(|w| help_lines(app, PLAIN, w), screen).1
}

/// A text window over everything but the message and key lines, scrolled by `scroll` lines.
fn text_window(
    title: &str,
    (lines, last): (Vec<Line<'static>>, u16),
    scroll: u16,
    frame: &mut Frame,
    area: Rect,
) {
    // the screen under it is cleared whole: no border of it beside the window's own
    frame.render_widget(
        Clear,
        Rect {
            height: area.height.saturating_sub(2),
            ..area
        },
    );
    // in words: an arrow's ASCII form ("v more") would read as a key
    let more = if scroll < last { " more below " } else { "" };
    let block = Block::default()
        .borders(Borders::ALL)
        .title(format!(" {title} "))
        .title_bottom(Line::from(more).right_aligned());
    frame.render_widget(
        Paragraph::new(lines)
            .block(block)
            .scroll((scroll.min(last), 0)),
        help_rect(area),
    );
}

/// The help window, scrolled by `scroll` lines.
pub fn help(app: &App, scroll: u16, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let layout = window_layout(|w| help_lines(app, style, w), area);
    text_window("help", layout, scroll, frame, area);
}

/// The preset's name, its file, the status in full, the chart's legend and the harmonics' table
/// whole (what a crowded status or chart counts as "+2 more: i"), and its whole description wrapped at spaces to `width`, a blank line before "Look at:"
/// and "Try:".
pub fn about_lines(app: &App, style: RenderOptions, width: usize) -> Vec<Line<'static>> {
    let doc = &app.doc;
    let mut lines = vec![Line::styled(doc.preset.name.clone(), style.heading())];
    if let Some(source) = &doc.source {
        lines.extend(wrap(source, width).into_iter().map(Line::from));
    }
    for warning in crate::preset::warnings(&doc.preset) {
        lines.extend(
            wrap(&format!("warning: {warning}"), width)
                .into_iter()
                .map(|l| Line::styled(l, style.error())),
        );
    }
    let changed = crate::tui::form::differences(&doc.opened, &doc.preset);
    if !changed.is_empty() {
        let note = format!(
            "edited since opened ({}): the description below was written for the values as opened",
            changed.join(", ")
        );
        lines.extend(
            wrap(&note, width)
                .into_iter()
                .map(|l| Line::styled(l, style.error())),
        );
    }
    let full = crate::tui::view::status::in_full(app);
    if !full.is_empty() {
        lines.push(Line::from(""));
        lines.push(Line::styled("the status in full:", style.heading()));
        for part in &full {
            lines.extend(pack(part, width, "  ").into_iter().map(Line::from));
        }
    }
    let legend = crate::tui::view::legend_full::in_full(app, style);
    if !legend.is_empty() {
        lines.push(Line::from(""));
        lines.push(Line::styled("the chart's legend in full:", style.heading()));
        lines.extend(legend.into_iter().map(Line::from));
    }
    let harmonics = crate::tui::view::harmonic_table::in_full(app);
    if !harmonics.is_empty() {
        lines.push(Line::from(""));
        lines.push(Line::styled("the harmonics in full:", style.heading()));
        lines.extend(harmonics.into_iter().map(Line::from));
    }
    lines.extend(paragraphs(&doc.preset.description, width));
    lines
}

/// A preset's description wrapped at spaces to `width`, each paragraph after a blank line (a
/// new paragraph at "Look at:" and "Try:").
pub(super) fn paragraphs(description: &str, width: usize) -> Vec<Line<'static>> {
    let mut lines = Vec::new();
    for paragraph in reflow(description).lines() {
        lines.push(Line::from(""));
        lines.extend(wrap(paragraph, width).into_iter().map(Line::from));
    }
    lines
}

/// The largest scroll of the preset's description on `screen`.
pub fn about_last(app: &App, screen: Rect) -> u16 {
    window_layout(|w| about_lines(app, PLAIN, w), screen).1
}

/// The preset's name and whole description (`i`), scrolled by `scroll` lines.
pub fn about(app: &App, scroll: u16, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let layout = window_layout(|w| about_lines(app, style, w), area);
    text_window("about this preset", layout, scroll, frame, area);
}

/// A preset description as paragraphs: its hard line breaks are joined, except before
/// "Look at:" and "Try:", which start lines of their own.
pub(super) fn reflow(text: &str) -> String {
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
