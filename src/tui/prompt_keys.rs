//! The keys of the prompts (typing a value, a choice list, the picker, the help or the preset's
//! description, a yes/no question, the sweep form) with their footer text: what a key does in
//! each, and each prompt's footer, are drawn from `PROMPT_KEYS`.

use ratatui::crossterm::event::{KeyCode, KeyEvent};

use crate::tui::keys::{Key, ch, key};

/// What a key does in a prompt (typing a value, a choice list, the help or the preset's
/// description, the picker, the save
/// prompt, a yes/no question).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PromptAction {
    /// Move up in a list, or scroll up.
    Up,
    /// Move down, or scroll down.
    Down,
    /// A page up.
    PageUp,
    /// A page down.
    PageDown,
    /// The first entry of a list, or the top of a text.
    First,
    /// The last entry of a list, or the end of a text.
    Last,
    /// Apply / open / save.
    Accept,
    /// Close without doing anything.
    Cancel,
    /// Delete the last character typed.
    Backspace,
    /// Answer yes.
    Yes,
    /// Answer no.
    No,
    /// The previous choice of a form's row, or the cursor left in typed text.
    Left,
    /// The next choice of a form's row, or the cursor right in typed text.
    Right,
    /// Choose or leave the highlighted entry of a list of toggles.
    Toggle,
}

/// The kinds of prompt, for their key lists.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Prompt {
    /// Typing text (a value, a file name).
    Text,
    /// Choosing from a list (a choice row).
    List,
    /// Choosing a preset, its description scrolling.
    Picker,
    /// Reading the help or the preset's description.
    Help,
    /// A yes/no question.
    Question,
    /// A form of several rows (the sweep's and the map's axes).
    Form,
    /// The lesson's questions, an answer being typed.
    Quiz,
    /// A list of toggles (the inputs a fit frees).
    Toggles,
}

/// The keys of each prompt with their footer text ("" for a key the footer does not name).
#[rustfmt::skip]
pub const PROMPT_KEYS: [(Prompt, Key, PromptAction, &str); 69] = [
    (Prompt::Text, key(KeyCode::Enter), PromptAction::Accept, "⏎ apply"),
    (Prompt::Text, key(KeyCode::Esc), PromptAction::Cancel, "Esc cancel"),
    (Prompt::Text, key(KeyCode::Backspace), PromptAction::Backspace, "⌫ delete"),
    (Prompt::Text, key(KeyCode::Left), PromptAction::Left, "←→ Home End edit"),
    (Prompt::Text, key(KeyCode::Right), PromptAction::Right, ""),
    (Prompt::Text, key(KeyCode::Home), PromptAction::First, ""),
    (Prompt::Text, key(KeyCode::End), PromptAction::Last, ""),
    (Prompt::List, key(KeyCode::Up), PromptAction::Up, "↑↓ choose"),
    (Prompt::List, ch('k'), PromptAction::Up, ""),
    (Prompt::List, key(KeyCode::Down), PromptAction::Down, ""),
    (Prompt::List, ch('j'), PromptAction::Down, ""),
    (Prompt::List, key(KeyCode::Home), PromptAction::First, ""),
    (Prompt::List, key(KeyCode::End), PromptAction::Last, ""),
    (Prompt::List, key(KeyCode::PageUp), PromptAction::PageUp, ""),
    (Prompt::List, key(KeyCode::PageDown), PromptAction::PageDown, ""),
    (Prompt::List, key(KeyCode::Enter), PromptAction::Accept, "⏎ take"),
    (Prompt::List, key(KeyCode::Esc), PromptAction::Cancel, "Esc cancel"),
    (Prompt::Picker, key(KeyCode::Up), PromptAction::Up, "type: find  ↑↓ Home End"),
    (Prompt::Picker, key(KeyCode::Down), PromptAction::Down, ""),
    (Prompt::Picker, key(KeyCode::Home), PromptAction::First, ""),
    (Prompt::Picker, key(KeyCode::End), PromptAction::Last, ""),
    (Prompt::Picker, key(KeyCode::PageUp), PromptAction::PageUp, "PgUp PgDn text"),
    (Prompt::Picker, key(KeyCode::PageDown), PromptAction::PageDown, ""),
    (Prompt::Picker, key(KeyCode::Backspace), PromptAction::Backspace, ""),
    (Prompt::Picker, key(KeyCode::Enter), PromptAction::Accept, "⏎ open"),
    (Prompt::Picker, key(KeyCode::Esc), PromptAction::Cancel, "Esc cancel"),
    (Prompt::Help, key(KeyCode::Up), PromptAction::Up, "↑↓ PgUp PgDn Home End scroll"),
    (Prompt::Help, key(KeyCode::Down), PromptAction::Down, ""),
    (Prompt::Help, key(KeyCode::PageUp), PromptAction::PageUp, ""),
    (Prompt::Help, key(KeyCode::PageDown), PromptAction::PageDown, ""),
    (Prompt::Help, key(KeyCode::Home), PromptAction::First, ""),
    (Prompt::Help, key(KeyCode::End), PromptAction::Last, ""),
    (Prompt::Help, key(KeyCode::Esc), PromptAction::Cancel, "Esc or ? close"),
    (Prompt::Help, ch('?'), PromptAction::Cancel, ""),
    (Prompt::Help, ch('q'), PromptAction::Cancel, ""),
    (Prompt::Question, ch('y'), PromptAction::Yes, "y yes"),
    (Prompt::Question, ch('n'), PromptAction::No, "n no"),
    (Prompt::Question, key(KeyCode::Esc), PromptAction::No, "Esc no"),
    (Prompt::Form, key(KeyCode::Up), PromptAction::Up, "↑↓ row"),
    (Prompt::Form, key(KeyCode::Down), PromptAction::Down, ""),
    (Prompt::Form, key(KeyCode::Left), PromptAction::Left, "←→ choose or edit"),
    (Prompt::Form, key(KeyCode::Right), PromptAction::Right, ""),
    (Prompt::Form, key(KeyCode::Home), PromptAction::First, ""),
    (Prompt::Form, key(KeyCode::End), PromptAction::Last, ""),
    (Prompt::Form, key(KeyCode::Backspace), PromptAction::Backspace, "type ⌫"),
    (Prompt::Form, key(KeyCode::Enter), PromptAction::Accept, "⏎ show"),
    (Prompt::Form, key(KeyCode::Esc), PromptAction::Cancel, "Esc cancel"),
    (Prompt::Quiz, key(KeyCode::Up), PromptAction::Up, "↑↓ question"),
    (Prompt::Quiz, key(KeyCode::Down), PromptAction::Down, ""),
    (Prompt::Quiz, key(KeyCode::PageUp), PromptAction::PageUp, ""),
    (Prompt::Quiz, key(KeyCode::PageDown), PromptAction::PageDown, ""),
    (Prompt::Quiz, key(KeyCode::Enter), PromptAction::Accept, "⏎ check"),
    (Prompt::Quiz, key(KeyCode::Backspace), PromptAction::Backspace, "⌫ delete"),
    (Prompt::Quiz, key(KeyCode::Left), PromptAction::Left, "←→ edit"),
    (Prompt::Quiz, key(KeyCode::Right), PromptAction::Right, ""),
    (Prompt::Quiz, key(KeyCode::Home), PromptAction::First, ""),
    (Prompt::Quiz, key(KeyCode::End), PromptAction::Last, ""),
    (Prompt::Quiz, key(KeyCode::Esc), PromptAction::Cancel, "Esc close"),
    (Prompt::Toggles, key(KeyCode::Up), PromptAction::Up, "↑↓ input"),
    (Prompt::Toggles, ch('k'), PromptAction::Up, ""),
    (Prompt::Toggles, key(KeyCode::Down), PromptAction::Down, ""),
    (Prompt::Toggles, ch('j'), PromptAction::Down, ""),
    (Prompt::Toggles, key(KeyCode::PageUp), PromptAction::PageUp, ""),
    (Prompt::Toggles, key(KeyCode::PageDown), PromptAction::PageDown, ""),
    (Prompt::Toggles, key(KeyCode::Home), PromptAction::First, ""),
    (Prompt::Toggles, key(KeyCode::End), PromptAction::Last, ""),
    (Prompt::Toggles, ch(' '), PromptAction::Toggle, "space free/fixed"),
    (Prompt::Toggles, key(KeyCode::Enter), PromptAction::Accept, "⏎ fit"),
    (Prompt::Toggles, key(KeyCode::Esc), PromptAction::Cancel, "Esc cancel"),
];

