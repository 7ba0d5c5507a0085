//! The form's material row: Right and Left step through the bundled table, each choice setting
//! E, nu and the strengths (whose rows then show, with Archard's K beside k); a value typed
//! afterwards makes the row read "custom" (and the message says why); a figure's caption names a
//! table material only.

use ratatui::crossterm::event::KeyCode;

use super::*;
use crate::materials::{CUSTOM, MATERIALS};
use crate::preset::Key;
use crate::tui::charts::export::caption;
use crate::tui::form;
use crate::units::format_si;

fn shown(app: &App, symbol: &str) -> String {
    let row = app.rows().into_iter().find(|r| r.param().symbol == symbol);
    row.map(|r| form::show(&app.doc.preset, &r))
        .unwrap_or_else(|| panic!("no row {symbol}"))
}

#[test]
fn choosing_a_material_sets_its_values_and_typing_one_makes_it_custom() {
    let mut app = app("polymer-coating.toml");
    assert_eq!(shown(&app, "material"), CUSTOM);
    select(&mut app, "material", None);
    press(&mut app, KeyCode::Right);
    let steel = &MATERIALS[0];
    assert_eq!(shown(&app, "material"), steel.name);
    assert_eq!(app.doc.preset.material.youngs_modulus, steel.youngs_modulus);
    assert_eq!(app.doc.preset.strength, steel.strength);
    // the hardness is known now: its row and Archard's K = k H show
    assert_eq!(shown(&app, "H"), "7.50 GPa");
    let k = app.doc.preset.wear;
    assert_eq!(
        shown(&app, "K"),
        form::show(
            &app.doc.preset,
            &Key::parse("wear.archard_coefficient").unwrap()
        )
    );
    assert!(
        (form::get(
            &app.doc.preset,
            &Key::parse("wear.archard_coefficient").unwrap()
        ) - k * 7.5e9)
            .abs()
            < 1e-9 * k * 7.5e9
    );
    // the message names what was set and the table's friction and wear, which it leaves alone
    let said = app.ui.message.as_ref().map(|m| m.text.clone());
    let wear = format_si(steel.wear_rate / crate::materials::MM3_PER_NM, "");
    assert_eq!(
        said,
        Some(format!(
            "{}: E, nu, H set; typical against steel, dry: mu {}, k {wear} mm3/Nm (not set: \
             type them on the mu and k rows)",
            steel.name,
            format_si(steel.friction, "")
        ))
    );
    assert_eq!(
        (app.doc.preset.wear, app.doc.preset.friction.coefficient),
        (k, 0.3)
    );
    let text = caption(&app.doc.preset, 200).join(" ");
    assert!(
        text.contains(&format!("material = {},", steel.name)),
        "{text}"
    );
    // Left from the first material is "custom", which only typing gives: refused, with the names
    press(&mut app, KeyCode::Left);
    assert_eq!(shown(&app, "material"), steel.name);
    let said = app
        .ui
        .message
        .as_ref()
        .map(|m| m.text.clone())
        .unwrap_or_default();
    assert!(
        said.contains("choose one of the table's materials"),
        "{said}"
    );
    select(&mut app, "E", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "200 GPa");
    press(&mut app, KeyCode::Enter);
    assert_eq!(shown(&app, "material"), CUSTOM);
    // the message says why the row changed
    let said = app.ui.message.as_ref().map(|m| m.text.clone());
    assert_eq!(
        said.as_deref(),
        Some("E: 210 GPa -> 200 GPa, not the table's AISI 52100: the material row reads custom")
    );
    assert!(
        !caption(&app.doc.preset, 200)
            .join(" ")
            .contains("material =")
    );
}
