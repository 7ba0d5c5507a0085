//! The spatial charts drawn from the contact solved on the period cell: the nodal
//! pressure with the zones out of contact, the running-in in time, mu* against the mean pressure
//! over the whole range. `fields` says, for every chart, whether the closed form of the
//! harmonics holds at t (`SpatialOutput::closed_form_holds`) or the nodes of the cell are drawn.

use crate::engine::{CellOutput, SpatialOutput};
use crate::physics::SolveError;
use crate::physics::spatial::partial::state::State;
use crate::physics::spatial::partial::sweep::LoadCurve;
use crate::preset::Preset;
use crate::units::format_si;

use crate::tui::charts::{Axis, Figure, Map, Mark, NoFigure, Plot, Scale, Series, axis};

/// What the map and the line draw at t.
pub enum Fields<'a> {
    /// The closed form of the harmonics (`SpatialState::field`): the contact is complete at t and
    /// has been since t = 0, so the closed form holds exactly.
    Closed,
    /// The contact state on the nodes of the period cell.
    Nodes(&'a State),
}

/// Where the fields at t come from, or why there are none.
pub fn fields(out: &SpatialOutput) -> Result<Fields<'_>, NoFigure> {
    if out.closed_form_holds() {
        return Ok(Fields::Closed);
    }
    let simulated = out.state.solution.inputs.simulated();
    match &out.cell {
        Ok(c) => c.state.as_deref().map(Fields::Nodes).map_err(error),
        Err(why) if simulated.is_some() => Err(NoFigure::Error(format!(
            "{}; the simulation needs a period cell: {why}",
            simulated.unwrap_or_default()
        ))),
        // complete at t but not at t = 0: the closed form at t is not what the wear made of a
        // partial contact
        Err(why) if out.state.contact.complete => Err(NoFigure::Error(format!(
            "Complete contact is lost at t = 0: the harmonics as given would need a negative \
             pressure, so the closed form at t = {} does not hold, and partial contact is solved \
             only on a period cell: {why}",
            format_si(out.state.solution.time, "s"),
        ))),
        Err(why) => Err(NoFigure::Error(format!(
            "Complete contact is lost at t = {}: the complete-contact solution would need a \
             negative pressure (p_min = {}), and partial contact is solved only on a period cell: \
             {why}",
            format_si(out.state.solution.time, "s"),
            format_si(out.state.contact.min_pressure, "Pa"),
        ))),
    }
}

fn error(why: &SolveError) -> NoFigure {
    NoFigure::Error(why.to_string())
}

/// The nodal cell output whenever the closed form does not hold from t = 0.
pub fn stepped(out: &SpatialOutput) -> Option<&CellOutput> {
    out.cell.as_ref().ok().filter(|c| !c.complete_from_start)
}

/// Rows a map of a shape constant along y is drawn with: its one row repeated over the cell's
/// extent in y. The map's aspect is the spans of its cell-centred points, lx (1 - 1/nx) by
/// ly (1 - 1/rows): rows = nx up to 64 keeps it within 1.6 % of lx/ly for any grid, while a
/// 4096-point row stays 2 MB instead of 134 MB drawn as 4096 x 4096.
const STRETCH_ROWS: usize = 64;

/// The y points and values of a map whose `values` hold `rows` rows of `row_len` points: a single
/// row (a shape constant along y) stretched over `ly` [m], else as it is, on `ys`.
pub fn stretched(values: &[f64], row_len: usize, ys: Vec<f64>, ly: f64) -> (Vec<f64>, Vec<f64>) {
    if ys.len() != 1 {
        return (ys, values.to_vec());
    }
    let rows = row_len.clamp(2, STRETCH_ROWS);
    let y = (0..rows)
        .map(|j| (j as f64 + 0.5) * ly / rows as f64)
        .collect();
    (y, values.repeat(rows))
}

