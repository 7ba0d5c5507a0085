//! The exports of a chart: its data as CSV (`e`) and a figure as SVG (`E`), both exactly the
//! figure the view draws, its pins included, both naming the parameters they were computed from
//! (the answered request's preset): the CSV in comment lines (TOML), the SVG in its caption. The
//! sweep chart and the regime map are exported as SVG from what their view draws.

use crate::engine::Answer;
use crate::preset::{Preset, to_toml};
use crate::sweeps::map::{Map, MapSpec};

use crate::materials;
use crate::tui::charts::overlay::{self, Overlay};
use crate::tui::charts::svg::{Page, regime, svg as draw_svg};
use crate::tui::charts::{Axis, Chart, Figure, NoFigure, Plot};
use crate::tui::form;

/// What an export writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// The data, as CSV.
    Csv,
    /// A figure, as SVG.
    Svg,
}

/// The file name of a chart's export: `wearlab-<title words>.csv` (or `.svg`).
pub fn file_name(chart: Chart, format: Format) -> String {
    named(chart.title(), format)
}

/// The file name of an export titled `title`: `wearlab-<title words>.csv` (or `.svg`).
pub fn named(title: &str, format: Format) -> String {
    let stem = title
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
        .collect::<Vec<_>>()
        .join("-");
    let ext = match format {
        Format::Csv => "csv",
        Format::Svg => "svg",
    };
    format!("wearlab-{stem}.{ext}")
}

/// A column name with its unit: "x [m]", "mu* [-]" for a pure number.
fn column(axis: &Axis) -> String {
    match axis.unit {
        "" => format!("{} [-]", axis.label),
        u => format!("{} [{u}]", axis.label),
    }
}

/// The column of a y axis' standard deviations: "mu* sd [-]", as a data file names it.
fn sd_column(axis: &Axis) -> String {
    match axis.unit {
        "" => format!("{} sd [-]", axis.label),
        u => format!("{} sd [{u}]", axis.label),
    }
}

