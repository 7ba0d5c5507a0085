//! A regime map for the explorer: one quantity over two parameters, with the lines that matter
//! drawn from the library's own verdicts:
//! - theta = 0: the sign of the wide model's theta (4.5) at the point (the preset model's when the
//!   wide model has no solution there); on a half-plane theta = 0 is where mu* - mu changes sign,
//!   the line between contacts where friction dominates (mu* < mu, a > b) and where wear does;
//!   which effect dominates at a point is said from that point's own mu* - mu and a - b
//!   (`Sample::dominance`);
//! - the validity boundaries of the wide and the narrow models: `strip_check::verdict`'s `ok` of
//!   each model solved at the point (whatever the preset's model), its measurements against the
//!   strip model shared between the samples whose groups agree (`verdict_table`; the lines'
//!   bisection below measures each of its points itself);
//! - complete contact (spatial): the report's `contact.complete`;
//! - yield (plane, with a yield strength or hardness given): where the preset's model's contact
//!   starts to yield (`map_yield`, judged from the second pass on: each judge costs 10-50 map
//!   points).
//!
//! Each crossing between two computed points is located on its edge: in the final pass by
//! bisection on the verdict for the plane lines (each step a wide or narrow solve, and a strip
//! solve where the study's estimate doubts the model), by
//! linear interpolation of the smallest complete-contact pressure (0 on the line) for the spatial
//! one; in the coarse passes at the middle of the edge (plane) or by the same interpolation.
//!
//! The map is computed coarse first and refined: the first pass takes every `stride`-th point of
//! each axis (about three per side, both ends always included), each later pass halves the
//! stride, keeping what is computed. `on_pass` receives the map after each pass; the caller's
//! `Stop` is asked before every solve, and inside a spatial point before every time step of its
//! running-in.

use rayon::prelude::*;

use crate::physics::plane::Model;
use crate::physics::plane::dominance::Dominance;
use crate::physics::plane::verdict_table::VerdictTable;
use crate::physics::stop::Stop;
use crate::preset::{Key, Preset, Problem};
use crate::sweeps::axis::Axis;
use crate::sweeps::curve::{holds, probe, solve_at_until};
use crate::sweeps::locate::{Node, Probe, Segment, between, bisect, contour, locate_change};
use crate::sweeps::map_yield;
use crate::sweeps::point::Point;
use crate::sweeps::quantity::QuantityKey;

/// What to map.
#[derive(Clone, Debug, PartialEq)]
pub struct MapSpec {
    /// The parameter along x and its range.
    pub x: Axis,
    /// The parameter along y and its range.
    pub y: Axis,
    /// The quantity shown.
    pub quantity: QuantityKey,
}

/// What is known at one point of the map.
#[derive(Clone, Debug, PartialEq)]
pub struct Sample {
    /// The quantity (the preset's model), or why there is none.
    pub value: Result<f64, String>,
    /// Plane: theta (4.5) [-], the shift of the edge exponents: > 0 where friction shifts them
    /// more than wear, < 0 where wear does (`PlaneSolution::theta`).
    pub theta: Option<f64>,
    /// Plane: which effect dominates, from the signs of the preset's model's mu* - mu and a - b.
    pub dominance: Option<Dominance>,
    /// Plane: whether the wide model holds here (None: no wide solution).
    pub wide_holds: Option<bool>,
    /// Plane: whether the narrow model holds here (None: no narrow solution, e.g. h = inf).
    pub narrow_holds: Option<bool>,
    /// Spatial: whether the contact is complete.
    pub complete: Option<bool>,
    /// Spatial: the smallest complete-contact pressure p_cc [Pa] (negative where partial).
    pub min_pressure: Option<f64>,
    /// Plane, with a yield strength or hardness given: whether the preset's model's contact
    /// yields here (`yield_onset::judge`); None without a strength, where yield is not judged
    /// (the narrow model) and until a pass after the first has judged the point.
    pub yields: Option<bool>,
}

