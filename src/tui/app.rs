//! The explorer's state and its update function (The Elm Architecture): `update(&mut App, Msg)`
//! changes the state and returns what the loop must do; it never draws and never solves.

use std::path::PathBuf;

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use wearlab::engine::Output;
use wearlab::preset::{self, Preset, Problem};
use wearlab::units::parse_si;

use crate::tui::form::{self, Key, Nudge};

/// The charts of each problem, in Tab order.
pub fn chart_titles(problem: Problem) -> &'static [&'static str] {
    match problem {
        Problem::Plane => &[
            "pressure and shear",
            "wear",
            "mu* against load",
            "contact edges against load",
        ],
        Problem::Spatial => &[
            "pressure map",
            "pressure and shape along a line",
            "amplitudes and mu* in time",
            "mu* against mean pressure",
            "dispersion: drift velocity",
        ],
    }
}

/// What the keyboard is doing.
#[derive(Clone, Debug, PartialEq)]
pub enum Mode {
    /// Browsing the form.
    Normal,
    /// Typing a value for the selected row.
    Editing(String),
    /// The help screen.
    Help,
    /// Choosing a preset to open.
    Picker {
        entries: Vec<PickerEntry>,
        selected: usize,
    },
    /// Typing a file name to save to.
    SaveAs(String),
    /// The file exists: overwrite?
    ConfirmOverwrite(PathBuf),
    /// Unsaved edits: quit anyway?
    ConfirmQuit,
}

/// A preset the picker offers.
#[derive(Clone, Debug, PartialEq)]
pub struct PickerEntry {
    /// What the list shows.
    pub title: String,
    /// Where it comes from ("bundled" or a path).
    pub source: String,
    /// The preset, or why it could not be read.
    pub preset: Result<Preset, String>,
}

/// Input to `update`.
#[derive(Clone, Debug)]
pub enum Msg {
    /// A key press.
    Key(KeyEvent),
    /// A solve finished.
    Solved(u64, Box<Output>),
    /// Time passes while playing (spatial).
    Tick,
}

/// What the loop must do after an update.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    /// Solve this preset (generation number attached).
    Solve(u64, Box<Preset>),
    /// Write a file.
    Save(PathBuf, Box<Preset>),
    /// Export the visible chart's data.
    Export,
    /// Leave.
    Quit,
}

/// The whole model.
pub struct App {
    /// The preset being explored (always valid).
    pub preset: Preset,
    /// The file it came from or was saved to.
    pub path: Option<PathBuf>,
    /// Edited since the last save or load.
    pub dirty: bool,
    /// Selected form row.
    pub selected: usize,
    /// Keyboard mode.
    pub mode: Mode,
    /// Visible chart index.
    pub chart: usize,
    /// The last message for the user and whether it is an error.
    pub message: Option<(String, bool)>,
    /// The newest solver output shown.
    pub output: Option<Output>,
    /// The generation of the newest request.
    pub generation: u64,
    /// The generation of `output`.
    pub shown: u64,
    /// Earlier presets, for undo.
    pub undo: Vec<Preset>,
    /// Time is playing (spatial).
    pub playing: bool,
    /// Where user presets live (the picker lists them).
    pub user_dir: Option<PathBuf>,
}

impl App {
    /// A new app on a preset; the first solve is requested by `start`.
    pub fn new(preset: Preset, path: Option<PathBuf>, user_dir: Option<PathBuf>) -> App {
        App {
            preset,
            path,
            dirty: false,
            selected: 0,
            mode: Mode::Normal,
            chart: 0,
            message: None,
            output: None,
            generation: 0,
            shown: 0,
            undo: Vec::new(),
            playing: false,
            user_dir,
        }
    }

    /// The command that asks for the first solve.
    pub fn start(&mut self) -> Vec<Command> {
        vec![self.request()]
    }

    /// True while a newer request than the one shown is being solved.
    pub fn solving(&self) -> bool {
        self.shown != self.generation
    }

    fn request(&mut self) -> Command {
        self.generation += 1;
        Command::Solve(self.generation, Box::new(self.preset.clone()))
    }

    fn say(&mut self, text: impl Into<String>, error: bool) {
        self.message = Some((text.into(), error));
    }

    /// Replaces the preset by an edited one (undo keeps the old) and asks for a solve.
    fn apply(&mut self, next: Preset) -> Vec<Command> {
        if next == self.preset {
            return Vec::new();
        }
        self.undo.push(std::mem::replace(&mut self.preset, next));
        if self.undo.len() > 200 {
            self.undo.remove(0);
        }
        self.dirty = true;
        self.fit_selection();
        vec![self.request()]
    }

