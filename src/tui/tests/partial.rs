//! Partial contact and its running-in in the explorer: the screens, each read as a student
//! would read it; time replaying the cached running-in; progress while it is
//! stepped; the zones out of contact drawn apart, with and without colour.

use crate::engine::{Engine, Output, Progress};
use ratatui::crossterm::event::KeyCode;
use ratatui::style::Color;

use super::*;
use crate::tui::charts::{Chart, Figure, NoFigure, SpatialChart};
use crate::tui::view::popups::help_lines;

/// The app showing `chart`, solved.
pub(super) fn on(app: &App, chart: SpatialChart) -> App {
    let mut app = app.clone();
    app.ui.chart = Chart::Spatial(chart);
    // the mu*(pbar) chart asks for its curve
    let cmds = app.start();
    settle(&mut app, cmds);
    app
}

#[test]
fn partial_contact_screens() {
    let lost = solved("contact-lost.toml");
    for (name, style) in [("plain", PLAIN), ("ascii", ASCII)] {
        insta::assert_snapshot!(
            format!("lost_map_{name}_80x24"),
            screen(&lost, 80, 24, style)
        );
        insta::assert_snapshot!(
            format!("lost_map_{name}_120x40"),
            screen(&lost, 120, 40, style)
        );
    }
    let history = on(&lost, SpatialChart::History);
    insta::assert_snapshot!("lost_history_80x24", screen(&history, 80, 24, PLAIN));
    insta::assert_snapshot!("lost_history_120x40", screen(&history, 120, 40, PLAIN));
    let mu = on(&lost, SpatialChart::MuStar);
    insta::assert_snapshot!("lost_mu_star_120x40", screen(&mu, 120, 40, PLAIN));
    // the rubber lesson at t = 0 and at 3 ks: the crests of p and U in the legend move back
    let mut rubber = on(&solved("rubber-running-in.toml"), SpatialChart::Line);
    insta::assert_snapshot!("rubber_line_80x24", screen(&rubber, 80, 24, PLAIN));
    rubber.doc.preset.spatial.time = 3000.0;
    let cmds = rubber.start();
    settle(&mut rubber, cmds);
    insta::assert_snapshot!("rubber_line_3ks_120x40", screen(&rubber, 120, 40, PLAIN));
}

#[test]
fn the_status_and_the_cursor_write_the_contact_fraction_alike() {
    // contact-lost.toml at t = 0: half the cell touches (`wearlab solve` gives contact.fraction
    // = 0.5); the time history's cursor starts on the operating point, t = 0
    let mut history = on(&solved("contact-lost.toml"), SpatialChart::History);
    press(&mut history, KeyCode::Char('x'));
    let s = screen(&history, 120, 40, PLAIN);
    assert!(s.contains("partial contact (fraction 0.5)"), "{s}");
    assert!(s.contains("contact fraction = 0.5 "), "{s}");
    // between two steps of the running-in, interpolated: four digits, as the status writes it
    press(&mut history, KeyCode::Char(']'));
    let s = screen(&history, 120, 40, PLAIN);
    let read = s
        .split("contact fraction = ")
        .nth(1)
        .and_then(|r| r.split_whitespace().next())
        .unwrap_or_default();
    assert!(read.len() <= 6 && read.starts_with("0."), "{read}:\n{s}");
}

