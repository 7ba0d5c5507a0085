//! `wearlab check PRESET`: the answer key of a preset's lesson, for the instructor. Each question
//! with the program's answer, in the unit of `wearlab solve --output` (`cli/solve_output.rs`),
//! at the question's inputs: by default two lines each (the question, then `KEY = value unit`
//! with the tolerance and whether students see the value); with `--format json` one array
//! `[{"text", "answer", "value", "unit"}]` (a yes/no answer's value true/false). A question the
//! solver cannot answer is exit 3 naming it, as `solve`.

use std::path::Path;
use std::process::ExitCode;

use clap::ValueEnum;

use wearlab::finite;
use wearlab::physics::SolveError;
use wearlab::preset::{Question, Tolerance};

use super::solve_output::number;
use super::{EXIT_INVALID, EXIT_UNSOLVABLE, load, print, say};

/// How the answer key is written.
#[derive(Clone, Copy, ValueEnum)]
pub enum CheckFormat {
    /// The question, then `KEY = value unit` (tolerance; shown to students or not).
    Text,
    /// `[{"text", "answer", "value", "unit"}]`.
    Json,
}

/// The value as text: true/false for a yes/no quantity, else `number`.
fn shown(q: &Question, v: f64) -> String {
    if q.answer.quantity().flag {
        (v != 0.0).to_string()
    } else {
        number(v)
    }
}

fn tolerance(q: &Question) -> String {
    let unit = q.answer.quantity().unit;
    match q.tolerance {
        _ if q.answer.quantity().flag => "yes or no".into(),
        Tolerance::Percent(p) => format!("within {p} %"),
        Tolerance::Absolute(a) if unit.is_empty() => format!("within {}", number(a)),
        Tolerance::Absolute(a) => format!("within {} {unit}", number(a)),
    }
}

/// Prints the answer key of the preset at `path`.
pub fn run(path: &Path, format: CheckFormat) -> ExitCode {
    let preset = match load(path) {
        Ok(p) => p,
        Err(code) => return code,
    };
    let questions = match &preset.lesson {
        Some(l) if !l.questions.is_empty() => &l.questions,
        _ => {
            say(&format!(
                "error: {}: the preset has no [[lesson.questions]] (docs/lessons.md says how to \
                 write them)",
                path.display()
            ));
            return ExitCode::from(EXIT_INVALID);
        }
    };
    let mut values = Vec::new();
    for (n, q) in questions.iter().enumerate() {
        match q.solve(&preset) {
            Ok(v) => values.push(v),
            Err(e) => {
                say(&format!("error: question {} (\"{}\"): {e}", n + 1, q.text));
                return ExitCode::from(match e {
                    SolveError::InvalidInput(_) => EXIT_INVALID,
                    SolveError::NoSolution(_) => EXIT_UNSOLVABLE,
                });
            }
        }
    }
    let guard = finite::check(&values);
    let text = match format {
        CheckFormat::Text => questions
            .iter()
            .zip(&values)
            .enumerate()
            .map(|(n, (q, &v))| {
                let unit = match q.answer.quantity().unit {
                    u if u.is_empty() || q.answer.quantity().flag => String::new(),
                    u => format!(" {u}"),
                };
                let at = if q.at.is_empty() {
                    String::new()
                } else {
                    format!("; at {}", q.at.join(", "))
                };
                let seen = if q.reveal { "shown" } else { "not shown" };
                format!(
                    "{}. {}\n   {} = {}{unit}  ({}{at}; {seen} to students)\n",
                    n + 1,
                    q.text,
                    q.answer,
                    shown(q, v),
                    tolerance(q)
                )
            })
            .collect(),
        CheckFormat::Json => {
            // each object's keys in the documented order (serde_json's own map would sort them)
            let str = |t: &str| serde_json::Value::String(t.to_string());
            let items: Vec<String> = questions
                .iter()
                .zip(&values)
                .map(|(q, &v)| {
                    let value = if q.answer.quantity().flag {
                        serde_json::Value::Bool(v != 0.0)
                    } else {
                        serde_json::json!(v)
                    };
                    format!(
                        "  {{\"text\": {}, \"answer\": {}, \"value\": {value}, \"unit\": {}}}",
                        str(&q.text),
                        str(&q.answer.to_string()),
                        str(q.answer.quantity().unit)
                    )
                })
                .collect();
            format!("[\n{}\n]\n", items.join(",\n"))
        }
    };
    print(&text, guard)
}
