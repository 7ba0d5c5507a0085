//! The builders of the plane charts: from an engine answer to what is drawn.

use crate::engine::PlaneOutput;
use crate::physics::Spacing;
use crate::physics::plane::energy::{Energy, Undefined};
use crate::physics::plane::sweep::Sweep;
use crate::physics::plane::{Model, OperatingPoint};
use crate::preset::Preset;

use crate::tui::charts::{Axis, Figure, Mark, NoFigure, Plot, Scale, Series, axis, gaps, zip};

fn point(out: &PlaneOutput) -> Result<&OperatingPoint, NoFigure> {
    out.point
        .as_deref()
        .map_err(|e| NoFigure::Error(e.to_string()))
}

fn sweep(out: &PlaneOutput) -> Result<&Sweep, NoFigure> {
    out.sweep.as_deref().ok_or(NoFigure::Solving)
}

/// A plot along x, with the contact edges and the punch tip marked.
fn along_x(p: &OperatingPoint, y_label: &str, y_unit: &'static str, series: Vec<Series>) -> Plot {
    let s = &p.solution;
    let mut plot = Plot::new(
        axis("x", "m", Scale::Linear),
        axis(y_label, y_unit, Scale::Linear),
        series,
    );
    plot.x_marks = vec![
        Mark {
            at: -s.a,
            label: "-a".into(),
        },
        Mark {
            at: 0.0,
            label: "tip".into(),
        },
        Mark {
            at: s.b,
            label: "b".into(),
        },
    ];
    plot
}

fn against_load(preset: &Preset, y_label: &str, y_unit: &'static str) -> (Axis, Axis) {
    let x = if preset.plane.sweep.spacing == Spacing::Log {
        Scale::Log
    } else {
        Scale::Linear
    };
    (axis("P", "N/m", x), axis(y_label, y_unit, Scale::Linear))
}

/// The loads where the model has a value, with the value.
fn of_load(name: String, load: &[f64], values: &[Option<f64>]) -> Series {
    Series {
        name,
        points: load
            .iter()
            .zip(values)
            .filter_map(|(p, v)| Some((*p, (*v)?)))
            .collect(),
    }
}

pub(super) fn pressure(_: &Preset, out: &PlaneOutput) -> Result<Figure, NoFigure> {
    let op = point(out)?;
    let p = &op.profile;
    Ok(Figure::Plots(vec![along_x(
        op,
        "stress",
        "Pa",
        vec![
            Series {
                name: "pressure q2".into(),
                points: zip(&p.x, &p.pressure),
            },
            Series {
                name: "shear q1".into(),
                points: zip(&p.x, &p.shear),
            },
        ],
    )]))
}

pub(super) fn wear(_: &Preset, out: &PlaneOutput) -> Result<Figure, NoFigure> {
    let op = point(out)?;
    let p = &op.profile;
    let (axis, law) = wear_law(op.solution.inputs.wear.exponent);
    Ok(Figure::Plots(vec![
        along_x(
            op,
            "wear/pass",
            "m",
            vec![Series {
                name: "wear per pass".into(),
                points: zip(&p.x, &p.wear),
            }],
        ),
        along_x(
            op,
            axis,
            "",
            vec![Series {
                name: format!("wear rate {law}"),
                points: zip(&p.x, &p.wear_rate),
            }],
        ),
    ]))
}

/// The wear rate's axis label and its law as the legend writes it: k q2 for the linear law,
/// k q2 (q2/p0)^(n-1) with n's value otherwise.
fn wear_law(exponent: f64) -> (&'static str, String) {
    if exponent == 1.0 {
        ("k q2", "k q2".into())
    } else {
        ("F(q2)", format!("k q2 (q2/p0)^(n-1), n = {exponent}"))
    }
}

