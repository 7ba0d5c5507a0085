//! What the chart keys do to the model (part of `update`: pure): the cursor readout, pins, the
//! expanded chart and the log y axis.

use crate::engine::Output;

use crate::tui::app::{App, Command, HeatScale, Mode, Pin};
use crate::tui::charts::contact::Fields;
use crate::tui::charts::range::{Frame, constant, frames, plotted};
use crate::tui::charts::{Figure, Plot, Scale, overlay};
use crate::tui::keys::Action;
use crate::tui::on_screen::on_screen;
use crate::tui::text_field::TextField;
use crate::units::{format_si, parse_si};

/// Pins a chart keeps at most.
pub const MAX_PINS: usize = 3;

/// Carries out a chart key.
pub fn act(app: &mut App, action: Action) -> Vec<Command> {
    match action {
        Action::Cursor => {
            app.ui.cursor = match app.ui.cursor {
                Some(_) => {
                    app.say("cursor off");
                    None
                }
                None => {
                    app.say("cursor: [ ] move it a data point, { } ten; the status reads the curves there");
                    let plots = plots(app);
                    Some(start(&frames(&plots, &pins(app), false)))
                }
            };
        }
        Action::MoveCursor(by) => match app.ui.cursor {
            Some(at) => {
                let plots = plots(app);
                app.ui.cursor = Some(cursor_moved(
                    &frames(&plots, &pins(app), false),
                    at,
                    by.data_points(),
                ));
            }
            None => app.say("x shows the cursor first"),
        },
        Action::GoTo => {
            if plots(app).is_empty() {
                app.complain("g sends the cursor of a chart with curves (Tab to one)");
            } else {
                app.ui.message = None;
                app.ui.mode = Mode::GoTo(TextField::default());
            }
        }
        Action::Pin => pin(app),
        Action::ClearPins => {
            let chart = app.ui.chart;
            let before = app.ui.pins.len();
            app.ui.pins.retain(|p| p.chart != chart);
            match before - app.ui.pins.len() {
                0 => app.say("this chart has no pins"),
                1 => app.say("cleared the pin"),
                n => app.say(format!("cleared {n} pins")),
            }
        }
        Action::Expand => {
            app.ui.expanded = !app.ui.expanded;
            app.say(if app.ui.expanded {
                "chart expanded (f gives the form back)"
            } else {
                "form back"
            });
        }
        Action::LogY => log_y(app),
        _ => {}
    }
    Vec::new()
}

/// The x axis of the visible chart: its label, unit and scale, and the range it spans [plot
/// coordinates]; None without curves.
fn x_axis(app: &App) -> Option<(String, &'static str, Scale, [f64; 2])> {
    let plots = plots(app);
    let pins = pins(app);
    let frames = frames(&plots, &pins, false);
    let f = frames.first()?;
    Some((f.plot.x.label.clone(), f.plot.x.unit, f.plot.x.scale, f.x))
}

/// The prompt of `g`: the x axis and the range it spans, with its unit ("cursor to x (-320 um ..
/// 320 um, in m):").
pub fn go_to_prompt(app: &App) -> String {
    let Some((label, unit, scale, range)) = x_axis(app) else {
        return "cursor to x:".into();
    };
    let [lo, hi] = range.map(|p| format_si(scale.value_at(p), unit));
    let unit = if unit.is_empty() {
        "a number".to_string()
    } else {
        format!("in {unit}")
    };
    format!("cursor to {label} ({lo} .. {hi}, {unit}):")
}

