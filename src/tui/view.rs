//! Drawing: a pure function of the App (no solving, no I/O).

use ratatui::Frame;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{
    Axis, Block, Borders, Chart, Clear, Dataset, GraphType, Paragraph, Widget, Wrap,
};
use wearlab::engine::{Output, PlaneOutput, SpatialOutput};
use wearlab::physics::Spacing;
use wearlab::preset::Problem;
use wearlab::units::format_si;

use crate::tui::app::{App, Mode, chart_titles};
use crate::tui::form;

/// How to draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderOptions {
    /// Plain ASCII markers instead of Braille.
    pub ascii: bool,
    /// Colours allowed (NO_COLOR unset).
    pub color: bool,
}

/// One curve: its name and points (x, y), already in plot coordinates.
pub struct Curve {
    /// Legend text.
    pub name: String,
    /// Points.
    pub points: Vec<(f64, f64)>,
}

/// Everything one chart needs.
pub struct ChartSpec {
    /// x-axis label with unit.
    pub x_label: String,
    /// y-axis label with unit.
    pub y_label: String,
    /// x unit for tick labels.
    pub x_unit: &'static str,
    /// y unit for tick labels.
    pub y_unit: &'static str,
    /// x values are log10 of the quantity.
    pub log_x: bool,
    /// The curves.
    pub curves: Vec<Curve>,
    /// Marked points (the current operating point, the punch's harmonics), drawn as blocks.
    pub markers: Vec<(f64, f64)>,
    /// The legend of the marked points.
    pub marker_label: &'static str,
    /// The y-range follows only the first curve (and the markers); the others are overlays,
    /// clipped, so that a model far outside its range does not flatten the one being explored.
    pub overlays: bool,
}

const COLORS: [Color; 6] = [
    Color::Cyan,
    Color::Yellow,
    Color::Magenta,
    Color::Green,
    Color::Red,
    Color::Blue,
];

/// The smallest terminal the explorer draws in.
pub const MIN_SIZE: (u16, u16) = (80, 24);

/// Draws the whole screen.
pub fn view(app: &App, style: RenderOptions, frame: &mut Frame) {
    let area = frame.area();
    if area.width < MIN_SIZE.0 || area.height < MIN_SIZE.1 {
        let text = vec![
            Line::from("terminal too small"),
            Line::from(format!(
                "{}x{}: wearlab needs at least {}x{}",
                area.width, area.height, MIN_SIZE.0, MIN_SIZE.1
            )),
            Line::from("enlarge the window, or q to quit"),
        ];
        let y = area.height / 2;
        let rect = Rect {
            x: 0,
            y: y.saturating_sub(1),
            width: area.width,
            height: 3.min(area.height),
        };
        frame.render_widget(
            Paragraph::new(text).alignment(ratatui::layout::Alignment::Center),
            rect,
        );
        return;
    }
    let [main, message, footer] = Layout::vertical([
        Constraint::Min(10),
        Constraint::Length(1),
        Constraint::Length(1),
    ])
    .areas(area);
    let [form_area, right] = Layout::horizontal([
        Constraint::Length(if area.width < 100 { 30 } else { 34 }),
        Constraint::Min(40),
    ])
    .areas(main);
    let status_height = if area.height >= 32 { 9 } else { 7 };
    let [chart_area, status_area] =
        Layout::vertical([Constraint::Min(8), Constraint::Length(status_height)]).areas(right);
    draw_form(app, frame, form_area);
    draw_charts(app, style, frame, chart_area);
    draw_status(app, style, frame, status_area);
    draw_message(app, style, frame, message);
    draw_footer(app, frame, footer);
    match &app.mode {
        Mode::Help => draw_help(app, frame, area),
        Mode::Picker { entries, selected } => draw_picker(entries, *selected, frame, area),
        _ => {}
    }
}

