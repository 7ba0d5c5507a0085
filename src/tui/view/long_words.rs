//! A word wider than its line (a path, a file name, a long number) broken into pieces that fit,
//! so that a line is wrapped instead of cut at the screen's edge: after a '/' where one falls in
//! the second half of a piece, else after the last character that fits. Widths are display
//! columns (a wide character takes two, a combining mark none and stays with its letter).

use unicode_width::{UnicodeWidthChar, UnicodeWidthStr};

/// The fewest columns left on a line where a long word starts rather than on the next line.
pub const LEAST_START: usize = 12;

/// `word` in pieces: the first of at most `first` columns, the others of at most `width` (a
/// piece holds at least one character).
pub fn pieces(word: &str, first: usize, width: usize) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = word;
    let mut most = first.max(1);
    while rest.width() > most {
        let mut columns = 0;
        let mut end = 0;
        for (i, c) in rest.char_indices() {
            let w = c.width().unwrap_or(0);
            if end > 0 && columns + w > most {
                break;
            }
            columns += w;
            end = i + c.len_utf8();
        }
        let after_slash = rest[..end]
            .rfind('/')
            .map(|i| i + 1)
            .filter(|&i| i * 2 >= end && i < end);
        let cut = after_slash.unwrap_or(end);
        out.push(rest[..cut].to_string());
        rest = &rest[cut..];
        most = width.max(1);
    }
    if !rest.is_empty() || out.is_empty() {
        out.push(rest.to_string());
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_word_is_broken_into_pieces_that_fit() {
        assert_eq!(pieces("short", 10, 10), ["short"]);
        assert_eq!(pieces("", 10, 10), [""]);
        assert_eq!(
            pieces("/tmp/labs/2026/session-one.toml", 12, 12),
            ["/tmp/labs/", "2026/session", "-one.toml"]
        );
        assert_eq!(pieces("abcdefgh", 3, 3), ["abc", "def", "gh"]);
        // two columns each; a combining mark stays with its letter
        assert_eq!(pieces("😀😀😀", 5, 5), ["😀😀", "😀"]);
        assert_eq!(pieces("ee\u{301}e", 2, 2), ["ee\u{301}", "e"]);
        assert_eq!(pieces("😀", 1, 1), ["😀"]);
        // the first piece fills what is left of a line
        assert_eq!(pieces("abcdefgh", 2, 4), ["ab", "cdef", "gh"]);
    }
}
