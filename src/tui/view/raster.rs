//! Curves rasterized into terminal cells: Braille dots (2 x 4 per cell) in colour, or one
//! character per cell, each curve its own (`*`, `+`, ...) so that curves stay apart without
//! colour. The raster knows which cells hold data, so that nothing else is drawn on them.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;

use crate::tui::charts::range::clip;

/// How a curve is drawn: its character (in character mode, or always for `solid` curves) and
/// style.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ink {
    /// The character of the curve in character mode.
    pub glyph: char,
    /// Drawn with its glyph even on a Braille raster (pins, markers).
    pub solid: bool,
    /// In character cells, the character of every other column (a pinned curve in character
    /// mode: the pin's number and the curve's own glyph in turn, "1+1+", so that the pinned
    /// curves of a pin stay apart without colour).
    pub second: Option<char>,
    /// Colour and modifiers.
    pub style: Style,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Cell {
    Empty,
    /// Braille dot bits.
    Dots(u8, Ink),
    /// One character.
    Glyph(Ink),
}

/// A grid of cells over a plot area.
#[derive(Clone, Debug)]
pub struct Raster {
    width: u16,
    height: u16,
    braille: bool,
    cells: Vec<Cell>,
}

/// The Braille bit of dot (column 0..2, row 0..4) of a cell.
const BITS: [[u8; 4]; 2] = [[0x01, 0x02, 0x04, 0x40], [0x08, 0x10, 0x20, 0x80]];

impl Raster {
    /// An empty raster of `width` x `height` cells.
    pub fn new(width: u16, height: u16, braille: bool) -> Raster {
        Raster {
            width,
            height,
            braille,
            cells: vec![Cell::Empty; width as usize * height as usize],
        }
    }

    /// Dots per cell across and down for an ink.
    fn resolution(&self, ink: Ink) -> (f64, f64) {
        if self.braille && !ink.solid {
            (2.0, 4.0)
        } else {
            (1.0, 1.0)
        }
    }

    /// Marks one dot, in dot coordinates of the ink's resolution (inside the raster).
    fn dot(&mut self, dx: i64, dy: i64, ink: Ink) {
        let (rx, ry) = self.resolution(ink);
        let (col, row) = (dx / rx as i64, dy / ry as i64);
        if col < 0 || row < 0 || col >= self.width as i64 || row >= self.height as i64 {
            return;
        }
        let cell = &mut self.cells[row as usize * self.width as usize + col as usize];
        if rx == 1.0 {
            *cell = Cell::Glyph(match ink.second {
                Some(glyph) if col % 2 == 1 => Ink { glyph, ..ink },
                _ => ink,
            });
            return;
        }
        let bit = BITS[(dx % 2) as usize][(dy % 4) as usize];
        *cell = match *cell {
            Cell::Dots(bits, _) => Cell::Dots(bits | bit, ink),
            _ => Cell::Dots(bit, ink),
        };
    }

    /// Dot coordinates of a point given as fractions of the area (x from the left, y from the
    /// bottom, 0..1).
    fn to_dots(&self, (fx, fy): (f64, f64), ink: Ink) -> (f64, f64) {
        let (rx, ry) = self.resolution(ink);
        let w = self.width as f64 * rx - 1.0;
        let h = self.height as f64 * ry - 1.0;
        (fx * w, (1.0 - fy) * h)
    }

    /// Draws a polyline through points given as fractions of the area; segments are clipped to
    /// it.
    pub fn line(&mut self, points: &[(f64, f64)], ink: Ink) {
        if let [only] = points {
            self.point(*only, ink);
        }
        for pair in points.windows(2) {
            let (a, b) = (self.to_dots(pair[0], ink), self.to_dots(pair[1], ink));
            let (rx, ry) = self.resolution(ink);
            let limits = (self.width as f64 * rx - 1.0, self.height as f64 * ry - 1.0);
            if let Some((a, b)) = clip(a, b, [0.0, limits.0], [0.0, limits.1]) {
                self.segment(a, b, ink);
            }
        }
    }

    /// Marks the cell of one point given as fractions of the area (nothing outside it).
    pub fn point(&mut self, p: (f64, f64), ink: Ink) {
        if !(0.0..=1.0).contains(&p.0) || !(0.0..=1.0).contains(&p.1) {
            return;
        }
        let (x, y) = self.to_dots(p, ink);
        self.dot(x.round() as i64, y.round() as i64, ink);
    }

    /// Bresenham between two dot positions inside the raster.
    fn segment(&mut self, a: (f64, f64), b: (f64, f64), ink: Ink) {
        let (mut x, mut y) = (a.0.round() as i64, a.1.round() as i64);
        let (x1, y1) = (b.0.round() as i64, b.1.round() as i64);
        let (dx, dy) = ((x1 - x).abs(), -(y1 - y).abs());
        let (sx, sy) = ((x1 - x).signum(), (y1 - y).signum());
        let mut err = dx + dy;
        // at most dx - dy + 1 dots, both bounded by the raster's size
        for _ in 0..=(dx - dy) {
            self.dot(x, y, ink);
            if x == x1 && y == y1 {
                break;
            }
            let e2 = 2 * err;
            if e2 >= dy {
                err += dy;
                x += sx;
            }
            if e2 <= dx {
                err += dx;
                y += sy;
            }
        }
    }

    /// True when the cell (column, row) holds data.
    pub fn occupied(&self, col: u16, row: u16) -> bool {
        col < self.width
            && row < self.height
            && self.cells[row as usize * self.width as usize + col as usize] != Cell::Empty
    }

    /// How many cells of a rectangle (raster cells) hold data.
    pub fn count(&self, rect: Rect) -> usize {
        (rect.y..rect.y + rect.height)
            .flat_map(|r| (rect.x..rect.x + rect.width).map(move |c| (c, r)))
            .filter(|&(c, r)| self.occupied(c, r))
            .count()
    }

    /// Writes the cells that hold data into `buf` at `area`'s corner.
    pub fn render(&self, buf: &mut Buffer, area: Rect) {
        for row in 0..self.height.min(area.height) {
            for col in 0..self.width.min(area.width) {
                let (glyph, style) =
                    match self.cells[row as usize * self.width as usize + col as usize] {
                        Cell::Empty => continue,
                        Cell::Dots(bits, ink) => (
                            char::from_u32(0x2800 + bits as u32).unwrap_or(ink.glyph),
                            ink.style,
                        ),
                        Cell::Glyph(ink) => (ink.glyph, ink.style),
                    };
                buf[(area.x + col, area.y + row)]
                    .set_char(glyph)
                    .set_style(style);
            }
        }
    }
}
