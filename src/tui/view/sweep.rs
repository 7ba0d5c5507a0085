//! The chart area while the sweep chart or the regime map is shown: the title says what is
//! against what and whether it is still being computed, the figure (the sweep through the chart
//! widget, the map through `regime`), and under it, when the view is the one the preset's
//! `[explore]` section opens on, the preset's "Look at:" paragraph, so that the lesson's words
//! sit next to what they describe. The status's readout of the sweep's or the map's cursor is
//! here too.

use crate::engine::sweep_worker::SweepResult;
use crate::phrase::Phrase;
use crate::sweeps::{Opening, opening};
use crate::tui::text_field::TextField;
use crate::units::format_si;
use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Clear, Paragraph};

use crate::tui::app::App;
use crate::tui::charts::range::{self, frames};
use crate::tui::charts::readout::{at, readout as read};
use crate::tui::charts::{Figure, Plot, sweep};
use crate::tui::sweep_shown::{shown, title, wanted};
use crate::tui::sweep_state::View;
use crate::tui::sweep_state::{Field, SweepForm};
use crate::tui::view::chart::{self, Extras};
use crate::tui::view::layout::centered;
use crate::tui::view::theme::RenderOptions;
use crate::tui::view::{regime, wrap};

/// The plots of the sweep on screen (None while there is none).
pub fn sweep_plots(app: &App) -> Option<Vec<Plot>> {
    let (answer, _) = shown(app)?;
    let (Opening::Curve(spec), SweepResult::Curve(curve)) = (&answer.request.job, &answer.explored)
    else {
        return None;
    };
    let preset = &answer.request.preset;
    let dimensionless = app.explore.dimensionless;
    let mut figure = sweep::figure(
        preset.problem,
        preset.friction.coefficient,
        spec,
        curve,
        dimensionless,
    );
    if let Some(o) = &app.ui.data {
        o.add(&mut figure);
    }
    match figure {
        Figure::Plots(p) => Some(p),
        Figure::Map(_) => None,
    }
}

/// What the sweep's curve has drawn beside it: the cursor (no pins).
pub fn extras(app: &App) -> Extras {
    Extras {
        cursor: app.ui.cursor,
        pins: Vec::new(),
    }
}

/// The lines of the preset's lesson under the figure in the chart's `inner` area, and the area
/// left to the figure: a quarter of a tall chart's height; where the paragraph needs more, one
/// line saying where it is whole (never a sentence cut in the middle).
pub fn lesson_lines(app: &App, inner: Rect) -> (Vec<String>, Rect) {
    let Some(text) = lesson(app) else {
        return (Vec::new(), inner);
    };
    let whole = wrap(&text, inner.width as usize);
    let most = (inner.height / 4).max(1) as usize;
    let mut lines = if whole.len() <= most {
        whole
    } else {
        wrap(LESSON_ELSEWHERE, inner.width as usize)
    };
    lines.truncate(most);
    let rest = Rect {
        height: inner.height - lines.len() as u16,
        ..inner
    };
    (lines, rest)
}

/// The help's text on the sweep chart (`?` while it is shown).
pub const SWEEP_HELP: &str = "A quantity against one input over the range chosen with v (the form \
    says what each field allows): the preset's model first, the other plane models overlaid (the \
    first curve sets the y range; a curve outside it is named with its range). Where a model's own \
    validity check fails its curve is drawn dim (spatial: where the contact is partial), without \
    colour in a mark of its own that the legend names; where the verdict changes the x axis is \
    marked ('wide ok>', 'narrow fails>', 'complete>'), and the input's current value 'now'. x \
    shows a cursor (at now), [ ] { } move it, and the status reads every curve there. D puts the \
    input's dimensionless group on the x axis where it has one. E writes the figure as SVG, e says \
    the wearlab sweep command of the same numbers; Tab goes back to the charts.";

/// The help's text on the regime map (`?` while it is shown).
pub const MAP_HELP: &str = "A quantity over two inputs chosen with M, in colours (viridis, or \
    shades without colour) read on the bar at the right; coarse first, then refined pass by pass. \
    Letters draw the library's lines: 0 where theta = 0, where friction and wear shift the \
    pressure's edge exponents equally (pi mu chi = k m) and on a half-plane mu* - mu = 0; = where \
    the preset's model's mu* - mu changes sign (on a strip of finite thickness that sign, not \
    theta's, says which dominates: wear where mu* > mu), W and N where the wide and the narrow \
    model's validity checks change, C where \
    complete contact is lost; + is the preset's own point. x shows a \
    cursor, X (at the grid point nearest the preset's), [ ] move it along x, { } along y, and the status reads both \
    inputs, the quantity, theta and the verdicts there. E writes the map as SVG; Tab goes back to the \
    charts.";