/// What a key does in a prompt, if anything.
pub fn prompt_action(prompt: Prompt, ev: &KeyEvent) -> Option<PromptAction> {
    PROMPT_KEYS
        .iter()
        .find(|(p, k, _, _)| *p == prompt && k.matches(ev))
        .map(|(_, _, a, _)| *a)
}

/// The footer of a prompt: its keys, then Ctrl-C.
pub fn prompt_footer(prompt: Prompt) -> String {
    PROMPT_KEYS
        .iter()
        .filter(|(p, _, _, text)| *p == prompt && !text.is_empty())
        .map(|(_, _, _, text)| *text)
        .chain(["Ctrl-C quit"])
        .collect::<Vec<_>>()
        .join("  ")
}

/// The entries a page key moves a list's selection, or a text window's scroll.
pub const PAGE: usize = 10;

/// The scroll of a text window (the help, the preset's description) after a key, stopping at
/// `last`; None closes it.
pub fn scrolled(key: &KeyEvent, scroll: u16, last: u16) -> Option<u16> {
    match prompt_action(Prompt::Help, key)? {
        PromptAction::Up => Some(scroll.min(last).saturating_sub(1)),
        PromptAction::Down => Some(scroll.saturating_add(1).min(last)),
        PromptAction::PageUp => Some(scroll.min(last).saturating_sub(PAGE as u16)),
        PromptAction::PageDown => Some(scroll.saturating_add(PAGE as u16).min(last)),
        PromptAction::First => Some(0),
        PromptAction::Last => Some(last),
        _ => None,
    }
}

/// How far a key moves the cursor in typed text (`TextField::move_cursor`): ←→ one character,
/// Home End to either end; 0 for any other action.
pub fn cursor_step(action: PromptAction) -> isize {
    match action {
        PromptAction::Left => -1,
        PromptAction::Right => 1,
        PromptAction::First => isize::MIN,
        PromptAction::Last => isize::MAX,
        _ => 0,
    }
}
