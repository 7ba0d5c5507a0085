//! What the explorer writes to the terminal (what matters over SSH): bytes of a full redraw, of each
//! frame while time plays, and of a redraw with nothing changed, counted through the explorer's
//! backend (`backend`: the escape codes a terminal would receive; tests/replay.rs checks that
//! they draw the buffer), not timed.

use std::cell::Cell;
use std::io::Write;
use std::rc::Rc;

use ratatui::layout::Rect;
use ratatui::{Terminal, TerminalOptions, Viewport};

use super::*;
use crate::tui::backend::Compact;
use crate::tui::event_loop::FRAME;

/// A writer that counts what goes through it.
#[derive(Clone, Default)]
struct Counter(Rc<Cell<usize>>);

impl Write for Counter {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0.set(self.0.get() + buf.len());
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// A terminal of w x h cells whose output is counted.
fn terminal(w: u16, h: u16) -> (Terminal<Compact<Counter>>, Counter) {
    let counter = Counter::default();
    let options = TerminalOptions {
        viewport: Viewport::Fixed(Rect::new(0, 0, w, h)),
    };
    let t = Terminal::with_options(Compact::new(counter.clone()), options).unwrap();
    (t, counter)
}

/// Bytes written by one draw of the app.
fn draw(t: &mut Terminal<Compact<Counter>>, c: &Counter, app: &App, s: RenderOptions) -> usize {
    let before = c.0.get();
    t.draw(|f| view(app, s, f)).unwrap();
    c.0.get() - before
}

const TRUECOLOR: RenderOptions = RenderOptions {
    truecolor: true,
    ..COLOUR
};

/// Bytes of a full redraw and of each frame while time plays, at 120x40.
fn playing(file: &str, frames: usize, s: RenderOptions) -> (usize, Vec<usize>) {
    let mut app = solved(file);
    let (mut t, c) = terminal(120, 40);
    let full = draw(&mut t, &c, &app, s);
    app.ui.playing = true;
    let each = (0..frames)
        .map(|_| {
            let cmds = update(&mut app, Msg::Tick);
            settle(&mut app, cmds);
            draw(&mut t, &c, &app, s)
        })
        .collect();
    (full, each)
}

#[test]
fn playing_the_pressure_map_writes_under_60_kb_a_second() {
    let per_second = 1000 / FRAME.as_millis() as usize;
    // measured over 20 frames: dispersion 0.5 kB a frame on average, at most 1.7 kB,
    // wave-thick-layer 0.6 and 1.9, jgh-egg-box 0.6 and 1.4, contact-lost 0.6 and 1.7: at most
    // 10 kB/s at five frames a second
    for file in [
        "dispersion.toml",
        "wave-thick-layer.toml",
        "jgh-egg-box.toml",
        "contact-lost.toml",
    ] {
        let (full, frames) = playing(file, 20, COLOUR);
        let worst = frames.iter().max().unwrap();
        assert!(
            worst * per_second < 60_000,
            "{file}: {frames:?} at {per_second}/s"
        );
        // a full redraw of the map screen (7.0-7.7 kB): 3.3-3.6 kB of frame, form, footer,
        // status and bar, and a 52 x 26 map in 4-6 bands (3.7-4.3 kB) with a colour code
        // wherever a band changes
        assert!(full < 8_000, "{file}: {full}");
        // in 24-bit colour, whose codes are longer: 8.2-10.1 kB
        let (full, _) = playing(file, 0, TRUECOLOR);
        assert!(full < 11_000, "{file} in 24-bit colour: {full}");
    }
}

#[test]
fn a_full_redraw_of_a_chart_screen_is_under_8_kb_and_nothing_changed_writes_nothing() {
    for (file, chart) in [
        ("polymer-coating.toml", 0),
        ("polymer-coating.toml", 2),
        ("wave-thick-layer.toml", 2),
        ("dispersion.toml", 4),
    ] {
        let mut app = solved(file);
        app.ui.chart = crate::tui::charts::Chart::all(app.doc.preset.problem)[chart];
        let cmds = app.start();
        settle(&mut app, cmds);
        let (mut t, c) = terminal(120, 40);
        let full = draw(&mut t, &c, &app, COLOUR);
        // measured 4.1-5.2 kB
        assert!(full < 8_000, "{file} chart {chart}: {full} bytes");
        // the same screen again: the hidden cursor only (6 bytes)
        let again = draw(&mut t, &c, &app, COLOUR);
        assert!(again <= 6, "{file}: {again}");
    }
}