    fn open(&mut self, preset: Preset, path: Option<PathBuf>) -> Vec<Command> {
        self.undo.push(std::mem::replace(&mut self.preset, preset));
        self.path = path;
        self.dirty = false;
        self.selected = 0;
        self.chart = 0;
        self.playing = false;
        vec![self.request()]
    }

    /// Keeps the selected row and chart inside what the current problem has.
    fn fit_selection(&mut self) {
        let rows = form::rows(&self.preset).len();
        self.selected = self.selected.min(rows.saturating_sub(1));
        self.chart %= chart_titles(self.preset.problem).len();
    }

    fn current_row(&self) -> form::Row {
        let rows = form::rows(&self.preset);
        rows[self.selected.min(rows.len() - 1)]
    }
}

/// The picker's entries: the bundled presets, then the user's folder.
pub fn picker_entries(user_dir: Option<&PathBuf>) -> Vec<PickerEntry> {
    let mut out: Vec<PickerEntry> = preset::BUNDLED
        .iter()
        .map(|b| {
            let p = b.load().map_err(|e| e.to_string());
            PickerEntry {
                title: p
                    .as_ref()
                    .map(|p| p.name.clone())
                    .unwrap_or_else(|_| b.file.to_string()),
                source: format!("bundled: {}", b.file),
                preset: p,
            }
        })
        .collect();
    if let Some(dir) = user_dir
        && let Ok(read) = std::fs::read_dir(dir)
    {
        let mut files: Vec<PathBuf> = read
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        files.sort();
        for path in files {
            let p = preset::load(&path).map_err(|e| e.to_string());
            out.push(PickerEntry {
                title: p
                    .as_ref()
                    .map(|p| p.name.clone())
                    .unwrap_or_else(|_| "(unreadable)".into()),
                source: path.display().to_string(),
                preset: p,
            });
        }
    }
    out
}

/// Changes the state for one message; returns what the loop must do.
pub fn update(app: &mut App, msg: Msg) -> Vec<Command> {
    match msg {
        Msg::Solved(generation, output) => {
            // A result older than the one on screen is dropped; a newer one is shown even when a
            // still newer request is pending (playing time supersedes every request before its
            // answer arrives, and must still move the screen).
            if generation >= app.shown {
                app.output = Some(*output);
                app.shown = generation;
            }
            Vec::new()
        }
        Msg::Tick => {
            if !app.playing || app.preset.problem != Problem::Spatial {
                return Vec::new();
            }
            let sp = &app.preset.spatial;
            let mut next = app.preset.clone();
            next.spatial.time = sp.time + sp.duration / 100.0;
            if next.spatial.time > sp.duration {
                next.spatial.time = 0.0;
            }
            // playing is not an edit to undo
            app.preset = next;
            app.dirty = true;
            vec![app.request()]
        }
        Msg::Key(key) => on_key(app, key),
    }
}

