//! Prose written by people (a preset's description, a lesson's question, the help) as a phrase:
//! its words, with those that belong together kept as one piece by the rules of typesetting: a
//! number and its unit ("5 MPa"), a key pair ("[ ]"), both sides of a relation ("t = 62.6 s"),
//! a group's name of two words ("mu chi") and a short parenthesis holding a relation. Text the
//! program writes itself says its pieces when it is written (`Phrase`) and never comes here.

use crate::phrase::Phrase;
use crate::preset::Problem;
use crate::sweeps::quantity::problem_groups;

/// The pieces of `text`: its words, glued where they belong together; a parenthesis is kept
/// whole only up to `most` columns (and never beyond `PAREN`).
pub fn phrase(text: &str, most: usize) -> Phrase {
    let mut words: Vec<String> = Vec::new();
    let tokens = runs_kept_whole(text.split_whitespace().collect(), most.min(PAREN));
    for (i, word) in tokens.iter().enumerate() {
        let word = word.as_str();
        let after = tokens.get(i + 1).map_or("", String::as_str);
        match words.last_mut() {
            Some(last) if stays_on_line(last, word) || symbol_pair(last, word, after) => {
                last.push(' ');
                last.push_str(word);
            }
            _ => words.push(word.to_string()),
        }
    }
    words.into_iter().fold(Phrase::default(), Phrase::then)
}

/// The longest parenthesis kept on one line: a value with its name, not a clause (which would
/// leave a line of prose half empty).
const PAREN: usize = 32;

/// `tokens` with the runs that stay whole joined by spaces: a group's name of two words, and a
/// parenthesis (from a word that opens one to the word that closes it) that holds a relation,
/// of at most `most` columns.
fn runs_kept_whole(tokens: Vec<&str>, most: usize) -> Vec<String> {
    let names: Vec<&str> = [Problem::Plane, Problem::Spatial]
        .into_iter()
        .flat_map(problem_groups)
        .map(|q| q.symbol)
        .filter(|s| s.contains(' '))
        .collect();
    // "(k m", "mu chi),": a name with the punctuation around it
    let group_name = |a: &str, b: &str| {
        let pair = format!("{a} {b}");
        let core = pair.trim_start_matches(['(', '"']);
        names.iter().any(|n| {
            core.strip_prefix(n)
                .is_some_and(|rest| rest.chars().all(|c| ")],.;:\"".contains(c)))
        })
    };
    let mut out = Vec::new();
    let mut i = 0;
    while i < tokens.len() {
        let mut end = i + 1;
        // a parenthesis opened here, closed within `most` columns, with a relation inside
        let mut depth = 0i32;
        let mut len = 0;
        for (k, t) in tokens.iter().enumerate().skip(i) {
            depth += t.matches('(').count() as i32 - t.matches(')').count() as i32;
            len += t.chars().count() + usize::from(k > i);
            if depth <= 0 || len > most {
                let relation = tokens[i..=k].iter().any(|t| RELATIONS.contains(t));
                if k > i && depth <= 0 && len <= most && relation {
                    end = k + 1;
                }
                break;
            }
        }
        if end == i + 1 && i + 1 < tokens.len() && group_name(tokens[i], tokens[i + 1]) {
            end = i + 2;
        }
        out.push(tokens[i..end].join(" "));
        i = end;
    }
    out
}

/// The words that relate the ones on either side ("t = 62.6 s"): a line never breaks at them.
const RELATIONS: [&str; 5] = ["=", "<", ">", "<=", ">="];

/// Whether a name of two short symbols before a relation stays whole ("k m = 0.11", "mu chi =
/// 0.3"): `word` (the words glued so far) ends in a symbol, `next` is one and `after` relates.
fn symbol_pair(word: &str, next: &str, after: &str) -> bool {
    // short words that are English, not symbols ("at h = 1 um")
    const WORDS: [&str; 12] = [
        "at", "to", "in", "of", "is", "on", "by", "as", "an", "or", "if", "so",
    ];
    let symbol = |w: &str, most: usize| {
        let w = w.trim_start_matches('(');
        (1..=most).contains(&w.len())
            && w.chars().all(|c| c.is_ascii_alphabetic())
            && !WORDS.contains(&w)
    };
    let last = word.rsplit(' ').next().unwrap_or(word);
    RELATIONS.contains(&after) && symbol(last, 2) && symbol(next, 3)
}

/// Whether `next` stays on the line of `word` (the words glued so far): a unit after a number,
/// "]" after "[", "}" after "{", a relation ("=", "<", ...) and what it relates.
fn stays_on_line(word: &str, next: &str) -> bool {
    const UNITS: [&str; 9] = ["m", "s", "Pa", "N/m", "m/s", "rad", "rad/m", "1/Pa", "%"];
    const PREFIXES: [&str; 10] = ["", "f", "p", "n", "u", "m", "k", "M", "G", "T"];
    if (word == "[" && next.starts_with(']')) || (word == "{" && next.starts_with('}')) {
        return true;
    }
    let last = word.rsplit(' ').next().unwrap_or(word);
    if RELATIONS.contains(&next) || RELATIONS.contains(&last) {
        return true;
    }
    let word = last;
    let number = word.trim_start_matches(['(', '~']).parse::<f64>().is_ok();
    let unit = next.trim_end_matches([')', ',', '.', ';', ':']);
    number
        && UNITS.iter().any(|u| {
            unit.strip_suffix(u)
                .is_some_and(|prefix| PREFIXES.contains(&prefix))
        })
}
