//! Text made of pieces that a line break never splits: a word, or a value with its unit and
//! name ("t = 62.6 s", "(a+b)/h < 0.26"). Whoever writes a sentence says which words belong
//! together; a screen that wraps it breaks only between pieces and never reads the text again.

use std::fmt;

/// A sentence as pieces kept whole, written with one space between pieces.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Phrase {
    pieces: Vec<String>,
}

impl Phrase {
    /// Each word of `text` (split at whitespace) a piece of its own.
    pub fn words(text: &str) -> Self {
        Phrase::default().then_words(text)
    }

    /// `text` as one piece, never broken where a line has room for it.
    pub fn whole(text: impl Into<String>) -> Self {
        Phrase::default().then(text)
    }

    /// This phrase followed by `text` as one piece.
    pub fn then(mut self, text: impl Into<String>) -> Self {
        let text = text.into();
        if !text.trim().is_empty() {
            self.pieces.push(text);
        }
        self
    }

    /// This phrase followed by each word of `text`.
    pub fn then_words(mut self, text: &str) -> Self {
        self.pieces
            .extend(text.split_whitespace().map(str::to_string));
        self
    }

    /// This phrase with `tail` written right after its last piece ("62.6 s" and ", then:").
    pub fn ending(mut self, tail: &str) -> Self {
        match self.pieces.last_mut() {
            Some(last) => last.push_str(tail),
            None => self.pieces.push(tail.to_string()),
        }
        self
    }

    /// This phrase followed by the pieces of `other`.
    pub fn then_phrase(mut self, other: Phrase) -> Self {
        self.pieces.extend(other.pieces);
        self
    }

    /// The pieces, in order.
    pub fn pieces(&self) -> &[String] {
        &self.pieces
    }
}

impl From<String> for Phrase {
    /// The whole text as one piece.
    fn from(text: String) -> Self {
        Phrase::whole(text)
    }
}

impl From<&str> for Phrase {
    fn from(text: &str) -> Self {
        Phrase::words(text)
    }
}

impl fmt::Display for Phrase {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.pieces.join(" "))
    }
}

#[cfg(test)]
mod tests {
    use super::Phrase;

    #[test]
    fn pieces_are_written_one_space_apart_and_kept_whole() {
        let p = Phrase::words("wide needs")
            .then("(a+b)/h < 0.26")
            .then_words("here,  not")
            .then("0.405");
        assert_eq!(p.to_string(), "wide needs (a+b)/h < 0.26 here, not 0.405");
        assert_eq!(p.pieces()[2], "(a+b)/h < 0.26");
        assert_eq!(p.pieces().len(), 6);
        assert!(Phrase::whole("  ").pieces().is_empty());
    }
}
