//! Tests of the explorer: `update` for every action of the key table, the key table against the
//! help, footer and docs/guide.md, the charts' export against their builders, results labelled by their
//! own inputs, the loop, and screen snapshots (TestBackend + insta).

mod ascii;
mod axes;
mod bands;
mod bytes;
mod charts;
mod data_overlay;
mod explore;
mod files;
mod fit;
mod go_to;
mod groups;
mod kept_save;
mod keys;
mod legend;
mod lesson;
mod list_keys;
mod map_cursor;
mod map_words;
mod map_yield;
mod material_form;
mod monkey;
mod partial;
mod picker;
mod pin_marks;
mod pinned_exports;
mod regime_map;
mod replay;
mod save_prompt;
mod saved_current;
mod screens;
mod shape_form;
mod stale;
mod status_in_full;
mod surface_form;
mod surfaces;
mod sweep_export;
mod sweep_form;
mod ticks;
mod unanswered;
mod update;
mod validity;
mod verdict_kept;
mod verdict_sweep;
mod warned;
mod wear_law_status;
mod widgets;
mod yielding;

use std::time::{Duration, Instant};

use crate::engine::{Answer, Engine};
use crate::preset::Preset;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use crate::tui::app::{App, Command, Msg, Places};
use crate::tui::update::update;
use crate::tui::view::{RenderOptions, view};

fn bundled(file: &str) -> Preset {
    crate::preset::bundled(file).unwrap().unwrap()
}

fn app(file: &str) -> App {
    App::new(bundled(file), None, Places::default())
}

fn key(code: KeyCode) -> Msg {
    Msg::Key(KeyEvent::new(code, KeyModifiers::NONE))
}

fn press(app: &mut App, code: KeyCode) -> Vec<Command> {
    update(app, key(code))
}

fn ctrl(app: &mut App, c: char) -> Vec<Command> {
    update(
        app,
        Msg::Key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::CONTROL)),
    )
}

fn type_text(app: &mut App, text: &str) {
    for c in text.chars() {
        press(app, KeyCode::Char(c));
    }
}

/// Selects the row with this label (of harmonic `n` when given).
fn select(app: &mut App, label: &str, harmonic: Option<usize>) {
    app.ui.selected = app
        .rows()
        .iter()
        .position(|r| r.param().symbol == label && r.harmonic_index() == harmonic)
        .unwrap_or_else(|| panic!("no row {label}"));
}

/// Every answer the engine gives for the solve commands, all stages, as the worker would send.
fn answers(engine: &mut Engine, commands: &[Command]) -> Vec<Answer> {
    answers_within(engine, commands, Duration::MAX)
}

/// As [`answers`], each solve stopped between two of its steps once it has run for `patience`
/// (as the worker stops when a newer request waits); the engine keeps what it did.
fn answers_within(engine: &mut Engine, commands: &[Command], patience: Duration) -> Vec<Answer> {
    let mut out = Vec::new();
    for c in commands {
        if let Command::Solve(generation, request) = c {
            let request = std::sync::Arc::new((**request).clone());
            let start = Instant::now();
            let impatient = || start.elapsed() > patience;
            engine.run_cancellable(&request, &impatient, |output, complete| {
                out.push(Answer {
                    generation: *generation,
                    request: request.clone(),
                    output,
                    complete,
                });
                true
            });
        }
    }
    out
}

/// Delivers every answer to the commands (and to the commands those answers give).
fn settle(app: &mut App, commands: Vec<Command>) {
    let mut engine = Engine::new();
    for a in answers(&mut engine, &commands) {
        update(app, Msg::Answer(Box::new(a)));
    }
}

/// An app on a bundled preset with its first solve delivered.
fn solved(file: &str) -> App {
    let mut app = app(file);
    let commands = app.start();
    settle(&mut app, commands);
    app
}

/// The file and text of the one export command among `cmds`, which must not overwrite.
fn exported(cmds: &[Command]) -> (&std::path::PathBuf, &String) {
    match cmds {
        [
            Command::Export {
                path,
                text,
                overwrite: false,
            },
        ] => (path, text),
        _ => panic!("{cmds:?}"),
    }
}

fn screen(app: &App, w: u16, h: u16, options: RenderOptions) -> String {
    let mut terminal = Terminal::new(TestBackend::new(w, h)).unwrap();
    terminal.draw(|f| view(app, options, f)).unwrap();
    terminal.backend().to_string()
}

const PLAIN: RenderOptions = RenderOptions {
    ascii: false,
    color: false,
    truecolor: false,
};

const ASCII: RenderOptions = RenderOptions {
    ascii: true,
    color: false,
    truecolor: false,
};

/// Colour in the 256-colour palette (no truecolor).
const COLOUR: RenderOptions = RenderOptions {
    ascii: false,
    color: true,
    truecolor: false,
};