fn draw_form(app: &App, frame: &mut Frame, area: Rect) {
    let rows = form::rows(&app.preset);
    let title = match app.preset.problem {
        Problem::Plane => " plane: punch on a strip ",
        Problem::Spatial => " spatial: wavy punch ",
    };
    let block = Block::default().borders(Borders::ALL).title(title);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let mut lines: Vec<Line> = Vec::new();
    let mut selected_line = 0;
    let mut last_group = "";
    let mut last_harmonic = None;
    for (i, r) in rows.iter().enumerate() {
        let harmonic = crate::tui::app::harmonic_of(&r.key);
        if r.group != last_group || harmonic != last_harmonic {
            let heading = match harmonic {
                Some(n) => format!("harmonic {}", n + 1),
                None => r.group.to_string(),
            };
            lines.push(Line::from(Span::styled(
                heading,
                Style::default().add_modifier(Modifier::BOLD),
            )));
            last_group = r.group;
            last_harmonic = harmonic;
        }
        let value = match (&app.mode, i == app.selected) {
            (Mode::Editing(buffer), true) => format!("{buffer}_"),
            _ => form::show(&app.preset, r),
        };
        let width = (inner.width as usize).saturating_sub(11);
        let text = format!("  {:<9}{value:>width$}", r.label);
        let style = if i == app.selected {
            Style::default().add_modifier(Modifier::REVERSED)
        } else {
            Style::default()
        };
        if i == app.selected {
            selected_line = lines.len();
        }
        lines.push(Line::from(Span::styled(text, style)));
    }
    let height = inner.height as usize;
    let offset = selected_line
        .saturating_sub(height.saturating_sub(2))
        .min(lines.len().saturating_sub(height));
    frame.render_widget(Paragraph::new(lines).scroll((offset as u16, 0)), inner);
}

fn draw_charts(app: &App, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let title = chart_titles(app.preset.problem)[app.chart];
    let solving = if app.solving() { "  solving…" } else { "" };
    let block = Block::default()
        .borders(Borders::ALL)
        .title(format!(
            " {}/{} {title}{solving} ",
            app.chart + 1,
            chart_titles(app.preset.problem).len()
        ))
        .title_bottom(Line::from(" Tab: next chart ").right_aligned());
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let specs: Vec<ChartSpec> = match &app.output {
        None => {
            frame.render_widget(Paragraph::new("solving…"), inner);
            return;
        }
        Some(Output::Plane(out)) => match plane_charts(app, out) {
            Ok(s) => s,
            Err(why) => {
                frame.render_widget(
                    Paragraph::new(why)
                        .wrap(Wrap { trim: true })
                        .style(error_style(style)),
                    inner,
                );
                return;
            }
        },
        Some(Output::Spatial(Err(e))) => {
            frame.render_widget(
                Paragraph::new(e.to_string())
                    .wrap(Wrap { trim: true })
                    .style(error_style(style)),
                inner,
            );
            return;
        }
        Some(Output::Spatial(Ok(out))) => {
            if app.chart == 0 {
                draw_heatmap(out, style, frame.buffer_mut(), inner);
                return;
            }
            spatial_charts(app, out)
        }
    };
    let parts =
        Layout::vertical(vec![Constraint::Ratio(1, specs.len() as u32); specs.len()]).split(inner);
    for (spec, part) in specs.iter().zip(parts.iter()) {
        draw_chart(spec, style, frame, *part);
    }
}

fn error_style(style: RenderOptions) -> Style {
    if style.color {
        Style::default().fg(Color::Red)
    } else {
        Style::default().add_modifier(Modifier::BOLD)
    }
}

