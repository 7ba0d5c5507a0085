//! The half-block cells of a heatmap row written in the fewest bytes: which glyph, foreground
//! and background each cell takes, given the colour codes of its two halves.

use super::MOST_BANDS;

/// The colour code of the empty value (no contact); codes below it are bands.
pub(super) const EMPTY_CODE: u8 = MOST_BANDS as u8;
/// The colour code of the terminal's default colour, for a colour no glyph shows.
pub(super) const DEFAULT: u8 = EMPTY_CODE + 1;
/// Colour codes.
pub(super) const CODES: usize = DEFAULT as usize + 1;
/// The extra weight of a cell drawn in a form that depends on its neighbours (measured in bands
/// on four map presets at 120x40 in 256 colours, 20 frames: 0 writes a full draw 1-7 % smaller
/// and 27-137 % more a frame while time plays, 4 a full draw 0-2 % larger and 0-3 % less while
/// playing).
const APART: u32 = 2;

/// Bytes of the escape that changes the colours (foreground, background) from `a` to `b`, as
/// the terminal backend writes it: the changed ones in one code, `weight` the bytes of a
/// colour's parameter.
fn escape(weight: &[u32], a: (u8, u8), b: (u8, u8)) -> u32 {
    let w = |c: u8| weight[c as usize];
    match (a.0 != b.0, a.1 != b.1) {
        (false, false) => 0,
        (true, false) => 3 + w(b.0),
        (false, true) => 3 + w(b.1),
        (true, true) => 4 + w(b.0) + w(b.1),
    }
}

/// How to draw a row of text cells, each two half cells of colour codes (top, bottom), with the
/// fewest bytes: each cell's glyph, foreground and background code. The terminal backend writes
/// only the colours that differ from the cell written before (`backend`), so a cell of one
/// colour is a space on that background or a full block in that foreground, keeping the other
/// colour of its neighbours, and a cell of two colours is `▀` or `▄` (the same two colours
/// swapped). A search over the pair of colours after each cell (a shortest path); `weight`: the
/// bytes of each code's colour parameter.
pub(super) fn fewest_bytes(row: &[(u8, u8)], weight: &[u32]) -> Vec<(char, u8, u8)> {
    const STATES: usize = CODES * CODES;
    let index = |(f, b): (u8, u8)| f as usize * CODES + b as usize;
    let state = |i: usize| ((i / CODES) as u8, (i % CODES) as u8);
    // the glyph, the (foreground, background) it needs (None: the one before) and its weight:
    // its bytes, and more for the forms that depend on the neighbours (a cell whose colours did
    // not change then keeps its form while time plays, and is not written again)
    let options = |(a, b): (u8, u8)| -> Vec<(char, Option<u8>, Option<u8>, u32)> {
        if a == b {
            vec![
                (' ', Some(DEFAULT), Some(a), 1),
                (' ', None, Some(a), 1 + APART),
                ('█', Some(a), None, 3 + APART),
            ]
        } else {
            vec![
                ('▀', Some(a), Some(b), 3),
                ('▄', Some(b), Some(a), 3 + APART),
            ]
        }
    };
    // a row starts after text in the default colours
    let mut cost = vec![u32::MAX; STATES];
    cost[index((DEFAULT, DEFAULT))] = 0;
    // per cell and state after it: the state before and the option taken
    let mut from = vec![[(0u16, 0u8); STATES]; row.len()];
    for (i, &cell) in row.iter().enumerate() {
        let mut next = vec![u32::MAX; STATES];
        let options = options(cell);
        for (s, &c) in cost.iter().enumerate().filter(|(_, c)| **c < u32::MAX) {
            let (f, b) = state(s);
            for (k, &(_, need_f, need_b, glyph)) in options.iter().enumerate() {
                let after = (need_f.unwrap_or(f), need_b.unwrap_or(b));
                let bytes = c + glyph + escape(weight, (f, b), after);
                if bytes < next[index(after)] {
                    next[index(after)] = bytes;
                    from[i][index(after)] = (s as u16, k as u8);
                }
            }
        }
        cost = next;
    }
    // back from the cheapest end
    let mut s = (0..STATES).min_by_key(|&s| cost[s]).unwrap_or(0);
    let mut cells = vec![(' ', DEFAULT, DEFAULT); row.len()];
    for i in (0..row.len()).rev() {
        let (before, k) = from[i][s];
        let (f, b) = state(s);
        cells[i] = (options(row[i])[k as usize].0, f, b);
        s = before as usize;
    }
    cells
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bytes of a 256-colour level's parameter (`38;5;n`, n of two digits) and of the
    /// default's (`39`).
    const WEIGHT: [u32; CODES] = {
        let mut w = [7; CODES];
        w[DEFAULT as usize] = 2;
        w
    };

    /// Bytes of a row as the terminal backend writes it: each glyph, and the escape of the
    /// colours that differ from the cell before.
    fn bytes(cells: &[(char, u8, u8)]) -> u32 {
        let mut last = (DEFAULT, DEFAULT);
        let mut sum = 0;
        for &(glyph, f, b) in cells {
            sum += glyph.len_utf8() as u32 + escape(&WEIGHT, last, (f, b));
            last = (f, b);
        }
        sum
    }

    #[test]
    fn each_cell_shows_its_two_colours_in_no_more_bytes_than_one_form_for_all() {
        // rows of a smooth ramp, of noise (a linear congruential generator) and with empty cells
        let mut seed = 7u32;
        let mut noise = || {
            seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12_345);
            ((seed >> 16) % 5) as u8
        };
        let ramp: Vec<(u8, u8)> = (0..50).map(|i| (i / 7, (i + 1) / 7)).collect();
        let noisy: Vec<(u8, u8)> = (0..50).map(|_| (noise(), noise())).collect();
        let holes: Vec<(u8, u8)> = (0..50u8)
            .map(|i| {
                if i % 7 < 3 {
                    (EMPTY_CODE, i / 10)
                } else {
                    (i / 10, i / 10)
                }
            })
            .collect();
        for row in [ramp, noisy, holes] {
            let cells = fewest_bytes(&row, &WEIGHT);
            for (&(top, bottom), &(glyph, f, b)) in row.iter().zip(&cells) {
                let shown = match glyph {
                    ' ' => (b, b),
                    '█' => (f, f),
                    '▀' => (f, b),
                    '▄' => (b, f),
                    other => panic!("glyph {other}"),
                };
                assert_eq!(shown, (top, bottom), "{cells:?}");
            }
            // the one form for all: a space on its colour, else the upper half in the foreground
            let plain: Vec<(char, u8, u8)> = row
                .iter()
                .map(|&(a, b)| {
                    if a == b {
                        (' ', DEFAULT, a)
                    } else {
                        ('▀', a, b)
                    }
                })
                .collect();
            assert!(bytes(&cells) <= bytes(&plain), "{row:?}");
        }
    }
}