#[test]
fn the_zones_out_of_contact_are_grey_and_named_beside_the_bar() {
    let lost = solved("contact-lost.toml");
    let grey = COLOUR.empty().1;
    for (w, h) in [(80, 24), (120, 40)] {
        let mut terminal = Terminal::new(TestBackend::new(w, h)).unwrap();
        terminal.draw(|f| view(&lost, COLOUR, f)).unwrap();
        let buf = terminal.backend().buffer();
        // the map's top row: half the cell is out of contact, drawn grey; the rest in viridis
        let row: Vec<_> = (0..w).map(|x| &buf[(x, 1)]).collect();
        let greys = row.iter().filter(|c| c.bg == grey).count();
        let viridis = row
            .iter()
            .filter(|c| matches!(c.bg, Color::Indexed(_)) && c.bg != grey)
            .count();
        assert!(
            greys > 10 && viridis > 10,
            "{w}x{h}: {greys} grey, {viridis}"
        );
        // grey is no band's colour
        for n in 1..=crate::tui::view::heatmap::MOST_BANDS {
            assert!(!COLOUR.bands(n).contains(&grey));
        }
        // its swatch, then its name, at the top of the words beside the bar
        let text = screen(&lost, w, h, COLOUR);
        let line = text.lines().nth(1).unwrap();
        assert!(line.contains("  no contact. "), "{line}");
        let swatch = line.find(" no contact.").unwrap();
        // the line is quoted: one column for the quote, one for the swatch
        let x = line[..swatch].chars().count() as u16 - 2;
        assert_eq!(buf[(x, 1)].bg, grey, "{line}");
    }
    // without colour: dots, `~` with --ascii, never a shade
    for (style, glyph) in [(PLAIN, '·'), (ASCII, '~')] {
        let text = screen(&lost, 80, 24, style);
        let line = text.lines().nth(1).unwrap();
        assert!(line.contains(&format!("{glyph} no contact.")), "{line}");
        assert!(line.matches(glyph).count() > 10, "{line}");
    }
}

#[test]
fn a_time_step_replays_the_cached_running_in() {
    let mut engine = Engine::new();
    let mut app = app("contact-lost.toml");
    let cmds = app.start();
    for a in answers(&mut engine, &cmds) {
        update(&mut app, Msg::Answer(Box::new(a)));
    }
    let steps = engine.counts.wear_steps;
    assert_eq!(engine.counts.running_in, 1);
    select(&mut app, "t", None);
    for _ in 0..3 {
        let cmds = press(&mut app, KeyCode::Right);
        for a in answers(&mut engine, &cmds) {
            update(&mut app, Msg::Answer(Box::new(a)));
        }
    }
    // a hundredth of the duration per step; the state replayed, nothing stepped again
    assert_eq!(
        (engine.counts.running_in, engine.counts.wear_steps),
        (1, steps)
    );
    let s = screen(&app, 80, 24, PLAIN);
    // `wearlab solve presets/contact-lost.toml --time 3` gives contact.fraction = 0.53125
    assert!(
        s.contains("partial contact (fraction 0.5313)  t = 3.00 s"),
        "{s}"
    );
    // playing does the same
    press(&mut app, KeyCode::Char(' '));
    let cmds = update(&mut app, Msg::Tick);
    for a in answers(&mut engine, &cmds) {
        update(&mut app, Msg::Answer(Box::new(a)));
    }
    assert_eq!(
        (engine.counts.running_in, engine.counts.wear_steps),
        (1, steps)
    );
    assert!(screen(&app, 80, 24, PLAIN).contains("t = 4.00 s"));
}

#[test]
fn the_running_in_shows_its_progress_and_the_state_it_has_reached() {
    let mut engine = Engine::new();
    engine.progress_every = std::time::Duration::ZERO;
    let mut preset = bundled("contact-lost.toml");
    preset.spatial.time = 40.0;
    let mut app = App::new(preset, None, Places::default());
    let cmds = app.start();
    let all = answers(&mut engine, &cmds);
    // an answer on the way to t = 40 s: the last stepped state, said to be so
    let early = all
        .iter()
        .find(|a| {
            let Output::Spatial(Ok(out)) = &a.output else {
                return false;
            };
            let c = out.cell.as_ref().unwrap();
            matches!(c.progress, Progress::Running { reached, towards: Some(_) } if reached > 10.0)
        })
        .unwrap();
    update(&mut app, Msg::Answer(Box::new(early.clone())));
    // the first step past 10 s (the steps are sized by their error estimate)
    let Output::Spatial(Ok(out)) = &early.output else {
        unreachable!("found above")
    };
    let Progress::Running { reached, .. } = out.cell.as_ref().unwrap().progress else {
        unreachable!("found above")
    };
    let at = crate::units::format_si(reached, "s");
    let s = screen(&app, 80, 24, PLAIN);
    assert!(
        s.contains(&format!("running in: t = {at} of 40.0 s")),
        "{s}"
    );
    assert!(
        s.contains(&format!("t = {at}")) && s.contains("solving…"),
        "{s}"
    );
    let Ok(Figure::Map(map)) = app.ui.chart.build(early) else {
        panic!("a map")
    };
    assert!(
        map.caption.ends_with(&format!(
            "The state at t = {at}: the running-in has not reached t = 40.0 s yet."
        )),
        "{}",
        map.caption
    );
    // past t, on to complete contact: the state at t stays
    let past = all
        .iter()
        .find(|a| {
            let Output::Spatial(Ok(out)) = &a.output else {
                return false;
            };
            let c = out.cell.as_ref().unwrap();
            matches!(c.progress, Progress::Running { towards: None, .. })
        })
        .unwrap();
    update(&mut app, Msg::Answer(Box::new(past.clone())));
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains("running in to complete contact: t = "), "{s}");
    assert!(s.contains("t = 40.0 s"), "{s}");
    update(&mut app, Msg::Answer(Box::new(all.last().unwrap().clone())));
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains("complete after t = 62.6 s (simulated)"), "{s}");
    assert!(!s.contains("solving"), "{s}");
}