/// A CSV field, quoted when it holds a comma or a quote.
fn field(text: &str) -> String {
    if text.contains([',', '"']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// The CSV text of the figure drawn for `chart` from `answer` with its pins (their plots and
/// legend names): comment lines with the chart and the preset (TOML), then a header with units,
/// then the rows. A plot figure has one row per point: the curve's name, then its x and y in the
/// columns of its axes (plots that share an axis share its column); the overlaid data file's
/// points follow a plot's curves ("data: friction.csv"), their standard deviations in a column
/// of their own ("mu* sd [-]"); a pinned curve follows, named by its pin and its own name ("pin:
/// mu = 0.2: mu* wide"). A curve without an answer at some points has a comment line naming
/// them before the header ("# mu* wide: no answer at P >= 1.70 kN/m (11 of 40 loads),
/// none at P [N/m] = 1.70e3 ...").
pub fn csv(
    chart: Chart,
    answer: &Answer,
    pins: Vec<(&[Plot], String)>,
    data: Option<&Overlay>,
) -> Result<String, NoFigure> {
    let figure = overlay::figure(chart, answer, data)?;
    let mut out = format!("# wearlab: {}\n", chart.title());
    let preset = &answer.request.preset;
    for line in caption(preset, 100) {
        out.push_str(&format!("# {line}\n"));
    }
    out.push_str("# computed from these parameters (preset, TOML, SI units):\n");
    for line in to_toml(&answer.request.preset).lines() {
        out.push_str(&format!("#   {line}\n"));
    }
    if !pins.is_empty() {
        out.push_str(
            "# pinned curves (dashed in the figure), named by what differs from these parameters\n",
        );
    }
    let measured = matches!(&figure, Figure::Plots(ps) if ps.iter().any(|p| !p.data.is_empty()));
    if let Some(o) = data.filter(|_| measured) {
        out.push_str(&format!(
            "# measured points from {} (\"{}\"; one standard deviation in the sd column)\n",
            o.set.path, o.name
        ));
        for note in &o.set.notes {
            out.push_str(&format!("#   {note}\n"));
        }
    }
    match figure {
        Figure::Map(m) => {
            out.push_str(&format!("x [m],y [m],{} [{}]\n", m.name, m.unit));
            for (j, y) in m.y.iter().enumerate() {
                for (i, x) in m.x.iter().enumerate() {
                    let v = m.values[j * m.x.len() + i];
                    out.push_str(&format!("{x:e},{y:e},{v:e}\n"));
                }
            }
        }
        Figure::Plots(plots) => {
            let mut columns: Vec<String> = Vec::new();
            let mut at = |name: String| match columns.iter().position(|c| *c == name) {
                Some(i) => i,
                None => {
                    columns.push(name);
                    columns.len() - 1
                }
            };
            let places: Vec<(usize, usize)> = plots
                .iter()
                .map(|p| (at(column(&p.x)), at(column(&p.y))))
                .collect();
            let sd_places: Vec<Option<usize>> = plots
                .iter()
                .map(|p| (p.data.iter().any(|d| d.sd.is_some())).then(|| at(sd_column(&p.y))))
                .collect();
            // a curve without an answer at some points: named with them before the header
            for p in &plots {
                for u in &p.unanswered {
                    let at: Vec<String> = u.at.iter().map(|x| format!("{x:e}")).collect();
                    out.push_str(&format!(
                        "# {}: {}, none at {} = {}\n",
                        p.series[u.curve].name,
                        u.words,
                        column(&p.x),
                        at.join(" ")
                    ));
                }
            }
            let header: Vec<String> = columns.iter().map(|c| field(c)).collect();
            out.push_str(&format!("curve,{}\n", header.join(",")));
            let row_with = |name: &str,
                            (x, y): (f64, f64),
                            (xc, yc): (usize, usize),
                            sd: Option<(usize, f64)>| {
                let mut row = vec![String::new(); columns.len()];
                row[xc] = format!("{x:e}");
                row[yc] = format!("{y:e}");
                if let Some((sc, s)) = sd {
                    row[sc] = format!("{s:e}");
                }
                format!("{},{}\n", field(name), row.join(","))
            };
            let row = |name: &str, point: (f64, f64), place: (usize, usize)| {
                row_with(name, point, place, None)
            };
            for ((p, &place), &sd_place) in plots.iter().zip(&places).zip(&sd_places) {
                for s in p.series.iter().chain(&p.markers) {
                    for &point in &s.points {
                        out.push_str(&row(&s.name, point, place));
                    }
                }
                for d in &p.data {
                    for (k, &point) in d.points.iter().enumerate() {
                        let sd = sd_place.zip(d.sd.as_ref().map(|s| s[k]));
                        out.push_str(&row_with(&d.name, point, place, sd));
                    }
                }
            }
            for (pinned, name) in &pins {
                for (p, &place) in pinned.iter().zip(&places) {
                    for s in &p.series {
                        let curve = format!("{name}: {}", s.name);
                        for &point in &s.points {
                            out.push_str(&row(&curve, point, place));
                        }
                    }
                }
            }
        }
    }
    Ok(out)
}

/// The caption of a figure: the preset's name, then its parameters as the form shows them
/// (with units; the material's name only where it is one of the table's), in lines of at most
/// `width` characters.
pub fn caption(preset: &Preset, width: usize) -> Vec<String> {
    let rows: Vec<_> = form::rows(preset)
        .into_iter()
        .filter(|r| form::show(preset, r) != materials::CUSTOM)
        .collect();
    let items: Vec<String> = rows
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let sep = if i + 1 < rows.len() { "," } else { "" };
            format!("{} = {}{sep}", r.symbol(), form::show(preset, r))
        })
        .collect();
    let mut lines = vec![format!(
        "{} ({} problem)",
        preset.name,
        preset.problem.name()
    )];
    lines.extend(
        crate::tui::view::wrapping::pack(&items, width, "")
            .into_iter()
            .map(|l| l.replace(",  ", ", ")),
    );
    lines
}

/// The SVG of the figure drawn for `chart` from `answer`, with the pins (their plots and legend
/// names), the overlaid data file's points, the y axes toggled or not, and a map's colour scale.
pub fn svg(
    chart: Chart,
    answer: &Answer,
    pins: Vec<(&[Plot], String)>,
    data: Option<&Overlay>,
    toggled: bool,
    scale: Option<[f64; 2]>,
) -> Result<String, NoFigure> {
    let figure = overlay::figure(chart, answer, data)?;
    let page = Page {
        title: chart.title(),
        caption: caption(&answer.request.preset, 130),
        pins,
        toggled,
        scale,
    };
    draw_svg(&figure, &page).map_err(NoFigure::Error)
}

/// The SVG of the sweep chart's plots (no pins, the y axis as drawn) under `title`, with the
/// parameters of `preset` (the ones the sweep was computed from) in its caption.
pub fn sweep_svg(title: &str, preset: &Preset, plots: Vec<Plot>) -> Result<String, String> {
    let page = Page {
        title,
        caption: caption(preset, 130),
        pins: Vec::new(),
        toggled: false,
        scale: None,
    };
    draw_svg(&Figure::Plots(plots), &page)
}

/// The SVG of a regime map under `title`, with the parameters of `preset` (the ones the map was
/// computed from) in its caption.
pub fn map_svg(title: &str, preset: &Preset, spec: &MapSpec, map: &Map) -> Result<String, String> {
    regime(spec, map, title, &caption(preset, 130))
}
