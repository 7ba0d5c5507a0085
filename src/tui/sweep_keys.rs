//! The keys of the sweep chart and the regime map (part of `update`: pure): the dimensionless
//! view, the map's cursor, a newly opened preset's view, what the chart keys say there, and the
//! requests to the sweep worker (`engine::sweep_worker`), one whenever what should be shown changes.

use crate::engine::latest::Delivery;
use crate::engine::sweep_worker::SweepAnswer;
use crate::preset::Problem;
use crate::sweeps::Opening;
use crate::sweeps::axis::Axis;
use crate::sweeps::map::MapSpec;

use crate::tui::app::{App, Command};
use crate::tui::keys::Action;
use crate::tui::map_cursor::{CursorChange, cursor_key};
use crate::tui::sweep_shown::{map_spec, shown, wanted};
use crate::tui::sweep_state::Explore;

/// A request to the explorer when what should be shown is not what was asked last (an input
/// edited, another view, axis or quantity): the newer request cancels the older one's work.
pub fn sweep_request(app: &mut App) -> Vec<Command> {
    let want = wanted(app);
    if want.is_none() || want == app.explore.requested {
        return Vec::new();
    }
    app.explore.generation += 1;
    app.explore.requested = want.clone();
    want.map(|w| Command::Explore(app.explore.generation, Box::new(w)))
        .into_iter()
        .collect()
}

/// Keeps an answer unless an answer to a newer request is already shown.
pub fn on_answer(app: &mut App, answer: SweepAnswer) {
    if answer.replaces(app.explore.shown.as_ref()) {
        app.explore.shown = Some(answer);
    }
}

/// After a preset is opened: its own view, the generation counting on.
pub fn reopen(app: &mut App) {
    let generation = app.explore.generation;
    let dimensionless = app.explore.dimensionless;
    app.explore = Explore {
        generation,
        dimensionless,
        ..Explore::opened(&app.doc.preset)
    };
}

/// `D`: the dimensionless view on or off.
pub fn toggle_dimensionless(app: &mut App) {
    app.explore.dimensionless = !app.explore.dimensionless;
    app.say(if app.explore.dimensionless {
        "dimensionless view: status, sweep x and v/M choices in groups (? defines them)"
    } else {
        "dimensionless view off"
    });
}

/// The map's cursor: `x` shows or hides it, `[ ]` move it along x, `{ }` along y (a grid point).
pub fn move_cell(app: &mut App, action: Action) {
    let Some(spec) = map_spec(app) else {
        return;
    };
    let (nx, ny) = (spec.x.range.points, spec.y.range.points);
    let (cell, said) = cursor_key(action, app.explore.cell, (nx, ny), || {
        own_cell(app, &spec).unwrap_or((nx / 2, ny / 2))
    });
    app.explore.cell = cell;
    app.say(match said {
        Some(CursorChange::On) => {
            "cursor: [ ] move it along x, { } along y; the status reads the map there"
        }
        Some(CursorChange::Off) => "cursor off",
        Some(CursorChange::NotShown) => "x shows the cursor first",
        None => return,
    });
}

/// The grid point nearest the preset's own point on the map shown (in each axis' spacing), when
/// the point lies within the map: where `x` puts the cursor, so that its first read is the
/// student's own point.
fn own_cell(app: &App, spec: &MapSpec) -> Option<(usize, usize)> {
    let (answer, _) = shown(app)?;
    let crate::engine::sweep_worker::SweepResult::Map(map) = &answer.explored else {
        return None;
    };
    let nearest = |values: &[f64], at: f64, log: bool| {
        let place = |v: f64| if log { v.ln() } else { v };
        let (lo, hi) = (*values.first()?, *values.last()?);
        if !(lo.min(hi)..=lo.max(hi)).contains(&at) {
            return None;
        }
        (0..values.len()).min_by(|&i, &j| {
            let d = |k: usize| (place(values[k]) - place(at)).abs();
            d(i).total_cmp(&d(j))
        })
    };
    let log = |a: &Axis| a.range.spacing == crate::physics::Spacing::Log;
    Some((
        nearest(&map.x, map.current[0], log(&spec.x))?,
        nearest(&map.y, map.current[1], log(&spec.y))?,
    ))
}

/// What pins, the log y axis and the CSV export say in the sweep and map views: they work on the
/// charts (Tab); the sweep's numbers come from `wearlab sweep` (the command, with the preset's
/// file when it holds what is on screen, and this view's axes).
pub fn not_here(app: &App) -> String {
    let job = wanted(app).map(|w| w.job);
    let axes: Vec<String> = match &job {
        Some(Opening::Curve(c)) => vec![vary(&c.axis)],
        Some(Opening::Map(m)) => vec![vary(&m.x), vary(&m.y)],
        None => Vec::new(),
    };
    // the command solves the preset's model only: where other models are overlaid, it gives
    // that model's curve, not every number on screen
    let what = match &job {
        Some(Opening::Curve(c))
            if app.doc.preset.problem == Problem::Plane && c.models.len() > 1 =>
        {
            format!("the {} curve", app.doc.preset.plane.model.name())
        }
        _ => "these numbers".to_string(),
    };
    // the file, when it holds what is on screen; else the edits must be saved first
    let preset = match &app.doc.path {
        Some(path) if !app.doc.dirty => path.display().to_string(),
        _ => "PRESET (s saves the edits to one)".into(),
    };
    // the command first: where the message line cuts, it cuts the words after it
    format!(
        "{what} as CSV: wearlab sweep {preset} {} (E: the figure as SVG; pins and y work on the charts: Tab)",
        axes.join(" ")
    )
}

/// `--vary KEY=FROM:TO:N[:log]` for `axis`: the ends in SI units without a unit, each the
/// shortest text that reads back to the same number (`limits::show`), so the command runs the
/// sweep on screen.
pub fn vary(axis: &Axis) -> String {
    let r = &axis.range;
    let log = if r.spacing == crate::physics::Spacing::Log {
        ":log"
    } else {
        ""
    };
    format!(
        "--vary {}={}:{}:{}{log}",
        axis.key,
        crate::physics::limits::show(r.min),
        crate::physics::limits::show(r.max),
        r.points
    )
}
