//! The terminal explorer: terminal set-up and restore, the input thread, and the modules of the
//! explorer (The Elm Architecture: `app` the model, `update` the only change, `view` the drawing,
//! `event_loop` the loop that carries out the commands).

pub mod actions;
pub mod app;
pub mod backend;
pub mod chart_keys;
pub mod charts;
pub mod cursor_move;
pub mod data_keys;
pub mod edit;
pub mod effects;
pub mod event_loop;
pub mod fit_keys;
pub mod fit_state;
pub mod form;
pub mod glossary;
pub mod harmonic_keys;
pub mod key_scope;
pub mod keys;
pub mod lesson_keys;
pub mod lesson_state;
pub mod map_cursor;
pub mod messages;
pub mod on_screen;
pub mod picker_entry;
pub mod picker_keys;
pub mod prompt_keys;
#[cfg(unix)]
pub mod save_name;
pub mod signals;
pub mod surface_keys;
pub mod sweep_export;
pub mod sweep_form_keys;
pub mod sweep_keys;
pub mod sweep_shown;
pub mod sweep_state;
pub mod text_field;
pub mod update;
pub mod view;
pub mod warned;

#[cfg(test)]
mod tests;

use std::io;
use std::path::{Path, PathBuf};
use std::sync::mpsc::channel;

use crate::preset::Preset;
use ratatui::Terminal;
use ratatui::crossterm::cursor::Show;
use ratatui::crossterm::event::{self, DisableMouseCapture, EnableMouseCapture};
use ratatui::crossterm::execute;

use app::{App, Places};
use backend::Compact;
pub use event_loop::{Ending, Loop, LoopEvent};
use view::RenderOptions;

/// Options of the explorer from the command line and the environment.
#[derive(Clone, Copy, Debug)]
pub struct Options {
    /// Draw charts with ASCII dots instead of Braille.
    pub ascii: bool,
    /// Capture the mouse.
    pub mouse: bool,
}

/// Where the user's presets live: $XDG_DATA_HOME/wearlab/presets (or the platform's data dir).
pub fn user_preset_dir() -> Option<PathBuf> {
    dirs::data_dir().map(|d| d.join("wearlab").join("presets"))
}

/// The environment variable naming folders of shared presets, separated by ':' as in PATH.
pub const SHARED_PRESETS_VARIABLE: &str = "WEARLAB_PRESETS";

/// The folders of shared presets: those of `variable` (empty parts skipped), then the folder of
/// the file the explorer was started on.
pub fn shared_folders(
    variable: Option<std::ffi::OsString>,
    started_on: Option<&Path>,
) -> Vec<PathBuf> {
    let mut folders: Vec<PathBuf> = variable
        .map(|v| {
            std::env::split_paths(&v)
                .filter(|p| !p.as_os_str().is_empty())
                .collect()
        })
        .unwrap_or_default();
    let started = started_on.map(|p| match p.parent() {
        Some(f) if !f.as_os_str().is_empty() => f.to_path_buf(),
        _ => PathBuf::from("."),
    });
    folders.extend(started.filter(|f| !folders.contains(f)));
    folders
}

/// Runs the explorer until the user quits or a signal of `signals::ENDING` arrives. The terminal
/// is restored on every exit path: a quit, an error, one of those signals, and a panic
/// (ratatui's init installs a hook that restores it first).
pub fn run(preset: Preset, path: Option<PathBuf>, options: Options) -> io::Result<Ending> {
    let render = RenderOptions {
        ascii: options.ascii,
        color: std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty()),
        truecolor: std::env::var("COLORTERM").is_ok_and(|v| v == "truecolor" || v == "24bit"),
    };
    let places = Places {
        home: dirs::home_dir(),
        presets: user_preset_dir(),
        shared: shared_folders(std::env::var_os(SHARED_PRESETS_VARIABLE), path.as_deref()),
    };
    let (tx, rx) = channel();
    // before the terminal changes, so that no moment is left where a signal kills it unrestored
    #[cfg(unix)]
    let signals = signals::forward(tx.clone())?;
    // raw mode, the alternate screen and the panic hook that restores them; the terminal drawn
    // on is our own, whose backend writes fewer bytes (`backend`)
    drop(ratatui::init());
    let result = Terminal::new(Compact::new(io::stdout())).and_then(|terminal| {
        if options.mouse {
            execute!(io::stdout(), EnableMouseCapture)?;
        }
        let input = tx.clone();
        std::thread::spawn(move || {
            while let Ok(ev) = event::read() {
                if input.send(LoopEvent::Input(ev)).is_err() {
                    return;
                }
            }
        });
        let mut app = App::new(preset, path, places);
        if app.doc.source.is_none() {
            app.doc.source = Some(format!("bundled: {}", crate::preset::BUNDLED[0].file));
        }
        Loop::new(terminal, app, render, tx, rx).and_then(|mut l| l.run())
    });
    restore(options.mouse);
    #[cfg(unix)]
    signals.close();
    result
}

/// Gives the terminal back as it was: mouse reporting off (when it was turned on), the cursor
/// shown, raw mode off, the main screen. Errors are dropped: after a hang-up there is no
/// terminal to restore.
fn restore(mouse: bool) {
    if mouse {
        let _ = execute!(io::stdout(), DisableMouseCapture);
    }
    let _ = execute!(io::stdout(), Show);
    ratatui::restore();
}
