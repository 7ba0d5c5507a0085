//! The lesson in the explorer (part of `update`: pure): the keys its `[lesson]` locks refuse
//! every edit with the reason, and the questions window (`a`) grades typed answers against the
//! program's, which the loop computes once (`Command::AnswerLesson`).

use ratatui::crossterm::event::{KeyCode, KeyEvent};

use crate::preset::{Key, Preset, grade};
use crate::units::format_si;

use crate::tui::app::{App, Command, Mode};
use crate::tui::form;
use crate::tui::lesson_state::{Mark, Quiz};
use crate::tui::prompt_keys::{PAGE, Prompt, PromptAction, cursor_step, prompt_action};
use crate::tui::text_field::TextField;

/// True when the preset's lesson locks this key.
pub fn locked(app: &App, key: Key) -> bool {
    (app.doc.preset.lesson.as_ref()).is_some_and(|l| l.locks(key))
}

/// Why a locked key cannot change.
pub fn why_locked(app: &App, key: Key) -> String {
    let value = match key.harmonic_index() {
        Some(n) if n >= app.doc.preset.spatial.harmonics.len() => String::new(),
        _ => format!(": it stays {}", form::show(&app.doc.preset, &key)),
    };
    format!("{} is locked by the lesson{value}", key.symbol())
}

/// Says so when the selected row is locked.
pub fn say_if_locked(app: &mut App) {
    let row = app.row();
    if locked(app, row) {
        app.say(why_locked(app, row));
    }
}

/// `a`: opens the questions, asking for the program's answers the first time.
pub fn open(app: &mut App) -> Vec<Command> {
    let count = app.lesson.marks.len();
    if count == 0 {
        app.complain(
            "this preset has no lesson questions (docs/lessons.md says how to write them)",
        );
        return Vec::new();
    }
    app.ui.mode = Mode::Questions(Quiz {
        selected: 0,
        typed: TextField::default(),
    });
    app.ui.message = None;
    match app.lesson.values {
        Some(_) => Vec::new(),
        None => vec![Command::AnswerLesson(Box::new(app.lesson.preset.clone()))],
    }
}

/// The program's answers arrived (for the lesson's inputs: else they are another preset's).
pub fn answered(app: &mut App, preset: Preset, values: Vec<Result<f64, String>>) {
    if preset == app.lesson.preset {
        app.lesson.values = Some(values);
    }
}

/// A key in the questions window.
pub fn key(app: &mut App, key: KeyEvent, mut quiz: Quiz) -> Vec<Command> {
    let count = app.lesson.marks.len();
    match prompt_action(Prompt::Quiz, &key) {
        Some(PromptAction::Cancel) => {
            app.ui.mode = Mode::Normal;
            app.ui.message = None;
            return Vec::new();
        }
        Some(PromptAction::Up) => {
            quiz.selected = quiz.selected.checked_sub(1).unwrap_or(count - 1);
            quiz.typed = TextField::default();
        }
        Some(PromptAction::Down) => {
            quiz.selected = (quiz.selected + 1) % count;
            quiz.typed = TextField::default();
        }
        Some(PromptAction::PageUp) => {
            quiz.selected = quiz.selected.saturating_sub(PAGE);
            quiz.typed = TextField::default();
        }
        Some(PromptAction::PageDown) => {
            quiz.selected = (quiz.selected + PAGE).min(count - 1);
            quiz.typed = TextField::default();
        }
        Some(PromptAction::Backspace) => quiz.typed.backspace(),
        Some(
            action @ (PromptAction::Left
            | PromptAction::Right
            | PromptAction::First
            | PromptAction::Last),
        ) => quiz.typed.move_cursor(cursor_step(action)),
        Some(PromptAction::Accept) => check(app, &mut quiz),
        _ => {
            if let KeyCode::Char(c) = key.code {
                quiz.typed.insert(c);
            }
        }
    }
    app.ui.mode = Mode::Questions(quiz);
    Vec::new()
}

/// Grades the typed answer of the selected question, or says why it cannot yet.
fn check(app: &mut App, quiz: &mut Quiz) {
    let typed = quiz.typed.text().trim().to_string();
    if typed.is_empty() {
        app.say("type your answer with its unit, then Enter");
        return;
    }
    let Some(question) =
        (app.lesson.preset.lesson.as_ref()).and_then(|l| l.questions.get(quiz.selected))
    else {
        return;
    };
    let value = match app.lesson.values.as_ref().map(|v| v[quiz.selected].clone()) {
        None => {
            app.say("the program is still computing its answers: Enter again in a moment");
            return;
        }
        Some(Err(why)) => {
            app.complain(format!("the program has no answer to this question: {why}"));
            return;
        }
        Some(Ok(v)) => v,
    };
    let quantity = question.answer.quantity();
    match grade(&typed, value, quantity, question.tolerance) {
        Err(why) => app.complain(format!("{why}: type the answer again")),
        Ok(right) => {
            let verdict = if right { "right" } else { "not right" };
            let shown = if !question.reveal {
                String::new()
            } else if quantity.flag {
                format!(
                    " (the program: {})",
                    if value != 0.0 { "yes" } else { "no" }
                )
            } else {
                format!(" (the program: {})", format_si(value, quantity.unit))
            };
            app.say(format!("question {}: {verdict}{shown}", quiz.selected + 1));
            app.lesson.marks[quiz.selected] = Some(Mark { typed, right });
            quiz.typed = TextField::default();
        }
    }
}