/// Which line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LineKind {
    /// theta = 0.
    ThetaZero,
    /// mu* = mu: where the preset's model's mu* - mu changes sign (which effect dominates; on a
    /// strip of finite thickness apart from theta = 0).
    MuStarEqualsMu,
    /// Where the model's validity check changes.
    Validity(Model),
    /// Where complete contact is lost (spatial).
    CompleteContact,
    /// Where the contact starts to yield (plane, with a yield strength or hardness).
    Yield,
}

/// A line on the map: segments in the parameters' units (x, y).
#[derive(Clone, Debug, PartialEq)]
pub struct Line {
    /// Which line.
    pub kind: LineKind,
    /// Its pieces.
    pub segments: Vec<Segment>,
}

/// A map, possibly still coarse.
#[derive(Clone, Debug, PartialEq)]
pub struct Map {
    /// The x parameter's values (all, computed or not).
    pub x: Vec<f64>,
    /// The y parameter's values.
    pub y: Vec<f64>,
    /// Row-major samples (x fastest), None where not computed yet.
    pub samples: Vec<Option<Sample>>,
    /// Grid steps between computed points (1 once complete).
    pub stride: usize,
    /// The lines, from the computed points.
    pub lines: Vec<Line>,
    /// The preset's own (x, y) (the marker).
    pub current: [f64; 2],
}

impl Map {
    /// The sample at grid point (i, j), or the nearest computed one while the map is coarse.
    pub fn sample(&self, i: usize, j: usize) -> Option<&Sample> {
        let near = |k: usize, n: usize| {
            let idx = indices(n, self.stride);
            idx.iter()
                .copied()
                .min_by_key(|m| m.abs_diff(k))
                .unwrap_or(0)
        };
        let (i, j) = (near(i, self.x.len()), near(j, self.y.len()));
        self.samples.get(j * self.x.len() + i)?.as_ref()
    }
}

/// The grid indices computed at `stride`: every stride-th, and the last.
fn indices(n: usize, stride: usize) -> Vec<usize> {
    let mut idx: Vec<usize> = (0..n).step_by(stride.max(1)).collect();
    if idx.last() != Some(&(n - 1)) {
        idx.push(n - 1);
    }
    idx
}

/// The first stride: a power of two leaving about three points per side (so that a first screen
/// of the strip model, each point a collocation solve, comes within 100 ms).
fn first_stride(n: usize) -> usize {
    let mut s = 1;
    while (n - 1) / (2 * s) >= 2 {
        s *= 2;
    }
    s
}

fn sample(base: &Preset, spec: &MapSpec, at: [f64; 2], table: &VerdictTable, stop: Stop) -> Sample {
    let axes = [spec.x, spec.y];
    let solve = |model| solve_at_until(base, &axes, &at, model, stop);
    let main = match base.problem {
        Problem::Plane => solve(Some(base.plane.model)),
        Problem::Spatial => solve(None),
    };
    let value = main
        .as_ref()
        .map_err(Clone::clone)
        .and_then(|p| spec.quantity.value(p));
    if let Ok(Point::Spatial(s)) = &main {
        return Sample {
            value,
            theta: None,
            dominance: None,
            wide_holds: None,
            narrow_holds: None,
            complete: Some(s.result.contact.complete),
            min_pressure: Some(s.result.contact.min_pressure),
            yields: None,
        };
    }
    // the wide and narrow models' own solutions, the preset's reused when it is one of them
    let solved = |model: Model| match &main {
        Ok(_) if base.plane.model == model => None,
        _ => Some(solve(Some(model))),
    };
    let (wide, narrow) = (solved(Model::Wide), solved(Model::Narrow));
    fn own<'a>(
        other: &'a Option<Result<Point, String>>,
        main: &'a Result<Point, String>,
    ) -> Option<&'a Point> {
        match other {
            Some(r) => r.as_ref().ok(),
            None => main.as_ref().ok(),
        }
    }
    let main_theta = || main.as_ref().ok().and_then(theta_of);
    Sample {
        value,
        theta: own(&wide, &main).and_then(theta_of).or_else(main_theta),
        dominance: match &main {
            Ok(Point::Plane(p)) => Some(Dominance::of(&p.solution)),
            _ => None,
        },
        wide_holds: own(&wide, &main).map(|p| judged(p, table)),
        narrow_holds: own(&narrow, &main).map(|p| judged(p, table)),
        complete: None,
        min_pressure: None,
        yields: None,
    }
}

