//! `update(&mut App, Msg)`: the only place the model changes. A pure function: it never draws,
//! never solves and never touches a file; it returns the commands the loop carries out, and the
//! loop reports back with messages (`Answer`, `PresetsListed`, `Saved`, `Exported`, ...).

use crate::engine::Answer;
use crate::engine::latest::Delivery;
use crate::preset::Problem;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use crate::tui::actions::{act, export, open, quit};
use crate::tui::app::{App, Command, Mode, Msg};
use crate::tui::chart_keys;
use crate::tui::edit::apply;
use crate::tui::keys::{self, Open, Scope};
use crate::tui::picker_keys;
use crate::tui::prompt_keys::{self, Prompt, PromptAction};
use crate::tui::save_name;
use crate::tui::text_field::TextField;
use crate::tui::view::windows_on_last_screen;

impl App {
    /// The commands that ask for the first solve (and the first sweep, when the preset opens on
    /// one, and its data file, when it names one).
    pub fn start(&mut self) -> Vec<Command> {
        let mut commands = vec![self.request()];
        commands.extend(crate::tui::sweep_keys::sweep_request(self));
        commands.extend(crate::tui::data_keys::of_preset(self));
        commands
    }
}

/// Changes the model for one message; returns what the loop must do.
pub fn update(app: &mut App, msg: Msg) -> Vec<Command> {
    let mut commands = dispatch(app, msg);
    commands.extend(crate::tui::fit_keys::stale(app));
    commands.extend(crate::tui::sweep_keys::sweep_request(app));
    commands
}

fn dispatch(app: &mut App, msg: Msg) -> Vec<Command> {
    match msg {
        Msg::Key(key) => on_key(app, key),
        Msg::Tick => tick(app),
        Msg::Answer(answer) => on_answer(app, *answer),
        Msg::PresetsListed(entries) => {
            // on the preset shown, while it is unedited (its description is what `i` gave)
            let selected = (entries.iter())
                .position(|e| e.preset.as_ref().ok() == Some(&app.doc.preset))
                .unwrap_or(0);
            app.ui.mode = Mode::Picker {
                entries,
                selected,
                scroll: 0,
                filter: String::new(),
            };
            Vec::new()
        }
        Msg::PresetRead(entry) => picker_keys::chosen(app, *entry),
        Msg::SaveExists(target) => {
            app.ui.mode = Mode::ConfirmOverwrite(target);
            Vec::new()
        }
        Msg::Saved(target, preset, result) => {
            match result {
                Ok(said) => {
                    // edits made while the file was written stay unsaved; the data files are
                    // named from the folder saved to
                    app.doc.preset = crate::preset::with_data_files_of(&app.doc.preset, &preset);
                    app.doc.opened = *preset;
                    app.doc.dirty = app.doc.edited();
                    app.say(said);
                    app.doc.source = Some(target.path.display().to_string());
                    app.doc.path = Some(target.path);
                }
                Err(why) => app.complain(format!("not saved: {why}")),
            }
            Vec::new()
        }
        Msg::Explored(answer) => {
            crate::tui::sweep_keys::on_answer(app, *answer);
            crate::tui::sweep_export::on_answer(app)
        }
        Msg::LessonAnswered(preset, values) => {
            crate::tui::lesson_keys::answered(app, *preset, values);
            Vec::new()
        }
        Msg::ExportExists(path, text) => {
            app.ui.mode = Mode::ConfirmExport(Box::new((path, text)));
            Vec::new()
        }
        Msg::DataRead(result) => crate::tui::data_keys::read(app, result),
        Msg::Fitted(answer) => crate::tui::fit_keys::fitted(app, *answer),
        Msg::Exported(path, result) => {
            match result {
                Ok(()) => app.say(format!("exported the chart to {}", path.display())),
                Err(why) => app.complain(format!("export failed: {}: {why}", path.display())),
            }
            Vec::new()
        }
    }
}

fn tick(app: &mut App) -> Vec<Command> {
    if !app.ui.playing || app.doc.preset.problem != Problem::Spatial {
        return Vec::new();
    }
    let sp = &mut app.doc.preset.spatial;
    sp.time += sp.duration / 100.0;
    if sp.time > sp.duration {
        sp.time = 0.0;
    }
    vec![app.request()]
}

