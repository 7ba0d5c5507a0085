//! Text wrapped to a width: a phrase between the pieces its writer kept whole (`lines_of`),
//! prose written by people between the words that belong together (`wrap`), within a number of rows (`wrap_within`), and items packed
//! into lines whole (`pack`). Nothing here reads the words: what stays together was said by
//! whoever wrote them (`Phrase`).

use crate::phrase::Phrase;
use crate::tui::view::long_words;
use crate::tui::view::prose;
use crate::tui::view::theme::RenderOptions;
use unicode_width::UnicodeWidthStr;

/// Packs items into lines of at most `width` columns, two spaces apart, never splitting an item
/// that fits a line (one longer than a line is wrapped between its own pieces, `lines_of`; a
/// text is one piece); continuation lines start with `indent`.
pub fn pack<P: Clone + Into<Phrase>>(items: &[P], width: usize, indent: &str) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for item in items.iter().cloned().map(Into::into) {
        let item: Phrase = item;
        let text = item.to_string();
        let len = line.width();
        if !line.is_empty() && len + 2 + text.width() > width {
            lines.push(std::mem::replace(&mut line, indent.to_string()));
        } else if !line.is_empty() && line != indent {
            line.push_str("  ");
        }
        let room = width.saturating_sub(line.width());
        if text.width() <= room {
            line.push_str(&text);
            continue;
        }
        // too long for any line: wrapped, each part on a line of its own but the last
        let mut parts = lines_of(&item, width.saturating_sub(indent.len()).max(1)).into_iter();
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

/// The count of the items a crowded status leaves out, with the key whose window shows them all
/// (`i`: the status in full).
pub fn more(n: usize) -> String {
    format!("+{n} more: i")
}

/// `pack` in at most `rows` lines: where the items do not fit, the first ones that do with a
/// count of the others ("+2 more: i") after them; no line at all when not even that fits.
pub fn pack_within<P: Clone + Into<Phrase>>(
    items: &[P],
    width: usize,
    indent: &str,
    rows: usize,
) -> Vec<String> {
    let items: Vec<Phrase> = items.iter().cloned().map(Into::into).collect();
    let lines = pack(&items, width, indent);
    if lines.len() <= rows {
        return lines;
    }
    (0..items.len())
        .rev()
        .map(|shown| {
            let mut kept = items[..shown].to_vec();
            kept.push(Phrase::whole(more(items.len() - shown)));
            pack(&kept, width, indent)
        })
        .find(|lines| lines.len() <= rows)
        .unwrap_or_default()
}

/// `pack_within`, leaving out first the items at the indices `give_up` names, in its order (their
/// count "+2 more: i" after the others), and only then the last ones.
pub fn pack_giving_up<P: Clone + Into<Phrase>>(
    items: &[P],
    width: usize,
    rows: usize,
    give_up: &[usize],
) -> Vec<String> {
    let items: Vec<Phrase> = items.iter().cloned().map(Into::into).collect();
    let lines = pack(&items, width, "");
    if lines.len() <= rows {
        return lines;
    }
    (1..=give_up.len())
        .map(|n| {
            let mut kept: Vec<Phrase> = (items.iter().enumerate())
                .filter(|(i, _)| !give_up[..n].contains(i))
                .map(|(_, item)| item.clone())
                .collect();
            kept.push(Phrase::whole(more(n)));
            pack(&kept, width, "")
        })
        .find(|lines| lines.len() <= rows)
        .unwrap_or_else(|| pack_within(&items, width, "", rows))
}

/// Wraps prose written by people into lines of at most `width` columns, never between the words
/// that belong together (`prose::phrase`: "5 MPa", "t = 62.6 s", "[ ] move").
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    lines_of(&prose::phrase(text, width), width)
}

/// Wraps `phrase` into lines of at most `width` columns between its pieces, each piece whole
/// where a line has room for it: a piece wider than the line is broken at its spaces, and a
/// single word wider than half the line (a path) is broken to fill the lines (`long_words`).
pub fn lines_of(phrase: &Phrase, width: usize) -> Vec<String> {
    let words = phrase.pieces().iter().flat_map(|piece| {
        if piece.width() > width && piece.contains(' ') {
            piece.split_whitespace().map(str::to_string).collect()
        } else {
            vec![piece.clone()]
        }
    });
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in words {
        // a single word wider than half a line (a path; not a piece of several words) starts on
        // this line where enough is left of it, and goes on below
        let long = width > 0 && !word.contains(' ') && word.width() > width / 2;
        let room = width.saturating_sub(line.width() + usize::from(!line.is_empty()));
        let parts = match (long, room >= long_words::LEAST_START) {
            (false, _) => vec![word],
            (true, true) => long_words::pieces(&word, room, width),
            (true, false) => long_words::pieces(&word, width, width),
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

/// `lines_of` in at most `rows` lines: a phrase longer still ends in "…" (`...` with `--ascii`) after
/// its last whole clause on the last line (after a ',' or ';') where that keeps half the line,
/// else after its last whole word; never cut inside a word, but for a word wider than the line.
pub fn wrap_within(
    phrase: &Phrase,
    width: usize,
    rows: usize,
    style: RenderOptions,
) -> Vec<String> {
    let mut lines = lines_of(phrase, width);
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
