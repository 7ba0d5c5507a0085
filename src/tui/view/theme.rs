//! Colours and styles, with the fallbacks for NO_COLOR and `--ascii`.

use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::Marker;

/// How to draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderOptions {
    /// Plain ASCII markers instead of Braille.
    pub ascii: bool,
    /// Colours allowed (NO_COLOR unset).
    pub color: bool,
}

const SERIES: [Color; 6] = [
    Color::Cyan,
    Color::Yellow,
    Color::Magenta,
    Color::Green,
    Color::Red,
    Color::Blue,
];

/// The shades of the heatmap without colour, lightest first.
pub const SHADES: [char; 5] = [' ', '░', '▒', '▓', '█'];

impl RenderOptions {
    /// Errors and warnings: red, or bold without colour.
    pub fn error(self) -> Style {
        if self.color {
            Style::default().fg(Color::Red)
        } else {
            Style::default().add_modifier(Modifier::BOLD)
        }
    }

    /// A verdict that holds: green, or plain.
    pub fn ok(self) -> Style {
        if self.color {
            Style::default().fg(Color::Green)
        } else {
            Style::default()
        }
    }

    /// A result for other inputs than the form's (shown while the current one is solving).
    pub fn stale(self) -> Style {
        Style::default().add_modifier(Modifier::DIM)
    }

    /// The selected row or list entry.
    pub fn selected(self) -> Style {
        Style::default().add_modifier(Modifier::REVERSED)
    }

    /// A group heading.
    pub fn heading(self) -> Style {
        Style::default().add_modifier(Modifier::BOLD)
    }

    /// The footer's key list.
    pub fn footer(self) -> Style {
        Style::default().add_modifier(Modifier::DIM)
    }

    /// The i-th curve of a chart.
    pub fn series(self, i: usize) -> Style {
        if self.color {
            Style::default().fg(SERIES[i % SERIES.len()])
        } else {
            Style::default()
        }
    }

    /// Marked points.
    pub fn marker(self) -> Style {
        if self.color {
            Style::default()
                .fg(Color::White)
                .add_modifier(Modifier::BOLD)
        } else {
            Style::default()
        }
    }

    /// How curves are drawn.
    pub fn line_marker(self) -> Marker {
        if self.ascii {
            Marker::Dot
        } else {
            Marker::Braille
        }
    }

    /// The heatmap colour of t in [0, 1]: blue (low) through green to red (high).
    pub fn heat(self, t: f64) -> Color {
        let t = t.clamp(0.0, 1.0);
        let (r, g, b) = if t < 0.5 {
            let s = t / 0.5;
            (0.0, s, 1.0 - s)
        } else {
            let s = (t - 0.5) / 0.5;
            (s, 1.0 - s, 0.0)
        };
        let level = |v: f64| (40.0 + 215.0 * v) as u8;
        Color::Rgb(level(r), level(g), level(b))
    }

    /// The shade of t in [0, 1] without colour.
    pub fn shade(self, t: f64) -> char {
        SHADES[(t.clamp(0.0, 1.0) * 4.0).round() as usize]
    }
}