/// The plane charts' data for the visible chart (also what `e` exports).
pub fn plane_charts(app: &App, out: &PlaneOutput) -> Result<Vec<ChartSpec>, String> {
    let log = app.preset.plane.sweep.spacing == Spacing::Log;
    let lx = |p: f64| if log { p.log10() } else { p };
    let point = out.point.as_ref().map_err(|e| e.to_string());
    let sweep_curve = |name: String, ys: &[Option<f64>], loads: &[f64], scale: f64| Curve {
        name,
        points: loads
            .iter()
            .zip(ys)
            .filter_map(|(p, y)| y.map(|y| (lx(*p), y * scale)))
            .collect(),
    };
    Ok(match app.chart {
        0 => {
            let p = point?;
            let x: Vec<f64> = p.profile.x.clone();
            vec![ChartSpec {
                x_label: "x".into(),
                y_label: "stress".into(),
                x_unit: "m",
                y_unit: "Pa",
                log_x: false,
                overlays: false,
                marker_label: "now",
                curves: vec![
                    Curve {
                        name: "pressure q2".into(),
                        points: x
                            .iter()
                            .copied()
                            .zip(p.profile.pressure.iter().copied())
                            .collect(),
                    },
                    Curve {
                        name: "shear q1".into(),
                        points: x
                            .iter()
                            .copied()
                            .zip(p.profile.shear.iter().copied())
                            .collect(),
                    },
                ],
                markers: Vec::new(),
            }]
        }
        1 => {
            let p = point?;
            let x: Vec<f64> = p.profile.x.clone();
            vec![
                ChartSpec {
                    x_label: "x".into(),
                    y_label: "wear/pass".into(),
                    x_unit: "m",
                    y_unit: "m",
                    log_x: false,
                    overlays: false,
                    marker_label: "now",
                    curves: vec![Curve {
                        name: "wear per pass".into(),
                        points: x
                            .iter()
                            .copied()
                            .zip(p.profile.wear.iter().copied())
                            .collect(),
                    }],
                    markers: Vec::new(),
                },
                ChartSpec {
                    x_label: "x".into(),
                    y_label: "k q2".into(),
                    x_unit: "m",
                    y_unit: "",
                    log_x: false,
                    overlays: false,
                    marker_label: "now",
                    curves: vec![Curve {
                        name: "wear rate k q2".into(),
                        points: x
                            .iter()
                            .copied()
                            .zip(p.profile.wear_rate.iter().copied())
                            .collect(),
                    }],
                    markers: Vec::new(),
                },
            ]
        }
        2 => {
            let marker = point
                .as_ref()
                .ok()
                .map(|p| (lx(app.preset.plane.load), p.solution.mu_star));
            vec![ChartSpec {
                x_label: "P [N/m]".into(),
                y_label: "mu*".into(),
                x_unit: "N/m",
                y_unit: "",
                log_x: log,
                overlays: true,
                marker_label: "now",
                curves: out
                    .sweep
                    .iter()
                    .map(|s| (app.preset.plane.model, s))
                    .chain(out.overlays.iter().map(|(m, s)| (*m, s)))
                    .map(|(m, s)| {
                        sweep_curve(format!("mu* {}", m.name()), &s.mu_star, &s.load, 1.0)
                    })
                    .collect(),
                markers: marker.into_iter().collect(),
            }]
        }
        _ => {
            let Some(s) = &out.sweep else {
                return Err("solving…".into());
            };
            vec![ChartSpec {
                x_label: "P [N/m]".into(),
                y_label: "edge".into(),
                x_unit: "N/m",
                y_unit: "m",
                log_x: log,
                overlays: false,
                marker_label: "now",
                curves: vec![
                    sweep_curve("a (trailing)".into(), &s.a, &s.load, 1.0),
                    sweep_curve("b (leading)".into(), &s.b, &s.load, 1.0),
                ],
                markers: Vec::new(),
            }]
        }
    })
}

