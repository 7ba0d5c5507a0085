//! What each action of the key table does to the model (part of `update`: pure).

use crate::preset::{Key, Preset, Problem};

use crate::tui::app::{App, Command, Mode, PickerEntry};
use crate::tui::chart_keys;
use crate::tui::charts::export::Format;
use crate::tui::charts::{Chart, NoFigure, export as csv};
use crate::tui::edit::apply;
use crate::tui::form::{self, Change};
use crate::tui::harmonic_keys;
use crate::tui::keys::Action;
use crate::tui::lesson_keys;
use crate::tui::lesson_state::{LessonState, invitation};
use crate::tui::map_cursor;
use crate::tui::surface_keys;
use crate::tui::sweep_form_keys;
use crate::tui::sweep_keys;
use crate::tui::sweep_state::View;
use crate::tui::text_field::TextField;

/// Carries out an action of the main screen.
pub fn act(app: &mut App, action: Action) -> Vec<Command> {
    let rows = app.rows().len();
    match action {
        Action::PrevField => {
            app.ui.selected = app.ui.selected.checked_sub(1).unwrap_or(rows - 1);
            lesson_keys::say_if_locked(app);
            Vec::new()
        }
        Action::NextField => {
            app.ui.selected = (app.ui.selected + 1) % rows;
            lesson_keys::say_if_locked(app);
            Vec::new()
        }
        Action::Nudge { .. } | Action::Edit if lesson_keys::locked(app, app.row()) => {
            app.complain(lesson_keys::why_locked(app, app.row()));
            Vec::new()
        }
        Action::Nudge { up, large } => {
            let row = app.row();
            let value = form::nudged(&app.doc.preset, &row, up, large);
            set(app, value)
        }
        Action::Edit => {
            // typing needs the form
            app.ui.expanded = false;
            let row = app.row();
            match row.param().choices() {
                None if app.doc.preset.fixed_text(row).is_some() => {
                    if let Err(why) = form::set(&app.doc.preset, &row, 0.0) {
                        app.complain(why);
                    }
                }
                Some(_) => {
                    app.ui.mode = Mode::Choosing(form::get(&app.doc.preset, &row) as usize);
                    app.say(format!("{}: {}", row.symbol(), row.param().allowed()));
                }
                None => {
                    app.ui.mode = Mode::Editing(TextField::default());
                    app.say(format!("type {} ({})", row.symbol(), row.param().allowed()));
                }
            }
            Vec::new()
        }
        Action::NextChart | Action::PrevChart if app.explore.view.is_some() => {
            app.explore.view = None;
            app.say("back to the charts (v sweep, M map)");
            Vec::new()
        }
        Action::NextChart | Action::PrevChart => {
            let step = if action == Action::NextChart { 1 } else { -1 };
            app.ui.chart = app.ui.chart.step(step);
            let chart = app.ui.chart;
            if (chart.draws_overlays() && !app.solve.overlays)
                || (chart.draws_energies() && !app.solve.energies)
            {
                vec![app.request()]
            } else {
                Vec::new()
            }
        }
        Action::SwitchProblem => {
            let mut next = app.doc.preset.clone();
            next.problem = match next.problem {
                Problem::Plane => Problem::Spatial,
                Problem::Spatial => Problem::Plane,
            };
            let change = Change {
                name: "problem".into(),
                from: app.doc.preset.problem.name().into(),
                to: next.problem.name().into(),
            };
            app.ui.selected = 0;
            app.ui.playing = false;
            let commands = apply(app, next, change);
            app.say(format!("problem: {}", app.doc.preset.problem.name()));
            commands
        }
        Action::CycleModel => {
            let row = Key::of("plane.model").expect("the registry has the plane model");
            let value = form::nudged(&app.doc.preset, &row, true, false);
            match form::set(&app.doc.preset, &row, value) {
                Ok((next, change)) => {
                    let commands = apply(app, next, change);
                    app.say(format!("model: {}", app.doc.preset.plane.model.name()));
                    commands
                }
                Err(why) => {
                    app.complain(why);
                    Vec::new()
                }
            }
        }
        Action::PlayPause => {
            app.ui.playing = !app.ui.playing;
            app.say(if app.ui.playing {
                "playing time (space pauses)"
            } else {
                "paused"
            });
            Vec::new()
        }
        Action::AddHarmonic | Action::RemoveHarmonic
            if app.doc.preset.spatial.surface.is_some() =>
        {
            surface_keys::no_harmonics(app)
        }
        Action::AddHarmonic => edited(app, harmonic_keys::added(&app.doc.preset)),
        Action::NewSeed => edited(app, surface_keys::new_seed(&app.doc.preset)),
        Action::RemoveHarmonic => {
            let selected = app.row().harmonic_index();
            edited(app, harmonic_keys::removed(&app.doc.preset, selected))
        }
        Action::Open => vec![Command::ListPresets],
        Action::Save => {
            app.ui.mode = Mode::SaveAs(TextField::proposed(proposed_name(app)));
            Vec::new()
        }
        Action::ExportSvg if app.explore.view.is_some() => crate::tui::sweep_export::export(app),
        Action::Pin | Action::ClearPins | Action::LogY | Action::Export
            if app.explore.view.is_some() =>
        {
            app.complain(sweep_keys::not_here(app));
            Vec::new()
        }
        Action::Export => export(app, app.ui.chart, Format::Csv),
        Action::ExportSvg => export(app, app.ui.chart, Format::Svg),
        Action::Sweep => sweep_form_keys::open(app, View::Sweep),
        Action::Map => sweep_form_keys::open(app, View::Map),
        Action::Data => crate::tui::data_keys::open(app),
        Action::Fit => crate::tui::fit_keys::open(app),
        Action::StopFit => crate::tui::fit_keys::stop(app),
        Action::Dimensionless => {
            sweep_keys::toggle_dimensionless(app);
            Vec::new()
        }
        Action::GoTo if app.explore.view == Some(View::Map) || map_cursor::on_map(app) => {
            app.complain(
                "g sends the cursor of a chart with curves to a typed x; on a map [ ] { } move it",
            );
            Vec::new()
        }
        Action::Cursor | Action::MoveCursor(_) if app.explore.view == Some(View::Map) => {
            sweep_keys::move_cell(app, action);
            Vec::new()
        }
        Action::Cursor | Action::MoveCursor(_) if map_cursor::on_map(app) => {
            map_cursor::act(app, action);
            Vec::new()
        }
        Action::Cursor
        | Action::MoveCursor(_)
        | Action::GoTo
        | Action::Pin
        | Action::ClearPins
        | Action::Expand
        | Action::LogY => chart_keys::act(app, action),
        Action::Undo => match app.doc.undo.pop() {
            Some((previous, change)) => {
                app.doc.preset = previous;
                app.doc.dirty = app.doc.edited();
                app.fit();
                // undoing an open brings back the other preset's lesson
                if app.doc.preset.lesson != app.lesson.preset.lesson {
                    app.lesson = LessonState::opened(&app.doc.preset);
                }
                app.say(format!(
                    "undo: {} {} -> {}",
                    change.name, change.to, change.from
                ));
                vec![app.request()]
            }
            None => {
                app.say("nothing to undo");
                Vec::new()
            }
        },
        Action::Help => {
            app.ui.mode = Mode::Help(0);
            Vec::new()
        }
        Action::About => {
            app.ui.mode = Mode::About(0);
            Vec::new()
        }
        Action::Questions => lesson_keys::open(app),
        Action::Quit => quit(app),
    }
}

