//! The builders of the spatial charts: from an engine answer to what is drawn.

use crate::engine::SpatialOutput;
use crate::physics::Spacing;
use crate::preset::Preset;
use crate::units::format_si;

use crate::tui::charts::contact::{self, Fields};
use crate::tui::charts::{Figure, Map, Mark, NoFigure, Plot, Scale, Series, axis, zip};

/// Directions whose drift velocities differ by less than this fraction of the chart's range
/// draw as one line (a Braille dot is a fortieth of a ten-row chart).
const COINCIDE: f64 = 0.02;

pub(super) fn pressure_map(_: &Preset, out: &SpatialOutput) -> Result<Figure, NoFigure> {
    let st = &out.state;
    let cell = &st.cell;
    let caption = format!(
        "One period cell, {} (x, to the right) by {} (y); the layer slides to -x.",
        format_si(cell.lx, "m"),
        format_si(cell.ly, "m")
    );
    let f = &st.field;
    Ok(Figure::Map(match contact::fields(out)? {
        Fields::Nodes(state) => contact::map(st.solution.time, cell.ly, state, caption),
        Fields::Closed => {
            let (y, values) = contact::stretched(&f.pressure, f.n, f.y.clone(), cell.ly);
            Map {
                name: "pressure",
                x: f.x.clone(),
                y,
                values,
                unit: "Pa",
                caption,
                empty: None,
            }
        }
    }))
}

pub(super) fn line(_: &Preset, out: &SpatialOutput) -> Result<Figure, NoFigure> {
    let (x, p, u, y) = match contact::fields(out)? {
        Fields::Nodes(state) => contact::row(state),
        Fields::Closed => {
            let f = &out.state.field;
            let row = f.y.len() / 2;
            let along = |v: &[f64]| v[row * f.n..(row + 1) * f.n].to_vec();
            (f.x.clone(), along(&f.pressure), along(&f.shape), f.y[row])
        }
    };
    Ok(line_plots(&x, &p, &u, y))
}

/// p and U against x along the row at `y` [m], each crest marked in its legend.
pub(super) fn line_plots(x: &[f64], p: &[f64], u: &[f64], y: f64) -> Figure {
    let y = format_si(y, "m");
    let x_axis = || axis("x", "m", Scale::Linear);
    let (p, u) = (zip(x, p), zip(x, u));
    let crest = |points: &[(f64, f64)]| {
        crest(points).map_or(String::new(), |c| {
            format!(", crest x = {}", format_si(c, "m"))
        })
    };
    Figure::Plots(vec![
        Plot::new(
            x_axis(),
            axis("p", "Pa", Scale::Linear),
            vec![Series {
                name: format!("p (y = {y}){}", crest(&p)),
                points: p,
            }],
        ),
        Plot::new(
            x_axis(),
            axis("U", "m", Scale::Linear),
            vec![Series {
                name: format!("shape U{}", crest(&u)),
                points: u,
            }],
        ),
    ])
}

pub(super) fn history(preset: &Preset, out: &SpatialOutput) -> Result<Figure, NoFigure> {
    if let Some(c) = contact::stepped(out) {
        return contact::running_in(preset, c);
    }
    let h = out.history.as_deref().ok_or(NoFigure::Solving)?;
    let s = &out.state.solution;
    let t = || axis("t", "s", Scale::Linear);
    let now = |points| Series {
        name: "now".into(),
        points,
    };
    let mut amplitudes = Plot::new(
        t(),
        axis("A", "m", Scale::Linear),
        h.amplitudes
            .iter()
            .enumerate()
            .map(|(n, a)| Series {
                name: format!("A{}", n + 1),
                points: zip(&h.time, a),
            })
            .collect(),
    );
    amplitudes.markers = Some(now(s
        .harmonics
        .iter()
        .map(|hs| (s.time, hs.state.amplitude))
        .collect()));
    let mut mu = Plot::new(
        t(),
        axis("mu*", "", Scale::Linear),
        vec![Series {
            name: "mu*(t)".into(),
            points: zip(&h.time, &h.mu_star),
        }],
    );
    mu.markers = Some(now(vec![(s.time, s.mu_star)]));
    mu.against_mu(preset.friction.coefficient);
    Ok(Figure::Plots(vec![amplitudes, mu]))
}

pub(super) fn mu_star(preset: &Preset, out: &SpatialOutput) -> Result<Figure, NoFigure> {
    let x = || {
        let scale = if preset.spatial.sweep.spacing == Spacing::Log {
            Scale::Log
        } else {
            Scale::Linear
        };
        axis("pbar", "Pa", scale)
    };
    if let Ok(c) = &out.cell {
        match &c.load_curve {
            Some(Ok(curve)) => return contact::load_curve(preset, c, curve, x()),
            Some(Err(why)) => return Err(NoFigure::Error(why.to_string())),
            // the closed form below holds for the shape at t only while it is the harmonics'
            None if !c.complete_from_start => return Err(NoFigure::Solving),
            None => {}
        }
    }
    let st = &out.state;
    let sw = &st.sweep;
    let mut plot = Plot::new(
        x(),
        axis("mu*", "", Scale::Linear),
        vec![Series {
            name: "mu*".into(),
            points: sw
                .mean_pressure
                .iter()
                .zip(&sw.mu_star)
                .filter_map(|(p, m)| Some((*p, (*m)?)))
                .collect(),
        }],
    );
    plot.markers = st.contact.complete.then(|| Series {
        name: "now".into(),
        points: vec![(st.solution.inputs.mean_pressure, st.solution.mu_star)],
    });
    plot.against_mu(preset.friction.coefficient);
    plot.shaded = super::gaps::gaps(&sw.mean_pressure, &sw.mu_star, "no complete contact");
    Ok(Figure::Plots(vec![plot]))
}

