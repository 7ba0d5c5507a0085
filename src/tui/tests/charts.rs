//! Each chart's exports are its builder's figure, headed by the parameters it came from: the CSV
//! with units in its column names, the SVG (parsed as XML) with its axis titles, ticks, legend
//! and caption as text.

use crate::engine::{Answer, Engine, Request};
use crate::preset::{Problem, parse};

use super::*;
use crate::tui::charts::export::{Format, csv, file_name, svg};
use crate::tui::charts::range::frames;
use crate::tui::charts::ticks::ticks;
use crate::tui::charts::{Axis, Chart, Figure};

/// The complete answer for a preset, overlays included.
fn complete(file: &str) -> Answer {
    let request = Request {
        preset: bundled(file),
        overlays: true,
        energies: true,
    };
    let cmds = [Command::Solve(1, Box::new(request))];
    answers(&mut Engine::new(), &cmds).pop().unwrap()
}

/// The fields of a CSV line (double quotes around a field holding a comma).
fn fields(line: &str) -> Vec<String> {
    let mut out = vec![String::new()];
    let mut quoted = false;
    for c in line.chars() {
        match c {
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(String::new()),
            c => out.last_mut().unwrap().push(c),
        }
    }
    out
}

/// The header and the data rows of an export.
fn table(text: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header = fields(lines.next().unwrap());
    (header, lines.map(fields).collect())
}

/// A number as written, read back, so that 1e2 and 100 compare.
fn number(text: &str) -> f64 {
    text.parse().unwrap()
}

fn unit(a: &Axis) -> String {
    let u = if a.unit.is_empty() { "-" } else { a.unit };
    format!("{} [{u}]", a.label)
}

#[test]
fn each_charts_csv_is_its_builders_figure_with_units_in_the_column_names() {
    for file in [
        "polymer-coating.toml",
        "hard-coating-strip.toml",
        "dispersion.toml",
        "wave-thick-layer.toml",
    ] {
        let answer = complete(file);
        for chart in Chart::all(answer.request.preset.problem) {
            let figure = chart.build(&answer).unwrap();
            let text = csv(chart, &answer, Vec::new(), None).unwrap();
            let (header, rows) = table(&text);
            match &figure {
                Figure::Map(m) => {
                    assert_eq!(header, ["x [m]", "y [m]", "pressure [Pa]"]);
                    assert_eq!(rows.len(), m.x.len() * m.y.len());
                    assert_eq!(number(&rows[1][2]), m.values[1], "{file}");
                }
                Figure::Plots(plots) => {
                    assert_eq!(header[0], "curve");
                    let col = |a: &Axis| header.iter().position(|h| *h == unit(a)).unwrap();
                    let mut expected = Vec::new();
                    for p in plots {
                        for s in p.series.iter().chain(&p.markers) {
                            for &(x, y) in &s.points {
                                expected.push((s.name.clone(), col(&p.x), x, col(&p.y), y));
                            }
                        }
                    }
                    assert_eq!(rows.len(), expected.len(), "{file} {chart:?}");
                    for (row, (name, xc, x, yc, y)) in rows.iter().zip(expected) {
                        assert_eq!(row[0], name);
                        assert_eq!(number(&row[xc]), x, "{file} {chart:?}");
                        assert_eq!(number(&row[yc]), y, "{file} {chart:?}");
                    }
                }
            }
            // headed by the parameters it was computed from: the TOML lines are a valid preset
            let toml: String = text
                .lines()
                .filter_map(|l| l.strip_prefix("#   "))
                .map(|l| format!("{l}\n"))
                .collect();
            let header = parse(&toml, "header".as_ref()).unwrap();
            assert_eq!(header, answer.request.preset, "{file} {chart:?}");
        }
    }
}

#[test]
fn the_mu_star_chart_overlays_the_other_models_and_exports_them() {
    let answer = complete("polymer-coating.toml");
    let chart = Chart::all(Problem::Plane)[2];
    assert_eq!(file_name(chart, Format::Csv), "wearlab-mu-against-load.csv");
    assert_eq!(file_name(chart, Format::Svg), "wearlab-mu-against-load.svg");
    let text = csv(chart, &answer, Vec::new(), None).unwrap();
    assert!(text.contains("\ncurve,P [N/m],mu* [-]\n"), "{text}");
    assert!(
        text.contains("# E = 3.00 GPa, nu = 0.35, h = 10.0 mm,"),
        "{text}"
    );
    for name in ["mu* wide", "mu* narrow", "mu* strip", "now"] {
        assert!(text.contains(&format!("\n{name},")), "{name}");
    }
    // loads in N/m, not their logarithms: the sweep starts at 100 N/m (polymer-coating.toml)
    let (_, rows) = table(&text);
    assert_eq!(number(&rows[0][1]).round(), 100.0);
}

/// Every text element of an SVG.
pub(super) fn texts(svg: &str) -> Vec<String> {
    let doc = roxmltree::Document::parse(svg).expect("the SVG is well-formed XML");
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    doc.descendants()
        .filter(|n| n.has_tag_name("text"))
        .map(|n| n.text().unwrap_or("").trim().to_string())
        .collect()
}

