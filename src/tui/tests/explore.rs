//! The sweep chart: the requests following the inputs and the sweep's screens (the sweep and
//! map form's own tests are in `sweep_form`, the regime map's in `regime_map`).

use std::sync::atomic::AtomicBool;

use crate::engine::sweep_worker::{SweepAnswer, explore};
use ratatui::crossterm::event::KeyCode;

use super::*;
use crate::tui::sweep_state::View;

/// Computes the explorer's requests among `commands` as its thread would (every map pass, then
/// the end) and delivers the answers; returns the commands the deliveries give.
pub(super) fn explored(app: &mut App, commands: &[Command]) -> Vec<Command> {
    explored_seen(app, commands, &mut |_| {})
}

/// `explored`, showing the app to `seen` after each answer but the last (a map refining).
pub(super) fn explored_seen(
    app: &mut App,
    commands: &[Command],
    seen: &mut dyn FnMut(&App),
) -> Vec<Command> {
    let mut out = Vec::new();
    for c in commands {
        let Command::Explore(generation, request) = c else {
            continue;
        };
        let request = std::sync::Arc::new((**request).clone());
        let answer = |explored, complete| SweepAnswer {
            generation: *generation,
            request: request.clone(),
            explored,
            complete,
        };
        let mut passes = Vec::new();
        let done = explore(&request, &AtomicBool::new(false), &mut |pass| {
            passes.push(answer(pass, false))
        })
        .expect("not cancelled");
        for a in passes {
            out.extend(update(app, Msg::Explored(Box::new(a))));
            seen(app);
        }
        out.extend(update(app, Msg::Explored(Box::new(answer(done, true)))));
    }
    out
}

pub(super) fn explore_commands(cmds: &[Command]) -> usize {
    cmds.iter()
        .filter(|c| matches!(c, Command::Explore(..)))
        .count()
}

#[test]
fn a_preset_with_an_explore_section_opens_on_its_sweep() {
    let mut app = app("coating-thickness-sweep.toml");
    let cmds = app.start();
    assert_eq!(app.explore.view, Some(View::Sweep));
    assert_eq!(explore_commands(&cmds), 1);
    let map = self::app("friction-or-wear-map.toml");
    assert_eq!(map.explore.view, Some(View::Map));
    let plain = self::app("polymer-coating.toml");
    assert_eq!(plain.explore.view, None);
}

#[test]
fn sweep_screens() {
    let mut app = app("coating-thickness-sweep.toml");
    let cmds = app.start();
    settle(&mut app, cmds.clone());
    explored(&mut app, &cmds);
    let small = screen(&app, 80, 24, PLAIN);
    // at 80x24 the status folds to four lines and the lesson to one: 6 rows from the top tick
    // to the x axis (the x title has a row of its own, so that the labels reach 10m, the
    // range's end)
    let lines: Vec<&str> = small.lines().collect();
    let top = lines.iter().position(|l| l.contains('┤')).unwrap();
    let axis = lines.iter().position(|l| l.contains(" └")).unwrap();
    assert!(axis - top >= 6, "{small}");
    assert!(small.contains(crate::tui::view::sweep::LESSON_ELSEWHERE));
    // without colour each model's failing part has its own mark, named in the legend
    assert!(
        small.contains(",, wide fails") && small.contains("'' narrow fails"),
        "{small}"
    );
    insta::assert_snapshot!("sweep_80x24", small);
    insta::assert_snapshot!("sweep_120x40", screen(&app, 120, 40, COLOUR));
    insta::assert_snapshot!("sweep_ascii_80x24", screen(&app, 80, 24, ASCII));
    press(&mut app, KeyCode::Char('x'));
    insta::assert_snapshot!("sweep_cursor_120x40", screen(&app, 120, 40, PLAIN));
}