/// The spatial line charts' data for the visible chart (1..=3).
pub fn spatial_charts(app: &App, out: &SpatialOutput) -> Vec<ChartSpec> {
    match app.chart {
        1 => {
            let f = &out.state.field;
            let row = f.n / 2;
            let x: Vec<f64> = f.x.clone();
            let line = |v: &[f64]| -> Vec<(f64, f64)> {
                x.iter()
                    .copied()
                    .zip(v[row * f.n..(row + 1) * f.n].iter().copied())
                    .collect()
            };
            let y_label = format!("along y = {}", format_si(f.y[row], "m"));
            vec![
                ChartSpec {
                    x_label: "x".into(),
                    y_label: "p".into(),
                    x_unit: "m",
                    y_unit: "Pa",
                    log_x: false,
                    overlays: false,
                    marker_label: "now",
                    curves: vec![Curve {
                        name: format!("pressure {y_label}"),
                        points: line(&f.pressure),
                    }],
                    markers: Vec::new(),
                },
                ChartSpec {
                    x_label: "x".into(),
                    y_label: "U".into(),
                    x_unit: "m",
                    y_unit: "m",
                    log_x: false,
                    overlays: false,
                    marker_label: "now",
                    curves: vec![Curve {
                        name: "shape U".into(),
                        points: line(&f.shape),
                    }],
                    markers: Vec::new(),
                },
            ]
        }
        2 => {
            let Some(h) = &out.history else {
                return Vec::new();
            };
            let t = app.preset.spatial.time;
            let amplitudes = h
                .amplitudes
                .iter()
                .enumerate()
                .map(|(n, a)| Curve {
                    name: format!("A{}", n + 1),
                    points: h.time.iter().copied().zip(a.iter().copied()).collect(),
                })
                .collect();
            let mu_at_t = out.state.solution.mu_star;
            vec![
                ChartSpec {
                    x_label: "t [s]".into(),
                    y_label: "A".into(),
                    x_unit: "s",
                    y_unit: "m",
                    log_x: false,
                    overlays: false,
                    marker_label: "now",
                    curves: amplitudes,
                    markers: out
                        .state
                        .solution
                        .harmonics
                        .iter()
                        .map(|s| (t, s.state.amplitude))
                        .collect(),
                },
                ChartSpec {
                    x_label: "t [s]".into(),
                    y_label: "mu*".into(),
                    x_unit: "s",
                    y_unit: "",
                    log_x: false,
                    overlays: false,
                    marker_label: "now",
                    curves: vec![Curve {
                        name: "mu*(t)".into(),
                        points: h
                            .time
                            .iter()
                            .copied()
                            .zip(h.mu_star.iter().copied())
                            .collect(),
                    }],
                    markers: vec![(t, mu_at_t)],
                },
            ]
        }
        3 => {
            let s = &out.state.sweep;
            let log = app.preset.spatial.sweep.spacing == Spacing::Log;
            let lx = |p: f64| if log { p.log10() } else { p };
            vec![ChartSpec {
                x_label: "pbar [Pa]".into(),
                y_label: "mu*".into(),
                x_unit: "Pa",
                y_unit: "",
                log_x: log,
                overlays: false,
                marker_label: "now",
                curves: vec![Curve {
                    name: "mu* (complete contact only)".into(),
                    points: s
                        .mean_pressure
                        .iter()
                        .zip(&s.mu_star)
                        .filter_map(|(p, m)| m.map(|m| (lx(*p), m)))
                        .collect(),
                }],
                markers: out
                    .state
                    .contact
                    .complete
                    .then(|| {
                        (
                            lx(app.preset.spatial.mean_pressure),
                            out.state.solution.mu_star,
                        )
                    })
                    .into_iter()
                    .collect(),
            }]
        }
        _ => {
            let d = &out.dispersion;
            let (x_label, scale) = if d.scaled_by_thickness {
                ("kh", 1.0)
            } else {
                ("k [rad/m]", 1.0)
            };
            let curves = d
                .angles
                .iter()
                .zip(&d.drift_velocity)
                .map(|(a, c)| Curve {
                    name: format!("c at {:.0} deg", a.to_degrees()),
                    points: d
                        .k
                        .iter()
                        .zip(c)
                        .map(|(k, c)| ((k * scale).log10(), *c))
                        .collect(),
                })
                .collect();
            let h = app.preset.material.thickness;
            let unit = if d.scaled_by_thickness { h } else { 1.0 };
            let marks: Vec<(f64, f64)> = out
                .state
                .solution
                .harmonics
                .iter()
                .map(|s| {
                    (
                        (s.initial.wavenumber() * unit).log10(),
                        s.evolution.drift_velocity,
                    )
                })
                .collect();
            let mut curves: Vec<Curve> = curves;
            let ends = [d.k[0].log10(), d.k[d.k.len() - 1].log10()];
            curves.push(Curve {
                name: "c = 0".into(),
                points: vec![(ends[0], 0.0), (ends[1], 0.0)],
            });
            vec![ChartSpec {
                x_label: x_label.into(),
                y_label: "c".into(),
                x_unit: "",
                y_unit: "m/s",
                log_x: true,
                overlays: false,
                marker_label: "harmonics",
                curves,
                markers: marks,
            }]
        }
    }
}

fn bounds(values: impl Iterator<Item = f64>) -> [f64; 2] {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return [0.0, 1.0];
    }
    if hi - lo <= 1e-12 * hi.abs().max(lo.abs()).max(f64::MIN_POSITIVE) {
        let pad = if lo == 0.0 { 1.0 } else { 0.05 * lo.abs() };
        return [lo - pad, hi + pad];
    }
    [lo, hi]
}

