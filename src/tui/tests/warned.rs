//! The plausibility warnings inside the explorer: a preset whose value looks like a unit
//! mistake opens with the warning in the message line (at 80x24 and 120x40), `i` lists it whole,
//! and opening it from the picker says it too.

use ratatui::crossterm::event::KeyCode;

use super::*;
use crate::tui::app::PickerEntry;

/// The polymer coating with a wear coefficient of 1e-7 1/Pa: a specific wear rate of
/// 1e-7 mm3/Nm written as 1/Pa (`preset::plausible`'s rule: over 1 mm per metre at 1 MPa).
fn mistaken() -> Preset {
    let mut preset = bundled("polymer-coating.toml");
    preset.wear = 1e-7;
    preset
}

/// The screen's text without blanks (a wrapped line joined again).
fn squeezed(app: &App, w: u16, h: u16) -> String {
    screen(app, w, h, PLAIN)
        .lines()
        .map(|l| l.trim_matches('"'))
        .collect::<String>()
        .split_whitespace()
        .collect()
}

#[test]
fn a_preset_that_looks_mistaken_opens_with_its_warning() {
    let mut app = App::new(mistaken(), None, Places::default());
    let message = app.ui.message.clone().unwrap();
    assert!(message.error);
    assert_eq!(
        message.text,
        "warning (i repeats it): k = 1.000e-7 1/Pa: more than 1 mm of wear per metre of sliding \
         at 1 MPa: was a specific wear rate in mm3/Nm written as 1/Pa? (write \"... mm3/Nm\"; 1 \
         mm3/Nm = 1e-9 1/Pa)"
    );
    for (w, h) in [(80, 24), (120, 40)] {
        let shown = squeezed(&app, w, h);
        assert!(
            shown.contains("warning(irepeatsit):k=1.000e-71/Pa:morethan1mmofwear"),
            "{w}x{h}: {}",
            screen(&app, w, h, PLAIN)
        );
    }
    // i lists it whole
    press(&mut app, KeyCode::Char('i'));
    let about = squeezed(&app, 120, 40);
    assert!(
        about.contains("warning:k=1.000e-71/Pa:morethan1mmofwearpermetreofslidingat1MPa"),
        "{about}"
    );
    // a bundled preset says nothing of the kind
    let fine = App::new(bundled("polymer-coating.toml"), None, Places::default());
    assert!(crate::tui::warned::said(&fine.doc.preset).is_none());
}

#[test]
fn opening_a_mistaken_preset_from_the_picker_says_its_warning() {
    let mut app = app("hertz-check.toml");
    let entry = PickerEntry {
        title: "lab.toml: mistaken".into(),
        source: "/srv/course/lab.toml".into(),
        path: Some("/srv/course/lab.toml".into()),
        preset: Ok(mistaken()),
        folder: "shared: /srv/course".into(),
    };
    crate::tui::actions::open(&mut app, entry);
    let message = app.ui.message.clone().unwrap();
    assert!(
        message.error
            && message
                .text
                .starts_with("warning (i repeats it): k = 1.000e-7")
    );
}
