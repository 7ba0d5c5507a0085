//! The optional `[lesson]` section of a preset file: the view the explorer opens on, the keys
//! students cannot change there, and questions on quantities the program computes, each with a
//! tolerance; the program's answer to a question and the grading of a typed answer.
//!
//! ```toml
//! [lesson]
//! view = "mu* against load"              # a chart's title, "sweep" or "regime map"
//! locked = ["material.thickness"]         # preset keys
//! [[lesson.questions]]
//! text = "What is mu* at the preset's load?"
//! answer = "mu_star"                      # a quantity of `wearlab solve --output`
//! tolerance = "0.5 %"                     # relative, or absolute with the answer's unit
//! reveal = false                          # show the program's value after an answer
//! at = ["plane.load=2 kN/m"]              # optional: inputs set before answering
//! ```
//!
//! The file's layout is here too (`FileLesson`); `check` reads it through `read`.

use std::ops::Range;

use serde::{Deserialize, Serialize};
use toml::Spanned;

use crate::physics::SolveError;
use crate::preset::written::Written;
use crate::preset::{Key, Preset, PresetError};
use crate::sweeps::point;
use crate::sweeps::quantity::{self, Quantity, QuantityKey};
use crate::units::parse_si;
use crate::views::View;

/// The tolerance of a question whose file gives none.
pub const DEFAULT_TOLERANCE: Tolerance = Tolerance::Percent(1.0);

/// A preset's lesson.
#[derive(Clone, Debug, PartialEq)]
pub struct Lesson {
    /// The view the explorer opens on (None: the preset's usual one).
    pub view: Option<View>,
    /// The keys the explorer shows but does not let students change.
    pub locked: Vec<Key>,
    /// The questions, in file order.
    pub questions: Vec<Question>,
}

/// One question of a lesson.
#[derive(Clone, Debug, PartialEq)]
pub struct Question {
    /// What is asked.
    pub text: String,
    /// The quantity that answers it.
    pub answer: QuantityKey,
    /// How far a typed answer may be from the program's value.
    pub tolerance: Tolerance,
    /// The program's value is shown after a typed answer.
    pub reveal: bool,
    /// `KEY=VALUE` settings (as `--set` takes them) applied to the preset before answering.
    pub at: Vec<String>,
}

/// How far a typed answer may be from the program's value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Tolerance {
    /// A share of the program's value's magnitude, in percent (above 0).
    Percent(f64),
    /// A difference in the answer's SI unit (above 0).
    Absolute(f64),
}

impl Lesson {
    /// True when the lesson keeps this key as the file has it.
    pub fn locks(&self, key: Key) -> bool {
        self.locked.contains(&key)
    }
}

impl Preset {
    /// The first key its lesson locks whose value differs in `next` (an edit of it).
    pub fn locked_change(&self, next: &Preset) -> Option<Key> {
        let lesson = self.lesson.as_ref()?;
        (lesson.locked.iter().copied()).find(|k| self.get(*k).ok() != next.get(*k).ok())
    }
}

impl Question {
    /// The program's value [the answer quantity's SI unit] at the question's inputs (the preset
    /// with `at` applied). Err: InvalidInput when `at` no longer applies, NoSolution when the
    /// solver has no answer or the quantity no value there.
    pub fn solve(&self, preset: &Preset) -> Result<f64, SolveError> {
        let inputs = preset
            .with_settings(&self.at)
            .map_err(SolveError::InvalidInput)?;
        let point = point::solve(&inputs)?;
        let value = self.answer.value(&point).map_err(|why| {
            SolveError::NoSolution(format!("{} has no value here: {why}", self.answer))
        })?;
        if value.is_finite() {
            Ok(value)
        } else {
            Err(SolveError::NoSolution(format!(
                "{} is not finite here",
                self.answer
            )))
        }
    }
}

