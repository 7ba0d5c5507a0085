//! The form of `v` and `M` (part of `update`: pure): the parameter of each axis (any numeric
//! input of the problem), its range (typed with units, "10um", "3 GPa"), its number of points and
//! scale, and the quantity shown. It opens on what is shown now (or the defaults: a decade either
//! side of the current value, within the parameter's limits); Enter checks everything through
//! the library (`sweeps::Axis::new`) and either shows the sweep or the map, or says what is
//! wrong and what is allowed, the form staying open for the correction.

use crate::physics::Spacing;
use crate::physics::limits;
use crate::sweeps::Axis;
use crate::tui::text_field::TextField;
use crate::units::parse_si;

use crate::sweeps::curve::CurveSpec;
use crate::sweeps::map::MapSpec;
use crate::tui::app::{App, Command, Mode};
use crate::tui::prompt_keys::{self, Prompt, PromptAction};
use crate::tui::sweep_shown::{curve_spec, map_spec, parameters, quantities};
use crate::tui::sweep_state::{Draft, Field, SweepForm, View};
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// Opens the form on what the view shows now.
pub fn open(app: &mut App, view: View) -> Vec<Command> {
    let form = match view {
        View::Sweep => curve_spec(app).map(|c| SweepForm {
            view,
            axes: vec![Draft::of(&c.axis)],
            quantity: c.quantity,
            row: 0,
        }),
        View::Map => map_spec(app).map(|m| SweepForm {
            view,
            axes: vec![Draft::of(&m.x), Draft::of(&m.y)],
            quantity: m.quantity,
            row: 0,
        }),
    };
    match form {
        Some(form) => {
            app.ui.mode = Mode::Form(Box::new(form));
            app.say("↑↓ a row, ←→ a choice, type a value (units allowed: 10um, 3 GPa), ⏎ show");
        }
        None => app.complain("this problem has nothing to sweep"),
    }
    Vec::new()
}

fn cycle<T: PartialEq + Copy>(all: &[T], now: T, up: bool) -> T {
    let n = all.len();
    let i = all.iter().position(|x| *x == now).unwrap_or(0);
    all[if up { (i + 1) % n } else { (i + n - 1) % n }]
}

/// A key in the form.
pub fn key(app: &mut App, mut form: SweepForm, key: KeyEvent) -> Vec<Command> {
    let preset = &app.doc.preset;
    let rows = form.fields().len();
    match prompt_keys::prompt_action(Prompt::Form, &key) {
        Some(PromptAction::Accept) => return accept(app, form),
        Some(PromptAction::Cancel) => {
            app.ui.mode = Mode::Normal;
            app.say("sweep unchanged");
            return Vec::new();
        }
        Some(PromptAction::Up) => form.row = form.row.checked_sub(1).unwrap_or(rows - 1),
        Some(PromptAction::Down) => form.row = (form.row + 1) % rows,
        // on a typed row ←→ Home End edit the text; on a choice row ←→ choose
        Some(
            action @ (PromptAction::Left
            | PromptAction::Right
            | PromptAction::First
            | PromptAction::Last),
        ) if text_of(&mut form).is_some() => {
            if let Some(text) = text_of(&mut form) {
                text.move_cursor(prompt_keys::cursor_step(action));
            }
        }
        Some(action @ (PromptAction::Left | PromptAction::Right)) => {
            let up = action == PromptAction::Right;
            match form.field() {
                Field::Param(n) => {
                    let key = cycle(&parameters(preset), form.axes[n].key, up);
                    if let Ok(axis) = Axis::default_for(preset, key) {
                        let points = form.axes[n].points.clone();
                        form.axes[n] = Draft {
                            points,
                            ..Draft::of(&axis)
                        };
                    }
                }
                Field::Scale(n) => form.axes[n].log = !form.axes[n].log,
                Field::Quantity => {
                    let all = quantities(preset, app.explore.dimensionless);
                    if !all.is_empty() {
                        form.quantity = cycle(&all, form.quantity, up);
                    }
                }
                _ => {}
            }
        }
        Some(PromptAction::Backspace) => {
            if let Some(text) = text_of(&mut form) {
                text.backspace();
            }
        }
        _ => {
            let chord = key
                .modifiers
                .intersects(KeyModifiers::CONTROL | KeyModifiers::ALT);
            if let (KeyCode::Char(c), false) = (key.code, chord) {
                match text_of(&mut form) {
                    Some(text) => text.insert(c),
                    None => app.complain("this row is a choice: ←→ change it"),
                }
            }
        }
    }
    app.ui.mode = Mode::Form(Box::new(form));
    Vec::new()
}

fn text_of(form: &mut SweepForm) -> Option<&mut TextField> {
    match form.field() {
        Field::From(n) => Some(&mut form.axes[n].from),
        Field::To(n) => Some(&mut form.axes[n].to),
        Field::Points(n) => Some(&mut form.axes[n].points),
        _ => None,
    }
}

/// The axis a draft describes, checked by the library; Err says what is allowed.
pub fn axis(app: &App, draft: &Draft) -> Result<Axis, String> {
    let key = draft.key;
    let param = key.param();
    let allowed = param.limit().map_or("", |l| l.allowed);
    let value = |end: &str, text: &str| {
        parse_si(text, param.unit)
            .map_err(|why| format!("{}: {end} = {why} (allowed {allowed})", key.symbol()))
    };
    let points: usize = draft.points.text().trim().parse().map_err(|_| {
        format!(
            "{}: points = '{}' is not a whole number: allowed {}",
            key.symbol(),
            draft.points.text(),
            limits::SWEEP_POINTS.allowed
        )
    })?;
    let spacing = if draft.log {
        Spacing::Log
    } else {
        Spacing::Linear
    };
    let ends = [
        value("from", draft.from.text())?,
        value("to", draft.to.text())?,
    ];
    Axis::new(&app.doc.preset, key, ends, points, spacing)
}

fn accept(app: &mut App, form: SweepForm) -> Vec<Command> {
    let axes: Result<Vec<Axis>, String> = form.axes.iter().map(|d| axis(app, d)).collect();
    let axes = match axes {
        Ok(a) => a,
        Err(why) => {
            // the form stays open with the text, for the correction
            app.complain(why);
            app.ui.mode = Mode::Form(Box::new(form));
            return Vec::new();
        }
    };
    if let [x, y] = axes.as_slice() {
        if x.key == y.key {
            app.complain("the map needs two different parameters (←→ on a parameter row)");
            app.ui.mode = Mode::Form(Box::new(form));
            return Vec::new();
        }
    }
    app.ui.mode = Mode::Normal;
    let preset = &app.doc.preset;
    match form.view {
        View::Sweep => {
            app.explore.curve = Some(CurveSpec {
                axis: axes[0],
                quantity: form.quantity,
                models: crate::sweeps::models(preset, &axes[0]),
            });
        }
        View::Map => {
            app.explore.map = Some(MapSpec {
                x: axes[0],
                y: axes[1],
                quantity: form.quantity,
            });
        }
    }
    app.explore.view = Some(form.view);
    app.say(format!(
        "{} against {} (Tab: back to the charts)",
        form.quantity.symbol(),
        axes.iter()
            .map(|a| a.key.symbol())
            .collect::<Vec<_>>()
            .join(" and ")
    ));
    Vec::new()
}