/// Puts the cursor at the x typed (`g`), read in the x axis' unit with an SI prefix as any typed
/// value; refused where it is off the chart (the prompt stays for a correction).
pub fn go_to(app: &mut App, text: String) -> Vec<Command> {
    let Some((label, unit, scale, [lo, hi])) = x_axis(app) else {
        app.ui.mode = Mode::Normal;
        app.complain("the chart has no curves now: the cursor stays");
        return Vec::new();
    };
    let x = match parse_si(&text, unit) {
        Ok(x) => x,
        Err(why) => {
            app.complain(why);
            return Vec::new();
        }
    };
    let at = scale.to_plot(x).map(|p| (p - lo) / (hi - lo));
    match at {
        Some(at) if (0.0..=1.0).contains(&at) && hi > lo => {
            app.ui.cursor = Some(at);
            app.ui.mode = Mode::Normal;
            app.say(format!("cursor at {label} = {}", format_si(x, unit)));
        }
        _ => {
            let [from, to] = [lo, hi].map(|p| format_si(scale.value_at(p), unit));
            // the load charts span the form's sweep range, which a wider one needs
            let wider = match app.doc.preset.problem {
                crate::preset::Problem::Plane if label == "P" && app.explore.view.is_none() => {
                    ", the form's P min and P max"
                }
                _ => "",
            };
            app.complain(format!(
                "{label} = {} is off the chart: {from} .. {to}{wider}",
                format_si(x, unit)
            ))
        }
    }
    Vec::new()
}

/// The plots of the shown answer on the visible chart (none for a map or while solving).
fn plots(app: &App) -> Vec<Plot> {
    if app.explore.view.is_some() {
        return crate::tui::view::sweep::sweep_plots(app).unwrap_or_default();
    }
    let Some((answer, _)) = on_screen(app).answer() else {
        return Vec::new();
    };
    match overlay::figure(app.ui.chart, answer, app.ui.data.as_ref()) {
        Ok(Figure::Plots(plots)) => plots,
        _ => Vec::new(),
    }
}

/// The pinned plots of the visible chart, as the view draws them (the sweep view has none): the
/// cursor's fraction of the x range means the same x as on screen.
fn pins(app: &App) -> Vec<&[Plot]> {
    if app.explore.view.is_some() {
        return Vec::new();
    }
    let pins = app.ui.pins_of(app.ui.chart);
    pins.into_iter().map(|p| p.plots.as_slice()).collect()
}

/// Where `x` puts the cursor (a fraction of the x range): at the operating point when the chart
/// marks one (the current load or time, the sweep's "now": the first read is the student's own
/// point), else on the data point nearest the middle.
pub fn start(frames: &[Frame]) -> f64 {
    let Some(f) = frames.first() else {
        return 0.5;
    };
    let plot = f.plot;
    let marker = plot.markers.iter().flat_map(|m| m.points.first()).next();
    let now = plot.x_marks.iter().find(|m| m.label == "now").map(|m| m.at);
    let [lo, hi] = f.x;
    let point = marker.map(|p| p.0).or(now);
    match point.and_then(|x| plot.x.scale.to_plot(x)) {
        Some(x) => ((x - lo) / (hi - lo)).clamp(0.0, 1.0),
        // no point of the student's own: the data point nearest the middle, so that the first
        // reading is a computed value, not one between two
        None => (point_fractions(f).into_iter())
            .min_by(|a, b| (a - 0.5).abs().total_cmp(&(b - 0.5).abs()))
            .unwrap_or(0.5),
    }
}

/// The x of the first curve's points as fractions of the x range, in increasing order.
fn point_fractions(f: &Frame) -> Vec<f64> {
    let [lo, hi] = f.x;
    let mut xs: Vec<f64> = f
        .plot
        .series
        .first()
        .map(|s| plotted(&s.points, f.plot.x.scale, Scale::Linear))
        .unwrap_or_default()
        .iter()
        .map(|p| (p.0 - lo) / (hi - lo))
        .collect();
    xs.sort_by(f64::total_cmp);
    xs
}

/// The cursor `points` data points of the first curve away from `at` (a fraction of the x
/// range), or `points` hundredths of the range where there is no curve.
pub fn cursor_moved(frames: &[Frame], at: f64, points: i32) -> f64 {
    let Some(f) = frames.first() else {
        return (at + points as f64 / 100.0).clamp(0.0, 1.0);
    };
    let xs = point_fractions(f);
    if xs.is_empty() {
        return (at + points as f64 / 100.0).clamp(0.0, 1.0);
    }
    let eps = 1e-9;
    let i = if points > 0 {
        // the first point right of the cursor is one step
        let next = xs.iter().position(|&x| x > at + eps).unwrap_or(xs.len());
        next + points as usize - 1
    } else {
        let prev = xs.iter().rposition(|&x| x < at - eps);
        match prev {
            Some(p) => p.saturating_sub((-points) as usize - 1),
            None => 0,
        }
    };
    xs[i.min(xs.len() - 1)]
}

