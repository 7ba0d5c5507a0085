//! The fit's windows (`F`): the form that chooses the inputs to free, and the report of a fit
//! done (each estimate with its 95 % interval, the residual, what the data do not determine).

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Clear, Paragraph};

use crate::tui::app::App;
use crate::tui::fit_state::{FitForm, FitReport};
use crate::tui::form;
use crate::tui::view::layout::centered;
use crate::tui::view::theme::RenderOptions;
use crate::tui::view::wrap;

/// The widest the windows are drawn.
const WIDTH: u16 = 90;

/// The window's rectangle over `area` for `rows` rows of text: centred, above the message and
/// key lines.
fn window(area: Rect, rows: usize) -> Rect {
    let above = Rect {
        height: area.height.saturating_sub(2),
        ..area
    };
    let rows = u16::try_from(rows + 2).unwrap_or(u16::MAX);
    centered(above, WIDTH, rows)
}

/// The form: one line per input offered, its mark ("[x]" free, "[ ]" fixed, "[=]" locked by the
/// lesson), symbol, name and value; the highlighted one kept in view.
pub fn form(app: &App, form: &FitForm, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let heading = "free: [x]   fixed: [ ]   locked by the lesson: [=]";
    let rect = window(area, form.offered.len() + 1);
    let inner = (rect.height.saturating_sub(3)) as usize;
    let first = (form.selected + 1).saturating_sub(inner.max(1));
    let symbol_width = (form.offered.iter())
        .map(|o| o.key.symbol().chars().count())
        .max()
        .unwrap_or(1);
    let mut lines = vec![Line::styled(format!(" {heading}"), style.heading())];
    for (i, o) in form.offered.iter().enumerate().skip(first).take(inner) {
        let mark = match (o.locked, o.free) {
            (true, _) => "[=]",
            (false, true) => "[x]",
            (false, false) => "[ ]",
        };
        let text = format!(
            " {mark} {:symbol_width$}  {} = {}",
            o.key.symbol(),
            o.key.param().label,
            form::show(&app.doc.preset, &o.key)
        );
        lines.push(if i == form.selected {
            Line::styled(text, style.selected())
        } else {
            Line::from(text)
        });
    }
    let more = if first + inner < form.offered.len() {
        " more below "
    } else {
        ""
    };
    let block = Block::default()
        .borders(Borders::ALL)
        .title(" fit: the inputs to free ")
        .title_bottom(Line::from(more).right_aligned());
    frame.render_widget(Clear, rect);
    frame.render_widget(Paragraph::new(lines).block(block), rect);
}

/// The report's lines wrapped to `width` columns (an indented paragraph keeps its indent).
pub fn report_lines(report: &FitReport, width: usize) -> Vec<String> {
    let mut out = Vec::new();
    for p in &report.paragraphs {
        let text = p.trim_start();
        let indent = p.len() - text.len();
        if text.is_empty() {
            out.push(String::new());
            continue;
        }
        let pad = " ".repeat(indent + 1);
        let lines = wrap(text, width.saturating_sub(indent + 2).max(10));
        out.extend(lines.into_iter().map(|l| format!("{pad}{l}")));
    }
    out
}

/// The report's rectangle and lines on `area`.
fn report_layout(report: &FitReport, area: Rect) -> (Rect, Vec<String>) {
    let width = usize::from(WIDTH.min(area.width).saturating_sub(2));
    let lines = report_lines(report, width);
    (window(area, lines.len()), lines)
}

/// The largest scroll of the report on `screen`.
pub fn report_last(report: &FitReport, screen: Rect) -> u16 {
    let (rect, lines) = report_layout(report, screen);
    let shown = usize::from(rect.height.saturating_sub(2));
    u16::try_from(lines.len().saturating_sub(shown)).unwrap_or(u16::MAX)
}

/// The report of a fit, scrolled by `scroll` lines.
pub fn report(
    report: &FitReport,
    scroll: u16,
    style: RenderOptions,
    frame: &mut Frame,
    area: Rect,
) {
    let (rect, lines) = report_layout(report, area);
    let last = report_last(report, area);
    let more = if scroll.min(last) < last {
        " more below "
    } else {
        ""
    };
    let lines: Vec<Line> = lines
        .into_iter()
        .map(|l| {
            if l.contains(" not determined by these data: ") && !l.starts_with("  ") {
                Line::styled(l, style.error())
            } else {
                Line::from(l)
            }
        })
        .collect();
    let block = Block::default()
        .borders(Borders::ALL)
        .title(format!(" {} ", report.title))
        .title_bottom(Line::from(more).right_aligned());
    frame.render_widget(Clear, rect);
    frame.render_widget(
        Paragraph::new(lines)
            .block(block)
            .scroll((scroll.min(last), 0)),
        rect,
    );
}
