//! The plane status's validity lines: the model holds and its measured distance from
//! the exact strip model follows the point; it does not hold and the reason is said in a few
//! words; the strip model is said to be the exact one. Each snapshot is the status panel alone,
//! to be read as a student would read it.

use super::*;
use crate::physics::plane::Model;
use crate::physics::plane::operating_point::operating_point;
use crate::tui::view::{layout, validity_status};

/// The status panel of the screen, one string per row.
pub(super) fn status(app: &App, w: u16, h: u16) -> String {
    let mut terminal = Terminal::new(TestBackend::new(w, h)).unwrap();
    terminal.draw(|f| view(app, PLAIN, f)).unwrap();
    let area = layout::areas(terminal.backend().buffer().area, false, false)
        .unwrap()
        .status;
    let buffer = terminal.backend().buffer();
    (area.top()..area.bottom())
        .map(|y| {
            let row: String = (area.left()..area.right())
                .map(|x| buffer[(x, y)].symbol())
                .collect();
            format!("{row}\n")
        })
        .collect()
}

/// A bundled preset edited, solved to the end.
fn solved_with(file: &str, edit: impl FnOnce(&mut Preset)) -> App {
    let mut preset = bundled(file);
    edit(&mut preset);
    let mut app = App::new(preset, None, Places::default());
    let commands = app.start();
    settle(&mut app, commands);
    app
}

#[test]
fn a_model_that_holds_says_how_far_it_is_from_the_exact_strip_model() {
    let app = solved("polymer-coating.toml");
    let s = status(&app, 80, 24);
    assert!(
        s.contains("valid: (a+b)/h = 0.06104; wide model holds"),
        "{s}"
    );
    assert!(s.contains("of the exact strip solution"), "{s}");
    insta::assert_snapshot!("validity_holds_80x24", s);
    insta::assert_snapshot!("validity_holds_120x40", status(&app, 120, 40));
}

#[test]
fn a_model_that_does_not_hold_says_why_in_words() {
    // the Winkler strip of thin-strip-winkler.toml made nearly incompressible: the layer is then
    // softer than Winkler's, and its contact width needs a far wider contact (criteria.rs)
    let app = solved_with("thin-strip-winkler.toml", |p| {
        p.material.poisson_ratio = 0.49
    });
    let s = status(&app, 80, 24);
    // measured against the strip model (a few milliseconds here): the measurement is the
    // verdict, said with the tolerances it is judged by and the model that holds instead
    assert!(
        s.contains("narrow: off the exact strip solution by 29.8 %"),
        "{s}"
    );
    assert!(
        s.contains("! outside the tolerances: use the strip model"),
        "{s}"
    );
    // the study's estimates give way to the measurement: neither its threshold on (a+b)/h (not
    // where the measured verdict changes) nor its bound on the friction part of mu* - mu (far
    // above the 0.4 % measured) is shown beside it
    assert!(!s.contains("Winkler needs"), "{s}");
    assert!(!s.contains("lacks the friction part"), "{s}");
    insta::assert_snapshot!("validity_fails_80x24", s);
    insta::assert_snapshot!("validity_fails_120x40", status(&app, 120, 40));
}

#[test]
fn the_strip_model_is_said_to_be_the_exact_one() {
    let app = solved("hard-coating-strip.toml");
    let s = status(&app, 80, 24);
    assert!(s.contains("strip: the exact model"), "{s}");
    insta::assert_snapshot!("validity_strip_80x24", s);
    insta::assert_snapshot!("validity_strip_120x40", status(&app, 120, 40));
}

#[test]
fn every_warning_is_short_and_those_that_do_not_fit_are_counted() {
    // the default preset on a 1 mm coating at 1 MN/m: two warnings, each in a few words, and the
    // measurement in its short form at 80x24 so that both still fit (before the measurement, the
    // study's estimate gives two others: counted in one row below)
    let app = solved_with("polymer-coating.toml", |p| {
        p.material.thickness = 1e-3;
        p.plane.load = 1e6;
    });
    let warnings = [
        "! outside the tolerances: use the strip model",
        "! (a+b)/R = 0.174 > 0.1: slopes not small",
    ];
    let (tall, small) = (status(&app, 120, 40), status(&app, 80, 24));
    for s in [&tall, &small] {
        assert!(warnings.iter().all(|w| s.contains(w)), "{s}");
    }
    assert!(small.contains("off exact strip: width 78 %"), "{small}");
    // in one row (the cursor's readout and pins take the others), the first reason: the verdict,
    let point = operating_point(&app.doc.preset.plane_inputs(), Model::Wide, 11).unwrap();
    let one: Vec<String> = validity_status::lines(&point, None, PLAIN, 80, 1)
        .iter()
        .map(|l| l.to_string())
        .collect();
    // and after it, outside the row (the status's border), the count of what is left out
    assert_eq!(one.len(), 2, "{one:?}");
    assert_eq!(one[0], "! outside the tolerances: use the strip model");
    assert!(
        one[1].starts_with('+') && one[1].ends_with(" more: i"),
        "{one:?}"
    );
}

#[test]
fn the_operating_point_and_its_verdict_stay_when_the_cursor_reads_pins_at_80x24() {
    let mut app = solved("polymer-coating.toml");
    press(&mut app, KeyCode::Char('x'));
    press(&mut app, KeyCode::Char('c'));
    let s = status(&app, 80, 24);
    // the cursor's values and the pinned curve's do not all fit in the six rows: counted, with
    // the key that shows them all
    for shown in ["cursor x = ", "mu* = 0.299822", "valid: ", "more: i"] {
        assert!(s.contains(shown), "{shown} missing:\n{s}");
    }
    // with room for all of them, nothing is counted as hidden
    let tall = status(&app, 120, 40);
    assert!(
        tall.contains("[1] shear q1") && !tall.contains("more"),
        "{tall}"
    );
}