fn pin(app: &mut App) {
    let Some((answer, _)) = on_screen(app).answer() else {
        app.say("nothing to pin yet (solving…)");
        return;
    };
    let chart = app.ui.chart;
    match chart.build(answer) {
        Ok(Figure::Plots(plots)) => {
            let preset = answer.request.preset.clone();
            let mut dropped = false;
            if app.ui.pins_of(chart).len() >= MAX_PINS {
                let oldest = app.ui.pins.iter().position(|p| p.chart == chart);
                oldest.map(|i| app.ui.pins.remove(i));
                dropped = true;
            }
            app.ui.pins.push(Pin {
                chart,
                preset,
                plots,
            });
            let n = app.ui.pins_of(chart).len();
            app.say(if dropped {
                format!("pinned as {n} (the oldest of {MAX_PINS} pins dropped); C clears")
            } else {
                format!("pinned as {n}: edit a value to compare; C clears")
            });
        }
        Ok(Figure::Map(_)) => {
            app.complain("pins compare curves: the map has none (Tab to a chart with curves)")
        }
        Err(_) => app.say("nothing to pin yet (solving…)"),
    }
}

fn log_y(app: &mut App) {
    let chart = app.ui.chart;
    let plots = plots(app);
    if plots.is_empty() {
        app.complain("y toggles the y axis of a chart with curves");
        return;
    }
    match app.ui.log_y.iter().position(|c| *c == chart) {
        Some(i) => {
            app.ui.log_y.remove(i);
        }
        None => app.ui.log_y.push(chart),
    }
    let toggled = app.ui.log_y.contains(&chart);
    let scales: Vec<String> = frames(&plots, &[], toggled)
        .iter()
        .map(|f| match f.y_scale {
            Scale::Linear if toggled && constant(f).is_some() => format!(
                "{} stays linear (one value, {})",
                f.plot.y.label,
                crate::units::format_si(constant(f).unwrap_or_default(), f.plot.y.unit)
            ),
            Scale::Linear => format!("{} linear", f.plot.y.label),
            Scale::Log => format!("{} logarithmic", f.plot.y.label),
            Scale::SymLog(c) => format!(
                "{} symmetric log (linear within ±{})",
                f.plot.y.label,
                crate::units::format_si(c, f.plot.y.unit)
            ),
        })
        .collect();
    app.say(format!("y axis of {}", scales.join("; ")));
}

/// Keeps the pressure map's colour scale over the times seen of the same inputs (widened by each
/// new one), so that playing or stepping time shows a decay as fading colours; other inputs start
/// a scale of their own.
pub fn keep_heat_scale(app: &mut App) {
    let Some(answer) = &app.solve.shown else {
        return;
    };
    // the pressures the map draws: the closed form's, or the nodes' of the period cell or of a
    // height map's grid
    let pressure = match &answer.output {
        Output::Spatial(Ok(out)) => match crate::tui::charts::contact::fields(out) {
            Ok(Fields::Closed) => &out.state.field.pressure,
            Ok(Fields::Nodes(state)) => &state.pressure,
            Err(_) => return,
        },
        Output::Surface(Ok(out)) => match out.running_in().map(|c| &c.state) {
            Some(Ok(state)) => &state.pressure,
            _ => return,
        },
        _ => return,
    };
    let [lo, hi] = crate::tui::charts::range::bounds(pressure.iter().copied());
    let mut inputs = answer.request.preset.clone();
    inputs.spatial.time = 0.0;
    app.ui.heat_scale = Some(match app.ui.heat_scale.take() {
        Some(s) if s.inputs == inputs => HeatScale {
            range: [s.range[0].min(lo), s.range[1].max(hi)],
            inputs,
        },
        _ => HeatScale {
            inputs,
            range: [lo, hi],
        },
    });
}
