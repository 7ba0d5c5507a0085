//! The key table against itself, the help, the footers and docs/guide.md.

use std::collections::HashSet;

use crate::physics::plane::Model;
use crate::preset::Problem;

use super::{ASCII, PLAIN};
use crate::tui::keys::{Action, BINDINGS, CursorMove, Open, footer, lookup};
use crate::tui::prompt_keys::{Prompt, prompt_footer};

/// Every action, for the test that each one is bound.
const ACTIONS: [Action; 34] = [
    Action::PrevField,
    Action::NextField,
    Action::Nudge {
        up: false,
        large: false,
    },
    Action::Nudge {
        up: true,
        large: false,
    },
    Action::Nudge {
        up: false,
        large: true,
    },
    Action::Nudge {
        up: true,
        large: true,
    },
    Action::Edit,
    Action::GoTo,
    Action::NextChart,
    Action::PrevChart,
    Action::SwitchProblem,
    Action::CycleModel,
    Action::PlayPause,
    Action::NewSeed,
    Action::AddHarmonic,
    Action::RemoveHarmonic,
    Action::Open,
    Action::Save,
    Action::Export,
    Action::ExportSvg,
    Action::Cursor,
    Action::MoveCursor(CursorMove::Back),
    Action::MoveCursor(CursorMove::Forward),
    Action::MoveCursor(CursorMove::LongBack),
    Action::MoveCursor(CursorMove::LongForward),
    Action::Pin,
    Action::ClearPins,
    Action::Expand,
    Action::LogY,
    Action::Undo,
    Action::About,
    Action::Questions,
    Action::Help,
    Action::Quit,
];

fn event(k: &crate::tui::keys::Key) -> ratatui::crossterm::event::KeyEvent {
    use ratatui::crossterm::event::{KeyEvent, KeyModifiers};
    let mut mods = KeyModifiers::NONE;
    if k.shift {
        mods |= KeyModifiers::SHIFT;
    }
    if k.ctrl {
        mods |= KeyModifiers::CONTROL;
    }
    KeyEvent::new(k.code, mods)
}

#[test]
fn every_action_is_bound_and_every_binding_has_help() {
    for action in ACTIONS {
        assert!(
            BINDINGS
                .iter()
                .any(|b| b.keys.iter().any(|(_, a)| *a == action)),
            "{action:?} has no key"
        );
    }
    for b in &BINDINGS {
        assert!(!b.names.is_empty() && !b.help.is_empty(), "{b:?}");
        // a footer item names its keys and a word; `i` (about this preset) has none, the
        // bottom line naming the preset instead, nor `a` (a lesson's questions), which only a
        // lesson preset has and whose questions window says so, nor `F` (a fit), which only
        // data drawn with `d` allow, its form saying what it does
        let (keys, word, ..) = b.footer;
        assert_eq!(keys.is_empty(), word.is_empty(), "{b:?}");
        assert!(
            !keys.is_empty() || ["i", "a", "F, Esc"].contains(&b.names),
            "{b:?}"
        );
    }
}

#[test]
fn every_key_reaches_its_own_action_and_no_key_is_bound_twice() {
    let mut seen = HashSet::new();
    for b in &BINDINGS {
        for (k, action) in b.keys {
            assert!(seen.insert(format!("{k:?}")), "{k:?} bound twice");
            let (_, found) = lookup(&event(k)).unwrap_or_else(|| panic!("{k:?} unbound"));
            assert_eq!(found, *action, "{k:?}");
        }
    }
}

#[test]
fn the_model_key_names_every_model() {
    let m = BINDINGS.iter().find(|b| b.names == "m").unwrap();
    let names: Vec<&str> = Model::ALL.iter().map(|m| m.name()).collect();
    assert!(
        m.help.contains(&format!("({})", names.join(", "))),
        "{}",
        m.help
    );
}

#[test]
fn the_guide_key_table_is_the_key_table() {
    let guide = include_str!("../../../docs/guide.md");
    let start = guide
        .find("| key | what it does |")
        .expect("docs/guide.md has the key table");
    let rows: Vec<(String, String)> = guide[start..]
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            let cells: Vec<&str> = l.trim_matches('|').split(" | ").collect();
            (
                cells[0].trim().replace("\\|", "|"),
                cells[1].trim().to_string(),
            )
        })
        .collect();
    let table: Vec<(String, String)> = BINDINGS
        .iter()
        .map(|b| (b.names.to_string(), b.help.to_string()))
        .collect();
    assert_eq!(rows, table);
}

#[test]
fn footers_fit_and_name_every_key_of_the_problem() {
    let generated = Open {
        problem: Problem::Spatial,
        generated_surface: true,
    };
    for open in [Problem::Plane.into(), Problem::Spatial.into(), generated] {
        for width in [80, 120] {
            let text = footer(open, width, PLAIN);
            assert!(text.chars().count() <= width, "{width}: {text}");
            assert!(
                text.ends_with("? help  q quit") || text.ends_with("? help q quit"),
                "{text}"
            );
            for b in BINDINGS.iter().filter(|b| b.only.applies(open)) {
                assert!(
                    text.contains(b.footer.0),
                    "{width} {open:?} lacks {}: {text}",
                    b.footer.0
                );
            }
        }
    }
    // read as a user would (80 columns keeps the words of the keys a newcomer needs; the help
    // gives the others)
    assert_eq!(
        footer(Problem::Plane, 80, PLAIN),
        "↑↓ ←→ nudge ⏎ Tab chart p problem m x c/C f y v M D d o s e/E u i ? help q quit"
    );
    assert_eq!(
        footer(Problem::Spatial, 80, PLAIN),
        "↑↓ ←→ nudge ⏎ Tab chart p space +/- x c/C f y v M D d o s e/E u i ? help q quit"
    );
    assert_eq!(
        footer(Problem::Plane, 120, PLAIN),
        "↑↓ ←→ nudge ⏎ Tab chart p problem m x cursor c/C pin f full y log v M D groups d o s e/E u i ? help q quit"
    );
    // with --ascii the arrows and Enter take more columns: the footer still fits 80 with its end
    assert_eq!(
        footer(Problem::Spatial, 80, ASCII),
        "^v <> nudge Enter Tab p space +/- x c/C f y v M D d o s e/E u i ? help q quit"
    );
    assert_eq!(
        footer(Problem::Spatial, 120, PLAIN),
        "↑↓ ←→ nudge ⏎ Tab chart p problem space +/- x cursor c/C pin f full y log v M D groups d o s e/E u i ? help q quit"
    );
}

#[test]
fn every_prompt_says_how_to_leave_it() {
    for p in [
        Prompt::Text,
        Prompt::List,
        Prompt::Picker,
        Prompt::Help,
        Prompt::Question,
        Prompt::Form,
    ] {
        let text = prompt_footer(p);
        assert!(text.contains("Esc"), "{p:?}: {text}");
        assert!(text.ends_with("Ctrl-C quit"), "{p:?}: {text}");
    }
}
