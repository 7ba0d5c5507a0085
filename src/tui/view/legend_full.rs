//! The chart's legend in full, for the `i` box, where the chart on screen folds it into
//! "+3 more: i" (a small terminal, a crowded chart).

use ratatui::widgets::{Block, Borders};

use crate::tui::app::App;
use crate::tui::charts::range::{Frame, frames};
use crate::tui::charts::{Figure, overlay};
use crate::tui::on_screen::on_screen;
use crate::tui::view::chart::{self, Extras};
use crate::tui::view::{RenderOptions, layout, pins_and_extras, sweep};

/// Each entry of the chart's legend ("** mu* strip") where the chart on the last drawn screen
/// folds its legend; empty where it shows it whole.
pub fn in_full(app: &App, style: RenderOptions) -> Vec<String> {
    let sweeping = app.explore.view.is_some();
    let Some(areas) = layout::areas(app.ui.screen, app.ui.expanded, sweeping) else {
        return Vec::new();
    };
    let inner = Block::default().borders(Borders::ALL).inner(areas.chart);
    let folded = |frames: &[Frame], extras: &Extras, area| -> Vec<String> {
        let Some((laid, _)) = chart::layout(frames, style, extras, area) else {
            return Vec::new();
        };
        (laid.iter().filter_map(|l| l.full.as_ref()))
            .flatten()
            .map(|e| format!("{} {}", e.sample, e.text))
            .collect()
    };
    if sweeping {
        let plots = sweep::sweep_plots(app).unwrap_or_default();
        let (_, area) = sweep::lesson_lines(app, inner);
        return folded(&frames(&plots, &[], false), &sweep::extras(app), area);
    }
    let shown = on_screen(app);
    let Some((answer, _)) = shown.answer() else {
        return Vec::new();
    };
    let Ok(Figure::Plots(plots)) = overlay::figure(app.ui.chart, answer, app.ui.data.as_ref())
    else {
        return Vec::new();
    };
    let (pinned, extras) = pins_and_extras(app, &answer.request.preset);
    let log = app.ui.log_y.contains(&app.ui.chart);
    folded(&frames(&plots, &pinned, log), &extras, inner)
}
