//! A model without an answer at some loads says so, and a model that fails is drawn as failing:
//! the mu* chart's legend names the loads, the CSV names them before its header, and the parts
//! where the model's validity check fails are dim.

use ratatui::crossterm::event::KeyCode;

use super::*;
use crate::tui::charts::{Chart, Figure, PlaneChart, overlay};

/// hard-coating-strip.toml's mu* against load with the three models, solved.
fn mu_star_chart() -> App {
    let mut app = app("hard-coating-strip.toml");
    app.ui.chart = Chart::Plane(PlaneChart::MuStar);
    let cmds = app.start();
    settle(&mut app, cmds);
    app
}

#[test]
fn the_loads_without_an_answer_are_named_on_screen_and_in_the_csv() {
    // `wearlab solve presets/hard-coating-strip.toml --set plane.model=wide`: sweep.mu_star is
    // null at the last 11 of its 40 loads, from 1701.25 N/m, and sweep.valid false at all others
    let mut app = mu_star_chart();
    let words = "no answer at P >= 1.70 kN/m (11 of 40 loads)";
    let s = screen(&app, 120, 40, PLAIN);
    assert!(s.contains(words), "{s}");
    let cmds = press(&mut app, KeyCode::Char('e'));
    let (_, text) = exported(&cmds);
    let note = text
        .lines()
        .find(|l| l.starts_with("# mu* wide: "))
        .unwrap_or_else(|| panic!("{text}"));
    assert!(
        note.starts_with(&format!("# mu* wide: {words}, none at P [N/m] = 1.70125")),
        "{note}"
    );
    assert_eq!(note.split(" = ").last().unwrap().split(' ').count(), 11);
    // no row of the wide curve at those loads
    let rows = text.lines().filter(|l| l.starts_with("mu* wide,")).count();
    assert_eq!(rows, 29, "{text}");
}

#[test]
fn where_a_model_fails_its_curve_is_dim() {
    // the wide model fails at every load it answers (sweep.valid false), the strip model holds
    // at every one (the exact model of the bonded strip)
    let app = mu_star_chart();
    let answer = app.solve.shown.as_ref().unwrap();
    let Ok(Figure::Plots(plots)) = overlay::figure(app.ui.chart, answer, None) else {
        panic!()
    };
    let plot = &plots[0];
    let names: Vec<&str> = plot.series.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["mu* strip", "mu* wide", "mu* narrow"]);
    let dim_of = |i: usize| -> usize {
        (plot.dim.iter())
            .filter(|(j, _)| *j == i)
            .map(|(_, d)| d.points.len())
            .sum()
    };
    assert_eq!(dim_of(0), 0);
    assert_eq!(dim_of(1), plot.series[1].points.len());
    let s = screen(&app, 120, 40, PLAIN);
    assert!(s.contains(",, mu* wide: fails over the whole range"), "{s}");
    assert!(s.contains(",, no answer at P >= 1.70 kN/m"), "{s}");
}