fn on_answer(app: &mut App, answer: Answer) -> Vec<Command> {
    if answer.replaces(app.solve.shown.as_ref()) {
        app.solve.shown = Some(answer);
        chart_keys::keep_heat_scale(app);
    }
    match app.ui.export_waiting {
        Some((chart, format)) if !app.solve.solving() => {
            app.ui.export_waiting = None;
            export(app, chart, format)
        }
        _ => Vec::new(),
    }
}

fn on_key(app: &mut App, key: KeyEvent) -> Vec<Command> {
    if keys::is_ctrl_c(&key) {
        return match app.ui.mode {
            Mode::ConfirmQuit(_) => vec![Command::Quit],
            _ => quit(app),
        };
    }
    match app.ui.mode.clone() {
        Mode::Normal => match keys::lookup(&key) {
            Some((binding, action)) => match binding.only {
                Scope::Problem(problem) if problem != app.doc.preset.problem => {
                    app.complain(format!(
                        "{}: {} is for the {} problem (p switches)",
                        binding.names,
                        binding.help,
                        problem.name()
                    ));
                    Vec::new()
                }
                scope if !scope.applies(Open::of(&app.doc.preset)) => {
                    app.complain(format!(
                        "{}: {} is for {}",
                        binding.names,
                        binding.help,
                        scope.place().unwrap_or_default()
                    ));
                    Vec::new()
                }
                _ => act(app, action),
            },
            None => Vec::new(),
        },
        Mode::Editing(buffer) => text_key(app, key, buffer, Mode::Editing, accept_value),
        Mode::SaveAs(buffer) => text_key(app, key, buffer, Mode::SaveAs, save_name::accept),
        Mode::GoTo(buffer) => text_key(app, key, buffer, Mode::GoTo, chart_keys::go_to),
        Mode::DataPath(buffer) => text_key(
            app,
            key,
            buffer,
            Mode::DataPath,
            crate::tui::data_keys::accept,
        ),
        Mode::Choosing(selected) => {
            let choices = app.row().param().choices().unwrap_or_default();
            match prompt_keys::prompt_action(Prompt::List, &key) {
                Some(PromptAction::Accept) => {
                    app.ui.mode = Mode::Normal;
                    app.ui.message = None;
                    let row = app.row();
                    match crate::tui::form::set(&app.doc.preset, &row, selected as f64) {
                        Ok((next, change)) => apply(app, next, change),
                        Err(why) => {
                            app.complain(why);
                            Vec::new()
                        }
                    }
                }
                Some(PromptAction::Cancel) => {
                    app.ui.mode = Mode::Normal;
                    app.say("choice cancelled");
                    Vec::new()
                }
                action => {
                    app.ui.mode = Mode::Choosing(selection_moved(selected, choices.len(), action));
                    Vec::new()
                }
            }
        }
        Mode::Help(scroll) => {
            // scrolling stops at the end of the text on the last drawn screen
            let last = crate::tui::view::popups::help_last(app, windows_on_last_screen(app));
            app.ui.mode =
                prompt_keys::scrolled(&key, scroll, last).map_or(Mode::Normal, Mode::Help);
            Vec::new()
        }
        Mode::Questions(quiz) => crate::tui::lesson_keys::key(app, key, quiz),
        Mode::About(scroll) => {
            let last = crate::tui::view::popups::about_last(app, windows_on_last_screen(app));
            app.ui.mode =
                prompt_keys::scrolled(&key, scroll, last).map_or(Mode::Normal, Mode::About);
            Vec::new()
        }
        Mode::Picker {
            entries,
            selected,
            scroll,
            filter,
        } => picker_keys::key(app, key, entries, selected, scroll, filter),
        Mode::ConfirmOverwrite(target) => {
            app.ui.mode = Mode::Normal;
            if yes(&key) {
                let preset = Box::new(app.doc.preset.clone());
                vec![Command::Save {
                    target,
                    preset,
                    overwrite: true,
                    origin: app.doc.origin(),
                }]
            } else {
                app.say("not saved");
                Vec::new()
            }
        }
        Mode::ConfirmExport(file) => {
            app.ui.mode = Mode::Normal;
            if yes(&key) {
                let (path, text) = *file;
                vec![Command::Export {
                    path,
                    text,
                    overwrite: true,
                }]
            } else {
                app.say("not exported: the file stays as it was");
                Vec::new()
            }
        }
        Mode::ConfirmOpen(entry) => {
            app.ui.mode = Mode::Normal;
            if yes(&key) {
                open(app, *entry)
            } else {
                app.say("not opened: your edits stay");
                Vec::new()
            }
        }
        Mode::Form(form) => crate::tui::sweep_form_keys::key(app, *form, key),
        Mode::FitForm(form) => crate::tui::fit_keys::key(app, form, key),
        Mode::FitResult(report, scroll) => {
            let last = crate::tui::view::fit::report_last(&report, windows_on_last_screen(app));
            app.ui.mode = prompt_keys::scrolled(&key, scroll, last)
                .map_or(Mode::Normal, |s| Mode::FitResult(report, s));
            Vec::new()
        }
        Mode::ConfirmQuit(from) => {
            if yes(&key) {
                return vec![Command::Quit];
            }
            app.ui.mode = *from;
            app.say("still here");
            Vec::new()
        }
    }
}