#[test]
fn one_legend_entry_for_the_dim_parts_of_several_models_takes_no_models_colour() {
    // coating-thickness-sweep in colour: the wide and the narrow model both fail somewhere,
    // named once ("dim: the model's validity check fails"); its sample takes no model's
    // colour, since the dim parts are of both models
    let mut app = app("coating-thickness-sweep.toml");
    let cmds = app.start();
    settle(&mut app, cmds.clone());
    explored(&mut app, &cmds);
    let mut terminal = Terminal::new(TestBackend::new(80, 24)).unwrap();
    terminal.draw(|f| view(&app, COLOUR, f)).unwrap();
    let buffer = terminal.backend().buffer();
    let text = terminal.backend().to_string();
    let row = text
        .lines()
        .position(|l| l.contains("── dim: the model"))
        .unwrap();
    let line: Vec<char> = text
        .lines()
        .nth(row)
        .unwrap()
        .trim_matches('"')
        .chars()
        .collect();
    let column = (0..line.len())
        .find(|&c| line[c..].starts_with(&['─', '─', ' ', 'd']))
        .unwrap();
    let sample = &buffer[(column as u16, row as u16)];
    assert_eq!(sample.fg, ratatui::style::Color::Reset, "{sample:?}");
    assert!(sample.modifier.contains(ratatui::style::Modifier::DIM));
}

#[test]
fn sweep_screens_in_groups() {
    let mut app = app("coating-thickness-sweep.toml");
    let cmds = app.start();
    settle(&mut app, cmds.clone());
    explored(&mut app, &cmds);
    press(&mut app, KeyCode::Char('D'));
    let big = screen(&app, 120, 40, PLAIN);
    assert!(big.contains("(a+b)/h") && !big.contains("h [m]"), "{big}");
    insta::assert_snapshot!("sweep_groups_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("sweep_groups_120x40", big);
    press(&mut app, KeyCode::Char('x'));
    let cursor = screen(&app, 120, 40, PLAIN);
    assert!(cursor.contains("cursor (a+b)/h =") && cursor.contains("(strip: h = "));
    insta::assert_snapshot!("sweep_groups_cursor_120x40", cursor);
    // at 80x24 the status folds to four lines, one per curve: the swept input is on the
    // cursor's own line, not cut off after the curves
    let small = screen(&app, 80, 24, PLAIN);
    let line = small
        .lines()
        .find(|l| l.contains("cursor (a+b)/h ="))
        .unwrap();
    assert!(line.contains("(strip: h = "), "{small}");
    insta::assert_snapshot!("sweep_groups_cursor_80x24", small);
}

/// The significant digits of a number as written ("0.0035" 2, "2.5e-10" 2, "-3.14159265359" 12).

#[test]
fn the_cursor_starts_at_the_operating_point() {
    use crate::tui::charts::{Chart, PlaneChart, SpatialChart};
    // mu* against load: at the preset's load, P = 5 kN/m, where the curve of the preset's model
    // reads the operating point's own mu* (the status line "mu* = 0.299822 (mu 0.3)")
    let mut app = app("polymer-coating.toml");
    app.ui.chart = Chart::Plane(PlaneChart::MuStar);
    let cmds = app.start();
    settle(&mut app, cmds);
    press(&mut app, KeyCode::Char('x'));
    let s = screen(&app, 80, 24, PLAIN);
    assert!(
        s.contains("cursor P = 5.00 kN/m:") && s.contains("mu* wide = 0.299822"),
        "{s}"
    );
    assert!(s.contains("mu* = 0.299822 (mu 0.3)"), "{s}");
    // a sweep: at the swept input's value, h = 100 um (coating-thickness-sweep.toml's thickness)
    let mut sweep = self::app("coating-thickness-sweep.toml");
    let cmds = sweep.start();
    settle(&mut sweep, cmds.clone());
    explored(&mut sweep, &cmds);
    press(&mut sweep, KeyCode::Char('x'));
    let s = screen(&sweep, 120, 40, PLAIN);
    assert!(s.contains("cursor h = 100 um:"), "{s}");
    // amplitudes against time: at the preset's time, t = 0 (dispersion.toml)
    let mut history = self::app("dispersion.toml");
    history.ui.chart = Chart::Spatial(SpatialChart::History);
    let cmds = history.start();
    settle(&mut history, cmds);
    press(&mut history, KeyCode::Char('x'));
    let s = screen(&history, 120, 40, PLAIN);
    assert!(s.contains("cursor t = 0 s:"), "{s}");
}

#[test]
fn e_in_a_sweep_names_the_file_only_while_it_holds_what_is_shown() {
    let mut app = app("coating-thickness-sweep.toml");
    app.doc.path = Some("presets/coating-thickness-sweep.toml".into());
    press(&mut app, KeyCode::Char('e'));
    let said = app.ui.message.clone().unwrap().text;
    assert!(
        // the strip model's: the command solves the preset's model, not the overlaid ones
        said.starts_with("the strip curve as CSV: wearlab sweep presets/coating-thickness-sweep.toml --vary material.thickness=0.000001:0.01:40:log"),
        "{said}"
    );
    app.doc.dirty = true;
    press(&mut app, KeyCode::Char('e'));
    let said = app.ui.message.clone().unwrap().text;
    assert!(said.contains("wearlab sweep PRESET (s saves"), "{said}");
}

#[test]
fn the_help_explains_the_view_on_screen() {
    // in the sweep or map view the help's chart section is about that view, not about the chart
    // under it (not "This chart (1/4): pressure and shear" while the sweep is shown)
    let text = |app: &App| {
        crate::tui::view::popups::help_lines(app, PLAIN, 78)
            .iter()
            .map(|l| l.to_string())
            .collect::<Vec<_>>()
            .join("\n")
    };
    let sweep = app("coating-thickness-sweep.toml");
    let s = text(&sweep);
    assert!(
        s.contains("This view: the sweep chart (v)") && !s.contains("This chart"),
        "{s}"
    );
    let map = app("friction-or-wear-map.toml");
    assert!(text(&map).contains("This view: the regime map (M)"));
    let charts = app("polymer-coating.toml");
    assert!(text(&charts).contains("This chart (1/6): pressure and shear"));
}

#[test]
fn the_legend_names_only_the_dim_parts_that_show() {
    // polymer-coating's mu*(P) sweep: the narrow curve is off scale (0.3..0.3003 above the wide
    // one's range), its failing part with it; the legend named it (",, narrow fails") all the same
    let mut app = solved("polymer-coating.toml");
    press(&mut app, KeyCode::Char('v'));
    let cmds = press(&mut app, KeyCode::Enter);
    explored(&mut app, &cmds);
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains("mu* narrow: off scale"), "{s}");
    assert!(!s.contains("narrow fails"), "{s}");
}