fn on_key(app: &mut App, key: KeyEvent) -> Vec<Command> {
    let ctrl_c = key.code == KeyCode::Char('c') && key.modifiers.contains(KeyModifiers::CONTROL);
    match app.mode.clone() {
        Mode::Editing(mut buffer) => match key.code {
            KeyCode::Esc => {
                app.mode = Mode::Normal;
                app.say("edit cancelled", false);
                Vec::new()
            }
            KeyCode::Enter => {
                let row = app.current_row();
                let parsed = match row.nudge {
                    Nudge::Choice(names) => names
                        .iter()
                        .position(|n| *n == buffer.trim())
                        .map(|i| i as f64)
                        .ok_or_else(|| format!("type one of: {}", names.join(", "))),
                    _ => parse_si(&buffer, row.unit),
                };
                match parsed.and_then(|v| form::set(&app.preset, &row, v)) {
                    Ok(next) => {
                        app.mode = Mode::Normal;
                        app.message = None;
                        app.apply(next)
                    }
                    Err(why) => {
                        // the field keeps the last valid value; the text stays for correction
                        app.say(format!("{}: {why}", row.label), true);
                        Vec::new()
                    }
                }
            }
            KeyCode::Backspace => {
                buffer.pop();
                app.mode = Mode::Editing(buffer);
                Vec::new()
            }
            KeyCode::Char(c) if !ctrl_c => {
                buffer.push(c);
                app.mode = Mode::Editing(buffer);
                Vec::new()
            }
            _ => Vec::new(),
        },
        Mode::Help => {
            app.mode = Mode::Normal;
            if ctrl_c { quit(app) } else { Vec::new() }
        }
        Mode::Picker {
            entries,
            mut selected,
        } => match key.code {
            KeyCode::Esc | KeyCode::Char('q') => {
                app.mode = Mode::Normal;
                Vec::new()
            }
            KeyCode::Up | KeyCode::Char('k') => {
                selected = selected.saturating_sub(1);
                app.mode = Mode::Picker { entries, selected };
                Vec::new()
            }
            KeyCode::Down | KeyCode::Char('j') => {
                selected = (selected + 1).min(entries.len().saturating_sub(1));
                app.mode = Mode::Picker { entries, selected };
                Vec::new()
            }
            KeyCode::Enter => {
                let entry = entries[selected].clone();
                app.mode = Mode::Normal;
                match entry.preset {
                    Ok(p) => {
                        let path = (!entry.source.starts_with("bundled"))
                            .then(|| PathBuf::from(&entry.source));
                        app.say(format!("opened {}", entry.source), false);
                        app.open(p, path)
                    }
                    Err(why) => {
                        // a broken file: say why, keep the current state
                        app.say(why, true);
                        Vec::new()
                    }
                }
            }
            _ => {
                app.mode = Mode::Picker { entries, selected };
                Vec::new()
            }
        },
        Mode::SaveAs(mut buffer) => match key.code {
            KeyCode::Esc => {
                app.mode = Mode::Normal;
                Vec::new()
            }
            KeyCode::Backspace => {
                buffer.pop();
                app.mode = Mode::SaveAs(buffer);
                Vec::new()
            }
            KeyCode::Enter => {
                let name = buffer.trim();
                if name.is_empty() {
                    app.say("type a file name", true);
                    return Vec::new();
                }
                let mut path = PathBuf::from(name);
                if path.extension().is_none() {
                    path.set_extension("toml");
                }
                if path.is_relative() && !name.contains('/') {
                    if let Some(dir) = &app.user_dir {
                        path = dir.join(path);
                    }
                }
                if path.exists() {
                    app.mode = Mode::ConfirmOverwrite(path);
                    Vec::new()
                } else {
                    app.mode = Mode::Normal;
                    vec![Command::Save(path, Box::new(app.preset.clone()))]
                }
            }
            KeyCode::Char(c) if !ctrl_c => {
                buffer.push(c);
                app.mode = Mode::SaveAs(buffer);
                Vec::new()
            }
            _ => Vec::new(),
        },
        Mode::ConfirmOverwrite(path) => {
            app.mode = Mode::Normal;
            if key.code == KeyCode::Char('y') {
                vec![Command::Save(path, Box::new(app.preset.clone()))]
            } else {
                app.say("not saved", false);
                Vec::new()
            }
        }
        Mode::ConfirmQuit => {
            if matches!(key.code, KeyCode::Char('y') | KeyCode::Char('q')) || ctrl_c {
                vec![Command::Quit]
            } else {
                app.mode = Mode::Normal;
                app.say("still here", false);
                Vec::new()
            }
        }
        Mode::Normal => normal_key(app, key, ctrl_c),
    }
}

fn quit(app: &mut App) -> Vec<Command> {
    if app.dirty {
        app.mode = Mode::ConfirmQuit;
        Vec::new()
    } else {
        vec![Command::Quit]
    }
}

