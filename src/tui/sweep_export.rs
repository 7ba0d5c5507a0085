//! `E` in the sweep and map views (part of `update`: pure): the figure the view draws, as SVG,
//! titled as the view and captioned with the parameters it was computed from. While the view's
//! answer is not the current one, or a map is still refining, the export waits for it, as a
//! chart's export waits for its solve.

use crate::engine::sweep_worker::SweepResult;
use crate::sweeps::Opening;

use crate::tui::app::{App, Command};
use crate::tui::charts::export::{Format, map_svg, named, sweep_svg};
use crate::tui::sweep_shown::{shown, title};
use crate::tui::view::sweep::sweep_plots;

/// Whether the view shows the whole answer to what it should show.
fn ready(app: &App) -> bool {
    shown(app).is_some_and(|(answer, current)| current && answer.complete)
}

/// Exports the view's figure as SVG, or waits for it.
pub fn export(app: &mut App) -> Vec<Command> {
    if !ready(app) {
        app.explore.export_waiting = true;
        app.say("the export waits for the view's result (computing…)");
        return Vec::new();
    }
    let Some((answer, _)) = shown(app) else {
        return Vec::new();
    };
    let preset = &answer.request.preset;
    let title = title(preset, &answer.request.job, app.explore.dimensionless);
    let text = match (&answer.request.job, &answer.explored) {
        (Opening::Map(spec), SweepResult::Map(map)) => map_svg(&title, preset, spec, map),
        _ => sweep_svg(&title, preset, sweep_plots(app).unwrap_or_default()),
    };
    match text {
        Ok(text) => vec![Command::Export {
            path: named(&title, Format::Svg).into(),
            text,
            overwrite: false,
        }],
        Err(why) => {
            app.complain(format!("nothing to export: {why}"));
            Vec::new()
        }
    }
}

/// After an answer of the sweep worker: the export that waited for it, once it is whole.
pub fn on_answer(app: &mut App) -> Vec<Command> {
    if app.explore.export_waiting && ready(app) {
        app.explore.export_waiting = false;
        export(app)
    } else {
        Vec::new()
    }
}