/// Sets the selected row to `value`, or says why not.
/// Applies an edit of a key and says what it did, or says why there is none.
fn edited(app: &mut App, edit: Result<(Preset, Change, String), String>) -> Vec<Command> {
    match edit {
        Ok((next, change, said)) => {
            let commands = apply(app, next, change);
            app.say(said);
            commands
        }
        Err(why) => {
            app.complain(why);
            Vec::new()
        }
    }
}

fn set(app: &mut App, value: f64) -> Vec<Command> {
    let row = app.row();
    match form::set(&app.doc.preset, &row, value) {
        Ok((next, change)) => apply(app, next, change),
        Err(why) => {
            app.complain(why);
            Vec::new()
        }
    }
}

/// Opens a preset (undo can go back).
pub fn open(app: &mut App, entry: PickerEntry) -> Vec<Command> {
    let Ok(preset) = entry.preset else {
        return Vec::new();
    };
    let change = Change {
        name: "preset".into(),
        from: app.doc.preset.name.clone(),
        to: preset.name.clone(),
    };
    app.doc
        .undo
        .push((std::mem::replace(&mut app.doc.preset, preset), change));
    app.doc.opened = app.doc.preset.clone();
    app.doc.path = entry.path;
    app.doc.source = Some(entry.source.clone());
    app.doc.dirty = false;
    app.ui.selected = 0;
    app.ui.chart = Chart::opening(&app.doc.preset);
    // the cursors read the last preset's charts: off, as on a first start (pins stay, to
    // compare the presets)
    app.ui.cursor = None;
    app.ui.map_cell = None;
    app.lesson = LessonState::opened(&app.doc.preset);
    sweep_keys::reopen(app);
    app.ui.playing = false;
    let lesson = invitation(&app.doc.preset).map_or(String::new(), |l| format!("; {l}"));
    app.say(format!("opened {}{lesson}", entry.source));
    if let Some(warning) = crate::tui::warned::said(&app.doc.preset) {
        app.complain(warning);
    }
    let mut commands = vec![app.request()];
    commands.extend(crate::tui::data_keys::of_preset(app));
    commands
}

