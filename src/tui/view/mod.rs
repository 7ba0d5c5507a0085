//! Drawing: a pure function of the App (no solving, no I/O). Everything drawn from a result is
//! labelled by the inputs that result carries: while a newer request is solving, the previous
//! result stays visible, dimmed, and says whose it is.

pub mod axis;
pub mod bars;
pub mod chart;
pub mod contact_status;
pub mod explore;
pub mod form;
pub mod groups_status;
pub mod heatmap;
pub mod hidden;
pub mod layout;
pub mod legend;
pub mod picker;
pub mod popups;
pub mod raster;
pub mod regime;
pub mod status;
pub mod theme;
pub mod validity_status;

use crate::engine::Answer;
use crate::preset::{Preset, Problem};
use crate::sweeps::quantity::problem_groups;
use ratatui::Frame;
use ratatui::layout::{Alignment, Rect};
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Paragraph, Wrap};

use crate::tui::app::{App, Mode};
use crate::tui::charts::{Figure, NoFigure, Plot, range};
use chart::Extras;
pub use layout::MIN_SIZE;
pub use theme::RenderOptions;

/// How the shown result relates to the form.
#[derive(Clone, Debug)]
pub enum Shown<'a> {
    /// Nothing has arrived yet, or only a result of the other problem.
    Nothing,
    /// The result of the form's inputs; `solving` while more of it (or a newer one) is coming.
    Current(&'a Answer, bool),
    /// A result of other inputs, named by `label`, while the form's are solving.
    Previous(&'a Answer, String),
}

impl<'a> Shown<'a> {
    /// The answer to draw, and whether to dim it (it answers other inputs than the form's).
    pub fn answer(&self) -> Option<(&'a Answer, bool)> {
        match self {
            Shown::Nothing => None,
            Shown::Current(a, _) => Some((*a, false)),
            Shown::Previous(a, _) => Some((*a, true)),
        }
    }
}

/// What the screen shows of the newest answer, compared with the form's preset.
pub fn shown(app: &App) -> Shown<'_> {
    let Some(answer) = &app.solve.shown else {
        return Shown::Nothing;
    };
    let theirs = &answer.request.preset;
    let ours = &app.doc.preset;
    if theirs.problem != ours.problem {
        return Shown::Nothing;
    }
    // while time plays, each frame is a new request: a result a few frames old is labelled
    // by the t it shows, not dimmed
    let same = |a: &Preset, b: &Preset| {
        let mut a = a.clone();
        if app.ui.playing {
            a.spatial.time = b.spatial.time;
        }
        a == *b
    };
    if same(theirs, ours) {
        return Shown::Current(answer, app.solve.solving());
    }
    let label = if theirs.name != ours.name {
        format!("\"{}\"", theirs.name)
    } else if ours.problem == Problem::Plane && theirs.plane.model != ours.plane.model {
        format!("{} model", theirs.plane.model.name())
    } else {
        "previous inputs".to_string()
    };
    Shown::Previous(answer, label)
}

/// Draws the whole screen.
pub fn view(app: &App, style: RenderOptions, frame: &mut Frame) {
    let area = frame.area();
    let folded = app.explore.view.is_some();
    let Some(mut areas) = layout::areas(area, app.ui.expanded, folded) else {
        too_small(frame, area);
        return;
    };
    let message_rows = bars::message_height(app, style, area.width);
    if message_rows > 1 {
        // a long message takes the panels' last row rather than being cut
        areas.form.height -= 1;
        areas.status.height -= 1;
        areas.message.y -= 1;
        areas.message.height += 1;
    }
    let shown = shown(app);
    if !app.ui.expanded {
        form::draw(app, style, frame, areas.form);
    }
    draw_chart(app, &shown, style, frame, areas.chart);
    status::draw(app, &shown, style, frame, areas.status);
    bars::draw_message(app, style, frame, areas.message);
    bars::draw_footer(app, style, frame, areas.footer);
    let over = windows_area(app, style, area);
    match &app.ui.mode {
        Mode::Help(scroll) => popups::help(app, *scroll, style, frame, over),
        Mode::About(scroll) => popups::about(app, *scroll, style, frame, over),
        Mode::Picker {
            entries,
            selected,
            scroll,
        } => picker::draw(entries, *selected, *scroll, style, frame, over),
        Mode::Choosing(selected) => popups::choices(app, *selected, style, frame, areas.form),
        Mode::Form(form) => explore::form(form, style, frame, area),
        _ => {}
    }
    style.to_ascii(frame.buffer_mut());
}

