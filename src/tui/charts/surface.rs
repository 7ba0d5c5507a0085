//! The spatial charts of a height-map punch (`engine::SurfaceOutput`): every one drawn from the
//! nodes of the map's own grid (there is no closed form of a few harmonics), and the surface's
//! power spectrum as given and at the state shown.

use crate::engine::SurfaceOutput;
use crate::physics::spatial::result::SurfaceResult;
use crate::physics::{SolveError, Spacing};
use crate::preset::Preset;
use crate::units::format_si;

use crate::tui::charts::contact;
use crate::tui::charts::spatial::line_plots;
use crate::tui::charts::{Figure, NoFigure, Plot, Scale, Series, SpatialChart, axis};

/// The figure of `chart` for a height map.
pub(super) fn build(
    chart: SpatialChart,
    preset: &Preset,
    out: &SurfaceOutput,
) -> Result<Figure, NoFigure> {
    let error = |e: &SolveError| NoFigure::Error(e.to_string());
    let cell = || out.cell.as_ref().map_err(error);
    let state = || cell().and_then(|c| c.state.as_deref().map_err(error));
    match chart {
        SpatialChart::PressureMap => {
            let state = state()?;
            let g = state.grid;
            let ly = if g.ny == 1 {
                format!("{} (y, a profile drawn as ridges)", format_si(g.ly, "m"))
            } else {
                format!("{} (y)", format_si(g.ly, "m"))
            };
            let caption = format!(
                "The height map's cell, {} nodes over {} (x, to the right) by {ly}; the layer \
                 slides to -x.",
                if g.ny == 1 {
                    format!("{}", g.nx)
                } else {
                    format!("{} x {}", g.nx, g.ny)
                },
                format_si(g.lx, "m"),
            );
            Ok(Figure::Map(contact::map(out.time, g.ly, state, caption)))
        }
        SpatialChart::Line => {
            let (x, p, u, y) = contact::row(state()?);
            Ok(line_plots(&x, &p, &u, y))
        }
        SpatialChart::History => contact::running_in(preset, cell()?),
        SpatialChart::MuStar => match &cell()?.load_curve {
            Some(Ok(curve)) => {
                let scale = if preset.spatial.sweep.spacing == Spacing::Log {
                    Scale::Log
                } else {
                    Scale::Linear
                };
                contact::load_curve(preset, cell()?, curve, axis("pbar", "Pa", scale))
            }
            Some(Err(why)) => Err(NoFigure::Error(why.to_string())),
            None => Err(NoFigure::Solving),
        },
        SpatialChart::Dispersion => Err(NoFigure::Error(
            "A height map has a wave vector at every node of its grid, not a few harmonics to \
             mark on the drift velocity: each mode decays and drifts by the closed form once \
             the contact is complete (docs/physics/spatial-surface.md). Tab: the surface \
             spectrum shows which waves the running-in wears first."
                .into(),
        )),
        SpatialChart::Spectrum => Ok(spectrum(out)),
    }
}

/// The radially averaged PSD on log-log axes, as given and at the state shown.
fn spectrum(out: &SurfaceOutput) -> Figure {
    let given = &out.initial;
    // C(q) of a map is in m^4, of a profile in m^3; a prefix on m^4 would misread
    let label = if given.cell[1] == 0.0 {
        "C [m^3]"
    } else {
        "C [m^4]"
    };
    let positive = |r: &SurfaceResult| -> Vec<(f64, f64)> {
        (r.psd.wavenumber.iter().zip(&r.psd.psd))
            .filter(|(_, c)| **c > 0.0)
            .map(|(q, c)| (*q, *c))
            .collect()
    };
    let mut series = vec![Series {
        name: "as given (t = 0)".into(),
        points: positive(given),
    }];
    let at = out
        .running_in()
        .and_then(|c| c.state.as_deref().ok())
        .map(|s| s.time);
    if let (Some(shown), Some(t)) = (&out.shown, at.filter(|t| *t > 0.0)) {
        series.push(Series {
            name: format!("t = {}", format_si(t, "s")),
            points: positive(shown),
        });
    }
    Figure::Plots(vec![Plot::new(
        axis("q", "rad/m", Scale::Log),
        axis(label, "", Scale::Log),
        series,
    )])
}