/// `curve::holds` at a point of this map, a plane model's verdict read from the map's table.
fn judged(p: &Point, table: &VerdictTable) -> bool {
    match p {
        Point::Plane(p) => table.holds(&p.solution),
        Point::Spatial(_) => holds(p),
    }
}

fn theta_of(p: &Point) -> Option<f64> {
    match p {
        Point::Plane(p) => p.solution.theta,
        Point::Spatial(_) => None,
    }
}

/// Computes the map pass by pass; None when `stop` said so before it finished (a point being
/// solved then ends within one step of its running-in).
pub fn regime_map<'s>(
    preset: &Preset,
    spec: &MapSpec,
    stop: impl Into<Stop<'s>>,
    on_pass: &mut dyn FnMut(&Map),
) -> Option<Map> {
    let stop = stop.into();
    let table = VerdictTable::new();
    let yield_judged = map_yield::judged(preset);
    let (x, y) = (spec.x.values(), spec.y.values());
    let (nx, ny) = (x.len(), y.len());
    let mut map = Map {
        current: [preset.get(spec.x.key).ok()?, preset.get(spec.y.key).ok()?],
        samples: vec![None; nx * ny],
        stride: first_stride(nx.max(ny)),
        lines: Vec::new(),
        x,
        y,
    };
    let mut judged = vec![false; nx * ny];
    let first = map.stride;
    loop {
        let todo: Vec<usize> = indices(ny, map.stride)
            .iter()
            .flat_map(|&j| indices(nx, map.stride).into_iter().map(move |i| j * nx + i))
            .filter(|&k| map.samples[k].is_none())
            .collect();
        let found: Vec<Option<(usize, Sample)>> = todo
            .into_par_iter()
            .map(|k| {
                if stop.now() {
                    return None;
                }
                let s = sample(preset, spec, [map.x[k % nx], map.y[k / nx]], &table, stop);
                // a point told to stop half-way has no answer to keep
                (!stop.now()).then_some((k, s))
            })
            .collect();
        for (k, s) in found.into_iter().collect::<Option<Vec<_>>>()? {
            map.samples[k] = Some(s);
        }
        // yield after the first pass (the first screen comes without its cost), or in the only
        // pass of a small map
        if yield_judged && (map.stride < first || map.stride == 1) {
            judge_yields(preset, spec, &mut map, &mut judged, stop)?;
        }
        map.lines = lines(preset, spec, &map, stop)?;
        on_pass(&map);
        if map.stride == 1 {
            return Some(map);
        }
        map.stride /= 2;
    }
}

/// Judges yield at every computed sample of `map` not judged yet (`done` marks them, row-major
/// as the samples); None when `stop` said so before the last.
fn judge_yields(
    preset: &Preset,
    spec: &MapSpec,
    map: &mut Map,
    done: &mut [bool],
    stop: Stop,
) -> Option<()> {
    let nx = map.x.len();
    let todo: Vec<(usize, [f64; 2])> = (0..map.samples.len())
        .filter(|&k| map.samples[k].is_some() && !done[k])
        .map(|k| (k, [map.x[k % nx], map.y[k / nx]]))
        .collect();
    for (k, yields) in map_yield::judge_all(preset, [spec.x, spec.y], todo, stop)? {
        if let Some(s) = map.samples[k].as_mut() {
            s.yields = yields;
        }
        done[k] = true;
    }
    Some(())
}

/// Bisection steps locating a line on an edge of the final pass: 2^-20 of the edge.
const BISECTIONS: usize = 20;
/// Bisection steps locating the yield line: 2^-12 of the edge.
const YIELD_BISECTIONS: usize = 12;

/// A verdict at a sample.
type Verdict = fn(&Sample) -> Option<bool>;

