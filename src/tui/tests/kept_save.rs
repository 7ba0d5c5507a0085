//! The explorer's save of a preset opened from a file keeps the author's text: a student's
//! edited copy of an instructor's hand-written preset differs from it only in the edited value
//! and the provenance, and a second save of the copy keeps the copy's text.

use std::fs;

use ratatui::crossterm::event::KeyCode;

use super::*;
use crate::tui::effects;

/// A preset as an instructor writes it: comments, units, its own key order.
const LAB: &str = r#"# Week 3: friction on a coating
schema = 1
name = "Week 3"
description = "A coating on steel: look at mu*."
problem = "plane"

[material]
thickness = "2 mm"   # the coating
youngs_modulus = "3 GPa"
poisson_ratio = 0.35

[friction]
coefficient = 0.1    # measured

[plane]
model = "wide"
radius = "50 mm"
load = "10 kN/m"
"#;

/// The effect of a save command, as the loop carries it out.
fn effect(cmds: Vec<Command>) -> Msg {
    let [
        Command::Save {
            target,
            preset,
            overwrite,
            origin,
        },
    ] = <[Command; 1]>::try_from(cmds).unwrap_or_else(|c| panic!("{c:?}"))
    else {
        unreachable!()
    };
    effects::save(target, preset, overwrite, origin, &[])
}

/// Saves as the loop does (saying yes to overwriting), the report back to `update`.
fn saved(app: &mut App, cmds: Vec<Command>) {
    let mut msg = effect(cmds);
    if matches!(msg, Msg::SaveExists(_)) {
        update(app, msg);
        msg = effect(press(app, KeyCode::Char('y')));
    }
    assert!(matches!(msg, Msg::Saved(_, _, Ok(_))), "{msg:?}");
    update(app, msg);
}

#[test]
fn a_students_copy_keeps_the_instructors_text() {
    let dir = tempfile::tempdir().unwrap();
    let (shared, mine) = (dir.path().join("shared"), dir.path().join("mine"));
    fs::create_dir(&shared).unwrap();
    let lab = shared.join("week3.toml");
    fs::write(&lab, LAB).unwrap();
    let places = Places {
        presets: Some(mine.clone()),
        shared: vec![shared],
        ..Places::default()
    };
    let mut app = App::new(crate::preset::load(&lab).unwrap(), Some(lab), places);
    select(&mut app, "mu", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "0.3");
    press(&mut app, KeyCode::Enter);
    press(&mut app, KeyCode::Char('s'));
    // the proposed name: a copy in the student's folder
    let cmds = press(&mut app, KeyCode::Enter);
    saved(&mut app, cmds);
    let copy = mine.join("week3-edited.toml");
    let expected = LAB
        .replacen("\"Week 3\"", "\"Week 3 (edited)\"", 1)
        .replacen(
            "description = \"A coating on steel: look at mu*.\"",
            &format!(
                "description = \"\"\"\nEdited from \"Week 3\": mu 0.1 -> 0.3.\n{}\nA coating on \
                 steel: look at mu*.\"\"\"",
                crate::tui::save_name::STALE
            ),
            1,
        )
        .replacen("coefficient = 0.1 ", "coefficient = 0.3 ", 1);
    assert_eq!(fs::read_to_string(&copy).unwrap(), expected);
    assert!(!app.doc.dirty);
    // the copy edited again and saved over itself: its own text kept, E in its unit
    select(&mut app, "E", None);
    press(&mut app, KeyCode::Enter);
    type_text(&mut app, "4 GPa");
    press(&mut app, KeyCode::Enter);
    press(&mut app, KeyCode::Char('s'));
    let cmds = press(&mut app, KeyCode::Enter);
    saved(&mut app, cmds);
    let again = fs::read_to_string(&copy).unwrap();
    assert!(again.contains("youngs_modulus = \"4 GPa\"\n"), "{again}");
    assert!(
        again.contains("thickness = \"2 mm\"   # the coating\n"),
        "{again}"
    );
}
