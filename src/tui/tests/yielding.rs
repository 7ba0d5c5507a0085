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
