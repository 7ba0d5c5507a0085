//! The sweep chart (`v`): a quantity against any numeric input, from the explorer's curve
//! (`sweeps::curve`). One curve per plane model, the preset's first (it sets the y range); where
//! a model's own validity check fails (the spatial problem: where the contact is not complete)
//! its curve is drawn dim, and each place where the verdict changes is marked on the x axis. The
//! current value of the parameter is marked "now". In the dimensionless view (`D`) the x axis is
//! the swept input's group (`Curve::group`, computed by the library at each point), each curve
//! drawn through its points in the sweep's order (a parametric curve where the group is not
//! monotone), "now" at the operating point's own group and the verdict changes at the group
//! interpolated between the neighbouring points; an input without a group keeps its dimensional
//! axis, titled so.

use crate::physics::Spacing;
use crate::preset::{Key, Problem};
use crate::sweeps::curve::{Curve, CurveSpec};

use crate::tui::charts::{Axis, Figure, Mark, Plot, Scale, Series};

/// The x axis of a parameter: its symbol and unit, log or linear as its range.
pub fn x_axis(key: Key, spacing: Spacing) -> Axis {
    Axis {
        label: key.symbol(),
        unit: key.param().unit,
        scale: match spacing {
            Spacing::Log => Scale::Log,
            Spacing::Linear => Scale::Linear,
        },
    }
}

/// The x axis in the dimensionless view: the group's symbol, log when the sweep is log; or, for
/// an input without a group, its dimensional axis titled "(dimensional: no group)".
fn group_axis(spec: &CurveSpec, curve: &Curve) -> Axis {
    let mut axis = x_axis(spec.axis.key, spec.axis.range.spacing);
    match curve.group {
        Some(g) => axis.label = g.symbol(),
        None => axis.label = format!("{} (dimensional: no group)", axis.label),
    }
    if curve.group.is_some() {
        axis.unit = "";
    }
    axis
}

/// The swept input against the group along the preset's curve (x: group, y: the input), for the
/// cursor readout to give the input's value at a group; None without a group.
pub fn input_along_group(curve: &Curve) -> Option<Series> {
    curve.group?;
    let s = curve.series.first()?;
    let point = |k: usize| Some((s.group[k]?, curve.x[k]));
    Some(Series {
        name: String::new(),
        points: through_now(curve, point, s.current_group.map(|g| (g, curve.current))),
    })
}

/// The legend name of the dim parts.
pub fn dim_label(problem: Problem) -> &'static str {
    match problem {
        Problem::Plane => "dim: the model's validity check fails",
        Problem::Spatial => "dim: partial contact (not complete)",
    }
}

/// Points of a series in the sweep's order with `now` (from the operating point, solved at the
/// preset's own value) among them where it lies strictly between two points of the sweep, so that the
/// curve and the cursor there give the operating point's own value, not one interpolated.
fn through_now(
    curve: &Curve,
    point: impl Fn(usize) -> Option<(f64, f64)>,
    now: Option<(f64, f64)>,
) -> Vec<(f64, f64)> {
    let x = &curve.x;
    let mut points: Vec<(f64, f64)> = (0..x.len()).filter_map(&point).collect();
    let (lo, hi) = x
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(*v), hi.max(*v))
        });
    if let Some(now) = now
        && lo < curve.current
        && curve.current < hi
        && !x.contains(&curve.current)
    {
        let rising = x.last() >= x.first();
        let before = (0..x.len())
            .filter(|&k| (x[k] < curve.current) == rising)
            .filter_map(&point)
            .count();
        points.insert(before, now);
    }
    points
}