fn tick(v: f64, unit: &str, log: bool) -> String {
    if log {
        format_si(10f64.powf(v), unit)
    } else {
        format_si(v, unit)
    }
}

fn draw_chart(spec: &ChartSpec, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let all = || {
        spec.curves
            .iter()
            .flat_map(|c| c.points.iter())
            .chain(spec.markers.iter())
    };
    let focus = || {
        let n = if spec.overlays { 1 } else { spec.curves.len() };
        spec.curves
            .iter()
            .take(n)
            .flat_map(|c| c.points.iter())
            .chain(spec.markers.iter())
    };
    let xb = bounds(all().map(|p| p.0));
    let yb = bounds(focus().map(|p| p.1));
    let marker = if style.ascii {
        Marker::Dot
    } else {
        Marker::Braille
    };
    let marker_points = &spec.markers;
    let mut datasets: Vec<Dataset> = spec
        .curves
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let ds = Dataset::default()
                .name(c.name.clone())
                .marker(marker)
                .graph_type(GraphType::Line)
                .data(&c.points);
            if style.color {
                ds.style(Style::default().fg(COLORS[i % COLORS.len()]))
            } else {
                ds
            }
        })
        .collect();
    if !marker_points.is_empty() {
        let ds = Dataset::default()
            .name(spec.marker_label)
            .marker(Marker::Block)
            .graph_type(GraphType::Scatter)
            .data(marker_points);
        datasets.push(if style.color {
            ds.style(
                Style::default()
                    .fg(Color::White)
                    .add_modifier(Modifier::BOLD),
            )
        } else {
            ds
        });
    }
    let xs = [
        tick(xb[0], spec.x_unit, spec.log_x),
        tick(0.5 * (xb[0] + xb[1]), spec.x_unit, spec.log_x),
        tick(xb[1], spec.x_unit, spec.log_x),
    ];
    let ys = [
        tick(yb[0], spec.y_unit, false),
        tick(0.5 * (yb[0] + yb[1]), spec.y_unit, false),
        tick(yb[1], spec.y_unit, false),
    ];
    let x_title = if spec.log_x {
        format!("{} (log)", spec.x_label)
    } else {
        spec.x_label.clone()
    };
    let chart = Chart::new(datasets)
        .x_axis(
            Axis::default()
                .title(x_title)
                .bounds(xb)
                .labels(xs.to_vec()),
        )
        .y_axis(
            Axis::default()
                .title(spec.y_label.clone())
                .bounds(yb)
                .labels(ys.to_vec()),
        )
        .legend_position(Some(ratatui::widgets::LegendPosition::TopRight))
        .hidden_legend_constraints((Constraint::Percentage(60), Constraint::Percentage(60)));
    frame.render_widget(chart, area);
}

/// A colour ramp from blue (low) through green to red (high), t in [0, 1].
fn ramp(t: f64) -> Color {
    let t = t.clamp(0.0, 1.0);
    let (r, g, b) = if t < 0.5 {
        let s = t / 0.5;
        (0.0, s, 1.0 - s)
    } else {
        let s = (t - 0.5) / 0.5;
        (s, 1.0 - s, 0.0)
    };
    Color::Rgb(
        (40.0 + 215.0 * r) as u8,
        (40.0 + 215.0 * g) as u8,
        (40.0 + 215.0 * b) as u8,
    )
}

const SHADES: [char; 5] = [' ', '░', '▒', '▓', '█'];

