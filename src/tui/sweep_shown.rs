//! What the sweep chart and the regime map show (read from the model, by the keys and the
//! drawing alike): the inputs a sweep can vary and the quantities it can show, the sweep and the
//! map to show (the ones chosen, or their defaults: the preset's `[explore]` section, else mu*
//! against the load or the mean pressure, and mu* - mu over the friction and wear coefficients),
//! the request for them, and the answer on screen.

use crate::engine::sweep_worker::{SweepAnswer, SweepRequest};
use crate::preset::{Key, Preset, Problem};
use crate::sweeps::axis::{Axis, GRID_POINTS};
use crate::sweeps::curve::CurveSpec;
use crate::sweeps::groups::of_input;
use crate::sweeps::map::MapSpec;
use crate::sweeps::{Opening, QuantityKey, models, opening};
use crate::tui::app::App;
use crate::tui::sweep_state::View;

/// The numeric inputs a sweep can vary: every number of the problem that is not a count and not
/// the range of the load or pressure charts (which changes no result).
pub fn parameters(preset: &Preset) -> Vec<Key> {
    Key::all(preset)
        .into_iter()
        .filter(|k| {
            let p = k.param();
            // the strength changes no quantity a sweep draws
            let strength = matches!(p.key, "material.yield_strength" | "material.hardness");
            p.limit().is_some() && !p.is_whole() && !p.key.contains(".sweep.") && !strength
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
pub fn wanted(app: &App) -> Option<SweepRequest> {
    let job = match app.explore.view? {
        View::Sweep => Opening::Curve(curve_spec(app)?),
        View::Map => Opening::Map(map_spec(app)?),
    };
    Some(SweepRequest {
        preset: app.doc.preset.clone(),
        job,
    })
}

/// The answer on screen and whether it answers what should be shown now (else it is drawn dim,
/// as the previous inputs', while the newer one is computed).
pub fn shown(app: &App) -> Option<(&SweepAnswer, bool)> {
    let answer = app.explore.shown.as_ref()?;
    let current = app.explore.requested.as_ref() == Some(&*answer.request);
    let same_kind = matches!(
        (&answer.request.job, app.explore.view?),
        (Opening::Curve(_), View::Sweep) | (Opening::Map(_), View::Map)
    );
    same_kind.then_some((answer, current))
}

/// What a sweep or a map of `preset` shows, as the view's title (and an exported figure's) says
/// it: "sweep: mu* against h", in the dimensionless view "sweep: mu* against (a+b)/h (swept:
/// h)"; "regime map: mu* - mu over mu and k".
pub fn title(preset: &Preset, job: &Opening, dimensionless: bool) -> String {
    match job {
        Opening::Curve(c) => format!(
            "sweep: {} against {}",
            c.quantity.symbol(),
            match of_input(preset, c.axis.key.param().key) {
                Some(g) if dimensionless => {
                    format!("{} (swept: {})", g.symbol(), c.axis.key.symbol())
                }
                _ => c.axis.key.symbol(),
            }
        ),
        Opening::Map(m) => format!(
            "regime map: {} over {} and {}",
            m.quantity.symbol(),
            m.x.key.symbol(),
            m.y.key.symbol()
        ),
    }
}