/// Where a sampled curve peaks, between its grid points: the vertex of the parabola through the
/// highest point and its neighbours (exact to O(h^2) for a smooth crest), so that a phase lead
/// smaller than the grid spacing can be read. None at the ends of the samples or for a flat
/// curve.
fn crest(points: &[(f64, f64)]) -> Option<f64> {
    let i =
        (1..points.len().saturating_sub(1)).max_by(|&a, &b| points[a].1.total_cmp(&points[b].1))?;
    let (a, b, c) = (points[i - 1], points[i], points[i + 1]);
    let curvature = a.1 - 2.0 * b.1 + c.1;
    (curvature < 0.0 && b.1 >= a.1 && b.1 >= c.1)
        .then(|| b.0 + 0.5 * (c.0 - b.0) * (a.1 - c.1) / curvature)
}

pub(super) fn dispersion(_: &Preset, out: &SpatialOutput) -> Result<Figure, NoFigure> {
    let d = &out.dispersion;
    let s = &out.state.solution;
    let unit = if d.scaled_by_thickness {
        s.inputs.material.thickness
    } else {
        1.0
    };
    let x = || {
        if d.scaled_by_thickness {
            axis("kh", "", Scale::Log)
        } else {
            axis("k", "rad/m", Scale::Log)
        }
    };
    let all = || d.drift_velocity.iter().flatten().copied();
    let both_signs = all().any(|c| c > 0.0) && all().any(|c| c < 0.0);
    let scale = if both_signs {
        Scale::symlog_for(all())
    } else {
        Scale::Linear
    };
    let (lo, hi) = all().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| {
        (a.min(c), b.max(c))
    });
    let first = &d.drift_velocity[0];
    let apart = |c: &Vec<f64>| {
        c.iter()
            .zip(first)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
    };
    // against the range drawn, which holds the line c = 0
    let drawn = hi.max(0.0) - lo.min(0.0);
    let coincide = d.drift_velocity[1..]
        .iter()
        .all(|c| apart(c) < COINCIDE * drawn.max(f64::MIN_POSITIVE));
    let degrees: Vec<String> = d
        .angles
        .iter()
        .map(|a| format!("{:.0}", a.to_degrees()))
        .collect();
    let series = if coincide {
        vec![Series {
            name: format!("c at {} deg, one line (see below)", degrees.join("/")),
            points: zip(&d.k, first),
        }]
    } else {
        degrees
            .iter()
            .zip(&d.drift_velocity)
            .map(|(a, c)| Series {
                name: format!("c at {a} deg"),
                points: zip(&d.k, c),
            })
            .collect()
    };
    let mut plot = Plot::new(x(), axis("c", "m/s", scale), series);
    plot.markers = Some(Series {
        name: "harmonics".into(),
        points: s
            .harmonics
            .iter()
            .map(|h| (h.initial.wavenumber() * unit, h.evolution.drift_velocity))
            .collect(),
    });
    plot.y_marks = vec![Mark {
        at: 0.0,
        label: "c = 0".into(),
    }];
    plot.x_marks = sign_changes(&d.k, first)
        .map(|at| Mark {
            at,
            label: "X*".into(),
        })
        .collect();
    if !coincide {
        return Ok(Figure::Plots(vec![plot]));
    }
    // the direction dependence, less than a line width above, as differences from the 0 deg
    // line
    let diff = Plot::new(
        x(),
        axis(&format!("c - c({} deg)", degrees[0]), "m/s", Scale::Linear),
        degrees[1..]
            .iter()
            .zip(&d.drift_velocity[1..])
            .map(|(a, c)| Series {
                name: format!("{a} deg"),
                points: d
                    .k
                    .iter()
                    .zip(c.iter().zip(first))
                    .map(|(k, (c, c0))| (*k, c - c0))
                    .collect(),
            })
            .collect(),
    );
    Ok(Figure::Plots(vec![plot, diff]))
}

/// Where a curve crosses zero, by linear interpolation between its points.
fn sign_changes<'a>(x: &'a [f64], y: &'a [f64]) -> impl Iterator<Item = f64> + 'a {
    x.windows(2)
        .zip(y.windows(2))
        .filter(|(_, y)| y[0] * y[1] < 0.0)
        .map(|(x, y)| x[0] + (x[1] - x[0]) * y[0] / (y[0] - y[1]))
}

/// A punch of harmonics has a line spectrum: each harmonic's amplitude against its wavenumber
/// |k|, as given and at t (a height map's chart draws its PSD instead).
pub(super) fn spectrum(_: &Preset, out: &SpatialOutput) -> Result<Figure, NoFigure> {
    let s = &out.state.solution;
    let mut given: Vec<(f64, f64)> = (s.harmonics.iter())
        .map(|h| (h.initial.wavenumber(), h.initial.amplitude.abs()))
        .filter(|(k, a)| *k > 0.0 && *a > 0.0)
        .collect();
    let mut at: Vec<(f64, f64)> = (s.harmonics.iter())
        .map(|h| (h.initial.wavenumber(), h.state.amplitude.abs()))
        .filter(|(k, a)| *k > 0.0 && *a > 0.0)
        .collect();
    given.sort_by(|a, b| a.0.total_cmp(&b.0));
    at.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut plot = Plot::new(
        // a few harmonics span less than a decade or two: a linear |k| labels both ends
        axis("|k|", "rad/m", Scale::Linear),
        axis("A [m]", "", Scale::Log),
        vec![Series {
            name: "harmonics as given (t = 0)".into(),
            points: given,
        }],
    );
    plot.markers = Some(Series {
        name: format!("t = {}", format_si(s.time, "s")),
        points: at,
    });
    Ok(Figure::Plots(vec![plot]))
}
