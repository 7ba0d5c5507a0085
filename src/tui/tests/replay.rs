//! The explorer's terminal backend (`backend`) checked by a route of its own: its bytes are
//! replayed through a terminal emulator (the vt100 crate), and after every draw each cell the
//! emulator shows must have the symbol, colours and attributes of ratatui's buffer. Over a full
//! redraw, time playing, edits, the help opening and closing, another chart and resizes, in 256
//! colours, 24-bit colour, without colour and with ASCII.

use std::cell::RefCell;
use std::io::Write;
use std::rc::Rc;

use ratatui::Terminal;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::KeyCode;
use ratatui::layout::Size;
use ratatui::style::{Color, Modifier};

use super::*;
use crate::tui::backend::Compact;

/// A writer that keeps what goes through it until taken.
#[derive(Clone, Default)]
struct Sink(Rc<RefCell<Vec<u8>>>);

impl Write for Sink {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0.borrow_mut().extend_from_slice(buf);
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// A terminal whose bytes an emulator receives.
struct Replay {
    terminal: Terminal<Compact<Sink>>,
    sink: Sink,
    emulator: vt100::Parser,
    style: RenderOptions,
}

impl Replay {
    fn new(w: u16, h: u16, style: RenderOptions) -> Replay {
        let sink = Sink::default();
        let mut backend = Compact::new(sink.clone());
        backend.set_size(Size::new(w, h));
        Replay {
            terminal: Terminal::new(backend).unwrap(),
            sink,
            emulator: vt100::Parser::new(nonzero(h), nonzero(w), 0),
            style,
        }
    }

    /// Draws the app, feeds the bytes to the emulator and compares every cell; the bytes.
    fn draw(&mut self, app: &App, what: &str) -> usize {
        let style = self.style;
        let buffer = self
            .terminal
            .draw(|f| view(app, style, f))
            .unwrap()
            .buffer
            .clone();
        let bytes = std::mem::take(&mut *self.sink.0.borrow_mut());
        self.emulator.process(&bytes);
        same(&buffer, self.emulator.screen(), what);
        bytes.len()
    }

    /// The terminal takes a new size (ratatui clears it and draws everything at the next draw).
    fn resize(&mut self, w: u16, h: u16) {
        self.terminal.backend_mut().set_size(Size::new(w, h));
        self.emulator.screen_mut().set_size(nonzero(h), nonzero(w));
    }
}

fn nonzero(n: u16) -> std::num::NonZeroU16 {
    std::num::NonZeroU16::new(n).unwrap()
}

/// The emulator's colour of a ratatui colour (the 16 named colours are the palette's first 16).
fn colour(c: Color) -> vt100::Color {
    let named = [
        Color::Black,
        Color::Red,
        Color::Green,
        Color::Yellow,
        Color::Blue,
        Color::Magenta,
        Color::Cyan,
        Color::Gray,
        Color::DarkGray,
        Color::LightRed,
        Color::LightGreen,
        Color::LightYellow,
        Color::LightBlue,
        Color::LightMagenta,
        Color::LightCyan,
        Color::White,
    ];
    match c {
        Color::Reset => vt100::Color::Default,
        Color::Indexed(i) => vt100::Color::Idx(i),
        Color::Rgb(r, g, b) => vt100::Color::Rgb(r, g, b),
        named_colour => {
            vt100::Color::Idx(named.iter().position(|&n| n == named_colour).unwrap() as u8)
        }
    }
}

/// Every cell of the buffer as the emulator shows it.
fn same(buffer: &Buffer, screen: &vt100::Screen, what: &str) {
    // the attributes the emulator keeps, bold and dim not together; the explorer uses no others
    let kept = Modifier::BOLD
        | Modifier::DIM
        | Modifier::ITALIC
        | Modifier::UNDERLINED
        | Modifier::REVERSED;
    let area = buffer.area;
    assert_eq!(
        screen.size(),
        (nonzero(area.height), nonzero(area.width)),
        "{what}"
    );
    let has = |c: &ratatui::buffer::Cell, m: Modifier| c.modifier.contains(m);
    for y in area.top()..area.bottom() {
        // the column right of a two-column symbol shows that symbol's second half
        let mut covered = false;
        for x in area.left()..area.right() {
            if std::mem::take(&mut covered) {
                continue;
            }
            let want = &buffer[(x, y)];
            covered = unicode_width::UnicodeWidthStr::width(want.symbol()) == 2;
            let got = screen.cell(y, x).unwrap();
            let symbol = match got.contents() {
                "" => " ",
                s => s,
            };
            let shown = (
                symbol,
                got.fgcolor(),
                got.bgcolor(),
                [
                    got.bold(),
                    got.dim(),
                    got.italic(),
                    got.underline(),
                    got.inverse(),
                ],
            );
            let wanted = (
                want.symbol(),
                colour(want.fg),
                colour(want.bg),
                [
                    has(want, Modifier::BOLD),
                    has(want, Modifier::DIM),
                    has(want, Modifier::ITALIC),
                    has(want, Modifier::UNDERLINED),
                    has(want, Modifier::REVERSED),
                ],
            );
            assert!(
                kept.contains(want.modifier)
                    && !want.modifier.contains(Modifier::BOLD | Modifier::DIM),
                "{what}: ({x}, {y}) {want:?}"
            );
            // (symbol, foreground, background, [bold, dim, italic, underlined, reversed])
            assert_eq!(shown, wanted, "{what}: cell ({x}, {y})");
        }
    }
}

/// Colour with ASCII charts (`--ascii` without NO_COLOR).
const ASCII_COLOUR: RenderOptions = RenderOptions {
    ascii: true,
    ..COLOUR
};

const TRUECOLOR: RenderOptions = RenderOptions {
    truecolor: true,
    ..COLOUR
};

#[test]
fn what_the_backend_writes_shows_the_buffer_in_a_terminal_emulator() {
    for style in [COLOUR, TRUECOLOR, PLAIN, ASCII, ASCII_COLOUR] {
        let mut app = solved("jgh-egg-box.toml");
        let mut t = Replay::new(120, 40, style);
        t.draw(&app, "full redraw");
        app.ui.playing = true;
        for frame in 0..8 {
            let cmds = update(&mut app, Msg::Tick);
            settle(&mut app, cmds);
            t.draw(&app, &format!("playing, frame {frame}"));
        }
        app.ui.playing = false;
        t.draw(&app, "paused");
        // a nudge, then a value typed (the edit field shows while typing) and left
        select(&mut app, "pbar", None);
        let cmds = press(&mut app, KeyCode::Right);
        settle(&mut app, cmds);
        t.draw(&app, "nudged");
        press(&mut app, KeyCode::Enter);
        type_text(&mut app, "2 MPa");
        t.draw(&app, "typing");
        press(&mut app, KeyCode::Esc);
        t.draw(&app, "edit left");
        press(&mut app, KeyCode::Char('?'));
        t.draw(&app, "help");
        press(&mut app, KeyCode::Esc);
        t.draw(&app, "help closed");
        let cmds = press(&mut app, KeyCode::Tab);
        settle(&mut app, cmds);
        t.draw(&app, "next chart");
        t.resize(80, 24);
        t.draw(&app, "80x24");
        let cmds = press(&mut app, KeyCode::Tab);
        settle(&mut app, cmds);
        t.draw(&app, "80x24, next chart");
        t.resize(150, 50);
        t.draw(&app, "150x50");
        // the same screen again writes no cell
        let again = t.draw(&app, "again");
        assert!(again <= 16, "{again}");
    }
}

/// A linear congruential generator (Numerical Recipes' constants).
struct Lcg(u32);

impl Lcg {
    /// A number below n.
    fn below(&mut self, n: u32) -> u32 {
        self.0 = self.0.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        (self.0 >> 8) % n
    }

