//! The status panel: the operating point of the shown result, read from that result and its
//! inputs (never from the form). Values are packed into lines whole, never broken across lines;
//! harmonics that do not fit are counted with the key that shows them ("+N more: i") and scroll with the selected row.

use crate::engine::{Answer, Output, SpatialOutput};
use crate::phrase::Phrase;
use crate::physics::plane::energy::RESIDUAL_ROUND_OFF;
use crate::physics::plane::{OperatingPoint, Shape};
use crate::units::format_si;
use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Paragraph, Wrap};

use crate::tui::app::App;
use crate::tui::charts::contact;
use crate::tui::charts::range::frames;
use crate::tui::charts::readout::readout;
use crate::tui::charts::{Figure, Plot, overlay};
use crate::tui::on_screen::OnScreen;
use crate::tui::view::status_values::{Checks, mu_star, number, per_output, table_within};
use crate::tui::view::theme::RenderOptions;
use crate::tui::view::validity_status::{self, with_validity};
use crate::tui::view::wrapping::{pack, pack_within};
use crate::tui::view::{contact_status, groups_status, harmonic_table, surface_status};
use crate::tui::view::{note, wrap};

/// Draws the status of the shown result into `area`.
pub fn draw(app: &App, shown: &OnScreen, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let mut block = Block::default().borders(Borders::ALL).title(format!(
        " {}{} ",
        groups_status::title(app),
        note(shown, style)
    ));
    let inner = block.inner(area);
    let Some((answer, dim)) = shown.answer() else {
        frame.render_widget(block, area);
        return;
    };
    let width = inner.width as usize;
    let rows = inner.height as usize;
    let selected = app.row().harmonic_index();
    let main = |height: usize| {
        if app.explore.dimensionless {
            groups_status::lines(&answer.output, selected, style, width, height)
        } else {
            per_output(
                &answer.output,
                style,
                |p, checks| plane(p, checks, style, width, height),
                |out| spatial(out, selected, style, width, height),
                |out| surface_status::lines(out, style, width),
            )
        }
    };
    // the cursor readout first, each value whole; beside a chart of the operating point, the
    // point (a, b, theta, mu*) and its verdict are always shown and the readout takes the rows
    // left, before the point's residual, psi and Q2 (its hidden values counted); under a sweep
    // or a map, whose chart marks the point, the readout of the sweep comes first and the point
    // gives up rows before the verdict does
    let kept = kept_rows(app, answer, width);
    let readout = status_readout(app, answer);
    let room = match app.explore.view {
        Some(_) => rows.saturating_sub(kept.map_or(0, |(_, verdict)| verdict)),
        None => rows.saturating_sub(kept.map_or(main(0).len() + 1, |(all, _)| all)),
    };
    let mut lines: Vec<Line> = readout
        .map(|items| pack_within(&items, width, "  ", room))
        .unwrap_or_default()
        .into_iter()
        .map(|l| Line::styled(l, style.cursor()))
        .collect();
    lines.extend(main(rows.saturating_sub(lines.len())));
    // the count of what the validity lines leave out comes after the rows: in the border
    if lines.len() > rows
        && lines.last().is_some_and(validity_status::is_count)
        && let Some(count) = lines.pop()
    {
        let look = count.style;
        block = block.title_bottom(Line::styled(format!(" {count} "), look).right_aligned());
    }
    frame.render_widget(block, area);
    frame.render_widget(Paragraph::new(lines).wrap(Wrap { trim: false }), inner);
    if dim {
        frame.buffer_mut().set_style(inner, style.stale());
    }
}

/// The readout the status starts with: of the sweep or map view's cursor, else of the chart's
/// cursor or the pressure map's cell cursor; None while no cursor is on.
fn status_readout(app: &App, answer: &Answer) -> Option<Vec<Phrase>> {
    match app.explore.view {
        Some(_) => crate::tui::view::sweep::readout(app),
        None => cursor_readout(app, answer).or_else(|| {
            crate::tui::view::map_readout::status(app)
                .map(|items| items.into_iter().map(Phrase::from).collect())
        }),
    }
}

/// What the status shows of the shown result before a crowded status counts some of it ("+2
/// more: i"), for the `i` window: the cursor's readout, then a plane point's values (as the
/// status writes them, in groups in the dimensionless view, after "operating point:"), then each
/// of its validity phrases, each part on lines of its own; empty where there is neither.
pub fn in_full(app: &App) -> Vec<Vec<Phrase>> {
    let Some((answer, _)) = crate::tui::on_screen::on_screen(app).answer() else {
        return Vec::new();
    };
    let mut parts: Vec<Vec<Phrase>> = status_readout(app, answer).into_iter().collect();
    if let Output::Plane(out) = &answer.output
        && let Ok(p) = &out.point
    {
        let mut point: Vec<Phrase> = vec![Phrase::words("operating point:")];
        point.extend(if app.explore.dimensionless {
            groups_status::plane_items(p)
                .into_iter()
                .map(Into::into)
                .collect()
        } else {
            plane_items(p)
        });
        parts.push(point);
        let checks = (out.strip_check.as_ref(), out.yield_check.as_ref());
        parts.extend(
            validity_status::in_full(p, checks)
                .into_iter()
                .map(|v| vec![v]),
        );
    }
    parts
}

