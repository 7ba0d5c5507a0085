//! A curve for the explorer's sweep chart: one quantity against one parameter, for the preset's
//! plane model and the other models as overlays (the spatial problem has one series), with the
//! model's verdict at every point and the parameter values where it changes, located by
//! bisection. Points run in parallel; the caller's `Stop` is asked before each solve, and inside a
//! spatial point before every time step of its running-in.
//!
//! The verdict is the library's own: `strip_check::verdict`'s `ok` for a plane model, the contact's
//! `complete` for the spatial problem (where it is not, the contact is partial and solved through
//! the running-in).

use rayon::prelude::*;

use crate::physics::SolveError;
use crate::physics::plane::sweep_verdicts::holds_along;
use crate::physics::plane::{Model, PlaneSolution};
use crate::physics::stop::Stop;
use crate::preset::{Preset, Problem};
use crate::sweeps::axis::Axis;
use crate::sweeps::groups;
use crate::sweeps::locate::{Probe, between, locate_change};
use crate::sweeps::point::{self, Point};
use crate::sweeps::quantity::QuantityKey;
use crate::sweeps::sweep::preset_at;

/// What to draw.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveSpec {
    /// The parameter on the x axis and its range.
    pub axis: Axis,
    /// The quantity on the y axis.
    pub quantity: QuantityKey,
    /// Plane: the models to draw, the main one first (usually the preset's, then the overlays).
    /// Spatial: ignored (one series).
    pub models: Vec<Model>,
}

/// Where a series' verdict changes between two points of the curve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Change {
    /// The parameter's value at the change (the axis's unit), to 2^-steps of the interval.
    pub at: f64,
    /// The verdict beyond it, in the direction of increasing x.
    pub holds_after: bool,
}

/// One model's curve.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// The plane model (None for the spatial problem).
    pub model: Option<Model>,
    /// The quantity at each x, or why there is none.
    pub y: Vec<Result<f64, String>>,
    /// The verdict at each x (None where there is no solution).
    pub holds: Vec<Option<bool>>,
    /// Where the verdict changes, in increasing x.
    pub changes: Vec<Change>,
    /// The swept input's group (`Curve::group`) at each x, from this model's solution there; None
    /// where there is no solution or the curve has no group.
    pub group: Vec<Option<f64>>,
    /// The quantity at the preset's own value of the input (`Curve::current`), from this model's
    /// solution there (the operating point itself, which may lie between the points of `y`);
    /// None where there is no solution.
    pub current_y: Option<f64>,
    /// The group at the preset's own value of the input (`Curve::current`), from this model's
    /// solution there: where "now" lies on the group axis (the operating point's own group, not
    /// one interpolated between sweep points); None as for `group`.
    pub current_group: Option<f64>,
}

impl Series {
    /// The group at parameter value `at` (the axis's unit), linear between the two neighbouring
    /// points of `x` (the curve's), for a mark placed on the group axis; None outside the curve or
    /// next to a point without a group.
    pub fn group_at(&self, x: &[f64], at: f64) -> Option<f64> {
        let (k, g0, g1) = self.bracket(x, at)?;
        let t = if x[k] == x[k - 1] {
            0.0
        } else {
            (at - x[k - 1]) / (x[k] - x[k - 1])
        };
        Some(g0 + t * (g1 - g0))
    }

    /// Whether the group grows with the parameter between the two points of `x` around `at`
    /// (a mark's "beyond" then points the same way on the group axis).
    pub fn group_rises_at(&self, x: &[f64], at: f64) -> Option<bool> {
        let (k, g0, g1) = self.bracket(x, at)?;
        Some((g1 > g0) == (x[k] > x[k - 1]))
    }

    fn bracket(&self, x: &[f64], at: f64) -> Option<(usize, f64, f64)> {
        let k = (1..x.len()).find(|&k| (x[k - 1].min(x[k])..=x[k - 1].max(x[k])).contains(&at))?;
        Some((k, self.group[k - 1]?, self.group[k]?))
    }
}

/// A computed curve.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    /// The parameter's values.
    pub x: Vec<f64>,
    /// The parameter's value in the preset (the marker).
    pub current: f64,
    /// One series per model, in the order of the spec.
    pub series: Vec<Series>,
    /// The dimensionless group the swept input is the natural variable of
    /// (`groups::of_input`), evaluated at every point into `Series::group`.
    pub group: Option<QuantityKey>,
    /// Whether the series' `holds` and `changes` are known: false for the curve delivered before
    /// its verdicts (`Solved::unjudged`), whose `holds` are None and `changes` empty.
    pub judged: bool,
}

