//! The state of a preset's lesson in the explorer (part of the model): the inputs its questions
//! are answered at, the program's answers once computed, and the student's answers so far; and
//! the state of the questions window (`a`).

use crate::preset::Preset;
use crate::tui::text_field::TextField;

/// A student's answer to a question and its verdict.
#[derive(Clone, Debug, PartialEq)]
pub struct Mark {
    /// The answer as typed.
    pub typed: String,
    /// Within the question's tolerance.
    pub right: bool,
}

/// The lesson of the preset shown.
#[derive(Clone, Debug, PartialEq)]
pub struct LessonState {
    /// The preset as opened: the questions are answered at its inputs (with each question's
    /// `at`), not at the student's edits, as `wearlab check` answers them.
    pub preset: Preset,
    /// The program's answer to each question [SI] or why it has none; None until computed.
    pub values: Option<Vec<Result<f64, String>>>,
    /// The student's last answer to each question.
    pub marks: Vec<Option<Mark>>,
}

impl LessonState {
    /// The state of a newly opened preset.
    pub fn opened(preset: &Preset) -> LessonState {
        let count = preset.lesson.as_ref().map_or(0, |l| l.questions.len());
        LessonState {
            preset: preset.clone(),
            values: None,
            marks: vec![None; count],
        }
    }
}

/// What the explorer says on opening a preset with questions: that `a` opens them.
pub fn invitation(preset: &Preset) -> Option<String> {
    let count = preset.lesson.as_ref()?.questions.len();
    let s = if count == 1 { "" } else { "s" };
    (count > 0).then(|| format!("a lesson: a opens its {count} question{s}"))
}

/// The questions window.
#[derive(Clone, Debug, PartialEq)]
pub struct Quiz {
    /// The question being answered (0-based).
    pub selected: usize,
    /// The answer being typed.
    pub typed: TextField,
}