/// The figure of a computed curve.
pub fn figure(
    problem: Problem,
    mu: f64,
    spec: &CurveSpec,
    curve: &Curve,
    dimensionless: bool,
) -> Figure {
    let q = spec.quantity;
    let grouped = dimensionless && curve.group.is_some();
    let symbol = q.symbol();
    let mut series = Vec::new();
    let mut dim = Vec::new();
    let mut x_marks = Vec::new();
    let mut unanswered = Vec::new();
    for (i, s) in curve.series.iter().enumerate() {
        let model = s.model.map(|m| m.name());
        // the x of a point or of a mark: the input's value, or in groups the model's own group
        let x_at = |at: f64| {
            if grouped {
                s.group_at(&curve.x, at)
            } else {
                Some(at)
            }
        };
        let x_of = |k: usize| {
            if grouped {
                s.group[k]
            } else {
                Some(curve.x[k])
            }
        };
        let point = |k: usize| Some((x_of(k)?, *s.y[k].as_ref().ok()?));
        // where the operating point lies on this series' x axis
        let now = if grouped {
            s.current_group
        } else {
            Some(curve.current)
        };
        if i == 0 {
            x_marks.extend(now.map(|at| Mark {
                at,
                label: "now".into(),
            }));
        }
        let pending = super::gaps::pending(curve.judged, model.is_some());
        series.push(Series {
            name: match model {
                Some(m) => format!("{symbol} {m}{pending}"),
                None => format!("{symbol}{pending}"),
            },
            points: through_now(curve, point, now.zip(s.current_y)),
        });
        // the points without an answer, named on the swept input's axis (they have no group)
        let values: Vec<Option<f64>> = s.y.iter().map(|y| y.as_ref().ok().copied()).collect();
        let input = x_axis(spec.axis.key, spec.axis.range.spacing);
        unanswered.extend(super::gaps::unanswered(
            i, &curve.x, &values, &input, "points",
        ));
        // each run of points where the verdict fails, as its own dim piece
        let fails = model.map_or_else(String::new, |m| format!("{m} fails"));
        dim.extend(super::gaps::failing_runs(i, &fails, &s.holds, point));
        // a model's check holds or fails; the spatial problem's contact is complete or partial
        let (holds, fails) = match model {
            Some(_) => ("ok", "fails"),
            None => ("complete", "partial"),
        };
        x_marks.extend(s.changes.iter().filter_map(|c| {
            let verdict = if c.holds_after { holds } else { fails };
            Some(Mark {
                at: x_at(c.at)?,
                label: format!(
                    "{}{}",
                    model.map(|m| format!("{m} ")).unwrap_or_default(),
                    // "beyond" is towards larger x: on a falling group, leftwards
                    if !grouped || s.group_rises_at(&curve.x, c.at)? {
                        format!("{verdict}>")
                    } else {
                        format!("<{verdict}")
                    }
                ),
            })
        }));
    }
    let quantity = q.quantity();
    let y = Axis {
        label: symbol,
        unit: quantity.unit,
        scale: Scale::Linear,
    };
    let x = if dimensionless {
        group_axis(spec, curve)
    } else {
        x_axis(spec.axis.key, spec.axis.range.spacing)
    };
    let mut plot = Plot::new(x, y, series);
    plot.focus = 1;
    // in increasing x, so that each label can sit at its own line
    x_marks.sort_by(|a, b| a.at.total_cmp(&b.at));
    plot.x_marks = x_marks;
    plot.dim = dim;
    plot.unanswered = unanswered;
    plot.dim_label = dim_label(problem).into();
    plot.fraction = quantity.name == "contact.fraction";
    // against mu itself the reference is the diagonal mu* = mu, a curve over the swept range
    let swept_mu = !dimensionless && spec.axis.key.param().key == "friction.coefficient";
    match quantity.name {
        "mu_star" if swept_mu => {
            // at every swept value, so that it is the diagonal on a log axis too
            plot.series.push(Series {
                name: "mu* = mu".into(),
                points: curve.x.iter().map(|&m| (m, m)).collect(),
            });
            plot.resolution = super::MU_STAR_RESOLUTION;
        }
        "mu_star" => plot.against_mu(mu),
        "mu_star_minus_mu" => {
            plot.y_marks = vec![Mark {
                at: 0.0,
                label: "0: mu* = mu".into(),
            }];
            plot.resolution = super::MU_STAR_RESOLUTION;
        }
        _ => {}
    }
    Figure::Plots(vec![plot])
}
