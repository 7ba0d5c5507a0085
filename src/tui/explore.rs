//! The explorer's sweep chart and regime map, the UI side (part of `update`: pure):
//! which view is shown, the sweep and the map chosen (or their defaults: the preset's
//! `[explore]` section, else mu* against the load or the mean pressure, and mu* - mu over the
//! friction and wear coefficients), the dimensionless view, the map's cursor, and the requests
//! to the explorer's thread (`engine::explore`), one whenever what should be shown changes.

use crate::engine::explore::{ExploreAnswer, ExploreRequest};
use crate::preset::{Key, Preset, Problem};
use crate::sweeps::axis::{Axis, GRID_POINTS};
use crate::sweeps::curve::CurveSpec;
use crate::sweeps::map::MapSpec;
use crate::sweeps::{Opening, QuantityKey, models, opening};

use crate::tui::app::{App, Command};
use crate::tui::keys::Action;
use crate::tui::map_cursor::{Said, stepped};

/// What the chart area shows instead of the charts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// A quantity against one parameter.
    Sweep,
    /// A quantity over two parameters.
    Map,
}

/// The explorer's state.
#[derive(Clone, Debug, Default)]
pub struct Explore {
    /// The view shown (None: the charts).
    pub view: Option<View>,
    /// The sweep chosen with `v` (None: the default of the preset).
    pub curve: Option<CurveSpec>,
    /// The map chosen with `M`.
    pub map: Option<MapSpec>,
    /// Status, axes and choices in the problem's dimensionless groups (`D`).
    pub dimensionless: bool,
    /// The map's cursor (grid column, row), when on.
    pub cell: Option<(usize, usize)>,
    /// The generation of the newest request.
    pub generation: u64,
    /// The newest request sent.
    pub requested: Option<ExploreRequest>,
    /// The newest answer received.
    pub shown: Option<ExploreAnswer>,
}

impl Explore {
    /// The state for a newly opened preset: on its `[explore]` section's view, if it has one.
    pub fn opened(preset: &Preset) -> Explore {
        Explore {
            view: match opening(preset) {
                Some(Ok(Opening::Curve(_))) => Some(View::Sweep),
                Some(Ok(Opening::Map(_))) => Some(View::Map),
                _ => None,
            },
            ..Explore::default()
        }
    }
}

/// The numeric inputs a sweep can vary: every number of the problem that is not a count and not
/// the range of the load or pressure charts (which changes no result).
pub fn parameters(preset: &Preset) -> Vec<Key> {
    Key::all(preset)
        .into_iter()
        .filter(|k| {
            let p = k.param();
            p.limit().is_some() && !p.is_whole() && !p.key.contains(".sweep.")
        })
        .collect()
}

/// The quantities a sweep can show: all of the problem and model (yes/no flags left out), or in
/// the dimensionless view its dimensionless groups and the other pure numbers.
pub fn quantities(preset: &Preset, dimensionless: bool) -> Vec<QuantityKey> {
    QuantityKey::all(preset)
        .into_iter()
        .filter(|q| !q.quantity().flag)
        .filter(|q| !dimensionless || q.quantity().unit.is_empty())
        .collect()
}

fn quantity(preset: &Preset, name: &str) -> Option<QuantityKey> {
    QuantityKey::parse(name, preset).ok()
}

fn fits(preset: &Preset, axis: &Axis) -> bool {
    parameters(preset).contains(&axis.key) && preset.get(axis.key).is_ok()
}

fn fits_quantity(preset: &Preset, q: QuantityKey) -> bool {
    QuantityKey::all(preset).contains(&q)
}

/// The default axis over `key` with `points` points.
fn default_axis(preset: &Preset, key: &str, points: usize) -> Option<Axis> {
    let key = Key::of(key).or_else(|| Key::parse(key).ok())?;
    let mut axis = Axis::default_for(preset, key).ok()?;
    axis.range.points = points;
    Some(axis)
}