/// What the chart says instead of the preset's "Look at:" paragraph where the paragraph does not
/// fit whole.
pub const LESSON_ELSEWHERE: &str = "Look at: i shows the preset's notes on this view";

/// The preset's "Look at:" paragraph, when the view shows what its `[explore]` section opens on.
fn lesson(app: &App) -> Option<String> {
    let want = wanted(app)?;
    let own = opening(&app.doc.preset)?.ok()?;
    if !same_axes(&want.job, &own) {
        return None;
    }
    let text = &app.doc.preset.description;
    let start = text.find("Look at")?;
    let end = text[start..]
        .find("Command line")
        .map_or(text.len(), |e| start + e);
    Some(
        text[start..end]
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" "),
    )
}

fn same_axes(a: &Opening, b: &Opening) -> bool {
    match (a, b) {
        (Opening::Curve(a), Opening::Curve(b)) => a.axis == b.axis && a.quantity == b.quantity,
        (Opening::Map(a), Opening::Map(b)) => a == b,
        _ => false,
    }
}

/// Draws the sweep or the map into the chart's area.
pub fn draw(app: &App, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let Some(want) = wanted(app) else {
        return;
    };
    let shown = shown(app);
    let done = shown.is_some_and(|(a, current)| current && a.complete);
    let what = title(&app.doc.preset, &want.job, app.explore.dimensionless);
    let note = match shown {
        _ if done => String::new(),
        Some((a, true)) => match &a.explored {
            SweepResult::Map(m) => format!("  refining (1 point in {})…", m.stride),
            SweepResult::Curve(_) => "  judging the verdicts…".into(),
        },
        Some((_, false)) => "  [previous inputs] computing…".into(),
        None => "  computing…".into(),
    };
    let key = match app.explore.view {
        Some(View::Map) => "M",
        _ => "v",
    };
    let block = Block::default()
        .borders(Borders::ALL)
        .title(style.text(&format!(" {what}{note} ")).into_owned())
        .title_bottom(Line::from(format!(" {key}: change  Tab: charts ")).right_aligned());
    let outer = block.inner(area);
    frame.render_widget(block, area);
    let (lines, inner) = lesson_lines(app, outer);
    for (i, l) in lines.iter().enumerate() {
        frame.buffer_mut().set_stringn(
            inner.x,
            inner.y + inner.height + i as u16,
            l,
            inner.width as usize,
            style.heading(),
        );
    }
    let Some((answer, current)) = shown else {
        return;
    };
    match &answer.explored {
        SweepResult::Curve(_) => {
            let plots = sweep_plots(app).unwrap_or_default();
            let frames = frames(&plots, &[], false);
            chart::draw(&frames, style, &extras(app), frame.buffer_mut(), inner);
        }
        SweepResult::Map(map) => {
            if let Opening::Map(spec) = &answer.request.job {
                regime::draw(
                    spec,
                    map,
                    app.explore.cell,
                    style,
                    frame.buffer_mut(),
                    inner,
                );
            }
        }
    }
    if !current {
        frame.buffer_mut().set_style(inner, style.stale());
    }
}

/// The status's first lines in the sweep or map view: the cursor's readout.
pub fn readout(app: &App) -> Option<Vec<Phrase>> {
    match app.explore.view? {
        View::Sweep => {
            let cursor = app.ui.cursor?;
            let plots = sweep_plots(app)?;
            let frames = frames(&plots, &[], false);
            let mut items = read(&frames, cursor).into_iter();
            // the swept input beside the group, on the first line: the status folds to four
            // lines below 32 rows, and at 80 columns each curve takes a line of its own
            let input = app
                .explore
                .dimensionless
                .then(|| input_at(app, &frames, cursor))
                .flatten();
            let first = Phrase::whole(format!("cursor {}", items.next()?));
            let first = input.map_or(first.clone(), |v| first.then(v)).ending(":");
            Some(
                std::iter::once(first)
                    .chain(items.map(Phrase::from))
                    .collect(),
            )
        }
        View::Map => {
            let (answer, _) = shown(app)?;
            let (Opening::Map(spec), SweepResult::Map(map)) =
                (&answer.request.job, &answer.explored)
            else {
                return None;
            };
            regime::readout(spec, map, app.explore.cell?)
                .map(|items| items.into_iter().map(Phrase::from).collect())
        }
    }
}