/// The verdict at a point: the model holds (plane: `PlanePoint::verdict`, as `wearlab solve`
/// gives it), the contact is complete (spatial).
pub fn holds(point: &Point) -> bool {
    match point {
        Point::Plane(p) => p.verdict().ok,
        Point::Spatial(s) => s.result.contact.complete,
    }
}

/// `holds` with the margin that decides it where there is one (`PlanePoint::verdict_margin`), for
/// `locate_change`.
pub fn probe(point: &Point) -> Probe {
    match point {
        Point::Plane(p) => (p.verdict().ok, p.verdict_margin()),
        Point::Spatial(_) => (holds(point), None),
    }
}

/// Bisection steps: 2^-30 of an interval for the cheap solves, fewer for the strip model and the
/// spatial running-in (each step a full solve).
fn steps(preset: &Preset, model: Option<Model>) -> usize {
    match (preset.problem, model) {
        (Problem::Plane, Some(Model::Strip)) => 12,
        (Problem::Plane, _) => 30,
        (Problem::Spatial, _) => 16,
    }
}

/// The preset at `values` of `axes`, with `model` for the plane problem, solved.
pub fn solve_at(
    base: &Preset,
    axes: &[Axis],
    values: &[f64],
    model: Option<Model>,
) -> Result<Point, String> {
    solve_at_until(base, axes, values, model, Stop::Never)
}

/// As [`solve_at`], told to stop by `stop` (`point::solve_until`): the error then says the
/// computation was cancelled.
pub fn solve_at_until(
    base: &Preset,
    axes: &[Axis],
    values: &[f64],
    model: Option<Model>,
    stop: Stop,
) -> Result<Point, String> {
    let mut base = base.clone();
    if let Some(m) = model {
        base.plane.model = m;
    }
    let preset = preset_at(&base, axes, values)?;
    point::solve_until(&preset, stop).map_err(|e| SolveError::from(e).to_string())
}

/// What decides the verdict at a point: a plane solution (judged along the series,
/// `sweep_verdicts::holds_along`), or the spatial contact's completeness.
enum Judge {
    Plane(Box<PlaneSolution>),
    Spatial(bool),
}

/// The quantity at a point, what decides the verdict there and the swept input's group.
type Answer = (Result<f64, String>, Option<Judge>, Option<f64>);

/// The verdicts of one series' points, in order (`holds`, the plane's judged along the series).
fn verdicts(judges: &[Option<&Judge>]) -> Vec<Option<bool>> {
    let plane: Vec<Option<PlaneSolution>> = judges
        .iter()
        .map(|j| match j {
            Some(Judge::Plane(s)) => Some(s.as_ref().clone()),
            _ => None,
        })
        .collect();
    let along = holds_along(&plane);
    judges
        .iter()
        .zip(along)
        .map(|(j, plane)| match j {
            Some(Judge::Spatial(complete)) => Some(*complete),
            _ => plane,
        })
        .collect()
}

/// Computes the curve; None when `stop` said so before it finished (a point being solved then
/// ends within one step of its running-in).
pub fn curve<'s>(preset: &Preset, spec: &CurveSpec, stop: impl Into<Stop<'s>>) -> Option<Curve> {
    let stop = stop.into();
    solve(preset, spec, stop)?.judged(stop)
}

/// A curve's points solved, before their verdicts: the curve can be drawn from it at once, and
/// the verdicts (strip solves where the study's estimate doubts a plane model, a bisection where
/// they change) follow (`Solved::judged`).
pub struct Solved {
    preset: Preset,
    axis: Axis,
    /// What decides the verdict at each point of each series (None where there is no solution).
    judges: Vec<Vec<Option<Judge>>>,
    /// The curve without verdicts.
    curve: Curve,
}

impl Solved {
    /// The curve without its verdicts (`judged` false).
    pub fn unjudged(&self) -> Curve {
        self.curve.clone()
    }

    /// The curve with the verdict at every point and where it changes; None when `stop` said so
    /// before it finished.
    pub fn judged(mut self, stop: Stop) -> Option<Curve> {
        for (series, judges) in self.curve.series.iter_mut().zip(&self.judges) {
            series.holds = verdicts(&judges.iter().map(Option::as_ref).collect::<Vec<_>>());
            let (axis, x) = (&self.axis, &self.curve.x);
            series.changes = changes(&self.preset, axis, x, &series.holds, series.model, stop)?;
        }
        self.curve.judged = true;
        Some(self.curve)
    }
}