/// The name `s` proposes: the preset's own file's name when that file is in the user's preset
/// folder (saved over it, after asking); else the name of the file it was read from (bundled or
/// shared), with "-edited" when it was edited, a bare name that saves a copy in the user's
/// folder; "lab" for a preset read from no file.
fn proposed_name(app: &App) -> String {
    let doc = &app.doc;
    let own = (doc.path.as_ref()).is_some_and(|p| {
        p.parent()
            .is_some_and(|d| Some(d) == app.places.presets.as_deref())
    });
    let stem = match (&doc.path, &doc.source) {
        (Some(path), _) => path.file_stem().map(|s| s.to_string_lossy().into_owned()),
        (None, Some(source)) => (source.strip_prefix("bundled: "))
            .map(|file| file.trim_end_matches(".toml").to_string()),
        (None, None) => None,
    };
    match stem {
        Some(stem) if own || !doc.dirty => stem,
        Some(stem) => format!("{stem}-edited"),
        None => "lab".into(),
    }
}

/// Quits, or asks first when there are unsaved edits.
pub fn quit(app: &mut App) -> Vec<Command> {
    if app.doc.dirty {
        let from = std::mem::replace(&mut app.ui.mode, Mode::Normal);
        app.ui.mode = Mode::ConfirmQuit(Box::new(from));
        Vec::new()
    } else {
        vec![Command::Quit]
    }
}

/// Exports `chart` as drawn, as CSV or SVG; waits for its result while it has none.
pub fn export(app: &mut App, chart: Chart, format: Format) -> Vec<Command> {
    let wait = |app: &mut App| {
        app.ui.export_waiting = Some((chart, format));
        app.say("the export waits for the chart's result (solving…)");
        Vec::new()
    };
    let Some(answer) = &app.solve.shown else {
        return wait(app);
    };
    let pins = app.ui.pins_of(chart);
    let now = &answer.request.preset;
    let pinned = pins
        .iter()
        .map(|p| (p.plots.as_slice(), p.name(now)))
        .collect();
    let text = match format {
        Format::Csv => csv::csv(chart, answer, pinned, app.ui.data.as_ref()),
        Format::Svg => {
            let toggled = app.ui.log_y.contains(&chart);
            let scale = app.ui.heat_scale_for(&answer.request.preset);
            csv::svg(chart, answer, pinned, app.ui.data.as_ref(), toggled, scale)
        }
    };
    match text {
        Ok(text) => vec![Command::Export {
            path: csv::file_name(chart, format).into(),
            text,
            overwrite: false,
        }],
        Err(NoFigure::Solving) => wait(app),
        Err(NoFigure::Error(why)) => {
            app.complain(format!("nothing to export: {why}"));
            Vec::new()
        }
    }
}
