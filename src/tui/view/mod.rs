//! Drawing: a pure function of the App (no solving, no I/O). Everything drawn from a result is
//! labelled by the inputs that result carries: while a newer request is solving, the previous
//! result stays visible, dimmed, and says whose it is.

pub mod axis;
pub mod bars;
pub mod chart;
pub mod contact_status;
pub mod fit;
pub mod form;
pub mod groups_status;
pub mod harmonic_table;
pub mod heatmap;
pub mod hidden;
pub mod layout;
pub mod legend;
pub mod legend_full;
pub mod lesson;
mod long_words;
pub mod map_readout;
pub mod picker;
pub mod popups;
pub mod prose;
pub mod raster;
pub mod regime;
pub mod status;
pub mod status_values;
pub mod surface_status;
pub mod sweep;
pub mod theme;
pub mod validity_status;
pub mod wrapping;

use ratatui::Frame;
use ratatui::layout::{Alignment, Rect};
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Paragraph, Wrap};

use crate::preset::Preset;
use crate::tui::app::{App, Mode};
use crate::tui::charts::{Figure, NoFigure, Plot, overlay, range};
use crate::tui::on_screen::{OnScreen, on_screen};
use chart::Extras;
pub use layout::MIN_SIZE;
pub use theme::RenderOptions;
pub use wrapping::{wrap, wrap_within};

/// Draws the whole screen.
pub fn view(app: &App, style: RenderOptions, frame: &mut Frame) {
    let area = frame.area();
    let folded = app.explore.view.is_some();
    let Some(mut areas) = layout::areas(area, app.ui.expanded, folded) else {
        too_small(frame, area);
        return;
    };
    let message_rows = bars::message_height(app, style, area.width);
    // a long message takes the panels' last rows rather than being cut
    let extra = message_rows.saturating_sub(1).min(areas.status.height);
    areas.form.height -= extra;
    areas.status.height -= extra;
    areas.message.y -= extra;
    areas.message.height += extra;
    let shown = on_screen(app);
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
            filter,
        } => picker::draw(entries, *selected, *scroll, filter, style, frame, over),
        Mode::Choosing(selected) => popups::choices(app, *selected, style, frame, areas.form),
        Mode::Form(form) => sweep::form(form, style, frame, area),
        Mode::Questions(quiz) => lesson::draw(app, quiz, style, frame, over),
        Mode::FitForm(form) => fit::form(app, form, style, frame, over),
        Mode::FitResult(report, scroll) => fit::report(report, *scroll, style, frame, over),
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

/// The note a title carries about the result under it ("" for the current, complete one).
pub fn note(shown: &OnScreen, style: RenderOptions) -> String {
    let note = match shown {
        OnScreen::Nothing | OnScreen::Current(_, true) => "  solving…".into(),
        OnScreen::Current(_, false) => String::new(),
        OnScreen::Previous(_, label) => format!("  [{label}] solving…"),
    };
    style.text(&note).into_owned()
}

fn draw_chart(app: &App, shown: &OnScreen, style: RenderOptions, frame: &mut Frame, area: Rect) {
    if app.explore.view.is_some() {
        return sweep::draw(app, style, frame, area);
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
    match overlay::figure(chart, answer, app.ui.data.as_ref()) {
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
            let (pinned, extras) = pins_and_extras(app, &answer.request.preset);
            let frames = range::frames(&plots, &pinned, app.ui.log_y.contains(&chart));
            chart::draw(&frames, style, &extras, frame.buffer_mut(), inner);
        }
    }
    if dim {
        frame.buffer_mut().set_style(inner, style.stale());
    }
}

/// The pinned plots of the chart on screen and what is drawn beside its plots: the cursor and
/// the pins' names (in `preset`'s words).
pub fn pins_and_extras<'a>(app: &'a App, preset: &Preset) -> (Vec<&'a [Plot]>, Extras) {
    let pins = app.ui.pins_of(app.ui.chart);
    let pinned = pins.iter().map(|p| p.plots.as_slice()).collect();
    let extras = Extras {
        cursor: app.ui.cursor,
        pins: pins.iter().map(|p| p.name(preset)).collect(),
    };
    (pinned, extras)
}

/// The area of the windows over the screen on the last drawn screen (`view::windows_area`; the
/// message's length does not depend on `--ascii` but for "…", three columns).
pub fn windows_on_last_screen(app: &App) -> ratatui::layout::Rect {
    let plain = crate::tui::view::RenderOptions {
        ascii: false,
        color: false,
        truecolor: false,
    };
    windows_area(app, plain, app.ui.screen)
}