    fn colour(&mut self) -> Color {
        match self.below(5) {
            0 => Color::Reset,
            1 => [Color::Red, Color::LightBlue, Color::White][self.below(3) as usize],
            2 | 3 => Color::Indexed(self.below(256) as u8),
            _ => Color::Rgb(self.below(256) as u8, self.below(256) as u8, 7),
        }
    }
}

#[test]
fn random_screens_and_changes_show_as_drawn() {
    // cells of random symbols (one and two columns wide), colours (reset, named, indexed,
    // 24-bit) and attributes, changed a few or many at a time, in a width that is even
    let mut r = Lcg(12_345);
    let symbols = ["a", " ", "─", "▀", "█", "·"];
    let modifiers = [
        Modifier::BOLD,
        Modifier::DIM,
        Modifier::ITALIC,
        Modifier::UNDERLINED,
        Modifier::REVERSED,
    ];
    let (w, h) = (30, 8);
    let mut t = Replay::new(w, h, PLAIN);
    let mut screen = Buffer::empty(ratatui::layout::Rect::new(0, 0, w, h));
    for frame in 0..300 {
        let changes = if frame % 10 == 0 {
            200
        } else {
            1 + r.below(12)
        };
        for _ in 0..changes {
            let (x, y) = (r.below(w.into()) as u16, r.below(h.into()) as u16);
            let mut chosen = Modifier::empty();
            for m in modifiers {
                if r.below(4) == 0 {
                    chosen |= m;
                }
            }
            // the emulator keeps one intensity, bold or dim
            if chosen.contains(Modifier::BOLD | Modifier::DIM) {
                chosen.remove(Modifier::DIM);
            }
            // the cell's whole style (a style adds to a cell's attributes)
            let style = ratatui::style::Style::default()
                .fg(r.colour())
                .bg(r.colour())
                .add_modifier(chosen)
                .remove_modifier(Modifier::all() - chosen);
            let symbol = symbols[r.below(symbols.len() as u32) as usize];
            if y == 0 {
                // the top row in pairs of columns, each a two-column symbol or two symbols (a
                // terminal blanks a two-column symbol written over by half, a buffer does not)
                let pair = if r.below(2) == 0 { "中" } else { "a▀" };
                screen.set_stringn(x / 2 * 2, y, pair, 2, style);
            } else {
                screen.set_stringn(x, y, symbol, 1, style);
            }
        }
        let drawn = t
            .terminal
            .draw(|f| f.buffer_mut().clone_from(&screen))
            .unwrap()
            .buffer
            .clone();
        let bytes = std::mem::take(&mut *t.sink.0.borrow_mut());
        t.emulator.process(&bytes);
        same(&drawn, t.emulator.screen(), &format!("frame {frame}"));
    }
}
