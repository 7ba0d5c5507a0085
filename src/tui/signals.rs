//! The signals that end the explorer from outside (SIGTERM, SIGINT sent by `kill`, SIGHUP when
//! the terminal goes away, SIGQUIT), turned into events of the event loop: the loop ends, the
//! terminal is restored as on a quit, and the process exits with 128 + the signal's number.
//! Without this their default action kills the process with the terminal left in raw mode, on
//! the alternate screen, cursor hidden and mouse reporting on.

use std::io;
use std::sync::mpsc::Sender;

use signal_hook::consts::{SIGHUP, SIGINT, SIGQUIT, SIGTERM};
use signal_hook::iterator::{Handle, Signals};

use crate::tui::event_loop::LoopEvent;

/// The signals the explorer restores the terminal on.
pub const ENDING: [i32; 4] = [SIGTERM, SIGINT, SIGHUP, SIGQUIT];

/// Forwards every signal of `ENDING` to the loop as `LoopEvent::Signal` from a thread of its own;
/// the handle stops the thread.
pub fn forward(wake: Sender<LoopEvent>) -> io::Result<Handle> {
    let mut signals = Signals::new(ENDING)?;
    let handle = signals.handle();
    std::thread::spawn(move || {
        for signal in signals.forever() {
            if wake.send(LoopEvent::Signal(signal)).is_err() {
                return;
            }
        }
    });
    Ok(handle)
}
