//! The yield check in the explorer: the form's Y and H rows read "none" until a value is typed,
//! and with one the status says where the contact would first yield, with the numbers `wearlab
//! solve` reports for the same inputs.

use ratatui::crossterm::event::KeyCode;

use super::validity::status;
use super::*;

#[test]
fn a_hardness_typed_into_the_form_gives_the_yield_line_at_80x24_and_120x40() {
    let mut app = solved("polymer-coating.toml");
    let s = screen(&app, 80, 24, PLAIN);
    let none = |row: &str| s.contains(&format!("│  {row}                     none│"));
    assert!(none("Y") && none("H"), "{s}");
    assert!(!status(&app, 120, 40).contains("yield"));
    // H = 15 MPa, so Y = H/3 = 5 MPa: `wearlab solve presets/polymer-coating.toml --set
    // material.hardness=15MPa` reports yield.von_mises_max = 6.4009e6 Pa at yield.depth =
    // 1.2584e-4 m, yields = true
    select(&mut app, "H", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "15 MPa");
    let cmds = press(&mut app, KeyCode::Enter);
    settle(&mut app, cmds);
    let tall = status(&app, 120, 40);
    assert!(
        tall.contains("yields: von Mises 6.40 MPa at 126 um depth > Y = H/3 = 5.00 MPa"),
        "{tall}"
    );
    // at 80x24 the point, the verdict and the yield line stay (wrapped between its pieces)
    let small = status(&app, 80, 24);
    for shown in [
        "mu* = 0.299822 (mu 0.3)",
        "valid: (a+b)/h = 0.06104; wide model holds",
        "yields: von Mises 6.40 MPa at 126 um depth",
        "> Y = H/3 = 5.00 MPa",
    ] {
        assert!(small.contains(shown), "{shown} missing:\n{small}");
    }
    // a strong strip: Y = 100 MPa typed, below yield by the same stress
    select(&mut app, "Y", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "100 MPa");
    let cmds = press(&mut app, KeyCode::Enter);
    settle(&mut app, cmds);
    let tall = status(&app, 120, 40);
    assert!(
        tall.contains("below yield: von Mises 6.40 MPa = 0.06 Y at 126 um depth"),
        "{tall}"
    );
}

/// A status's text as words: its rows joined, the borders and runs of spaces left out.
fn words(status: &str) -> String {
    status
        .replace('│', " ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// Types `text` into the row labelled `label` and delivers the solve.
fn typed(app: &mut App, label: &str, text: &str) {
    select(app, label, None);
    press(app, KeyCode::Enter);
    type_text(app, text);
    let cmds = press(app, KeyCode::Enter);
    settle(app, cmds);
}

#[test]
fn with_both_strengths_the_status_says_which_one_is_used_and_none_clears_one() {
    let mut app = solved("polymer-coating.toml");
    typed(&mut app, "H", "15 MPa");
    typed(&mut app, "Y", "100 MPa");
    // Y = 100 MPa is judged, not H/3 = 5 MPa: the same stress as above, 0.06 Y
    let tall = words(&status(&app, 120, 40));
    assert!(
        tall.contains(
            "below yield: von Mises 6.40 MPa = 0.06 Y at 126 um depth (Y as given; H not used)"
        ),
        "{tall}"
    );
    // the prompt names none among what may be typed; none clears Y, and H/3 is judged again
    select(&mut app, "Y", None);
    press(&mut app, KeyCode::Enter);
    let prompt = screen(&app, 120, 40, PLAIN);
    assert!(prompt.contains("or none to clear it"), "{prompt}");
    press(&mut app, KeyCode::Esc);
    typed(&mut app, "Y", "none");
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains("│  Y                     none│"), "{s}");
    let tall = status(&app, 120, 40);
    assert!(tall.contains("> Y = H/3 = 5.00 MPa"), "{tall}");
    assert!(!tall.contains("not used"), "{tall}");
    // and none in H too: no yield check at all
    typed(&mut app, "H", "none");
    assert!(!status(&app, 120, 40).contains("yield"));
}

#[test]
fn a_peak_stress_below_a_thin_coating_is_not_judged() {
    // a 50 um coating under the strip model at 1 kN/m with little friction: the contact is
    // about 3.5 h wide, and the half-plane's largest stress lies about 0.7 a deep (Johnson
    // (1985) section 4.2, the frictionless Hertz contact's von Mises maximum on the axis),
    // below the layer (`wearlab solve` gives yield.note "... at depth 56.8 um, below the layer
    // (h = 50.0 um)" for these inputs)
    let mut app = solved("polymer-coating.toml");
    typed(&mut app, "H", "15 MPa");
    typed(&mut app, "mu", "0.1");
    typed(&mut app, "h", "50 um");
    typed(&mut app, "P", "1 kN/m");
    // wide -> narrow -> strip
    for _ in 0..2 {
        let cmds = press(&mut app, KeyCode::Char('m'));
        settle(&mut app, cmds);
    }
    assert_eq!(
        app.doc.preset.plane.model,
        crate::physics::plane::Model::Strip
    );
    let judged = "yield not judged: peak stress 56.8 um deep, below h = 50.0 um";
    let tall = words(&status(&app, 120, 40));
    assert!(tall.contains(judged), "{tall}");
    assert!(
        !tall.contains("yields:") && !tall.contains("below yield"),
        "{tall}"
    );
    // whole at 80x24 too, the verdict above it
    let small = status(&app, 80, 24);
    assert!(words(&small).contains(judged), "{small}");
    assert!(!small.contains('…'), "{small}");
    assert!(small.contains("strip model holds"), "{small}");
}
