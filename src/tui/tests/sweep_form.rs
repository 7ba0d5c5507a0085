//! The sweep and map form (`v`, `M`): its keys through `update` (pure), refusing what is not
//! allowed and saying what is, typed values replacing the field's, and the default ranges of
//! every bundled preset accepted and run.

use ratatui::crossterm::event::KeyCode;

use super::explore::explore_commands;
use super::*;
use crate::tui::app::Mode;
use crate::tui::sweep_state::View;

#[test]
fn v_opens_a_form_that_refuses_what_is_not_allowed() {
    let mut app = solved("polymer-coating.toml");
    assert!(press(&mut app, KeyCode::Char('v')).is_empty());
    let Mode::Form(form) = &app.ui.mode else {
        panic!("{:?}", app.ui.mode)
    };
    // the default: mu* against the load, a decade either side of it
    assert_eq!(form.axes[0].key.to_string(), "plane.load");
    assert_eq!(form.quantity.to_string(), "mu_star");
    // the parameter row: → takes the next numeric input of the problem
    press(&mut app, KeyCode::Right);
    let Mode::Form(form) = &app.ui.mode else {
        panic!()
    };
    assert_ne!(form.axes[0].key.to_string(), "plane.load");
    // from = -1 for k (past E, nu, h, mu, tau0, tau_max): refused, saying what is allowed, the
    // form still open
    press(&mut app, KeyCode::Left);
    for _ in 0..7 {
        press(&mut app, KeyCode::Right);
    }
    let Mode::Form(form) = &app.ui.mode else {
        panic!()
    };
    let key = form.axes[0].key;
    press(&mut app, KeyCode::Down);
    for _ in 0..20 {
        press(&mut app, KeyCode::Backspace);
    }
    type_text(&mut app, "-1");
    let cmds = press(&mut app, KeyCode::Enter);
    assert_eq!(explore_commands(&cmds), 0);
    assert!(matches!(app.ui.mode, Mode::Form(_)));
    let message = app.ui.message.clone().unwrap();
    assert!(
        message.error && message.text.contains("allowed"),
        "{key}: {}",
        message.text
    );
    // a valid range shows the sweep and asks the explorer for it
    for _ in 0..2 {
        press(&mut app, KeyCode::Backspace);
    }
    let value = app.doc.preset.get(key).unwrap();
    type_text(&mut app, &format!("{}", value / 2.0));
    let cmds = press(&mut app, KeyCode::Enter);
    assert_eq!(app.ui.mode, Mode::Normal);
    assert_eq!(app.explore.view, Some(View::Sweep));
    assert_eq!(explore_commands(&cmds), 1);
    assert_eq!(app.explore.curve.as_ref().unwrap().axis.key, key);
    // an edit of an input asks again (the newer request cancels the older one's work)
    let cmds = press(&mut app, KeyCode::Right);
    assert_eq!(explore_commands(&cmds), 1);
    // Tab goes back to the charts; nothing more is asked
    let cmds = press(&mut app, KeyCode::Tab);
    assert_eq!(app.explore.view, None);
    assert_eq!(explore_commands(&cmds), 0);
}

#[test]
fn esc_leaves_the_form_and_the_view_unchanged() {
    let mut app = solved("polymer-coating.toml");
    press(&mut app, KeyCode::Char('v'));
    let cmds = press(&mut app, KeyCode::Esc);
    assert_eq!(app.ui.mode, Mode::Normal);
    assert_eq!(app.explore.view, None);
    assert_eq!(explore_commands(&cmds), 0);
}

#[test]
fn the_default_ranges_are_accepted_and_the_command_runs_the_sweep_on_screen() {
    // every numeric input of every bundled preset: the v form opens on a range that Enter
    // accepts as shown, and e names `--vary` ends that read back to that very sweep, in at most
    // 12 significant digits (units::CLEAN_DIGITS) - no 0.4999999999999999 nor 1.0000000000000002e-6
    for b in crate::preset::BUNDLED {
        let mut app = app(b.file);
        let count = crate::tui::sweep_shown::parameters(&app.doc.preset).len();
        for n in 0..count {
            press(&mut app, KeyCode::Char('v'));
            for _ in 0..n {
                press(&mut app, KeyCode::Right);
            }
            let Mode::Form(form) = &app.ui.mode else {
                panic!("{}: {:?}", b.file, app.ui.mode)
            };
            let draft = form.axes[0].clone();
            press(&mut app, KeyCode::Enter);
            assert_eq!(
                app.ui.mode,
                Mode::Normal,
                "{} {}: from {} to {}: {:?}",
                b.file,
                draft.key,
                draft.from.text(),
                draft.to.text(),
                app.ui.message
            );
            let shown = app.explore.curve.as_ref().unwrap().axis;
            press(&mut app, KeyCode::Char('e'));
            let said = app.ui.message.clone().unwrap().text;
            let vary = said.split("--vary ").nth(1).expect(&said);
            let vary = vary.split_whitespace().next().unwrap();
            let back = crate::sweeps::Axis::parse(&app.doc.preset, vary, 1).unwrap();
            assert_eq!(back, shown, "{}: {vary}", b.file);
            let (_, range) = vary.split_once('=').unwrap();
            for end in range.split(':').take(2) {
                assert!(significant_digits(end) <= 12, "{}: {vary}", b.file);
            }
        }
    }
}

#[test]
fn typing_into_a_sweep_field_replaces_its_value_at_a_visible_cursor() {
    let mut app = app("polymer-coating.toml");
    press(&mut app, KeyCode::Char('v'));
    press(&mut app, KeyCode::Down);
    let Mode::Form(form) = &app.ui.mode else {
        panic!()
    };
    let proposed = form.axes[0].from.text().to_string();
    assert!(screen(&app, 80, 24, PLAIN).contains(&format!("[{proposed}]_")));
    for c in "0.1".chars() {
        press(&mut app, KeyCode::Char(c));
    }
    press(&mut app, KeyCode::Left);
    press(&mut app, KeyCode::Char('5'));
    let Mode::Form(form) = &app.ui.mode else {
        panic!()
    };
    assert_eq!(form.axes[0].from.text(), "0.51");
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains("0.5|1"), "{s}");
}

fn significant_digits(text: &str) -> usize {
    let mantissa = text.split(['e', 'E']).next().unwrap_or("");
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    digits.trim_start_matches('0').trim_end_matches('0').len()
}