/// mu* of each model against the load, dim where the model fails its validity check (as the
/// status judges the operating point; the legend says when the verdicts are still being
/// measured), each curve's loads without an answer said in its legend.
pub(super) fn mu_star(preset: &Preset, out: &PlaneOutput) -> Result<Figure, NoFigure> {
    let own = sweep(out)?;
    let model = preset.plane.model;
    let sweeps: Vec<(Model, &Sweep)> = std::iter::once((model, own))
        .chain(out.overlays.iter().map(|(m, s)| (*m, &**s)))
        // a model that needs a finite thickness has no curve on a half-plane
        .filter(|(m, _)| !(m.needs_finite_thickness() && preset.material.is_half_space()))
        .collect();
    let series = (sweeps.iter())
        .map(|(m, s)| {
            let pending = super::gaps::pending(s.judged, true);
            of_load(format!("mu* {}{pending}", m.name()), &s.load, &s.mu_star)
        })
        .collect();
    let (x, y) = against_load(preset, "mu*", "");
    let mut plot = Plot::new(x, y, series);
    // the study judges the parabola with the linear laws only: elsewhere its verdicts are none
    let unjudged = !preset.plane_inputs().is_classical();
    let verdict = if unjudged { "not judged" } else { "fails" };
    for (i, (m, s)) in sweeps.iter().enumerate() {
        let point = |k: usize| Some((s.load[k], s.mu_star[k]?));
        let fails = format!("{} {verdict}", m.name());
        plot.dim
            .extend(gaps::failing_runs(i, &fails, &s.valid, point));
        plot.unanswered
            .extend(gaps::unanswered(i, &s.load, &s.mu_star, &plot.x, "loads"));
    }
    plot.dim_label = if unjudged {
        "dim: not judged (the validity study covers the parabola with the linear laws)".into()
    } else {
        super::sweep::dim_label(preset.problem).into()
    };
    plot.unjudged = unjudged;
    plot.focus = 1;
    plot.markers = point(out).ok().map(|p| Series {
        name: "now".into(),
        points: vec![(p.solution.inputs.load, p.solution.mu_star)],
    });
    plot.against_mu(preset.friction.coefficient);
    Ok(Figure::Plots(vec![plot]))
}

pub(super) fn edges(preset: &Preset, out: &PlaneOutput) -> Result<Figure, NoFigure> {
    let s = sweep(out)?;
    let (x, y) = against_load(preset, "edge", "m");
    Ok(Figure::Plots(vec![Plot::new(
        x,
        y,
        vec![
            of_load("a (trailing)".into(), &s.load, &s.a),
            of_load("b (leading)".into(), &s.load, &s.b),
        ],
    )]))
}

pub(super) fn punch(_: &Preset, out: &PlaneOutput) -> Result<Figure, NoFigure> {
    let op = point(out)?;
    let p = &op.profile;
    let series = |name: &str, values: &[f64]| Series {
        name: name.into(),
        points: zip(&p.x, values),
    };
    Ok(Figure::Plots(vec![
        along_x(
            op,
            "height",
            "m",
            vec![
                series("punch g(x)", &p.shape),
                series("strip v(x)", &p.surface),
            ],
        ),
        along_x(op, "groove", "m", vec![series("wear groove", &p.wear)]),
    ]))
}

/// An operating point's energy balance, as `energy` answers.
type Balance = Result<Energy, Undefined>;

pub(super) fn energy(preset: &Preset, out: &PlaneOutput) -> Result<Figure, NoFigure> {
    let e = out.energies.as_deref().ok_or(NoFigure::Solving)?;
    let now = point(out).ok();
    // one plot each: a share moves monotonically with load, its legend beside it
    let share = |name: &str, values: &[Option<f64>], at: fn(&Balance) -> Option<f64>| {
        let (x, y) = against_load(preset, name, "");
        let mut plot = Plot::new(x, y, vec![of_load(name.into(), &e.load, values)]);
        plot.markers = now.and_then(|p| {
            Some(Series {
                name: "now".into(),
                points: vec![(p.solution.inputs.load, at(&p.energy)?)],
            })
        });
        plot
    };
    Ok(Figure::Plots(vec![
        share("friction loss/T", &e.friction_share, |b| {
            b.as_ref().ok()?.friction_share()
        }),
        share("wear loss/T", &e.wear_share, |b| match b {
            Ok(energy) => energy.wear_share(),
            Err(undefined) => undefined.wear_share(),
        }),
    ]))
}