#[test]
fn the_help_explains_the_partial_contact_status() {
    let app = solved("contact-lost.toml");
    let help: String = help_lines(&app, PLAIN, 76)
        .iter()
        .map(|l| format!("{l}\n"))
        .collect();
    for symbol in [
        "partial contact (fraction f)",
        "p_max",
        "running in",
        "complete after t (simulated)",
        "after complete contact",
    ] {
        assert!(help.contains(symbol), "{symbol} not in the help:\n{help}");
    }
}

#[test]
fn the_time_of_complete_contact_heads_the_rates_only_above_them() {
    // the rates of the closed form hold after complete contact: "complete after ..., then:"
    // heads their rows at both sizes (at 120 columns "after complete contact:" followed phi in
    // the header, as if it were phi's); where no row fits under it (80x24 with the message on
    // two lines) the time is said without ", then:"
    for file in ["contact-lost.toml", "rubber-running-in.toml"] {
        let mut app = solved(file);
        app.doc.path = Some(format!("presets/{file}").into());
        app.ui.message = None;
        for (w, h) in [(80, 24), (120, 40)] {
            let s = screen(&app, w, h, PLAIN);
            assert!(s.contains("complete after t = "), "{s}");
            assert!(!s.contains("phi  after"), "{s}");
            let lines: Vec<&str> = s.lines().collect();
            for (i, l) in lines.iter().enumerate() {
                if l.contains(", then:") {
                    assert!(lines[i + 1].contains("1/beta"), "{w}x{h}: {s}");
                }
            }
        }
    }
}

#[test]
fn without_a_period_cell_the_closed_form_holds_only_for_a_contact_complete_from_the_start() {
    // rubber-running-in (partial at t = 0, complete after 4.31 ks of running-in) with a second,
    // tiny harmonic of wavenumber sqrt(2) times the first: no common period, no cell
    let mut preset = bundled("rubber-running-in.toml");
    let mut second = preset.spatial.harmonics[0];
    second.amplitude = 1e-9;
    second.wavenumber_x *= std::f64::consts::SQRT_2;
    preset.spatial.harmonics.push(second);
    preset.spatial.time = 6000.0;
    let mut app = App::new(preset.clone(), None, Places::default());
    let cmds = app.start();
    let answer = answers(&mut Engine::new(), &cmds).pop().unwrap();
    let Output::Spatial(Ok(out)) = &answer.output else {
        panic!("no spatial output: {:?}", answer.output)
    };
    // the closed form at t is complete, the harmonics as given are not: neither the explorer
    // nor `wearlab solve` (the pipeline) answers with the closed form
    assert!(out.cell.is_err() && out.state.contact.complete);
    assert_eq!(out.complete_at_start, Some(false));
    assert!(!out.closed_form_holds());
    let Err(NoFigure::Error(why)) = crate::tui::charts::contact::fields(out) else {
        panic!("the closed form is drawn")
    };
    assert!(
        why.starts_with("Complete contact is lost at t = 0"),
        "{why}"
    );
    let at = preset.spatial_state_at();
    let inputs = preset.spatial_inputs();
    assert!(crate::physics::spatial::pipeline::solve(&inputs, &at, &[], false).is_err());
    update(&mut app, Msg::Answer(Box::new(answer)));
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains("Complete contact is lost at t = 0"), "{s}");
    assert!(
        s.contains("contact lost at t = 0: the closed form at t"),
        "{s}"
    );
    assert!(!s.contains("complete contact"), "{s}");
}
