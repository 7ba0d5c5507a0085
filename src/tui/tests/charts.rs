//! Each chart's export is its builder's figure, headed by the parameters it came from.

use wearlab::engine::{Answer, Engine, Request};
use wearlab::preset::{Problem, parse};

use super::*;
use crate::tui::charts::export::{csv, file_name};
use crate::tui::charts::{Chart, Figure};

/// The complete answer for a preset, overlays included.
fn complete(file: &str) -> Answer {
    let request = Request {
        preset: bundled(file),
        overlays: true,
    };
    let cmds = [Command::Solve(1, Box::new(request))];
    answers(&mut Engine::new(), &cmds).pop().unwrap()
}

/// The data rows of an export, parsed back.
fn rows(text: &str) -> Vec<Vec<String>> {
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect()
}

/// The figure's points as export rows would hold them.
fn expected(figure: &Figure) -> Vec<Vec<String>> {
    match figure {
        Figure::Map(m) => {
            m.y.iter()
                .enumerate()
                .flat_map(|(j, y)| {
                    m.x.iter().enumerate().map(move |(i, x)| {
                        vec![
                            x.to_string(),
                            y.to_string(),
                            m.values[j * m.x.len() + i].to_string(),
                        ]
                    })
                })
                .collect()
        }
        Figure::Plots(plots) => plots
            .iter()
            .enumerate()
            .flat_map(|(n, p)| {
                p.series.iter().chain(&p.markers).flat_map(move |s| {
                    s.points.iter().map(move |(x, y)| {
                        vec![
                            (n + 1).to_string(),
                            s.name.clone(),
                            x.to_string(),
                            y.to_string(),
                        ]
                    })
                })
            })
            .collect(),
    }
}

/// Rows with the numbers read back as f64 and written the same way, so 1e2 and 100 compare.
fn normal(rows: Vec<Vec<String>>) -> Vec<Vec<String>> {
    rows.into_iter()
        .map(|r| {
            r.into_iter()
                .map(|c| c.parse::<f64>().map_or(c, |v| v.to_string()))
                .collect()
        })
        .collect()
}

#[test]
fn each_charts_export_is_its_builders_figure() {
    for file in [
        "polymer-coating.toml",
        "hard-coating-strip.toml",
        "dispersion.toml",
    ] {
        let answer = complete(file);
        for chart in Chart::all(answer.request.preset.problem) {
            let figure = chart.build(&answer).unwrap();
            let text = csv(chart, &answer).unwrap();
            assert_eq!(
                normal(rows(&text)),
                normal(expected(&figure)),
                "{file} {chart:?}"
            );
            // headed by the parameters it was computed from: the header is a valid preset
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
    assert_eq!(file_name(chart), "wearlab-mu-against-load.csv");
    let text = csv(chart, &answer).unwrap();
    for name in ["mu* wide", "mu* narrow", "mu* strip", "now"] {
        assert!(text.contains(&format!(",{name},")), "{name}");
    }
    // loads in N/m, not their logarithms: the sweep starts at 100 N/m (polymer-coating.toml)
    let first = &rows(&text)[0];
    assert_eq!(first[2].parse::<f64>().unwrap().round(), 100.0);
}

#[test]
fn the_map_exports_every_grid_point() {
    let answer = complete("jgh-egg-box.toml");
    let text = csv(Chart::first(Problem::Spatial), &answer).unwrap();
    assert!(text.contains("\nx,y,pressure\n"));
    let n = answer.request.preset.spatial.grid;
    assert_eq!(rows(&text).len(), n * n);
}
