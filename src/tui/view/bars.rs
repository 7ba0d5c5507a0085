//! The two lines under the panels: the message (or the prompt being answered) and the keys.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::Line;
use ratatui::widgets::Paragraph;

use crate::phrase::Phrase;
use crate::preset::resolve_save_path;
use crate::tui::app::{App, Mode};
use crate::tui::keys;
use crate::tui::prompt_keys::{self, Prompt};
use crate::tui::view::theme::RenderOptions;
use crate::tui::view::{wrap, wrap_within};

/// The prompt whose keys apply in a mode (None on the main screen).
pub fn prompt(mode: &Mode) -> Option<Prompt> {
    match mode {
        Mode::Normal => None,
        Mode::Editing(_) | Mode::SaveAs(_) | Mode::GoTo(_) | Mode::DataPath(_) => {
            Some(Prompt::Text)
        }
        Mode::Choosing(_) => Some(Prompt::List),
        Mode::Picker { .. } => Some(Prompt::Picker),
        Mode::Help(_) | Mode::About(_) | Mode::FitResult(..) => Some(Prompt::Help),
        Mode::FitForm(_) => Some(Prompt::Toggles),
        Mode::Form(_) => Some(Prompt::Form),
        Mode::Questions(_) => Some(Prompt::Quiz),
        Mode::ConfirmOverwrite(_)
        | Mode::ConfirmExport(_)
        | Mode::ConfirmOpen(_)
        | Mode::ConfirmQuit(_) => Some(Prompt::Question),
    }
}

/// The message line: a question being asked, the file name being typed, the last message, or
/// the preset's name.
fn message(app: &App, style: RenderOptions) -> (String, Style) {
    let (text, st) = match &app.ui.mode {
        Mode::SaveAs(buffer) => {
            // where the name goes, said before anything is written
            let places = &app.places;
            let home = places.home.as_deref();
            let goes = match resolve_save_path(buffer.text(), home, places.presets.as_deref()) {
                Ok(target) => format!("-> {}", target.path.display()),
                Err(_) => "(a name, or a path such as ~/lab.toml)".into(),
            };
            (
                format!("save as: {} {goes}", buffer.shown()),
                Style::default(),
            )
        }
        Mode::GoTo(buffer) => {
            // the axis and its range first; a typed x refused says why after the text
            let mut text = format!(
                "{} {}",
                crate::tui::chart_keys::go_to_prompt(app),
                buffer.shown()
            );
            let mut look = Style::default();
            if let Some(m) = app.ui.message.as_ref().filter(|m| m.error) {
                text = format!("{text}  ! {}", m.text);
                look = style.error();
            }
            (text, look)
        }
        Mode::DataPath(buffer) => (
            format!(
                "data file: {} {}",
                buffer.shown(),
                crate::tui::data_keys::prompt(app, buffer.text())
            ),
            Style::default(),
        ),
        Mode::ConfirmOverwrite(target) => (
            format!("{} exists: overwrite? y/n", target.path.display()),
            style.error(),
        ),
        Mode::ConfirmExport(file) => (
            format!("{} exists: overwrite? y/n", file.0.display()),
            style.error(),
        ),
        Mode::ConfirmOpen(entry) => (
            format!("unsaved edits: open \"{}\" anyway? y/n", entry.title),
            style.error(),
        ),
        Mode::ConfirmQuit(_) => ("unsaved edits: quit anyway? y/n".into(), style.error()),
        _ => match &app.ui.message {
            Some(m) if m.error => (m.text.clone(), style.error()),
            Some(m) => (m.text.clone(), Style::default()),
            None => {
                let doc = &app.doc;
                let name = match &doc.path {
                    Some(p) => format!("{} ({})", doc.preset.name, p.display()),
                    None => doc.preset.name.clone(),
                };
                // not "(edited)": the name of a saved edited copy already ends in it
                let edited = if doc.dirty { " (unsaved edits)" } else { "" };
                (format!("{name}{edited}"), Style::default())
            }
        },
    };
    (style.text(&text).into_owned(), st)
}

/// The most rows a refused name's reason takes above the save prompt.
const REASON_ROWS: usize = 3;

/// Why the name typed last was refused, while the save prompt stays open for a correction.
fn refusal(app: &App) -> Option<&str> {
    match (&app.ui.mode, &app.ui.message) {
        (Mode::SaveAs(_), Some(m)) if m.error => Some(&m.text),
        _ => None,
    }
}

/// The reason's lines above the save prompt, `width` wide.
fn reason_lines(app: &App, style: RenderOptions, width: usize) -> Vec<String> {
    refusal(app).map_or_else(Vec::new, |why| {
        wrap_within(&Phrase::words(&style.text(why)), width, REASON_ROWS, style)
    })
}

/// How many lines the message takes on a screen `width` wide: two when it does not fit on one
/// (the panels above give up their last rows meanwhile), else one; above the save prompt, the
/// reason a name was refused, wrapped, as well.
pub fn message_height(app: &App, style: RenderOptions, width: u16) -> u16 {
    let (text, _) = message(app, style);
    let own = if wrap(&text, width as usize).len() > 1 {
        2
    } else {
        1
    };
    own + reason_lines(app, style, width as usize).len() as u16
}

/// Draws the message, wrapped at spaces to the lines of `area`; a message longer still ends
/// in "…" (`wrap_within`). Above the save prompt, why the name typed was refused.
pub fn draw_message(app: &App, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let (text, st) = message(app, style);
    let width = area.width as usize;
    let reason = reason_lines(app, style, width);
    let rows = (area.height as usize).saturating_sub(reason.len()).max(1);
    let lines = wrap_within(&Phrase::words(&text), width, rows, style);
    let lines: Vec<Line> = (reason.into_iter())
        .map(|l| Line::styled(l, style.error()))
        .chain(lines.into_iter().map(|l| Line::styled(l, st)))
        .collect();
    frame.render_widget(Paragraph::new(lines), area);
}

/// Draws the keys of the main screen or of the prompt being answered.
pub fn draw_footer(app: &App, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let text = match prompt(&app.ui.mode) {
        None => keys::footer(keys::Open::of(&app.doc.preset), area.width as usize, style),
        Some(p) => style.text(&prompt_keys::prompt_footer(p)).into_owned(),
    };
    frame.render_widget(Paragraph::new(text).style(style.footer()), area);
}
