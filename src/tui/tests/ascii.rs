//! `--ascii`: every cell of every kind of screen of every bundled preset is ASCII (borders,
//! ticks, marks, arrows, keys), with and without colour, at 80x24 and 120x40, the sweep and map
//! views also while computing and refining; no arrow that reads as a key ("v more"); no sign
//! among the shades.

use ratatui::crossterm::event::KeyCode;

use super::explore::{explored, explored_seen};
use super::*;
use crate::tui::app::Mode;

const ASCII_COLOUR: RenderOptions = RenderOptions {
    ascii: true,
    color: true,
    truecolor: false,
};

/// Panics naming the screen and the first cell that is not ASCII, or the first arrow that
/// reads as a key ("v more": the `v` key is the sweep's).
fn all_ascii(app: &App, what: &str) {
    for (w, h) in [(80, 24), (120, 40)] {
        for options in [ASCII, ASCII_COLOUR] {
            let mut terminal = Terminal::new(TestBackend::new(w, h)).unwrap();
            terminal.draw(|f| view(app, options, f)).unwrap();
            let buf = terminal.backend().buffer();
            if let Some(i) = buf.content.iter().position(|c| !c.symbol().is_ascii()) {
                let (x, y) = buf.pos_of(i);
                panic!(
                    "{what} at {w}x{h} ({options:?}): {:?} at column {x}, row {y}\n{}",
                    buf.content[i].symbol(),
                    terminal.backend()
                );
            }
            let screen = terminal.backend().to_string();
            let arrow = ["v", "^", "^v"].map(|a| format!(" {a} "));
            if let Some(row) = screen
                .lines()
                .find(|r| r.contains("more") && arrow.iter().any(|a| r.contains(a.as_str())))
            {
                panic!("{what} at {w}x{h} ({options:?}): an arrow read as a key: {row}");
            }
        }
    }
}

/// Every chart, the cursor, a pin, the log axis, the popups, the prompts, the sweep and map
/// forms and views, and the groups of the problem shown.
fn every_screen_of_the_problem(app: &mut App, file: &str) {
    let (_, charts) = app.ui.chart.position();
    for n in 0..charts {
        let chart = format!("{file} chart {}", n + 1);
        all_ascii(app, &chart);
        for k in ['x', 'c', 'y'] {
            press(app, KeyCode::Char(k));
        }
        all_ascii(app, &format!("{chart} with cursor, pin, log y"));
        for k in ['x', 'C', 'y'] {
            press(app, KeyCode::Char(k));
        }
        let cmds = press(app, KeyCode::Tab);
        settle(app, cmds);
    }
    for (k, what) in [
        ('?', "help"),
        ('i', "about"),
        ('o', "picker"),
        ('s', "save as"),
    ] {
        press(app, KeyCode::Char(k));
        all_ascii(app, &format!("{file} {what}"));
        press(app, KeyCode::Esc);
    }
    press(app, KeyCode::Enter);
    all_ascii(app, &format!("{file} editing a value"));
    press(app, KeyCode::Esc);
    press(app, KeyCode::Char('D'));
    all_ascii(app, &format!("{file} groups"));
    press(app, KeyCode::Char('D'));
    // a coarse grid and a few points: the same screens, quicker to compute
    app.doc.preset.spatial.grid = app.doc.preset.spatial.grid.min(16);
    for (k, what) in [('v', "sweep"), ('M', "map")] {
        press(app, KeyCode::Char(k));
        all_ascii(app, &format!("{file} {what} form"));
        // a few points: the screen is the same kind, quicker to compute
        if let Mode::Form(form) = &mut app.ui.mode {
            for axis in &mut form.axes {
                axis.points = "3".into();
            }
        }
        let cmds = press(app, KeyCode::Enter);
        all_ascii(app, &format!("{file} {what} computing"));
        explored_seen(app, &cmds, &mut |app| {
            all_ascii(app, &format!("{file} {what} refining"))
        });
        all_ascii(app, &format!("{file} {what}"));
        press(app, KeyCode::Char('x'));
        press(app, KeyCode::Char('D'));
        all_ascii(app, &format!("{file} {what} in groups with the cursor"));
        press(app, KeyCode::Char('D'));
        press(app, KeyCode::Char('x'));
        // back to the charts
        press(app, KeyCode::Tab);
    }
}

#[test]
fn with_ascii_every_cell_of_every_screen_is_ascii() {
    for b in crate::preset::BUNDLED {
        let mut app = app(b.file);
        let cmds = app.start();
        settle(&mut app, cmds.clone());
        explored(&mut app, &cmds);
        all_ascii(&app, b.file);
        if app.explore.view.is_some() {
            press(&mut app, KeyCode::Tab);
        }
        every_screen_of_the_problem(&mut app, b.file);
        let cmds = press(&mut app, KeyCode::Char('p'));
        settle(&mut app, cmds);
        every_screen_of_the_problem(&mut app, b.file);
    }
}

#[test]
fn no_ascii_shade_reads_as_a_sign_or_a_mark() {
    // '+' and '-' read as a sign or a tick beside a bar's value; '~', 'o', 'X', '|' and the
    // letters are drawn over the maps (no contact, the preset's point, the cursor, the lines)
    for c in crate::tui::view::theme::ASCII_SHADES {
        assert!(
            !"+-~oX|".contains(c) && !c.is_ascii_alphanumeric(),
            "shade {c:?}"
        );
    }
}
