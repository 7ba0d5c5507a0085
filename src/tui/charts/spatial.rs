//! The builders of the spatial charts: from an engine answer to what is drawn.

use wearlab::engine::SpatialOutput;
use wearlab::physics::Spacing;
use wearlab::preset::Preset;
use wearlab::units::format_si;

use crate::tui::charts::{Axis, Figure, Map, NoFigure, Plot, Series, zip};

fn axis(label: &str, unit: &'static str, log: bool) -> Axis {
    Axis {
        label: label.into(),
        unit,
        log,
    }
}

fn plot(x: Axis, y: Axis, series: Vec<Series>, markers: Option<Series>) -> Plot {
    Plot {
        x,
        y,
        focus: series.len(),
        series,
        markers,
    }
}

pub(super) fn pressure_map(_: &Preset, out: &SpatialOutput) -> Result<Figure, NoFigure> {
    let f = &out.state.field;
    let cell = &out.state.cell;
    Ok(Figure::Map(Map {
        name: "pressure",
        x: f.x.clone(),
        y: f.y.clone(),
        values: f.pressure.clone(),
        unit: "Pa",
        caption: format!(
            "p(x, y) over {} x {}   x ->, sliding of the layer <-",
            format_si(cell.lx, "m"),
            format_si(cell.ly, "m")
        ),
    }))
}

pub(super) fn line(_: &Preset, out: &SpatialOutput) -> Result<Figure, NoFigure> {
    let f = &out.state.field;
    let row = f.n / 2;
    let along = |v: &[f64]| zip(&f.x, &v[row * f.n..(row + 1) * f.n]);
    let y = format_si(f.y[row], "m");
    let x = || axis("x", "m", false);
    Ok(Figure::Plots(vec![
        plot(
            x(),
            axis("p", "Pa", false),
            vec![Series {
                name: format!("pressure along y = {y}"),
                points: along(&f.pressure),
            }],
            None,
        ),
        plot(
            x(),
            axis("U", "m", false),
            vec![Series {
                name: "shape U".into(),
                points: along(&f.shape),
            }],
            None,
        ),
    ]))
}

pub(super) fn history(_: &Preset, out: &SpatialOutput) -> Result<Figure, NoFigure> {
    let h = out.history.as_deref().ok_or(NoFigure::Solving)?;
    let s = &out.state.solution;
    let t = || axis("t", "s", false);
    let now = |points| Series {
        name: "now".into(),
        points,
    };
    Ok(Figure::Plots(vec![
        plot(
            t(),
            axis("A", "m", false),
            h.amplitudes
                .iter()
                .enumerate()
                .map(|(n, a)| Series {
                    name: format!("A{}", n + 1),
                    points: zip(&h.time, a),
                })
                .collect(),
            Some(now(s
                .harmonics
                .iter()
                .map(|hs| (s.time, hs.state.amplitude))
                .collect())),
        ),
        plot(
            t(),
            axis("mu*", "", false),
            vec![Series {
                name: "mu*(t)".into(),
                points: zip(&h.time, &h.mu_star),
            }],
            Some(now(vec![(s.time, s.mu_star)])),
        ),
    ]))
}

pub(super) fn mu_star(preset: &Preset, out: &SpatialOutput) -> Result<Figure, NoFigure> {
    let st = &out.state;
    let sw = &st.sweep;
    Ok(Figure::Plots(vec![plot(
        axis("pbar", "Pa", preset.spatial.sweep.spacing == Spacing::Log),
        axis("mu*", "", false),
        vec![Series {
            name: "mu* (complete contact only)".into(),
            points: sw
                .mean_pressure
                .iter()
                .zip(&sw.mu_star)
                .filter_map(|(p, m)| Some((*p, (*m)?)))
                .collect(),
        }],
        st.contact.complete.then(|| Series {
            name: "now".into(),
            points: vec![(st.solution.inputs.mean_pressure, st.solution.mu_star)],
        }),
    )]))
}

pub(super) fn dispersion(_: &Preset, out: &SpatialOutput) -> Result<Figure, NoFigure> {
    let d = &out.dispersion;
    let s = &out.state.solution;
    let unit = if d.scaled_by_thickness {
        s.inputs.material.thickness
    } else {
        1.0
    };
    let mut series: Vec<Series> = d
        .angles
        .iter()
        .zip(&d.drift_velocity)
        .map(|(a, c)| Series {
            name: format!("c at {:.0} deg", a.to_degrees()),
            points: zip(&d.k, c),
        })
        .collect();
    series.push(Series {
        name: "c = 0".into(),
        points: vec![(d.k[0], 0.0), (d.k[d.k.len() - 1], 0.0)],
    });
    let x = if d.scaled_by_thickness {
        axis("kh", "", true)
    } else {
        axis("k", "rad/m", true)
    };
    Ok(Figure::Plots(vec![plot(
        x,
        axis("c", "m/s", false),
        series,
        Some(Series {
            name: "harmonics".into(),
            points: s
                .harmonics
                .iter()
                .map(|h| (h.initial.wavenumber() * unit, h.evolution.drift_velocity))
                .collect(),
        }),
    )]))
}