fn draw_heatmap(out: &SpatialOutput, style: RenderOptions, buf: &mut Buffer, area: Rect) {
    let f = &out.state.field;
    let [lo, hi] = bounds(f.pressure.iter().copied());
    let bar = 12u16;
    let w = area.width.saturating_sub(bar + 1).max(4);
    let h = area.height.saturating_sub(1).max(2);
    let sample = |col: u16, half_row: u16| -> f64 {
        let i = ((col as usize * f.n) / w as usize).min(f.n - 1);
        // row 0 at the top is the largest y
        let j = f.n - 1 - ((half_row as usize * f.n) / (2 * h as usize)).min(f.n - 1);
        (f.pressure[j * f.n + i] - lo) / (hi - lo)
    };
    for row in 0..h {
        for col in 0..w {
            let (top, bottom) = (sample(col, 2 * row), sample(col, 2 * row + 1));
            let cell = &mut buf[(area.x + col, area.y + row)];
            if style.color {
                cell.set_char('▀').set_fg(ramp(top)).set_bg(ramp(bottom));
            } else {
                let k = (((top + bottom) * 0.5) * 4.0).round().clamp(0.0, 4.0) as usize;
                cell.set_char(SHADES[k]);
            }
        }
    }
    // colour bar with its range
    let bx = area.x + w + 1;
    for row in 0..h {
        let t = 1.0 - row as f64 / (h - 1).max(1) as f64;
        let cell = &mut buf[(bx, area.y + row)];
        if style.color {
            cell.set_char('█').set_fg(ramp(t));
        } else {
            cell.set_char(SHADES[(t * 4.0).round() as usize]);
        }
    }
    let label = |v: f64| format_si(v, "Pa");
    Paragraph::new(label(hi)).render(
        Rect {
            x: bx + 2,
            y: area.y,
            width: bar - 2,
            height: 1,
        },
        buf,
    );
    Paragraph::new(label(lo)).render(
        Rect {
            x: bx + 2,
            y: area.y + h - 1,
            width: bar - 2,
            height: 1,
        },
        buf,
    );
    let caption = format!(
        "p(x, y) over {} x {}   x ->, sliding of the layer <-",
        format_si(out.state.cell.lx, "m"),
        format_si(out.state.cell.ly, "m")
    );
    Paragraph::new(caption).render(
        Rect {
            x: area.x,
            y: area.y + h,
            width: area.width,
            height: 1,
        },
        buf,
    );
}

fn draw_status(app: &App, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let block = Block::default()
        .borders(Borders::ALL)
        .title(" operating point ");
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let ok = if style.color {
        Style::default().fg(Color::Green)
    } else {
        Style::default()
    };
    let bad = error_style(style);
    let mut lines: Vec<Line> = Vec::new();
    match &app.output {
        None => lines.push(Line::from("solving…")),
        Some(Output::Plane(out)) => match &out.point {
            Err(e) => lines.push(Line::styled(e.to_string(), bad)),
            Ok(p) => {
                let s = &p.solution;
                let theta = s.theta.map_or("-".to_string(), |t| format!("{t:.4}"));
                lines.push(Line::from(format!(
                    "a = {}  b = {}  theta = {theta}  Q2 = {}",
                    format_si(s.a, "m"),
                    format_si(s.b, "m"),
                    format_si(s.normal_force, "N/m")
                )));
                lines.push(Line::from(format!(
                    "psi = {}  mu* = {:.6}  (mu = {})  I-J residual {:.1e}",
                    format_si(s.psi, "N/m"),
                    s.mu_star,
                    app.preset.friction.coefficient,
                    p.energy.residual
                )));
                if p.validity.ok {
                    lines.push(Line::styled(
                        format!(
                            "valid: (a+b)/h = {:.3}; {} model holds",
                            p.validity.contact_width_over_thickness,
                            s.model.name()
                        ),
                        ok,
                    ));
                }
                for w in &p.validity.warnings {
                    lines.push(Line::styled(format!("! {w}"), bad));
                }
            }
        },
        Some(Output::Spatial(Err(e))) => lines.push(Line::styled(e.to_string(), bad)),
        Some(Output::Spatial(Ok(out))) => {
            let s = &out.state.solution;
            lines.push(Line::from(format!(
                "t = {}  mu* = {:.6}  psi = {}  (mu = {})",
                format_si(s.time, "s"),
                s.mu_star,
                format_si(s.psi, "Pa"),
                app.preset.friction.coefficient
            )));
            match out.state.contact.failure() {
                Some(why) => lines.push(Line::styled(why, bad)),
                None => lines.push(Line::styled(
                    format!(
                        "complete contact, p_min = {} ({})",
                        format_si(out.state.contact.min_pressure, "Pa"),
                        if out.state.contact.exact {
                            "certified"
                        } else {
                            "bound"
                        }
                    ),
                    ok,
                )),
            }
            for (n, h) in s.harmonics.iter().enumerate() {
                let e = &h.evolution;
                lines.push(Line::from(format!(
                    "{}: kh {:.3}  1/beta {}  c {}  phi {:+.3}",
                    n + 1,
                    h.initial.wavenumber() * app.preset.material.thickness,
                    if e.decay_rate > 0.0 {
                        format_si(1.0 / e.decay_rate, "s")
                    } else {
                        "inf".into()
                    },
                    format_si(e.drift_velocity, "m/s"),
                    e.phase_lead
                )));
            }
        }
    }
    frame.render_widget(Paragraph::new(lines).wrap(Wrap { trim: true }), inner);
}