fn yes(key: &KeyEvent) -> bool {
    prompt_keys::prompt_action(Prompt::Question, key) == Some(PromptAction::Yes)
}

fn selection_moved(selected: usize, len: usize, action: Option<PromptAction>) -> usize {
    match action {
        Some(PromptAction::Up) => selected.saturating_sub(1),
        Some(PromptAction::Down) => (selected + 1).min(len.saturating_sub(1)),
        Some(PromptAction::PageUp) => selected.saturating_sub(prompt_keys::PAGE),
        Some(PromptAction::PageDown) => (selected + prompt_keys::PAGE).min(len.saturating_sub(1)),
        Some(PromptAction::First) => 0,
        Some(PromptAction::Last) => len.saturating_sub(1),
        _ => selected,
    }
}

/// A key in a text prompt: Enter hands the text to `accept`, Esc cancels, Backspace deletes,
/// ←→ Home End move the cursor; printable characters are typed (never Ctrl- or Alt- chords).
fn text_key(
    app: &mut App,
    key: KeyEvent,
    mut buffer: TextField,
    mode: fn(TextField) -> Mode,
    accept: fn(&mut App, String) -> Vec<Command>,
) -> Vec<Command> {
    match prompt_keys::prompt_action(Prompt::Text, &key) {
        Some(PromptAction::Accept) => accept(app, buffer.text().to_string()),
        Some(PromptAction::Cancel) => {
            let what = match app.ui.mode {
                Mode::SaveAs(_) => "not saved",
                Mode::GoTo(_) => "the cursor stays",
                Mode::DataPath(_) => "the data stay as they were",
                _ => "edit cancelled",
            };
            app.ui.mode = Mode::Normal;
            app.say(what);
            Vec::new()
        }
        Some(PromptAction::Backspace) => {
            buffer.backspace();
            edited(app, mode(buffer));
            Vec::new()
        }
        Some(
            action @ (PromptAction::Left
            | PromptAction::Right
            | PromptAction::First
            | PromptAction::Last),
        ) => {
            buffer.move_cursor(prompt_keys::cursor_step(action));
            app.ui.mode = mode(buffer);
            Vec::new()
        }
        _ => {
            let chord = key
                .modifiers
                .intersects(KeyModifiers::CONTROL | KeyModifiers::ALT);
            match (key.code, chord) {
                (KeyCode::Char(c), false) => {
                    buffer.insert(c);
                    edited(app, mode(buffer));
                }
                (KeyCode::Tab | KeyCode::BackTab, _) => {
                    let what = match app.ui.mode {
                        Mode::SaveAs(_) => {
                            "a file name holds no tabs, and wearlab does not \
                                            complete names: type the whole name"
                        }
                        _ => "a value holds no tabs",
                    };
                    app.complain(format!("Tab is not typed: {what}"));
                }
                _ => {}
            }
            Vec::new()
        }
    }
}

/// The prompt after its text changed: the reason a name typed before was refused no longer
/// applies to the text.
fn edited(app: &mut App, mode: Mode) {
    if matches!(mode, Mode::SaveAs(_)) && app.ui.message.as_ref().is_some_and(|m| m.error) {
        app.ui.message = None;
    }
    app.ui.mode = mode;
}

fn accept_value(app: &mut App, buffer: String) -> Vec<Command> {
    let row = app.row();
    match crate::tui::form::set_text(&app.doc.preset, &row, &buffer) {
        Ok((next, change)) => {
            app.ui.mode = Mode::Normal;
            app.ui.message = None;
            apply(app, next, change)
        }
        Err(why) => {
            // the field keeps the last valid value; the text stays for correction
            app.complain(why);
            Vec::new()
        }
    }
}
