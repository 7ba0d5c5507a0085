//! Text wrapped to a width: prose at spaces with values and their units kept whole (`wrap`),
//! within a number of rows (`wrap_within`), and items packed into lines whole (`pack`).

use crate::preset::Problem;
use crate::sweeps::quantity::problem_groups;
use crate::tui::view::long_words;
use crate::tui::view::theme::RenderOptions;
use unicode_width::UnicodeWidthStr;

/// Packs items into lines of at most `width` columns, two spaces apart, never splitting an item
/// that fits a line (one longer than a line is wrapped by `wrap`, whole values together);
/// continuation lines start with `indent`.
pub fn pack(items: &[String], width: usize, indent: &str) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for item in items {
        let len = line.chars().count();
        if !line.is_empty() && len + 2 + item.chars().count() > width {
            lines.push(std::mem::replace(&mut line, indent.to_string()));
        } else if !line.is_empty() && line != indent {
            line.push_str("  ");
        }
        let room = width.saturating_sub(line.chars().count());
        if item.chars().count() <= room {
            line.push_str(item);
            continue;
        }
        // too long for any line: wrapped, each part on a line of its own but the last
        let mut parts = wrap(item, width.saturating_sub(indent.len()).max(1)).into_iter();
        if let Some(first) = parts.next() {
            line.push_str(&first);
        }
        for part in parts {
            lines.push(std::mem::replace(&mut line, format!("{indent}{part}")));
        }
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// `pack` in at most `rows` lines: where the items do not fit, the first ones that do with a
/// count of the others ("+2 more") after them; no line at all when not even that fits.
pub fn pack_within(items: &[String], width: usize, indent: &str, rows: usize) -> Vec<String> {
    let lines = pack(items, width, indent);
    if lines.len() <= rows {
        return lines;
    }
    (0..items.len())
        .rev()
        .map(|shown| {
            let mut kept = items[..shown].to_vec();
            kept.push(format!("+{} more", items.len() - shown));
            pack(&kept, width, indent)
        })
        .find(|lines| lines.len() <= rows)
        .unwrap_or_default()
}

/// Wraps `text` into lines of at most `width` columns at spaces, never between a number and its
/// unit ("5 MPa", "1 um"), inside a key pair ("[ ]", "{ }"), on either side of a relation
/// ("t = 62.6 s", "residual < 1e-14"), inside a group's name of two words ("mu chi", "P/(m R)":
/// the library's names, `problem_groups`) nor inside a parenthesis that holds a relation, of at
/// most `PAREN` columns and fitting the line ("(narrow: P = 10.0 kN/m)"); a single word wider
/// than half the line (a path) is broken to fill the lines (`long_words`).
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut words: Vec<String> = Vec::new();
    let tokens = runs_kept_whole(text.split_whitespace().collect(), width.min(PAREN));
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
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in &words {
        // a single word wider than half a line (a path; not a group kept whole) starts on this
        // line where enough is left of it, and goes on below
        let long = width > 0 && !word.contains(' ') && word.width() > width / 2;
        let room = width.saturating_sub(line.width() + usize::from(!line.is_empty()));
        let parts = match (long, room >= long_words::LEAST_START) {
            (false, _) => vec![word.clone()],
            (true, true) => long_words::pieces(word, room, width),
            (true, false) => long_words::pieces(word, width, width),
        };
        for (k, part) in parts.iter().enumerate() {
            if !line.is_empty() && (k > 0 || line.width() + 1 + part.width() > width) {
                lines.push(std::mem::take(&mut line));
            }
            if !line.is_empty() {
                line.push(' ');
            }
            line.push_str(part);
        }
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// `wrap` in at most `rows` lines: a text longer still ends in "…" (`...` with `--ascii`) after
/// its last whole clause on the last line (after a ',' or ';') where that keeps half the line,
/// else after its last whole word; never cut inside a word, but for a word wider than the line.
pub fn wrap_within(text: &str, width: usize, rows: usize, style: RenderOptions) -> Vec<String> {
    let mut lines = wrap(text, width);
    if lines.len() <= rows {
        return lines;
    }
    lines.truncate(rows);
    let Some(last) = lines.last_mut() else {
        return lines;
    };
    let more = style.text(" …");
    let room = width.saturating_sub(more.chars().count());
    // (chars up to the clause's end, its end in bytes)
    let clause = last
        .char_indices()
        .enumerate()
        .filter(|&(n, (_, c))| matches!(c, ',' | ';') && n < room)
        .map(|(n, (i, _))| (n + 1, i + 1))
        .max();
    match clause {
        Some((chars, end)) if chars * 2 >= room => last.truncate(end),
        _ => {
            while last.width() > room {
                match last.rfind(' ') {
                    Some(i) => last.truncate(i),
                    // a piece of a word wider than the line: as much of it as fits
                    None => {
                        let piece = long_words::pieces(last, room, room).swap_remove(0);
                        *last = if piece.width() <= room {
                            piece
                        } else {
                            String::new()
                        };
                    }
                }
            }
        }
    }
    last.push_str(&more);
    lines
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