/// The pressure on the nodes at the preset's time `t` [s], zero pressure (no contact) drawn
/// apart. A 1-D shape (one node along y) is drawn stretched over `ly` [m], as the closed form is.
pub fn map(t: f64, ly: f64, state: &State, caption: String) -> Map {
    let g = state.grid;
    let (y, values) = stretched(&state.pressure, g.nx, g.ys(), ly);
    let when = if state.time == t {
        String::new()
    } else {
        format!(
            " The state at t = {}: the running-in has not reached t = {} yet.",
            format_si(state.time, "s"),
            format_si(t, "s")
        )
    };
    Map {
        name: "pressure",
        x: g.xs(),
        y,
        values,
        unit: "Pa",
        caption: format!("{caption}{when}"),
        empty: Some("no contact"),
    }
}

/// x, p, U along the middle row of the nodes, and that row's y [m].
pub fn row(state: &State) -> (Vec<f64>, Vec<f64>, Vec<f64>, f64) {
    let g = state.grid;
    let j = g.ny / 2;
    let along = |v: &[f64]| v[j * g.nx..(j + 1) * g.nx].to_vec();
    (g.xs(), along(&state.pressure), along(&state.shape), g.y(j))
}

/// The running-in in time: the contact fraction and mu*, the time of complete contact marked.
pub fn running_in(preset: &Preset, c: &CellOutput) -> Result<Figure, NoFigure> {
    let h = c.history.as_deref().map_err(error)?;
    let t = || axis("t", "s", Scale::Linear);
    // the time of complete contact marked where it is on the chart (a mark stretches the axis)
    let mark: Vec<Mark> = h
        .time_to_complete
        .filter(|tc| *tc <= preset.spatial.duration)
        .map(|at| Mark {
            at,
            label: "complete".into(),
        })
        .into_iter()
        .collect();
    let now = |y: fn(&State) -> f64| {
        c.state.as_deref().ok().map(|s| Series {
            name: "now".into(),
            points: vec![(s.time, y(s))],
        })
    };
    let mut fraction = Plot::new(
        t(),
        axis("contact", "", Scale::Linear),
        vec![Series {
            name: "contact fraction".into(),
            points: super::zip(&h.time, &h.contact_fraction),
        }],
    );
    fraction.markers = now(|s| s.outputs.contact_fraction);
    fraction.fraction = true;
    fraction.x_marks = mark.clone();
    let mut mu = Plot::new(
        t(),
        axis("mu*", "", Scale::Linear),
        vec![Series {
            name: "mu*(t)".into(),
            points: super::zip(&h.time, &h.mu_star),
        }],
    );
    mu.markers = now(|s| s.outputs.mu_star);
    mu.x_marks = mark;
    mu.against_mu(preset.friction.coefficient);
    Ok(Figure::Plots(vec![fraction, mu]))
}

/// mu* against pbar over the whole range, one curve: partial contact below the complete-contact
/// load (marked), complete above.
pub fn load_curve(
    preset: &Preset,
    c: &CellOutput,
    curve: &LoadCurve,
    x: Axis,
) -> Result<Figure, NoFigure> {
    let complete = curve.complete_mean_pressure;
    let p = &curve.mean_pressure;
    let mut plot = Plot::new(
        x,
        axis("mu*", "", Scale::Linear),
        vec![Series {
            name: format!(
                "mu*, contact complete from pbar = {}",
                format_si(complete, "Pa")
            ),
            points: curve
                .mean_pressure
                .iter()
                .zip(&curve.mu_star)
                .filter_map(|(p, m)| Some((*p, (*m)?)))
                .collect(),
        }],
    );
    // marked where it is on the chart (a mark stretches the axis to reach it)
    if p.first()
        .zip(p.last())
        .is_some_and(|(lo, hi)| (*lo..=*hi).contains(&complete))
    {
        plot.x_marks = vec![Mark {
            at: complete,
            label: "complete".into(),
        }];
    }
    plot.markers = c.state.as_deref().ok().map(|s| Series {
        name: "now".into(),
        points: vec![(preset.spatial.mean_pressure, s.outputs.mu_star)],
    });
    plot.against_mu(preset.friction.coefficient);
    plot.shaded = super::gaps::gaps(&curve.mean_pressure, &curve.mu_star, "P <= 0");
    Ok(Figure::Plots(vec![plot]))
}