/// The rows of a plane point's status that a readout never takes: (its values but those that
/// give way in a crowded status, and its verdict; the verdict alone); None for other outputs.
fn kept_rows(app: &App, answer: &Answer, width: usize) -> Option<(usize, usize)> {
    let Output::Plane(out) = &answer.output else {
        return None;
    };
    let p = out.point.as_ref().ok()?;
    let all = if app.explore.dimensionless {
        let items = groups_status::plane_items(p);
        validity_status::kept_rows((&items, &groups_status::GIVE_UP), p, width)
    } else {
        let items = plane_items(p);
        validity_status::kept_rows((&items, &give_up(items.len())), p, width)
    };
    Some((all, validity_status::verdict_rows(p, width)))
}

/// The cursor readout of the visible chart, when the cursor is on and the chart has curves.
fn cursor_readout(app: &App, answer: &Answer) -> Option<Vec<Phrase>> {
    let cursor = app.ui.cursor?;
    let chart = app.ui.chart;
    let Ok(Figure::Plots(plots)) = overlay::figure(chart, answer, app.ui.data.as_ref()) else {
        return None;
    };
    let pins = app.ui.pins_of(chart);
    let pinned: Vec<&[Plot]> = pins.iter().map(|p| p.plots.as_slice()).collect();
    let frames = frames(&plots, &pinned, app.ui.log_y.contains(&chart));
    let mut items = readout(&frames, cursor);
    items[0] = format!("cursor {}:", items[0]);
    Some(items.into_iter().map(Phrase::from).collect())
}

fn plane(
    p: &OperatingPoint,
    checks: Checks,
    style: RenderOptions,
    width: usize,
    height: usize,
) -> Vec<Line<'static>> {
    let items = plane_items(p);
    let give_up = give_up(items.len());
    with_validity((&items, &give_up), p, checks, style, width, height)
}

/// In a crowded status, the residual, psi and Q2 (the indices among `n` items of
/// `plane_items`) give way before mu*, a, b and theta.
fn give_up(n: usize) -> [usize; 3] {
    [n - 1, n - 3, n - 4]
}

/// The values of a plane operating point, in the order the status shows them.
fn plane_items(p: &OperatingPoint) -> Vec<Phrase> {
    let s = &p.solution;
    let mut items: Vec<Phrase> = vec![
        format!("a = {}", format_si(s.a, "m")).into(),
        format!("b = {}", format_si(s.b, "m")).into(),
    ];
    // a punch other than the parabola is named first (the parabola's R is in the form)
    if let Some(shape) = shape_name(&s.inputs.shape) {
        items.insert(0, shape);
    }
    // theta exists only for the models that have it: never a placeholder under another's label
    items.extend(
        s.theta
            .map(|t| format!("theta = {}", number("theta", t)).into()),
    );
    items.extend(
        [
            format!("Q2 = {}", format_si(s.normal_force, "N/m")),
            format!("psi = {}", format_si(s.psi, "N/m")),
            mu_star(s.mu_star, s.inputs.friction.coefficient),
            residual(p.energy.as_ref().ok().map(|e| e.residual)),
        ]
        .map(Phrase::from),
    );
    items
}

/// The punch's shape in a few words, each value with its name and unit a piece that a line
/// break never splits ("flat punch", "c = 1 mm,", "edges r = 0.2 mm"); None for the parabola.
fn shape_name(shape: &Shape) -> Option<Phrase> {
    let punch = Phrase::whole;
    match shape {
        Shape::Parabola { .. } => None,
        Shape::Power { radius, exponent } => Some(
            punch("power punch")
                .then(format!("n = {exponent},"))
                .then(format!("R = {}", format_si(*radius, "m"))),
        ),
        Shape::Flat {
            half_width,
            edge_radius,
        } => {
            let face = punch("flat punch").then(format!("c = {},", format_si(*half_width, "m")));
            Some(if *edge_radius == 0.0 {
                face.then("sharp corners")
            } else {
                face.then(format!("edges r = {}", format_si(*edge_radius, "m")))
            })
        }
        Shape::Table(t) => Some(punch("profile").then(t.file.clone())),
    }
}