fn normal_key(app: &mut App, key: KeyEvent, ctrl_c: bool) -> Vec<Command> {
    if ctrl_c {
        return quit(app);
    }
    let rows = form::rows(&app.preset);
    let shift = key.modifiers.contains(KeyModifiers::SHIFT);
    match key.code {
        KeyCode::Char('q') => quit(app),
        KeyCode::Up | KeyCode::Char('k') => {
            app.selected = app.selected.checked_sub(1).unwrap_or(rows.len() - 1);
            Vec::new()
        }
        KeyCode::Down | KeyCode::Char('j') => {
            app.selected = (app.selected + 1) % rows.len();
            Vec::new()
        }
        KeyCode::Left
        | KeyCode::Right
        | KeyCode::Char('h')
        | KeyCode::Char('l')
        | KeyCode::Char('H')
        | KeyCode::Char('L') => {
            let dir = if matches!(
                key.code,
                KeyCode::Left | KeyCode::Char('h') | KeyCode::Char('H')
            ) {
                -1.0
            } else {
                1.0
            };
            let large = shift || matches!(key.code, KeyCode::Char('H') | KeyCode::Char('L'));
            let row = app.current_row();
            let value = form::nudged(&app.preset, &row, dir, large);
            match form::set(&app.preset, &row, value) {
                Ok(next) => app.apply(next),
                Err(why) => {
                    app.say(format!("{}: {why}", row.label), true);
                    Vec::new()
                }
            }
        }
        KeyCode::Enter => {
            let row = app.current_row();
            let text = match row.nudge {
                Nudge::Choice(_) => form::show(&app.preset, &row),
                _ => String::new(),
            };
            app.mode = Mode::Editing(text);
            app.say(
                format!(
                    "type {} ({}), Enter to apply, Esc to cancel",
                    row.label, row.limit.allowed
                ),
                false,
            );
            Vec::new()
        }
        KeyCode::Tab => {
            app.chart = (app.chart + 1) % chart_titles(app.preset.problem).len();
            Vec::new()
        }
        KeyCode::BackTab => {
            let n = chart_titles(app.preset.problem).len();
            app.chart = (app.chart + n - 1) % n;
            Vec::new()
        }
        KeyCode::Char('p') => {
            let mut next = app.preset.clone();
            next.problem = match next.problem {
                Problem::Plane => Problem::Spatial,
                Problem::Spatial => Problem::Plane,
            };
            app.selected = 0;
            app.chart = 0;
            app.playing = false;
            app.apply(next)
        }
        KeyCode::Char('m') if app.preset.problem == Problem::Plane => {
            let row = form::rows(&app.preset)
                .into_iter()
                .find(|r| r.key == Key::Model)
                .expect("plane form has a model row");
            match form::set(
                &app.preset,
                &row,
                form::nudged(&app.preset, &row, 1.0, false),
            ) {
                Ok(next) => {
                    let cmds = app.apply(next);
                    app.say(format!("model: {}", app.preset.plane.model.name()), false);
                    cmds
                }
                Err(why) => {
                    app.say(why, true);
                    Vec::new()
                }
            }
        }
        KeyCode::Char(' ') if app.preset.problem == Problem::Spatial => {
            app.playing = !app.playing;
            app.say(
                if app.playing {
                    "playing time (space to pause)"
                } else {
                    "paused"
                },
                false,
            );
            Vec::new()
        }
        KeyCode::Char('+') if app.preset.problem == Problem::Spatial => {
            let mut next = app.preset.clone();
            let last = *next
                .spatial
                .harmonics
                .last()
                .expect("validated: at least one harmonic");
            let mut added = last;
            added.wavenumber_x *= 2.0;
            added.amplitude /= 2.0;
            while next.spatial.harmonics.iter().any(|h| {
                h.wavenumber_x == added.wavenumber_x && h.wavenumber_y == added.wavenumber_y
            }) {
                added.wavenumber_x *= 2.0;
            }
            next.spatial.harmonics.push(added);
            app.say(
                format!("added harmonic {}", next.spatial.harmonics.len()),
                false,
            );
            app.apply(next)
        }
        KeyCode::Char('-') if app.preset.problem == Problem::Spatial => {
            let n = harmonic_of(&app.current_row().key);
            if app.preset.spatial.harmonics.len() <= 1 {
                app.say("the punch needs at least one harmonic", true);
                return Vec::new();
            }
            let mut next = app.preset.clone();
            let index = n.unwrap_or(next.spatial.harmonics.len() - 1);
            next.spatial.harmonics.remove(index);
            app.say(format!("removed harmonic {}", index + 1), false);
            app.apply(next)
        }
        KeyCode::Char('u') => match app.undo.pop() {
            Some(previous) => {
                app.preset = previous;
                app.dirty = true;
                app.fit_selection();
                app.say("undone", false);
                vec![app.request()]
            }
            None => {
                app.say("nothing to undo", false);
                Vec::new()
            }
        },
        KeyCode::Char('?') => {
            app.mode = Mode::Help;
            Vec::new()
        }
        KeyCode::Char('o') => {
            app.mode = Mode::Picker {
                entries: picker_entries(app.user_dir.as_ref()),
                selected: 0,
            };
            Vec::new()
        }
        KeyCode::Char('s') => {
            let suggestion = app
                .path
                .as_ref()
                .and_then(|p| p.file_name())
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default();
            app.mode = Mode::SaveAs(suggestion);
            Vec::new()
        }
        KeyCode::Char('e') => vec![Command::Export],
        _ => Vec::new(),
    }
}

/// The harmonic a form row belongs to.
pub fn harmonic_of(key: &Key) -> Option<usize> {
    match *key {
        Key::Amplitude(n)
        | Key::WavenumberX(n)
        | Key::WavenumberY(n)
        | Key::PhaseX(n)
        | Key::PhaseY(n) => Some(n),
        _ => None,
    }
}