/// Where the windows over the screen (help, about, picker) are drawn: the screen but the
/// message's extra rows (the preset's name and file take two rows at 80x24 under `i`). Their
/// scrolling (update.rs) is bounded on the same area.
pub fn windows_area(app: &App, style: RenderOptions, screen: Rect) -> Rect {
    let extra = bars::message_height(app, style, screen.width).saturating_sub(1);
    Rect {
        height: screen.height.saturating_sub(extra),
        ..screen
    }
}

fn too_small(frame: &mut Frame, area: Rect) {
    let text = vec![
        Line::from("terminal too small"),
        Line::from(format!(
            "{}x{}: wearlab needs at least {}x{}",
            area.width, area.height, MIN_SIZE.0, MIN_SIZE.1
        )),
        Line::from("enlarge the window, or q to quit"),
    ];
    let rect = Rect {
        x: 0,
        y: (area.height / 2).saturating_sub(1),
        width: area.width,
        height: 3.min(area.height),
    };
    frame.render_widget(Paragraph::new(text).alignment(Alignment::Center), rect);
}

/// Wraps `text` into lines of at most `width` columns at spaces, never between a number and its
/// unit ("5 MPa", "1 um"), inside a key pair ("[ ]", "{ }"), on either side of a relation
/// ("t = 62.6 s", "residual < 1e-14"), inside a group's name of two words ("mu chi", "P/(m R)":
/// the library's names, `problem_groups`) nor inside a parenthesis that holds a relation, of at
/// most `PAREN` columns and fitting the line ("(narrow: P = 10.0 kN/m)").
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut words: Vec<String> = Vec::new();
    let tokens = whole(text.split_whitespace().collect(), width.min(PAREN));
    for (i, word) in tokens.iter().enumerate() {
        let word = word.as_str();
        let after = tokens.get(i + 1).map_or("", String::as_str);
        match words.last_mut() {
            Some(last) if glued(last, word) || named(last, word, after) => {
                last.push(' ');
                last.push_str(word);
            }
            _ => words.push(word.to_string()),
        }
    }
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in &words {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// `wrap` in at most `rows` lines: a text longer still ends in "…" (`...` with `--ascii`) after
/// its last whole clause on the last line (after a ',' or ';') where that keeps half the line,
/// else after its last whole word; never cut inside a word.
pub fn wrap_within(text: &str, width: usize, rows: usize, style: RenderOptions) -> Vec<String> {
    let mut lines = wrap(text, width);
    if lines.len() <= rows {
        return lines;
    }
    lines.truncate(rows);
    let Some(last) = lines.last_mut() else {
        return lines;
    };
    let more = style.text(" …");
    let room = width.saturating_sub(more.chars().count());
    // (chars up to the clause's end, its end in bytes)
    let clause = last
        .char_indices()
        .enumerate()
        .filter(|&(n, (_, c))| matches!(c, ',' | ';') && n < room)
        .map(|(n, (i, _))| (n + 1, i + 1))
        .max();
    match clause {
        Some((chars, end)) if chars * 2 >= room => last.truncate(end),
        _ => {
            while last.chars().count() > room {
                match last.rfind(' ') {
                    Some(i) => last.truncate(i),
                    None => last.clear(),
                }
            }
        }
    }
    last.push_str(&more);
    lines
}

/// The longest parenthesis kept on one line: a value with its name, not a clause (which would
/// leave a line of prose half empty).
const PAREN: usize = 32;

/// `tokens` with the runs that stay whole joined by spaces: a group's name of two words, and a
/// parenthesis (from a word that opens one to the word that closes it) that holds a relation,
/// of at most `most` columns.
fn whole(tokens: Vec<&str>, most: usize) -> Vec<String> {
    let names: Vec<&str> = [Problem::Plane, Problem::Spatial]
        .into_iter()
        .flat_map(problem_groups)
        .map(|q| q.symbol)
        .filter(|s| s.contains(' '))
        .collect();
    // "(k m", "mu chi),": a name with the punctuation around it
    let named = |a: &str, b: &str| {
        let pair = format!("{a} {b}");
        let core = pair.trim_start_matches(['(', '"']);
        names.iter().any(|n| {
            core.strip_prefix(n)
                .is_some_and(|rest| rest.chars().all(|c| ")],.;:\"".contains(c)))
        })
    };
    let mut out = Vec::new();
    let mut i = 0;
    while i < tokens.len() {
        let mut end = i + 1;
        // a parenthesis opened here, closed within `most` columns, with a relation inside
        let mut depth = 0i32;
        let mut len = 0;
        for (k, t) in tokens.iter().enumerate().skip(i) {
            depth += t.matches('(').count() as i32 - t.matches(')').count() as i32;
            len += t.chars().count() + usize::from(k > i);
            if depth <= 0 || len > most {
                let relation = tokens[i..=k].iter().any(|t| RELATIONS.contains(t));
                if k > i && depth <= 0 && len <= most && relation {
                    end = k + 1;
                }
                break;
            }
        }
        if end == i + 1 && i + 1 < tokens.len() && named(tokens[i], tokens[i + 1]) {
            end = i + 2;
        }
        out.push(tokens[i..end].join(" "));
        i = end;
    }
    out
}

/// The words that relate the ones on either side ("t = 62.6 s"): a line never breaks at them.
const RELATIONS: [&str; 5] = ["=", "<", ">", "<=", ">="];

/// Whether a name of two short symbols before a relation stays whole ("k m = 0.11", "mu chi =
/// 0.3"): `word` (the words glued so far) ends in a symbol, `next` is one and `after` relates.
fn named(word: &str, next: &str, after: &str) -> bool {
    // short words that are English, not symbols ("at h = 1 um")
    const WORDS: [&str; 12] = [
        "at", "to", "in", "of", "is", "on", "by", "as", "an", "or", "if", "so",
    ];
    let symbol = |w: &str, most: usize| {
        let w = w.trim_start_matches('(');
        (1..=most).contains(&w.len())
            && w.chars().all(|c| c.is_ascii_alphabetic())
            && !WORDS.contains(&w)
    };
    let last = word.rsplit(' ').next().unwrap_or(word);
    RELATIONS.contains(&after) && symbol(last, 2) && symbol(next, 3)
}

/// Whether `next` stays on the line of `word` (the words glued so far): a unit after a number,
/// "]" after "[", "}" after "{", a relation ("=", "<", ...) and what it relates.
fn glued(word: &str, next: &str) -> bool {
    const UNITS: [&str; 9] = ["m", "s", "Pa", "N/m", "m/s", "rad", "rad/m", "1/Pa", "%"];
    const PREFIXES: [&str; 10] = ["", "f", "p", "n", "u", "m", "k", "M", "G", "T"];
    if (word == "[" && next.starts_with(']')) || (word == "{" && next.starts_with('}')) {
        return true;
    }
    let last = word.rsplit(' ').next().unwrap_or(word);
    if RELATIONS.contains(&next) || RELATIONS.contains(&last) {
        return true;
    }
    let word = last;
    let number = word.trim_start_matches(['(', '~']).parse::<f64>().is_ok();
    let unit = next.trim_end_matches([')', ',', '.', ';', ':']);
    number
        && UNITS.iter().any(|u| {
            unit.strip_suffix(u)
                .is_some_and(|prefix| PREFIXES.contains(&prefix))
        })
}

/// The note a title carries about the result under it ("" for the current, complete one).
pub fn note(shown: &Shown, style: RenderOptions) -> String {
    let note = match shown {
        Shown::Nothing | Shown::Current(_, true) => "  solving…".into(),
        Shown::Current(_, false) => String::new(),
        Shown::Previous(_, label) => format!("  [{label}] solving…"),
    };
    style.text(&note).into_owned()
}

fn draw_chart(app: &App, shown: &Shown, style: RenderOptions, frame: &mut Frame, area: Rect) {
    if app.explore.view.is_some() {
        return explore::draw(app, style, frame, area);
    }
    let chart = app.ui.chart;
    let (i, n) = chart.position();
    let block = Block::default()
        .borders(Borders::ALL)
        .title(format!(" {i}/{n} {}{} ", chart.title(), note(shown, style)))
        .title_bottom(Line::from(" Tab: next chart ").right_aligned());
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let Some((answer, dim)) = shown.answer() else {
        return;
    };
    match chart.build(answer) {
        Err(NoFigure::Solving) => {}
        Err(NoFigure::Error(why)) => frame.render_widget(
            Paragraph::new(why)
                .wrap(Wrap { trim: true })
                .style(style.error()),
            inner,
        ),
        Ok(Figure::Map(map)) => {
            let fixed = app.ui.heat_scale_for(&answer.request.preset);
            let cell = app.ui.map_cell;
            heatmap::draw(&map, fixed, cell, style, frame.buffer_mut(), inner)
        }
        Ok(Figure::Plots(plots)) => {
            let pins = app.ui.pins_of(chart);
            let pinned: Vec<&[Plot]> = pins.iter().map(|p| p.plots.as_slice()).collect();
            let frames = range::frames(&plots, &pinned, app.ui.log_y.contains(&chart));
            let extras = Extras {
                cursor: app.ui.cursor,
                pins: pins
                    .iter()
                    .map(|p| p.name(&answer.request.preset))
                    .collect(),
            };
            chart::draw(&frames, style, &extras, frame.buffer_mut(), inner);
        }
    }
    if dim {
        frame.buffer_mut().set_style(inner, style.stale());
    }
}
