//! The form panel: the parameters grouped under headings, the selected row highlighted (showing
//! the text being typed), the rows a lesson locks marked `=`, scrolled to keep the selection
//! visible, the bottom border saying where rows are out of sight ("more below").

use crate::preset::{Problem, surface_from_file};
use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Paragraph};

use crate::tui::app::{App, Mode};
use crate::tui::form;
use crate::tui::view::theme::RenderOptions;

/// Columns of the label.
const LABEL: usize = 9;

/// Draws the form into `area`.
pub fn draw(app: &App, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let preset = &app.doc.preset;
    let title = match (preset.problem, &preset.spatial.surface) {
        (Problem::Plane, _) => " plane: punch on a strip ",
        (Problem::Spatial, None) => " spatial: wavy punch ",
        (Problem::Spatial, Some(_)) if surface_from_file(preset) => " spatial: measured surface ",
        (Problem::Spatial, Some(_)) => " spatial: generated surface ",
    };
    let block = Block::default().borders(Borders::ALL).title(title);
    let inner = block.inner(area);
    let width = (inner.width as usize).saturating_sub(LABEL + 2);
    let mut lines: Vec<Line> = Vec::new();
    let mut selected_line = 0;
    let mut heading = String::new();
    for (i, row) in app.rows().iter().enumerate() {
        if form::heading(preset, row) != heading {
            heading = form::heading(preset, row);
            lines.push(Line::styled(heading.clone(), style.heading()));
        }
        let selected = i == app.ui.selected;
        let value = match (&app.ui.mode, selected) {
            (Mode::Editing(buffer), true) => tail(&buffer.shown(), width),
            _ => form::show(&app.doc.preset, row),
        };
        // a key the lesson locks: marked, so that a refused edit is no surprise
        let mark = if crate::tui::lesson_keys::locked(app, *row) {
            "= "
        } else {
            "  "
        };
        let text = format!("{mark}{:<LABEL$}{value:>width$}", row.param().symbol);
        if selected {
            selected_line = lines.len();
            lines.push(Line::from(Span::styled(text, style.selected())));
        } else {
            lines.push(Line::from(text));
        }
    }
    let height = inner.height as usize;
    let offset = selected_line
        .saturating_sub(height.saturating_sub(2))
        .min(lines.len().saturating_sub(height));
    // rows scrolled out of sight, said on the bottom border (in words: an arrow's ASCII form
    // would read as a key)
    let more = match (offset > 0, offset + height < lines.len()) {
        (true, true) => " more above and below ",
        (true, false) => " more above ",
        (false, true) => " more below ",
        (false, false) => "",
    };
    frame.render_widget(block.title_bottom(Line::from(more).right_aligned()), area);
    frame.render_widget(Paragraph::new(lines).scroll((offset as u16, 0)), inner);
}

/// The last `width` characters of a text (what is being typed stays visible at its end).
fn tail(text: &str, width: usize) -> String {
    let n = text.chars().count();
    text.chars().skip(n.saturating_sub(width)).collect()
}
