//! The CSV export of a chart: exactly the figure the view draws, headed by the parameters it was
//! computed from (the answered request's preset as TOML, in comment lines).

use wearlab::engine::Answer;
use wearlab::preset::to_toml;

use crate::tui::charts::{Chart, Figure, NoFigure};

/// The file name of a chart's export: `wearlab-<title words>.csv`.
pub fn file_name(chart: Chart) -> String {
    let stem = chart
        .title()
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
        .collect::<Vec<_>>()
        .join("-");
    format!("wearlab-{stem}.csv")
}

/// The CSV text of the figure drawn for `chart` from `answer`.
pub fn csv(chart: Chart, answer: &Answer) -> Result<String, NoFigure> {
    let figure = chart.build(answer)?;
    let mut out = format!(
        "# wearlab: {}\n# computed from these parameters (preset, TOML):\n",
        chart.title()
    );
    for line in to_toml(&answer.request.preset).lines() {
        out.push_str(&format!("#   {line}\n"));
    }
    match figure {
        Figure::Map(m) => {
            out.push_str(&format!("# x [m], y [m], {} [{}]\n", m.name, m.unit));
            out.push_str(&format!("x,y,{}\n", m.name));
            for (j, y) in m.y.iter().enumerate() {
                for (i, x) in m.x.iter().enumerate() {
                    let v = m.values[j * m.x.len() + i];
                    out.push_str(&format!("{x:e},{y:e},{v:e}\n"));
                }
            }
        }
        Figure::Plots(plots) => {
            for (n, p) in plots.iter().enumerate() {
                out.push_str(&format!(
                    "# plot {}: x = {} [{}], y = {} [{}]\n",
                    n + 1,
                    p.x.label,
                    p.x.unit,
                    p.y.label,
                    p.y.unit
                ));
            }
            out.push_str("plot,curve,x,y\n");
            for (n, p) in plots.iter().enumerate() {
                for s in p.series.iter().chain(&p.markers) {
                    for (x, y) in &s.points {
                        out.push_str(&format!("{},{},{x:e},{y:e}\n", n + 1, s.name));
                    }
                }
            }
        }
    }
    Ok(out)
}
