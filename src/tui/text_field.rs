//! A line of typed text with a cursor: the value typed into a form row, the name in the save
//! prompt, a field of the sweep form. A value put there for the user (the field's value, a
//! proposed name) is replaced by the first character typed, as in a selected text box; ←→
//! Home End move the cursor and keep it for editing.

/// Typed text and where the next character goes.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TextField {
    text: String,
    /// The cursor, in characters from the start (0..=len).
    cursor: usize,
    /// A value put there, not typed: the first character typed replaces it.
    proposed: bool,
}

impl TextField {
    /// A value put there for the user, replaced by the first character typed.
    pub fn proposed(text: impl Into<String>) -> TextField {
        let text = text.into();
        TextField {
            cursor: text.chars().count(),
            text,
            proposed: true,
        }
    }

    /// The text.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// Whether the text is a value put there, which typing replaces.
    pub fn is_proposed(&self) -> bool {
        self.proposed
    }

    fn byte(&self, chars: usize) -> usize {
        self.text
            .char_indices()
            .nth(chars)
            .map_or(self.text.len(), |(i, _)| i)
    }

    /// Types `c` at the cursor (in place of a proposed value).
    pub fn insert(&mut self, c: char) {
        if self.proposed {
            *self = TextField::default();
        }
        let at = self.byte(self.cursor);
        self.text.insert(at, c);
        self.cursor += 1;
    }

    /// Deletes the character before the cursor (a proposed value whole).
    pub fn backspace(&mut self) {
        if self.proposed {
            *self = TextField::default();
        } else if self.cursor > 0 {
            self.cursor -= 1;
            let at = self.byte(self.cursor);
            self.text.remove(at);
        }
    }

    /// Moves the cursor: -1 left, +1 right, `isize::MIN` to the start, `isize::MAX` to the end;
    /// the text is then being edited, not replaced.
    pub fn move_cursor(&mut self, by: isize) {
        let len = self.text.chars().count();
        self.cursor = self.cursor.saturating_add_signed(by).min(len);
        self.proposed = false;
    }

    /// The text as drawn with its cursor: "_" after its end, "|" before a character; a proposed
    /// value in brackets ("[0.03]_"), to be replaced by typing.
    pub fn shown(&self) -> String {
        if self.proposed {
            return format!("[{}]_", self.text);
        }
        let at = self.byte(self.cursor);
        if at == self.text.len() {
            format!("{}_", self.text)
        } else {
            format!("{}|{}", &self.text[..at], &self.text[at..])
        }
    }
}

impl From<&str> for TextField {
    /// Text as if typed: the cursor at its end.
    fn from(text: &str) -> TextField {
        TextField {
            cursor: text.chars().count(),
            text: text.to_string(),
            proposed: false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn typing_replaces_a_proposed_value_and_edits_at_the_cursor() {
        let mut f = TextField::proposed("0.03");
        assert_eq!(f.shown(), "[0.03]_");
        for c in "0.1".chars() {
            f.insert(c);
        }
        assert_eq!((f.text(), f.shown().as_str()), ("0.1", "0.1_"));
        let mut f = TextField::proposed("0.03");
        f.move_cursor(-1);
        f.insert('5');
        assert_eq!((f.text(), f.shown().as_str()), ("0.053", "0.05|3"));
        f.move_cursor(isize::MIN);
        f.backspace();
        f.insert('-');
        assert_eq!(f.shown(), "-|0.053");
        f.move_cursor(isize::MAX);
        f.backspace();
        assert_eq!(f.text(), "-0.05");
        // multi-byte characters move and delete whole
        let mut f = TextField::from("5 µm");
        f.move_cursor(-1);
        f.backspace();
        assert_eq!(f.text(), "5 m");
        // Backspace on a proposed value clears it
        let mut f = TextField::proposed("lab");
        f.backspace();
        assert_eq!(f, TextField::default());
    }
}