#[test]
fn a_sweep_of_mu_star_against_mu_draws_the_diagonal_mu_star_equals_mu() {
    let preset = bundled("polymer-coating.toml");
    let spec = crate::sweeps::curve::CurveSpec {
        axis: crate::sweeps::Axis::parse(&preset, "friction.coefficient=0.1:0.9:5", 5).unwrap(),
        quantity: crate::sweeps::QuantityKey::parse("mu_star", &preset).unwrap(),
        models: vec![crate::physics::plane::Model::Wide],
    };
    let curve = crate::sweeps::curve::curve(&preset, &spec, &AtomicBool::new(false)).unwrap();
    let mu = preset.friction.coefficient;
    let crate::tui::charts::Figure::Plots(plots) =
        crate::tui::charts::sweep::figure(preset.problem, mu, &spec, &curve, false)
    else {
        panic!()
    };
    let plot = &plots[0];
    let diagonal = plot.series.iter().find(|s| s.name == "mu* = mu").unwrap();
    assert_eq!(diagonal.points.len(), 5);
    assert!(diagonal.points.iter().all(|&(x, y)| x == y));
    assert_eq!(diagonal.points[0].0, 0.1);
    // no horizontal line at the preset's own mu, which this chart sweeps away from
    assert!(plot.y_marks.is_empty(), "{:?}", plot.y_marks);
}
