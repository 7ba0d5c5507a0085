//! The lesson's questions window (`a`): each question wrapped, the student's last answer to it
//! with its verdict (and the program's value where the lesson reveals it), the answer being
//! typed under the selected question, and where the answers are computed.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Clear, Paragraph};

use crate::preset::{Question, Tolerance};
use crate::units::{format_si, prefixable};

use crate::tui::app::App;
use crate::tui::lesson_state::Quiz;
use crate::tui::view::layout::centered;
use crate::tui::view::popups::help_rect;
use crate::tui::view::theme::RenderOptions;
use crate::tui::view::wrap;

/// The indent of what follows a question's first line.
const INDENT: &str = "     ";

/// A text wrapped under a question.
fn indented(text: &str, width: usize) -> Vec<Line<'static>> {
    wrap(text, width.saturating_sub(INDENT.len()))
        .into_iter()
        .map(|l| Line::from(format!("{INDENT}{l}")))
        .collect()
}

/// What the answer line asks for: the unit and the tolerance.
fn asked(q: &Question) -> String {
    let quantity = q.answer.quantity();
    if quantity.flag {
        return "answer yes or no".into();
    }
    let within = match q.tolerance {
        Tolerance::Percent(p) => format!("{p} %"),
        Tolerance::Absolute(a) => format_si(a, quantity.unit),
    };
    match quantity.unit {
        "" => format!("answer (within {within})"),
        unit if prefixable(unit) => {
            format!("answer with its unit, {unit} or prefixed (within {within})")
        }
        unit => format!("answer in {unit} (within {within})"),
    }
}

/// The window's lines for a text `width` wide, and the line of the answer being typed.
pub fn lines(
    app: &App,
    quiz: &Quiz,
    style: RenderOptions,
    width: usize,
) -> (Vec<Line<'static>>, usize) {
    let mut out = Vec::new();
    let mut typing = 0;
    let Some(lesson) = app.lesson.preset.lesson.as_ref() else {
        return (out, 0);
    };
    let values = app.lesson.values.as_ref();
    for (n, q) in lesson.questions.iter().enumerate() {
        let selected = n == quiz.selected;
        let lead = format!("{} {}. ", if selected { ">" } else { " " }, n + 1);
        for (i, l) in wrap(&q.text, width.saturating_sub(INDENT.len()))
            .into_iter()
            .enumerate()
        {
            let text = if i == 0 {
                format!("{lead}{l}")
            } else {
                format!("{INDENT}{l}")
            };
            out.push(if selected {
                Line::styled(text, style.heading())
            } else {
                Line::from(text)
            });
        }
        if let Some(mark) = &app.lesson.marks[n] {
            let verdict = if mark.right { "right" } else { "not right" };
            let value = values.and_then(|v| v[n].as_ref().ok()).copied();
            let shown = match value {
                Some(v) if q.reveal && q.answer.quantity().flag => {
                    format!(" (the program: {})", if v != 0.0 { "yes" } else { "no" })
                }
                Some(v) if q.reveal => {
                    format!(" (the program: {})", format_si(v, q.answer.quantity().unit))
                }
                _ => String::new(),
            };
            let text = format!("your answer {}: {verdict}{shown}", mark.typed);
            out.extend(indented(&text, width));
        }
        if selected {
            out.extend(indented(&format!("{}:", asked(q)), width));
            typing = out.len();
            let typed = format!("{INDENT}{}", quiz.typed.shown());
            out.push(Line::styled(typed, style.selected()));
        }
        out.push(Line::from(""));
    }
    let mut note = String::from(
        "The program answers at the preset's inputs as it was opened (or at those a question \
         names), whatever you change meanwhile.",
    );
    if values.is_none() {
        note.push_str(" It is computing its answers…");
    }
    if !lesson.locked.is_empty() {
        note.push_str(" Rows marked = are locked by the lesson.");
    }
    out.extend(
        wrap(&note, width.saturating_sub(1))
            .into_iter()
            .map(|l| Line::from(format!(" {l}"))),
    );
    (out, typing)
}

/// Draws the window over the screen but the message and key lines, as tall as its text (at most
/// that), scrolled to keep the answer being typed in view.
pub fn draw(app: &App, quiz: &Quiz, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let most = help_rect(area);
    let (text, typing) = lines(app, quiz, style, most.width.saturating_sub(2) as usize);
    let above = Rect {
        height: area.height.saturating_sub(2),
        ..area
    };
    let rect = centered(above, most.width, (text.len() as u16).saturating_add(2));
    frame.render_widget(Clear, rect);
    let height = rect.height.saturating_sub(2) as usize;
    let scroll = (typing + 2)
        .saturating_sub(height)
        .min(text.len().saturating_sub(height));
    let answered = app.lesson.marks.iter().flatten().count();
    let right = app
        .lesson
        .marks
        .iter()
        .flatten()
        .filter(|m| m.right)
        .count();
    let block = Block::default().borders(Borders::ALL).title(format!(
        " lesson: {} questions, {answered} answered, {right} right ",
        app.lesson.marks.len()
    ));
    frame.render_widget(
        Paragraph::new(text).block(block).scroll((scroll as u16, 0)),
        rect,
    );
}