/// The energy identity's residual, or "< 1e-14" at round-off (whose digits mean nothing), or
/// that I and J have no number (sharp corners).
fn residual(r: Option<f64>) -> String {
    let Some(r) = r else {
        return "I, J undefined at sharp corners".to_string();
    };
    if r < RESIDUAL_ROUND_OFF {
        format!("I-J residual < {RESIDUAL_ROUND_OFF:.0e}")
    } else {
        format!("I-J residual {r:.1e}")
    }
}

fn spatial(
    out: &SpatialOutput,
    selected: Option<usize>,
    style: RenderOptions,
    width: usize,
    height: usize,
) -> Vec<Line<'static>> {
    let st = &out.state;
    let s = &st.solution;
    // while partial, the closed-form rates are what each harmonic does once contact is complete
    // (under a nonlinear wear law, what it would do under the linear one):
    // said by the line of the time of complete contact (", then:"), else on a line of its own
    // above the header (never after the header, where it read as phi's)
    let after = if s.inputs.linear_wear() {
        "after complete contact:"
    } else {
        "closed form (n = 1 only):"
    };
    // the state on the period cell, unless the closed form holds from t = 0
    let head = |then| match contact::stepped(out) {
        Some(c) => {
            let mu = s.inputs.friction.coefficient;
            contact_status::head(c, mu, s.inputs.wear_rate(), style, width, then)
        }
        None => (closed(out, style, width), false, false),
    };
    let (mut lines, partial, mut said) = head(true);
    if said && lines.len() + 1 >= height {
        // no row fits under ", then:": the time is said without it
        (lines, _, said) = head(false);
    }
    let own_line = partial && !said;
    let (header, blocks) = harmonic_table::dimensional(out);
    // the header says how many rows do not fit
    let room = height.saturating_sub(lines.len() + 1 + usize::from(own_line));
    if room == 0 {
        // no row fits: a header over nothing (with "+N more") is left out, as in the groups
        return lines;
    }
    if own_line {
        lines.push(Line::styled(after, style.heading()));
    }
    lines.extend(table_within(&header, &blocks, selected, room, width, style));
    lines
}

/// The head of the status from the closed form of the harmonics: t, mu*, psi and the
/// complete-contact check (with, when it fails, why partial contact is not solved).
fn closed(out: &SpatialOutput, style: RenderOptions, width: usize) -> Vec<Line<'static>> {
    let st = &out.state;
    let s = &st.solution;
    let items = [
        format!("t = {}", format_si(s.time, "s")),
        mu_star(s.mu_star, s.inputs.friction.coefficient),
        format!("psi = {}", format_si(s.psi, "Pa")),
    ];
    let mut lines: Vec<Line> = pack(&items, width, "")
        .into_iter()
        .map(Line::from)
        .collect();
    let c = &st.contact;
    let kind = if c.exact { "certified" } else { "bound" };
    let p_min = format!("p_min = {} ({kind})", format_si(c.min_pressure, "Pa"));
    // beside a certified minimum, the bound where it differs, so that the gap can be read; not
    // a bound below 0 under a complete contact (it proves nothing there)
    let bound = format_si(c.lower_bound, "Pa");
    let bound = (c.exact
        && bound != format_si(c.min_pressure, "Pa")
        && !(c.complete && c.lower_bound <= 0.0))
        .then(|| format!("lower bound {bound}"));
    let (items, verdict) = if c.complete && out.closed_form_holds() {
        let mut items = vec![format!("complete contact, {p_min}")];
        items.extend(bound);
        (items, style.ok())
    } else if let Some(note) = s.inputs.simulated() {
        // a nonlinear wear law: the closed form does not hold, the cell below says why not solved
        (vec![note], style.error())
    } else if c.complete {
        // complete at t by the closed form, but not at t = 0: not what the wear made of it
        let lost = "contact lost at t = 0: the closed form at t does not hold";
        (vec![lost.to_string()], style.error())
    } else {
        let mut items = vec![format!("contact lost: {p_min}")];
        items.extend(bound);
        // the closed-form bound, not the running-in (docs/physics/spatial-partial.md sec. 4)
        items.extend(
            c.complete_after
                .map(|t| format!("complete after t = {} (formal bound)", format_si(t, "s"))),
        );
        (items, style.error())
    };
    lines.extend(
        pack(&items, width, "")
            .into_iter()
            .map(|l| Line::styled(l, verdict)),
    );
    if let (Err(why), false) = (&out.cell, out.closed_form_holds()) {
        let why = if s.inputs.linear_wear() {
            format!("partial contact is not solved: {why}")
        } else {
            format!("the running-in is not simulated: {why}")
        };
        lines.extend(
            wrap(&why, width)
                .into_iter()
                .map(|l| Line::styled(l, style.error())),
        );
    }
    lines
}