/// Solves every point of the curve, its verdicts not yet judged; None when `stop` said so before
/// it finished.
pub fn solve(preset: &Preset, spec: &CurveSpec, stop: Stop) -> Option<Solved> {
    let models: Vec<Option<Model>> = match preset.problem {
        Problem::Plane => spec.models.iter().copied().map(Some).collect(),
        Problem::Spatial => vec![None],
    };
    let x = spec.axis.values();
    let axes = [spec.axis];
    let group = groups::of_input(preset, spec.axis.key.param().key);
    let jobs: Vec<(usize, f64)> = (0..models.len())
        .flat_map(|m| x.iter().map(move |v| (m, *v)))
        .collect();
    let answer = |solved: Result<Point, String>| -> Answer {
        match solved {
            Ok(p) => {
                let judge = match &p {
                    Point::Plane(pp) => Judge::Plane(Box::new(pp.solution.clone())),
                    Point::Spatial(sp) => Judge::Spatial(sp.result.contact.complete),
                };
                (
                    spec.quantity.value(&p),
                    Some(judge),
                    group.and_then(|g| g.value(&p).ok()),
                )
            }
            Err(why) => (Err(why), None, None),
        }
    };
    let answers: Vec<Option<Answer>> = jobs
        .into_par_iter()
        .map(|(m, v)| {
            if stop.now() {
                return None;
            }
            let solved = solve_at_until(preset, &axes, &[v], models[m], stop);
            // a point told to stop half-way has no answer to keep
            (!stop.now()).then(|| answer(solved))
        })
        .collect();
    let mut answers: Vec<_> = answers.into_iter().collect::<Option<_>>()?;
    // each model at the preset's own value: where "now" lies and what the curve reads there
    let current = preset.get(spec.axis.key).ok()?;
    let at_current: Vec<Answer> = models
        .par_iter()
        .map(|m| {
            if stop.now() {
                return None;
            }
            let solved = solve_at_until(preset, &axes, &[current], *m, stop);
            (!stop.now()).then(|| answer(solved))
        })
        .collect::<Option<_>>()?;
    let mut series = Vec::new();
    let mut judges = Vec::new();
    for (m, model) in models.iter().enumerate().rev() {
        let own: Vec<Answer> = answers.split_off(m * x.len());
        series.push(Series {
            model: *model,
            y: own.iter().map(|a| a.0.clone()).collect(),
            holds: vec![None; x.len()],
            changes: Vec::new(),
            group: own.iter().map(|a| a.2).collect(),
            current_y: at_current[m].0.as_ref().ok().copied(),
            current_group: at_current[m].2,
        });
        judges.push(own.into_iter().map(|a| a.1).collect());
    }
    series.reverse();
    judges.reverse();
    Some(Solved {
        preset: preset.clone(),
        axis: spec.axis,
        judges,
        curve: Curve {
            current,
            x,
            series,
            group,
            judged: false,
        },
    })
}

fn changes(
    preset: &Preset,
    axis: &Axis,
    x: &[f64],
    verdicts: &[Option<bool>],
    model: Option<Model>,
    stop: Stop,
) -> Option<Vec<Change>> {
    let steps = steps(preset, model);
    let found: Vec<Option<Option<Change>>> = (1..x.len())
        .into_par_iter()
        .map(|i| {
            let (Some(a), Some(b)) = (verdicts[i - 1], verdicts[i]) else {
                return Some(None);
            };
            if a == b {
                return Some(None);
            }
            let value = |u: f64| between(axis.range.spacing, x[i - 1], x[i], u);
            let side = |u: f64| {
                if stop.now() {
                    return None;
                }
                solve_at_until(preset, &[*axis], &[value(u)], model, stop)
                    .ok()
                    .map(|p| probe(&p))
            };
            let u = locate_change(steps, a, side);
            if stop.now() {
                return None;
            }
            Some(u.map(|u| Change {
                at: value(u),
                holds_after: b,
            }))
        })
        .collect();
    Some(
        found
            .into_iter()
            .collect::<Option<Vec<_>>>()?
            .into_iter()
            .flatten()
            .collect(),
    )
}
