//! The builders of the plane charts: from an engine answer to what is drawn.

use wearlab::engine::PlaneOutput;
use wearlab::physics::Spacing;
use wearlab::physics::plane::OperatingPoint;
use wearlab::physics::plane::sweep::Sweep;
use wearlab::preset::Preset;

use crate::tui::charts::{Axis, Figure, NoFigure, Plot, Series, zip};

fn point(out: &PlaneOutput) -> Result<&OperatingPoint, NoFigure> {
    out.point
        .as_deref()
        .map_err(|e| NoFigure::Error(e.to_string()))
}

fn sweep(out: &PlaneOutput) -> Result<&Sweep, NoFigure> {
    out.sweep.as_deref().ok_or(NoFigure::Solving)
}

fn along_x(y_label: &str, y_unit: &'static str, series: Vec<Series>) -> Plot {
    Plot {
        x: Axis {
            label: "x".into(),
            unit: "m",
            log: false,
        },
        y: Axis {
            label: y_label.into(),
            unit: y_unit,
            log: false,
        },
        focus: series.len(),
        series,
        markers: None,
    }
}

fn against_load(preset: &Preset, y_label: &str, y_unit: &'static str) -> (Axis, Axis) {
    (
        Axis {
            label: "P".into(),
            unit: "N/m",
            log: preset.plane.sweep.spacing == Spacing::Log,
        },
        Axis {
            label: y_label.into(),
            unit: y_unit,
            log: false,
        },
    )
}

/// The loads where the model has a value, with the value.
fn of_load(name: String, sweep: &Sweep, values: &[Option<f64>]) -> Series {
    Series {
        name,
        points: sweep
            .load
            .iter()
            .zip(values)
            .filter_map(|(p, v)| Some((*p, (*v)?)))
            .collect(),
    }
}

pub(super) fn pressure(_: &Preset, out: &PlaneOutput) -> Result<Figure, NoFigure> {
    let p = &point(out)?.profile;
    Ok(Figure::Plots(vec![along_x(
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
    let p = &point(out)?.profile;
    Ok(Figure::Plots(vec![
        along_x(
            "wear/pass",
            "m",
            vec![Series {
                name: "wear per pass".into(),
                points: zip(&p.x, &p.wear),
            }],
        ),
        along_x(
            "k q2",
            "",
            vec![Series {
                name: "wear rate k q2".into(),
                points: zip(&p.x, &p.wear_rate),
            }],
        ),
    ]))
}

pub(super) fn mu_star(preset: &Preset, out: &PlaneOutput) -> Result<Figure, NoFigure> {
    let own = sweep(out)?;
    let model = preset.plane.model;
    let series = std::iter::once((model, own))
        .chain(out.overlays.iter().map(|(m, s)| (*m, &**s)))
        .map(|(m, s)| of_load(format!("mu* {}", m.name()), s, &s.mu_star))
        .collect();
    let (x, y) = against_load(preset, "mu*", "");
    Ok(Figure::Plots(vec![Plot {
        x,
        y,
        series,
        focus: 1,
        markers: point(out).ok().map(|p| Series {
            name: "now".into(),
            points: vec![(p.solution.inputs.load, p.solution.mu_star)],
        }),
    }]))
}

pub(super) fn edges(preset: &Preset, out: &PlaneOutput) -> Result<Figure, NoFigure> {
    let s = sweep(out)?;
    let (x, y) = against_load(preset, "edge", "m");
    Ok(Figure::Plots(vec![Plot {
        x,
        y,
        series: vec![
            of_load("a (trailing)".into(), s, &s.a),
            of_load("b (leading)".into(), s, &s.b),
        ],
        focus: 2,
        markers: None,
    }]))
}