fn draw_message(app: &App, style: RenderOptions, frame: &mut Frame, area: Rect) {
    let (text, st) = match &app.mode {
        Mode::SaveAs(buffer) => (
            format!("save as (Enter to save, Esc to cancel): {buffer}_"),
            Style::default(),
        ),
        Mode::ConfirmOverwrite(path) => (
            format!("{} exists: overwrite? y/n", path.display()),
            error_style(style),
        ),
        Mode::ConfirmQuit => (
            "unsaved edits: quit anyway? y/n".to_string(),
            error_style(style),
        ),
        _ => match &app.message {
            Some((m, true)) => (m.clone(), error_style(style)),
            Some((m, false)) => (m.clone(), Style::default()),
            None => {
                let name = app
                    .path
                    .as_ref()
                    .map_or(app.preset.name.clone(), |p| p.display().to_string());
                (
                    format!("{name}{}", if app.dirty { " (edited)" } else { "" }),
                    Style::default(),
                )
            }
        },
    };
    frame.render_widget(Paragraph::new(text).style(st), area);
}

fn draw_footer(app: &App, frame: &mut Frame, area: Rect) {
    let wide = area.width >= 120;
    let keys = match (app.preset.problem, wide) {
        (Problem::Plane, true) => {
            "↑↓ field  ←→ nudge (⇧ more)  ⏎ type  Tab chart  p problem  m model  o open  s save  e export  u undo  ? help  q quit"
        }
        (Problem::Plane, false) => {
            "↑↓ field ←→ nudge ⏎ type Tab chart p problem m model o s e u ?help q"
        }
        (Problem::Spatial, true) => {
            "↑↓ field  ←→ nudge (⇧ more)  ⏎ type  Tab chart  space play  +/- harmonic  p problem  o open  s save  e export  ? help  q"
        }
        (Problem::Spatial, false) => {
            "↑↓ ←→ ⏎ type Tab chart space play +/- harm. p problem o s e u ?help q"
        }
    };
    frame.render_widget(
        Paragraph::new(keys).style(Style::default().add_modifier(Modifier::DIM)),
        area,
    );
}

fn centered(area: Rect, w: u16, h: u16) -> Rect {
    let w = w.min(area.width);
    let h = h.min(area.height);
    Rect {
        x: area.x + (area.width - w) / 2,
        y: area.y + (area.height - h) / 2,
        width: w,
        height: h,
    }
}

/// What each chart means, for the help screen.
fn chart_help(problem: Problem, chart: usize) -> &'static str {
    match (problem, chart) {
        (Problem::Plane, 0) => {
            "Pressure q2(x) and shear q1 = mu q2 + tau0 over the contact [-a, b]; b is the leading edge. A peak behind the tip (a > b) means friction dominates, ahead of it wear."
        }
        (Problem::Plane, 1) => {
            "Wear per pass: the depth a strip point loses while the punch passes over it (k times the integral of q2 from x to b). Wear rate k q2: depth per unit sliding distance."
        }
        (Problem::Plane, 2) => {
            "Total friction coefficient mu* against load: mu* = mu + [(1 + mu^2) psi + mu Delta_g tau0]/P. The block marks the current load; the other models are overlaid for comparison (the preset's model sets the scale)."
        }
        (Problem::Plane, _) => "Contact edges a (trailing) and b (leading) against load.",
        (Problem::Spatial, 0) => {
            "Contact pressure over one period cell (colour bar: Pa). The layer slides towards -x; friction on it points to +x."
        }
        (Problem::Spatial, 1) => {
            "Pressure and shape along the middle line y = const: the pressure leads the shape by the phase lead phi."
        }
        (Problem::Spatial, 2) => {
            "Harmonic amplitudes A_n(t) decaying by wear, and the run-in of mu*(t) towards mu. The block marks the current time."
        }
        (Problem::Spatial, 3) => {
            "mu* against the mean pressure, drawn only where contact is complete (p > 0 everywhere)."
        }
        (Problem::Spatial, _) => {
            "Drift velocity c of a wave against kh (k for a half-space) for wave vectors at 0, 45 and 75 degrees to the sliding line; the punch's harmonics are marked. c > 0 is along +x, with the friction on the layer; for nu > 1/4, waves with kh < X* drift backwards."
        }
    }
}