fn lines(preset: &Preset, spec: &MapSpec, map: &Map, stop: Stop) -> Option<Vec<Line>> {
    // on a half-plane mu* = mu where theta = 0: one line says both
    let thickness = Key::parse("material.thickness").ok();
    let half_plane = preset.material.thickness.is_infinite()
        && [spec.x.key, spec.y.key]
            .iter()
            .all(|k| Some(*k) != thickness);
    let mut kinds: Vec<(LineKind, Verdict)> = match preset.problem {
        Problem::Plane => vec![
            (LineKind::ThetaZero, |s| s.theta.map(|t| t > 0.0)),
            (LineKind::MuStarEqualsMu, |s| {
                s.dominance.map(|d| d.mu_star_minus_mu > 0.0)
            }),
            (LineKind::Validity(Model::Wide), |s| s.wide_holds),
            (LineKind::Validity(Model::Narrow), |s| s.narrow_holds),
            (LineKind::Yield, |s| s.yields),
        ],
        Problem::Spatial => vec![(LineKind::CompleteContact, |s| s.complete)],
    };
    kinds.retain(|(kind, _)| !(half_plane && *kind == LineKind::MuStarEqualsMu));
    let (xs, ys) = (
        indices(map.x.len(), map.stride),
        indices(map.y.len(), map.stride),
    );
    let at = |n: Node| -> Option<&Sample> { map.samples[ys[n.1] * map.x.len() + xs[n.0]].as_ref() };
    let point = |a: Node, b: Node, u: f64| {
        [
            between(spec.x.range.spacing, map.x[xs[a.0]], map.x[xs[b.0]], u),
            between(spec.y.range.spacing, map.y[ys[a.1]], map.y[ys[b.1]], u),
        ]
    };
    let mut out = Vec::new();
    for (kind, verdict) in kinds {
        let side = |n: Node| at(n).and_then(verdict);
        let locate = |a: Node, b: Node| -> Option<[f64; 2]> {
            if stop.now() {
                return None;
            }
            let u = match kind {
                // linear between the samples: on the grid's scale, without solving again
                LineKind::CompleteContact => {
                    let (pa, pb) = (at(a)?.min_pressure?, at(b)?.min_pressure?);
                    (pa / (pa - pb)).clamp(0.0, 1.0)
                }
                LineKind::MuStarEqualsMu => {
                    let excess = |n: Node| Some(at(n)?.dominance?.mu_star_minus_mu);
                    let (da, db) = (excess(a)?, excess(b)?);
                    (da / (da - db)).clamp(0.0, 1.0)
                }
                // a coarse pass is replaced soon: the middle of the edge is enough
                _ if map.stride > 1 => 0.5,
                // each step a judge of 4-20 ms: to 2^-12 of the edge, below a screen's cell
                LineKind::Yield => bisect(YIELD_BISECTIONS, side(a)?, |u| {
                    if stop.now() {
                        return None;
                    }
                    map_yield::yields_at(preset, [spec.x, spec.y], point(a, b, u), stop)
                })?,
                _ => locate_change(BISECTIONS, side(a)?, |u| {
                    if stop.now() {
                        return None;
                    }
                    verdict_at(preset, spec, point(a, b, u), kind, stop)
                })?,
            };
            Some(point(a, b, u))
        };
        let segments = contour(xs.len(), ys.len(), &side, &locate);
        if stop.now() {
            return None;
        }
        out.push(Line { kind, segments });
    }
    Some(out)
}

/// A plane line's verdict at a point between samples with the margin that decides it: the sign
/// of theta (the wide model's, else the preset model's; theta its margin), or whether the model
/// holds (`curve::probe`).
fn verdict_at(
    base: &Preset,
    spec: &MapSpec,
    at: [f64; 2],
    kind: LineKind,
    stop: Stop,
) -> Option<Probe> {
    let axes = [spec.x, spec.y];
    let solve = |model: Model| solve_at_until(base, &axes, &at, Some(model), stop).ok();
    match kind {
        LineKind::ThetaZero => {
            let theta = |model: Model| solve(model).and_then(|p| theta_of(&p));
            theta(Model::Wide)
                .or_else(|| theta(base.plane.model))
                .map(|t| (t > 0.0, Some(t)))
        }
        LineKind::Validity(model) => solve(model).map(|p| probe(&p)),
        LineKind::MuStarEqualsMu | LineKind::CompleteContact | LineKind::Yield => None,
    }
}