/// In the dimensionless view, the swept input's value with its unit at the cursor's group, read
/// along the preset's curve (the first point of the sweep there, where the group is not
/// monotone): "(strip: h = 85.8 um)".
fn input_at(app: &App, frames: &[range::Frame], cursor: f64) -> Option<String> {
    let (answer, _) = shown(app)?;
    let (Opening::Curve(spec), SweepResult::Curve(curve)) = (&answer.request.job, &answer.explored)
    else {
        return None;
    };
    let along = sweep::input_along_group(curve)?;
    let f = frames.first()?;
    let xp = f.x[0] + cursor.clamp(0.0, 1.0) * (f.x[1] - f.x[0]);
    let input = sweep::x_axis(spec.axis.key, spec.axis.range.spacing);
    let v = at(&along, xp, f.plot.x.scale, input.scale)?;
    let model = curve
        .series
        .first()?
        .model
        .map(|m| format!("{}: ", m.name()));
    Some(format!(
        "({}{} = {})",
        model.unwrap_or_default(),
        input.label,
        format_si(v, input.unit)
    ))
}

/// The form of `v` and `M`, over the chart.
pub fn form(form: &SweepForm, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let rows = form.fields();
    let rect = centered(area, 64, rows.len() as u16 + 5);
    frame.render_widget(Clear, rect);
    let title = match form.view {
        View::Sweep => " sweep: one parameter along x ",
        View::Map => " regime map: two parameters ",
    };
    let block = Block::default().borders(Borders::ALL).title(title);
    let inner = block.inner(rect);
    frame.render_widget(block, rect);
    let axis_name = |n: usize| match (form.view, n) {
        (View::Sweep, _) => "x",
        (View::Map, 0) => "x",
        _ => "y",
    };
    let mut lines: Vec<Line> = rows
        .iter()
        .enumerate()
        .map(|(i, f)| {
            let (label, value) = match *f {
                Field::Param(n) => {
                    let k = form.axes[n].key;
                    let p = k.param();
                    let unit = if p.unit.is_empty() { "-" } else { p.unit };
                    (
                        format!("{} parameter", axis_name(n)),
                        format!("◀ {}: {} [{unit}] ▶", k.symbol(), p.label),
                    )
                }
                Field::From(n) => ("  from".into(), typed(&form.axes[n].from, i == form.row)),
                Field::To(n) => ("  to".into(), typed(&form.axes[n].to, i == form.row)),
                Field::Points(n) => (
                    "  points".into(),
                    typed(&form.axes[n].points, i == form.row),
                ),
                Field::Scale(n) => (
                    "  scale".into(),
                    if form.axes[n].log {
                        "◀ log ▶"
                    } else {
                        "◀ linear ▶"
                    }
                    .into(),
                ),
                Field::Quantity => {
                    let q = form.quantity;
                    let unit = q.quantity().unit;
                    let unit = if unit.is_empty() { "-" } else { unit };
                    ("quantity".into(), format!("◀ {} [{unit}] ▶", q.symbol()))
                }
            };
            let text = format!("{label:<12} {value}");
            if i == form.row {
                Line::styled(text, style.selected())
            } else {
                Line::from(text)
            }
        })
        .collect();
    let hint = match form.field() {
        Field::Param(n) | Field::From(n) | Field::To(n) | Field::Scale(n) => {
            let k = form.axes[n].key;
            let allowed = k.param().limit().map_or("", |l| l.allowed);
            format!("{}: allowed {allowed}", k.symbol())
        }
        Field::Points(_) => format!(
            "points: allowed {}",
            crate::physics::limits::SWEEP_POINTS.allowed
        ),
        Field::Quantity => {
            let q = form.quantity.quantity();
            format!("{}: {}", form.quantity.symbol(), q.description)
        }
    };
    lines.push(Line::from(""));
    lines.extend(
        wrap(&hint, inner.width as usize)
            .into_iter()
            .take(3)
            .map(|l| Line::styled(l, Style::default())),
    );
    frame.render_widget(Paragraph::new(lines), inner);
}

/// A typed field of the form: on the selected row with its cursor (`TextField::shown`), else its
/// text.
fn typed(field: &TextField, selected: bool) -> String {
    if selected {
        field.shown()
    } else {
        field.text().to_string()
    }
}