#[test]
fn each_charts_svg_is_xml_with_its_axes_ticks_legend_and_caption_as_text() {
    for file in ["polymer-coating.toml", "wave-thick-layer.toml"] {
        let answer = complete(file);
        let preset = &answer.request.preset;
        for chart in Chart::all(preset.problem) {
            let figure = chart.build(&answer).unwrap();
            let text = svg(chart, &answer, Vec::new(), None, false, None).unwrap();
            let t = texts(&text);
            let has = |s: &str| {
                assert!(
                    t.iter().any(|x| x == s),
                    "{file} {chart:?}: no {s} in {t:?}"
                )
            };
            has(chart.title());
            has(&format!(
                "{} ({} problem)",
                preset.name,
                preset.problem.name()
            ));
            assert!(t.iter().any(|x| x.starts_with("E = ")), "{t:?}");
            match &figure {
                Figure::Plots(plots) => {
                    for f in frames(plots, &[], false) {
                        let p = f.plot;
                        let x = ticks(f.x, p.x.scale, &p.x.label, p.x.unit, 9);
                        let y = ticks(f.y, f.y_scale, &p.y.label, p.y.unit, 7);
                        has(&x.title);
                        has(&y.title);
                        for (_, label) in x.ticks.iter().chain(&y.ticks) {
                            has(label);
                        }
                        for s in &p.series {
                            assert!(
                                t.iter().any(|x| x.starts_with(&s.name)),
                                "{} in {t:?}",
                                s.name
                            );
                        }
                        for m in &p.y_marks {
                            has(&m.label);
                        }
                    }
                }
                Figure::Map(m) => {
                    // a 1 mm cell; 10 to 30 MPa (wave-thick-layer.toml: 20 MPa +- 10.3 MPa)
                    has("x [um]");
                    has("y [um]");
                    has("pressure [MPa]");
                    has(&m.caption);
                }
            }
        }
    }
}

#[test]
fn the_svg_holds_the_pins_and_the_toggled_axis() {
    let mut app = solved("hertz-check.toml");
    app.ui.chart = Chart::all(Problem::Plane)[3];
    let cmds = app.start();
    settle(&mut app, cmds);
    update(&mut app, key(ratatui::crossterm::event::KeyCode::Char('c')));
    update(&mut app, key(ratatui::crossterm::event::KeyCode::Char('y')));
    select(&mut app, "R", None);
    let cmds = update(&mut app, key(ratatui::crossterm::event::KeyCode::Right));
    settle(&mut app, cmds);
    let cmds = update(&mut app, key(ratatui::crossterm::event::KeyCode::Char('E')));
    let (path, text) = exported(&cmds);
    assert_eq!(
        path.to_str(),
        Some("wearlab-contact-edges-against-load.svg")
    );
    let t = texts(text);
    // the pin's two curves each in the legend, the first with the pin's name
    assert!(
        t.contains(&"pin: R = 50.0 mm, a (trailing)".to_string()),
        "{t:?}"
    );
    assert!(t.contains(&"b (leading)".to_string()), "{t:?}");
    assert!(t.contains(&"edge [m] (log)".to_string()), "{t:?}");
}

#[test]
fn without_a_duration_the_time_charts_span_five_of_the_slowest_decay_times() {
    // the default spatial side of a plane preset (1/beta = 4.68 ms: a fixed span such as 200 s
    // would show nothing of it); and wave-thick-layer.toml with its duration line taken out
    let text = crate::preset::BUNDLED
        .iter()
        .find(|b| b.file == "wave-thick-layer.toml")
        .unwrap()
        .text
        .replace("duration = 200.0\n", "");
    let mut switched = bundled("polymer-coating.toml");
    switched.problem = Problem::Spatial;
    for preset in [switched, parse(&text, "wave.toml".as_ref()).unwrap()] {
        let request = Request {
            preset,
            overlays: false,
            energies: false,
        };
        let answer = answers(&mut Engine::new(), &[Command::Solve(1, Box::new(request))])
            .pop()
            .unwrap();
        let Figure::Plots(plots) = Chart::Spatial(crate::tui::charts::SpatialChart::History)
            .build(&answer)
            .unwrap()
        else {
            panic!()
        };
        // the slowest harmonic's amplitude falls by e^-5 over the chart (A(t) = A(0) e^(-beta t))
        let slowest = plots[0]
            .series
            .iter()
            .map(|s| s.points.last().unwrap().1 / s.points[0].1)
            .fold(0.0, f64::max);
        assert!((slowest / (-5f64).exp() - 1.0).abs() < 1e-9, "{slowest}");
    }
}

#[test]
fn the_wear_chart_names_the_wear_law_it_draws() {
    use crate::tui::charts::PlaneChart;
    for (file, axis, legend) in [
        ("polymer-coating.toml", "k q2", "wear rate k q2"),
        (
            "wear-law-squared.toml",
            "F(q2)",
            "wear rate k q2 (q2/p0)^(n-1), n = 2",
        ),
    ] {
        let answer = complete(file);
        let Ok(Figure::Plots(plots)) = Chart::Plane(PlaneChart::Wear).build(&answer) else {
            panic!("{file}: no wear chart")
        };
        let rate = &plots[1];
        assert_eq!(rate.y.label, axis, "{file}");
        assert_eq!(rate.series[0].name, legend, "{file}");
    }
}