fn draw_help(app: &App, frame: &mut Frame, area: Rect) {
    let rect = centered(area, 76, 22);
    frame.render_widget(Clear, rect);
    let keys = [
        ("Up/Down, j/k", "choose a field"),
        (
            "Left/Right, h/l",
            "nudge the value (Shift or H/L: larger step)",
        ),
        ("Enter", "type a value: 3e9, 3 GPa, 50mm, inf; Esc cancels"),
        ("Tab / Shift-Tab", "next / previous chart"),
        ("p", "switch plane / spatial problem"),
        ("m", "cycle the plane model (wide, narrow)"),
        ("space", "play / pause time (spatial)"),
        (
            "+ / -",
            "add a harmonic / remove the selected one (spatial)",
        ),
        ("o", "open a preset (bundled or your folder)"),
        (
            "s",
            "save the preset (asks a name; asks before overwriting)",
        ),
        ("e", "export the visible chart's data as CSV"),
        ("u", "undo the last change"),
        ("?", "this help"),
        ("q, Ctrl-C", "quit (asks when there are unsaved edits)"),
    ];
    let mut lines: Vec<Line> = keys
        .iter()
        .map(|(k, what)| Line::from(format!("  {k:<18}{what}")))
        .collect();
    lines.push(Line::from(""));
    lines.push(Line::from(Span::styled(
        format!(
            "This chart: {}",
            chart_titles(app.preset.problem)[app.chart]
        ),
        Style::default().add_modifier(Modifier::BOLD),
    )));
    lines.push(Line::from(chart_help(app.preset.problem, app.chart)));
    let p = Paragraph::new(lines).wrap(Wrap { trim: false }).block(
        Block::default()
            .borders(Borders::ALL)
            .title(" help (any key closes) "),
    );
    frame.render_widget(p, rect);
}

/// A preset description as paragraphs: its hard line breaks are joined, except before
/// "Look at:" and "Try:", which start lines of their own.
fn reflow(text: &str) -> String {
    let mut out = String::new();
    for line in text.trim().lines().map(str::trim) {
        if line.starts_with("Look at") || line.starts_with("Try") {
            out.push('\n');
        } else if !out.is_empty() {
            out.push(' ');
        }
        out.push_str(line);
    }
    out
}

fn draw_picker(
    entries: &[crate::tui::app::PickerEntry],
    selected: usize,
    frame: &mut Frame,
    area: Rect,
) {
    let rect = centered(area, 78, 22);
    frame.render_widget(Clear, rect);
    let block = Block::default()
        .borders(Borders::ALL)
        .title(" open a preset (Enter opens, Esc closes) ");
    let inner = block.inner(rect);
    frame.render_widget(block, rect);
    let list_height = (entries.len() as u16).min(inner.height / 2);
    let [list, desc] =
        Layout::vertical([Constraint::Length(list_height), Constraint::Min(3)]).areas(inner);
    let offset = selected.saturating_sub(list_height.saturating_sub(1) as usize);
    let lines: Vec<Line> = entries
        .iter()
        .enumerate()
        .map(|(i, e)| {
            let st = if i == selected {
                Style::default().add_modifier(Modifier::REVERSED)
            } else {
                Style::default()
            };
            let mark = if e.preset.is_err() { "!" } else { " " };
            Line::styled(format!("{mark}{}", e.title), st)
        })
        .collect();
    frame.render_widget(Paragraph::new(lines).scroll((offset as u16, 0)), list);
    if let Some(e) = entries.get(selected) {
        let text = match &e.preset {
            Ok(p) => format!("{}\n{}", e.source, reflow(&p.description)),
            Err(why) => format!("{}\ncannot be opened: {why}", e.source),
        };
        frame.render_widget(
            Paragraph::new(text)
                .wrap(Wrap { trim: true })
                .block(Block::default().borders(Borders::TOP)),
            desc,
        );
    }
}
