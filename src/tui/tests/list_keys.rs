//! PgUp, PgDn, Home and End in every list or text that scrolls: the picker (Home End choose among
//! the presets, PgUp PgDn scroll the highlighted one's description), a row's choice list, the
//! help, the preset's description (`i`) and the lesson's questions (PgUp PgDn choose a question;
//! Home End move the cursor in the answer being typed).

use ratatui::crossterm::event::KeyCode;
use ratatui::layout::Rect;

use super::{app, press};
use crate::tui::app::{App, Command, Mode, Places};
use crate::tui::effects;
use crate::tui::prompt_keys::{PAGE, Prompt, PromptAction, prompt_action};
use crate::tui::update::update;

const KEYS: [KeyCode; 4] = [
    KeyCode::PageUp,
    KeyCode::PageDown,
    KeyCode::Home,
    KeyCode::End,
];

/// The mode after each of `keys`, pressed in turn.
fn after(app: &mut App, keys: &[KeyCode]) -> Vec<Mode> {
    keys.iter()
        .map(|k| {
            press(app, *k);
            app.ui.mode.clone()
        })
        .collect()
}

#[test]
fn every_scrolling_list_takes_page_up_page_down_home_and_end() {
    // the key table: each of the four does something in each of these prompts
    for prompt in [Prompt::List, Prompt::Picker, Prompt::Help, Prompt::Quiz] {
        for code in KEYS {
            let ev = ratatui::crossterm::event::KeyEvent::from(code);
            assert!(prompt_action(prompt, &ev).is_some(), "{prompt:?} {code:?}");
        }
    }
    let screen = Rect::new(0, 0, 80, 24);

    // a choice list (the material row: "custom" and the table's nine materials)
    let mut a = app("polymer-coating.toml");
    a.ui.screen = screen;
    a.ui.selected = 0;
    press(&mut a, KeyCode::Enter);
    let Mode::Choosing(0) = a.ui.mode else {
        panic!("{:?}", a.ui.mode)
    };
    let last = a.row().param().choices().unwrap().len() - 1;
    assert!((2..2 * PAGE).contains(&last), "{last}");
    let moves = after(&mut a, &[KeyCode::End, KeyCode::Home, KeyCode::PageDown]);
    let down = PAGE.min(last);
    assert_eq!(
        moves,
        [
            Mode::Choosing(last),
            Mode::Choosing(0),
            Mode::Choosing(down)
        ]
    );
    let moves = after(&mut a, &[KeyCode::Up, KeyCode::PageUp]);
    assert_eq!(moves, [Mode::Choosing(down - 1), Mode::Choosing(0)]);

    // the picker: Home End choose among the presets, PgUp PgDn scroll the description
    let mut a = app("polymer-coating.toml");
    a.ui.screen = screen;
    update(&mut a, effects::list_presets(&Places::default()));
    let picked = |a: &App| match &a.ui.mode {
        Mode::Picker {
            entries,
            selected,
            scroll,
            ..
        } => (*selected, entries.len(), *scroll),
        m => panic!("{m:?}"),
    };
    press(&mut a, KeyCode::End);
    let (selected, count, _) = picked(&a);
    assert!(
        count > PAGE && selected == count - 1,
        "{selected} of {count}"
    );
    press(&mut a, KeyCode::Home);
    assert_eq!(picked(&a).0, 0);
    press(&mut a, KeyCode::PageDown);
    let (_, _, scrolled) = picked(&a);
    assert!(
        scrolled > 0,
        "the first preset's description fits: pick a longer one"
    );
    press(&mut a, KeyCode::PageUp);
    assert_eq!(picked(&a), (0, count, 0));

    // the help and the preset's description (`i`), long enough to scroll at 80x24
    for (open, mode) in [('?', Mode::Help as fn(u16) -> Mode), ('i', Mode::About)] {
        let mut a = app("contact-lost.toml");
        a.ui.screen = screen;
        a.doc.preset.description = a.doc.preset.description.repeat(4);
        press(&mut a, KeyCode::Char(open));
        let moves = after(&mut a, &[KeyCode::PageDown, KeyCode::End]);
        let last = match moves[1] {
            Mode::Help(s) | Mode::About(s) => s,
            ref m => panic!("{m:?}"),
        };
        assert!(last > PAGE as u16, "{open}: {last}");
        assert_eq!(moves[0], mode(PAGE as u16), "{open}");
        let moves = after(&mut a, &[KeyCode::PageUp, KeyCode::Home]);
        assert_eq!(moves, [mode(last - PAGE as u16), mode(0)], "{open}");
    }

    // the lesson's questions: PgDn to the last, PgUp to the first; Home End edit the answer
    let mut a = app("friction-half-plane.toml");
    let commands = press(&mut a, KeyCode::Char('a'));
    let [Command::AnswerLesson(preset)] = commands.as_slice() else {
        panic!("{commands:?}");
    };
    update(&mut a, effects::answer_lesson((**preset).clone()));
    let question = |a: &App| match &a.ui.mode {
        Mode::Questions(q) => (q.selected, q.typed.text().to_string()),
        m => panic!("{m:?}"),
    };
    let count = a.lesson.marks.len();
    assert!((2..=PAGE).contains(&count), "{count}");
    press(&mut a, KeyCode::PageDown);
    assert_eq!(question(&a).0, count - 1);
    press(&mut a, KeyCode::PageUp);
    assert_eq!(question(&a).0, 0);
    for c in "0.3".chars() {
        press(&mut a, KeyCode::Char(c));
    }
    press(&mut a, KeyCode::Home);
    press(&mut a, KeyCode::Char('1'));
    press(&mut a, KeyCode::End);
    press(&mut a, KeyCode::Char('9'));
    assert_eq!(question(&a), (0, "10.39".to_string()));
    assert_eq!(
        prompt_action(Prompt::Quiz, &KeyCode::Home.into()),
        Some(PromptAction::First)
    );
}
