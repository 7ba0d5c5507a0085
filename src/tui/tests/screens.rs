//! Screen snapshots, each read as a user would before it was accepted.

use ratatui::crossterm::event::KeyCode;

use super::*;
use crate::tui::app::Mode;
use crate::tui::charts::{Chart, PlaneChart, SpatialChart};
use crate::tui::view::popups::help_lines;

#[test]
fn plane_screens() {
    let mut app = solved("polymer-coating.toml");
    insta::assert_snapshot!("plane_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("plane_120x40", screen(&app, 120, 40, PLAIN));
    press(&mut app, KeyCode::Tab);
    let cmds = press(&mut app, KeyCode::Tab);
    settle(&mut app, cmds);
    assert_eq!(app.ui.chart, Chart::Plane(PlaneChart::MuStar));
    insta::assert_snapshot!("plane_mu_star_120x40", screen(&app, 120, 40, PLAIN));
    insta::assert_snapshot!("plane_mu_star_ascii_80x24", screen(&app, 80, 24, ASCII));
}

#[test]
fn spatial_screens() {
    let mut app = solved("dispersion.toml");
    insta::assert_snapshot!("spatial_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("spatial_120x40", screen(&app, 120, 40, PLAIN));
    app.ui.chart = Chart::Spatial(SpatialChart::History);
    insta::assert_snapshot!("spatial_history_120x40", screen(&app, 120, 40, PLAIN));
    // contact-lost.toml: tests/partial.rs
    let mut drift = solved("rubber-backward-drift.toml");
    drift.ui.chart = Chart::Spatial(SpatialChart::Dispersion);
    insta::assert_snapshot!("spatial_dispersion_120x40", screen(&drift, 120, 40, PLAIN));
}

#[test]
fn many_harmonics_show_how_many_more_and_follow_the_selection() {
    let mut app = app("dispersion.toml");
    for _ in 0..5 {
        press(&mut app, KeyCode::Char('+'));
    }
    let cmds = app.start();
    settle(&mut app, cmds);
    let s = screen(&app, 80, 24, PLAIN);
    // 80x24: the certified minimum without its bound, -41.8 kPa (below 0 under a complete
    // contact it proves nothing), and room for three lines under the header: two rows and the
    // count of the others with the key that shows them, on its own line (the header has no
    // room for it)
    assert!(!s.contains("lower bound"), "{s}");
    assert!(s.contains("│+7 more: i "), "{s}");
    assert!(s.contains("│  1 1.571 "), "{s}");
    select(&mut app, "A", Some(8));
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains("│+7 more: i "), "{s}");
    assert!(s.contains("│  8 ") && s.contains("│  9 "), "{s}");
    insta::assert_snapshot!("spatial_nine_harmonics_80x24", s);
}

#[test]
fn help_picker_choices_error_and_too_small() {
    let mut app = solved("polymer-coating.toml");
    press(&mut app, KeyCode::Char('?'));
    insta::assert_snapshot!("help_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("help_120x40", screen(&app, 120, 40, PLAIN));
    press(&mut app, KeyCode::Esc);
    let Msg::PresetsListed(entries) = crate::tui::effects::list_presets(&Places::default()) else {
        panic!()
    };
    update(&mut app, Msg::PresetsListed(entries));
    insta::assert_snapshot!("picker_80x24", screen(&app, 80, 24, PLAIN));
    // at 80x24 not every preset fits: the picker says that more follow
    let count = crate::tui::effects::list_presets(&Places::default());
    let Msg::PresetsListed(listed) = count else {
        panic!()
    };
    let n = listed.len();
    for _ in 1..n {
        press(&mut app, KeyCode::Down);
    }
    let s = screen(&app, 80, 24, PLAIN);
    // nine rows of the list at 80x24: the presets and the heading above them
    assert!(
        s.contains(&format!(
            "rows {}-{} of {} (more above)",
            n - 7,
            n + 1,
            n + 1
        )),
        "{s}"
    );
    // End and Home go to the last and the first at once
    press(&mut app, KeyCode::Home);
    assert!(screen(&app, 80, 24, PLAIN).contains("(more below)"));
    press(&mut app, KeyCode::End);
    assert!(screen(&app, 80, 24, PLAIN).contains("(more above)"));
    // the bundled presets and their heading outgrow a 120x40 list too, by fewer rows
    let tall = screen(&app, 120, 40, PLAIN);
    assert!(
        tall.contains(&format!("of {} (more above)", n + 1))
            && !tall.contains(&format!("rows {}-", n - 7)),
        "{tall}"
    );
    for _ in 1..n {
        press(&mut app, KeyCode::Up);
    }
    press(&mut app, KeyCode::Esc);
    select(&mut app, "model", None);
    press(&mut app, KeyCode::Enter);
    insta::assert_snapshot!("choices_80x24", screen(&app, 80, 24, PLAIN));
    press(&mut app, KeyCode::Esc);
    select(&mut app, "h", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "-3 mm");
    press(&mut app, KeyCode::Enter);
    insta::assert_snapshot!("error_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("too_small_60x20", screen(&app, 60, 20, PLAIN));
}

#[test]
fn the_help_explains_every_status_symbol_of_both_problems() {
    for file in ["polymer-coating.toml", "dispersion.toml"] {
        let app = solved(file);
        let help: String = help_lines(&app, PLAIN, 76)
            .iter()
            .map(|l| format!("{l}\n"))
            .collect();
        let status = screen(&app, 120, 40, PLAIN);
        for symbol in [
            "a = ",
            "b = ",
            "theta",
            "Q2",
            "psi",
            "mu*",
            "I-J residual",
            "kh",
            "1/beta",
            " c ",
            "phi",
            "p_min",
            "(a+b)/h",
        ] {
            if status.contains(symbol) {
                let name = symbol
                    .trim()
                    .trim_end_matches(" =")
                    .trim_end_matches('=')
                    .trim();
                assert!(
                    help.contains(&format!("  {name}"))
                        || help.contains(&format!("{name},"))
                        || help.contains(&format!(", {name}")),
                    "{file}: {name} not in the help"
                );
            }
        }
    }
}

#[test]
fn every_help_line_fits_and_long_symbols_stand_above_their_text() {
    // no help line is cut (e.g. "partial contact (fraction f) [-]the contact, solved on the
    // nodes of the period cel"): a long symbol stands on a line above its text
    for file in ["polymer-coating.toml", "contact-lost.toml"] {
        let app = app(file);
        for width in [76, 98] {
            let help: Vec<String> = help_lines(&app, PLAIN, width)
                .iter()
                .map(|l| l.to_string())
                .collect();
            assert!(help.iter().all(|l| l.chars().count() <= width), "{file}");
            if file != "contact-lost.toml" {
                continue;
            }
            let at = |text: &str| help.iter().position(|l| l.contains(text)).unwrap();
            let head = at("  complete after t (simulated) [s]");
            assert_eq!(help[head].trim(), "complete after t (simulated) [s]");
            assert!(
                help[head + 1]
                    .trim_start()
                    .starts_with("when the simulated")
            );
        }
    }
}

#[test]
fn a_long_message_takes_two_lines_and_is_never_cut_mid_word() {
    // typing 10um for E gives a message longer than 80 columns: it wraps, never cut mid-word
    let mut app = solved("polymer-coating.toml");
    select(&mut app, "E", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "10um");
    press(&mut app, KeyCode::Enter);
    let message = app.ui.message.as_ref().unwrap().text.clone();
    for (w, h) in [(80, 24), (120, 40)] {
        let s = screen(&app, w, h, PLAIN);
        let rows: Vec<&str> = s.lines().collect();
        let shown: String = rows[h as usize - 3..h as usize - 1]
            .iter()
            .map(|r| r.trim_matches('"').trim())
            .collect::<Vec<_>>()
            .join(" ");
        assert!(shown.ends_with(message.as_str()), "{w}x{h}:\n{s}");
        if w == 80 {
            insta::assert_snapshot!("long_message_80x24", s);
        }
    }
}

/// A chart mode's screen, at 80x24 and 120x40.
fn both(name: &str, app: &App, style: RenderOptions) {
    insta::assert_snapshot!(format!("{name}_80x24"), screen(app, 80, 24, style));
    insta::assert_snapshot!(format!("{name}_120x40"), screen(app, 120, 40, style));
}

#[test]
fn cursor_pin_expand_log_y_and_ascii_markers() {
    // the cursor, three points right of the middle: the status reads both curves there
    let mut app = solved("polymer-coating.toml");
    press(&mut app, KeyCode::Char('x'));
    for _ in 0..3 {
        press(&mut app, KeyCode::Char(']'));
    }
    both("mode_cursor", &app, PLAIN);
    // a pin, then a heavier load: the pinned curves drawn with their number, named by the load
    press(&mut app, KeyCode::Char('x'));
    press(&mut app, KeyCode::Char('c'));
    select(&mut app, "P", None);
    let cmds = press(&mut app, KeyCode::Char('L'));
    settle(&mut app, cmds);
    both("mode_pin", &app, PLAIN);
    // the map expanded: the form gives its columns, the map takes the height
    let mut map = solved("jgh-egg-box.toml");
    press(&mut map, KeyCode::Char('f'));
    // at 80x24 the status keeps three lines: no room for a harmonic's row, so no header over
    // nothing ("n k [rad/m] 1/beta ... +1 more"), as in the groups status
    let small = screen(&map, 80, 24, PLAIN);
    assert!(
        !small.contains("1/beta") && !small.contains("more"),
        "{small}"
    );
    both("mode_expand", &map, PLAIN);
    // a(P) of the Hertz check on log axes: a straight line of slope 1/2
    let mut hertz = solved("hertz-check.toml");
    hertz.ui.chart = Chart::Plane(PlaneChart::Edges);
    press(&mut hertz, KeyCode::Char('y'));
    both("mode_log_y", &hertz, PLAIN);
    // four amplitudes and mu*(t) without colour: each curve its own character
    let mut history = solved("dispersion.toml");
    history.ui.chart = Chart::Spatial(SpatialChart::History);
    let cmds = history.start();
    settle(&mut history, cmds);
    both("mode_ascii_markers", &history, ASCII);
}

#[test]
fn i_shows_the_whole_description_and_scrolls_it() {
    let mut app = app("contact-lost.toml");
    app.doc.path = Some("presets/contact-lost.toml".into());
    app.doc.source = Some("presets/contact-lost.toml".into());
    // with no message, the bottom line names the preset beside its file
    app.ui.message = None;
    let s = screen(&app, 120, 40, PLAIN);
    assert!(
        s.contains(
            "Running-in: partial contact worn to complete contact (presets/contact-lost.toml)"
        ),
        "{s}"
    );
    press(&mut app, KeyCode::Char('i'));
    assert_eq!(app.ui.mode, Mode::About(0));
    insta::assert_snapshot!("about_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("about_120x40", screen(&app, 120, 40, PLAIN));
    // a description longer than the screen scrolls, and stops where its last line is at the
    // bottom
    let long = format!(
        "{}\nTry: the end of it.",
        app.doc.preset.description.repeat(2)
    );
    app.doc.preset.description = long;
    app.ui.screen = ratatui::layout::Rect::new(0, 0, 80, 24);
    press(&mut app, KeyCode::PageDown);
    press(&mut app, KeyCode::PageDown);
    let last = crate::tui::view::popups::about_last(&app, app.ui.screen);
    assert!(last > 0);
    assert_eq!(app.ui.mode, Mode::About(last));
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains("Try: the end of it."), "{s}");
    press(&mut app, KeyCode::Esc);
    assert_eq!(app.ui.mode, Mode::Normal);
}

#[test]
fn a_window_leaves_the_message_rows_free() {
    // rubber-backward-drift's name and file take two rows at 80x24: under `i` the name stays visible
    let mut app = solved("rubber-backward-drift.toml");
    app.doc.path = Some("presets/rubber-backward-drift.toml".into());
    press(&mut app, KeyCode::Char('i'));
    let s = screen(&app, 80, 24, PLAIN);
    let rows: Vec<&str> = s.lines().collect();
    assert!(rows[21].contains("Thin rubber layer"), "{s}");
    assert!(
        rows[22].contains("(presets/rubber-backward-drift.toml)"),
        "{s}"
    );
}