/// Grades a typed answer against the program's value: Ok(true) when it is within the tolerance
/// (a yes/no quantity: when it says the same), Err when the text cannot be read as a value of the
/// quantity's unit (the reason, to type it again).
pub fn grade(
    typed: &str,
    value: f64,
    quantity: &Quantity,
    tolerance: Tolerance,
) -> Result<bool, String> {
    if quantity.flag {
        let yes = match typed.trim().to_ascii_lowercase().as_str() {
            "yes" | "true" | "y" | "1" => true,
            "no" | "false" | "n" | "0" => false,
            other => return Err(format!("'{other}': answer yes or no")),
        };
        return Ok(yes == (value != 0.0));
    }
    let typed = parse_si(typed, quantity.unit)?;
    if !typed.is_finite() {
        return Err("type a finite number".into());
    }
    let allowed = match tolerance {
        Tolerance::Percent(p) => p / 100.0 * value.abs(),
        Tolerance::Absolute(a) => a,
    };
    Ok((typed - value).abs() <= allowed)
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileLesson {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    view: Option<Spanned<String>>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    locked: Vec<Spanned<String>>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    questions: Vec<Spanned<FileQuestion>>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct FileQuestion {
    text: Spanned<String>,
    answer: Spanned<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    tolerance: Option<Spanned<Written>>,
    #[serde(default)]
    reveal: bool,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    at: Vec<Spanned<String>>,
}

/// The section as `to_toml` writes it: the tolerance in percent or as an SI number.
pub(super) fn to_file(lesson: &Lesson) -> FileLesson {
    let plain = |s: String| Spanned::new(0..0, s);
    FileLesson {
        view: lesson.view.map(|v| plain(v.name().to_string())),
        locked: lesson.locked.iter().map(|k| plain(k.to_string())).collect(),
        questions: lesson
            .questions
            .iter()
            .map(|q| {
                Spanned::new(
                    0..0,
                    FileQuestion {
                        text: plain(q.text.clone()),
                        answer: plain(q.answer.to_string()),
                        tolerance: Some(Spanned::new(
                            0..0,
                            match q.tolerance {
                                Tolerance::Percent(p) => Written::Text(format!("{p} %")),
                                Tolerance::Absolute(a) => Written::Number(a),
                            },
                        )),
                        reveal: q.reveal,
                        at: q.at.iter().cloned().map(plain).collect(),
                    },
                )
            })
            .collect(),
    }
}

/// Reads the section, checked against the rest of the preset (with its `[explore]` section);
/// `error` turns a span and a reason into the file's `path:line: reason`.
pub(super) fn read(
    file: &Spanned<FileLesson>,
    preset: &Preset,
    error: &dyn Fn(Option<Range<usize>>, String) -> PresetError,
) -> Result<Lesson, PresetError> {
    let l = file.get_ref();
    let view = match &l.view {
        Some(v) => {
            Some(View::parse(v.get_ref(), preset).map_err(|why| error(Some(v.span()), why))?)
        }
        None => None,
    };
    let locked = l
        .locked
        .iter()
        .map(|k| {
            preset
                .key(k.get_ref())
                .map_err(|why| error(Some(k.span()), format!("locked: {why}")))
        })
        .collect::<Result<Vec<Key>, _>>()?;
    let questions = l
        .questions
        .iter()
        .map(|q| question(q, preset, error))
        .collect::<Result<Vec<Question>, _>>()?;
    Ok(Lesson {
        view,
        locked,
        questions,
    })
}

fn question(
    file: &Spanned<FileQuestion>,
    preset: &Preset,
    error: &dyn Fn(Option<Range<usize>>, String) -> PresetError,
) -> Result<Question, PresetError> {
    let q = file.get_ref();
    if q.text.get_ref().trim().is_empty() {
        return Err(error(
            Some(q.text.span()),
            "text is empty: write the question, e.g. text = \"What is mu* at the preset's load?\""
                .into(),
        ));
    }
    let at: Vec<String> = q.at.iter().map(|s| s.get_ref().clone()).collect();
    let inputs = preset.with_settings(&at).map_err(|why| {
        let span = q.at.first().map_or(file.span(), |s| s.span());
        error(Some(span), format!("at: {why}"))
    })?;
    let answer = QuantityKey::parse(q.answer.get_ref(), &inputs).map_err(|why| {
        error(
            Some(q.answer.span()),
            answer_refused(q.answer.get_ref(), &inputs, why),
        )
    })?;
    let tolerance = match &q.tolerance {
        Some(t) => {
            tolerance(t.get_ref(), answer.quantity()).map_err(|why| error(Some(t.span()), why))?
        }
        None => DEFAULT_TOLERANCE,
    };
    Ok(Question {
        text: q.text.get_ref().trim().to_string(),
        answer,
        tolerance,
        reveal: q.reveal,
        at,
    })
}

/// Why an answer key is refused: a known quantity the preset's model lacks says so; an unknown
/// one names a few that exist, those like it first.
fn answer_refused(typed: &str, preset: &Preset, why: String) -> String {
    if !why.starts_with("unknown output") {
        return format!("answer = {why}");
    }
    let typed = typed.trim();
    let all: Vec<String> = QuantityKey::all(preset)
        .iter()
        .map(|k| k.to_string())
        .collect();
    let stem: String = typed.chars().take(2).collect();
    let mut few: Vec<&String> = all
        .iter()
        .filter(|n| !stem.is_empty() && (n.starts_with(&stem) || n.contains(typed)))
        .take(5)
        .collect();
    if few.is_empty() {
        few = quantity::defaults(preset)
            .iter()
            .filter_map(|k| all.iter().find(|n| **n == k.to_string()))
            .take(5)
            .collect();
    }
    let names: Vec<String> = few.iter().map(|n| format!("\"{n}\"")).collect();
    format!(
        "answer = \"{typed}\" is not a quantity of a {} preset: e.g. {} (docs/cli.md lists them all)",
        preset.problem.name(),
        names.join(", ")
    )
}

/// A tolerance as written: "x %" relative, else absolute in the answer's unit (a number: SI).
fn tolerance(written: &Written, quantity: &Quantity) -> Result<Tolerance, String> {
    let example = if quantity.unit.is_empty() {
        "e.g. tolerance = \"0.5 %\" or 0.01".to_string()
    } else {
        format!("e.g. tolerance = \"0.5 %\" or \"1 {}\"", quantity.unit)
    };
    let t = match written {
        Written::Number(v) => Tolerance::Absolute(*v),
        Written::Text(text) => match text.trim().strip_suffix('%') {
            Some(p) => Tolerance::Percent(p.trim().parse().map_err(|_| {
                format!("tolerance = \"{text}\": '{p}' is not a number; {example}")
            })?),
            None => Tolerance::Absolute(
                parse_si(text, quantity.unit)
                    .map_err(|why| format!("tolerance = \"{text}\": {why}; {example}"))?,
            ),
        },
    };
    let (Tolerance::Percent(v) | Tolerance::Absolute(v)) = t;
    if v.is_finite() && v > 0.0 {
        Ok(t)
    } else {
        Err(format!(
            "the tolerance must be above 0 and finite; {example}"
        ))
    }
}