/// The sweep to show: the one chosen if it still fits the preset, else the preset's own, else mu*
/// against the load (plane) or the mean pressure (spatial).
pub fn curve_spec(app: &App) -> Option<CurveSpec> {
    let preset = &app.doc.preset;
    let chosen = app.explore.curve.clone().or_else(|| match opening(preset) {
        Some(Ok(Opening::Curve(c))) => Some(c),
        _ => None,
    });
    let (axis, q) = match chosen {
        Some(c) if fits(preset, &c.axis) && fits_quantity(preset, c.quantity) => {
            (c.axis, c.quantity)
        }
        _ => {
            let key = match preset.problem {
                Problem::Plane => "plane.load",
                Problem::Spatial => "spatial.mean_pressure",
            };
            let points = crate::sweeps::axis::CURVE_POINTS;
            (
                default_axis(preset, key, points)?,
                quantity(preset, "mu_star")?,
            )
        }
    };
    Some(CurveSpec {
        models: models(preset, &axis),
        axis,
        quantity: q,
    })
}

/// The map to show: the one chosen if it still fits, else the preset's own, else mu* - mu over
/// (mu, k) (plane) or mu* over (pbar, A1) (spatial).
pub fn map_spec(app: &App) -> Option<MapSpec> {
    let preset = &app.doc.preset;
    let chosen = app.explore.map.clone().or_else(|| match opening(preset) {
        Some(Ok(Opening::Map(m))) => Some(m),
        _ => None,
    });
    match chosen {
        Some(m)
            if fits(preset, &m.x) && fits(preset, &m.y) && fits_quantity(preset, m.quantity) =>
        {
            Some(m)
        }
        _ => {
            let (x, y, q) = match preset.problem {
                Problem::Plane => (
                    "friction.coefficient",
                    "wear.coefficient",
                    "mu_star_minus_mu",
                ),
                Problem::Spatial => (
                    "spatial.mean_pressure",
                    "spatial.harmonics.0.amplitude",
                    "mu_star",
                ),
            };
            Some(MapSpec {
                x: default_axis(preset, x, GRID_POINTS)?,
                y: default_axis(preset, y, GRID_POINTS)?,
                quantity: quantity(preset, q)?,
            })
        }
    }
}

/// The request for what the view should show now.
pub fn wanted(app: &App) -> Option<ExploreRequest> {
    let job = match app.explore.view? {
        View::Sweep => Opening::Curve(curve_spec(app)?),
        View::Map => Opening::Map(map_spec(app)?),
    };
    Some(ExploreRequest {
        preset: app.doc.preset.clone(),
        job,
    })
}

/// A request to the explorer when what should be shown is not what was asked last (an input
/// edited, another view, axis or quantity): the newer request cancels the older one's work.
pub fn follow(app: &mut App) -> Vec<Command> {
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
pub fn on_answer(app: &mut App, answer: ExploreAnswer) {
    let newer = app.explore.shown.as_ref().is_none_or(|s| {
        answer.generation > s.generation || (answer.generation == s.generation && !s.complete)
    });
    if newer {
        app.explore.shown = Some(answer);
    }
}

/// The answer on screen and whether it answers what should be shown now (else it is drawn dim,
/// as the previous inputs', while the newer one is computed).
pub fn shown(app: &App) -> Option<(&ExploreAnswer, bool)> {
    let answer = app.explore.shown.as_ref()?;
    let current = app.explore.requested.as_ref() == Some(&*answer.request);
    let same_kind = matches!(
        (&answer.request.job, app.explore.view?),
        (Opening::Curve(_), View::Sweep) | (Opening::Map(_), View::Map)
    );
    same_kind.then_some((answer, current))
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
    let (cell, said) = stepped(action, app.explore.cell, (nx, ny), || {
        own_cell(app, &spec).unwrap_or((nx / 2, ny / 2))
    });
    app.explore.cell = cell;
    app.say(match said {
        Some(Said::On) => {
            "cursor: [ ] move it along x, { } along y; the status reads the map there"
        }
        Some(Said::Off) => "cursor off",
        Some(Said::NotShown) => "x shows the cursor first",
        None => return,
    });
}

/// The grid point nearest the preset's own point on the map shown (in each axis' spacing), when
/// the point lies within the map: where `x` puts the cursor, so that its first read is the
/// student's own point.
fn own_cell(app: &App, spec: &MapSpec) -> Option<(usize, usize)> {
    let (answer, _) = shown(app)?;
    let crate::engine::explore::Explored::Map(map) = &answer.explored else {
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

/// What pins, the log y axis and the exports say in the sweep and map views: they work on the
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
        "{what} as CSV: wearlab sweep {preset} {} (pins, y and exports work on the charts: Tab)",
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
