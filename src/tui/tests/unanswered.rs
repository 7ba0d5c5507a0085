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

#[test]
fn the_sweep_chart_names_the_points_without_an_answer_as_the_mu_star_chart_does() {
    // hard-coating-strip's sweep (`v`, Enter): mu* against P, 50 loads from 100 N/m to 10 kN/m
    // on a log axis, P_k = 100 * 100^(k/49). `wearlab solve presets/hard-coating-strip.toml
    // --set plane.model=wide --set plane.load=...` answers at P_29 = 1526.4 N/m (exit 0) and
    // not at P_30 = 1676.8 N/m (exit 3: the contact does not contain the punch tip), so the
    // wide curve has no answer at the last 20 of the 50 loads
    let mut app = solved("hard-coating-strip.toml");
    press(&mut app, KeyCode::Char('v'));
    let cmds = press(&mut app, KeyCode::Enter);
    super::explore::explored(&mut app, &cmds);
    let words = "no answer at P >= 1.68 kN/m (20 of 50 points)";
    for (w, h) in [(80, 24), (120, 40)] {
        let s = screen(&app, w, h, PLAIN);
        assert!(s.contains(&format!(",, {words}")), "{w}x{h}\n{s}");
    }
    // the dimensionless view names them on the swept input too: they have no group
    press(&mut app, KeyCode::Char('D'));
    let s = screen(&app, 120, 40, PLAIN);
    assert!(s.contains(words), "{s}");
    // and so does its SVG (`E`), under the wide curve's name
    let cmds = press(&mut app, KeyCode::Char('E'));
    let (_, text) = exported(&cmds);
    let t = super::charts::texts(text);
    let at = t
        .iter()
        .position(|x| x == "mu* wide")
        .unwrap_or_else(|| panic!("{t:?}"));
    assert!(t[at + 1..].iter().take(2).any(|x| x == words), "{t:?}");
}
