//! The `F` key (part of `update`: pure): with a data file drawn, a form chooses the inputs to
//! free; the fit, the library's `fit::fit` as `wearlab fit` runs it, goes to the fit thread
//! (`Command::Fit`, answered by `Msg::Fitted`) while the screen stays live; Esc or an edit stops
//! it. Its best values enter the form as one undo step, and a window gives each estimate with
//! its 95 % interval, the residual, and in words what the data do not determine.

use ratatui::crossterm::event::KeyEvent;

use crate::data::DataSet;
use crate::engine::fit_worker::{FitAnswer, FitJob, FitRequest};
use crate::fit::{Fit, Free};
use crate::preset::{Key, Preset};
use crate::tui::app::{App, Command, Mode};
use crate::tui::edit::apply;
use crate::tui::fit_state::{FitForm, FitReport, Fitting, Offered};
use crate::tui::form::{self, Change};
use crate::tui::lesson_keys;
use crate::tui::prompt_keys::{PAGE, Prompt, PromptAction, prompt_action};
use crate::units::format_si;

/// The inputs offered first: the friction coefficient and the wear coefficient.
const FIRST: [&str; 2] = ["friction.coefficient", "wear.coefficient"];

/// Whether the form offers `key`: a number a fit can vary (`Free::new`) and the preset gives
/// (not a yield strength or hardness shown as "none"), not the data's x, not a setting of the
/// charts (the sweeps' ranges, the time shown and its duration).
fn offered(preset: &Preset, data: &DataSet, key: Key) -> bool {
    let name = key.param().key;
    !name.contains(".sweep.")
        && !matches!(name, "spatial.time" | "spatial.duration")
        && form::show(preset, &key) != "none"
        && Free::new(preset, key, data.x.key).is_ok()
}

/// The form's inputs: mu and k first, then the others in the form's order.
pub fn inputs(preset: &Preset, data: &DataSet) -> Vec<Offered> {
    let mut keys: Vec<Key> = (form::rows(preset).into_iter())
        .filter(|k| offered(preset, data, *k))
        .collect();
    keys.sort_by_key(|k| {
        FIRST
            .iter()
            .position(|f| *f == k.param().key)
            .unwrap_or(FIRST.len())
    });
    keys.into_iter()
        .map(|key| Offered {
            key,
            free: false,
            locked: (preset.lesson.as_ref()).is_some_and(|l| l.locks(key)),
        })
        .collect()
}

/// `F`: opens the form, or says why not (no data drawn, a fit running).
pub fn open(app: &mut App) -> Vec<Command> {
    let Some(overlay) = &app.ui.data else {
        app.complain("F fits the inputs to a data file: draw one first (d and its path)");
        return Vec::new();
    };
    if app.ui.fitting.is_some() {
        app.complain("a fit is running (Esc stops it)");
        return Vec::new();
    }
    let offered = inputs(&app.doc.preset, &overlay.set);
    if offered.is_empty() {
        app.complain("this problem has no input a fit can free");
        return Vec::new();
    }
    app.ui.expanded = false;
    app.ui.mode = Mode::FitForm(FitForm {
        offered,
        selected: 0,
    });
    app.say(format!(
        "fit to {}: space frees or fixes an input, Enter fits the free ones",
        overlay.name.trim_start_matches("data: ")
    ));
    Vec::new()
}

/// A key in the form.
pub fn key(app: &mut App, mut form: FitForm, key: KeyEvent) -> Vec<Command> {
    let last = form.offered.len().saturating_sub(1);
    match prompt_action(Prompt::Toggles, &key) {
        Some(PromptAction::Cancel) => {
            app.ui.mode = Mode::Normal;
            app.say("no fit: the inputs stay as they were");
            return Vec::new();
        }
        Some(PromptAction::Accept) => return start(app, &form),
        Some(PromptAction::Up) => form.selected = form.selected.checked_sub(1).unwrap_or(last),
        Some(PromptAction::Down) => form.selected = (form.selected + 1) % (last + 1),
        Some(PromptAction::PageUp) => form.selected = form.selected.saturating_sub(PAGE),
        Some(PromptAction::PageDown) => form.selected = (form.selected + PAGE).min(last),
        Some(PromptAction::First) => form.selected = 0,
        Some(PromptAction::Last) => form.selected = last,
        Some(PromptAction::Toggle) => {
            let o = &mut form.offered[form.selected];
            if o.locked {
                let why = lesson_keys::why_locked(app, o.key);
                app.complain(format!("{why}; a fit cannot free it"));
            } else {
                o.free = !o.free;
                if app.ui.message.as_ref().is_some_and(|m| m.error) {
                    app.ui.message = None;
                }
            }
        }
        _ => {}
    }
    app.ui.mode = Mode::FitForm(form);
    Vec::new()
}

/// The symbols of `keys`, joined ("mu, k").
fn symbols(keys: &[Key]) -> String {
    keys.iter()
        .map(|k| k.symbol())
        .collect::<Vec<_>>()
        .join(", ")
}

/// Enter in the form: sends the fit of the inputs chosen.
fn start(app: &mut App, form: &FitForm) -> Vec<Command> {
    let keys = form.chosen();
    let Some(overlay) = &app.ui.data else {
        app.ui.mode = Mode::Normal;
        return Vec::new();
    };
    if keys.is_empty() {
        app.complain("no input is free: space frees the highlighted one");
        app.ui.mode = Mode::FitForm(form.clone());
        return Vec::new();
    }
    let data = overlay.set.clone();
    let said = format!(
        "fitting {} to {} ({} points)… Esc stops it, as does an edit",
        symbols(&keys),
        overlay.name.trim_start_matches("data: "),
        data.len()
    );
    app.ui.fit_runs += 1;
    let generation = app.ui.fit_runs;
    app.ui.fitting = Some(Fitting {
        generation,
        from: app.doc.preset.clone(),
        data: data.path.clone(),
    });
    app.ui.mode = Mode::Normal;
    app.say(said);
    let request = FitRequest {
        preset: app.doc.preset.clone(),
        data,
        keys,
    };
    vec![Command::Fit(
        generation,
        Box::new(FitJob::Fit(Box::new(request))),
    )]
}

/// Esc on the main screen: stops a running fit.
pub fn stop(app: &mut App) -> Vec<Command> {
    if app.ui.fitting.take().is_none() {
        return Vec::new();
    }
    app.say("fit stopped: the inputs stay as they were");
    vec![cancel(app)]
}

fn cancel(app: &mut App) -> Command {
    app.ui.fit_runs += 1;
    Command::Fit(app.ui.fit_runs, Box::new(FitJob::Cancel))
}

/// After every update: a running fit whose inputs or data changed is stopped (its answer would
/// be another preset's).
pub fn stale(app: &mut App) -> Vec<Command> {
    let Some(fitting) = &app.ui.fitting else {
        return Vec::new();
    };
    let data = app.ui.data.as_ref().map(|o| o.set.path.as_str());
    if fitting.from == app.doc.preset && data == Some(fitting.data.as_str()) {
        return Vec::new();
    }
    app.ui.fitting = None;
    if app.ui.message.is_none() {
        app.say("fit stopped: the inputs or the data changed (F fits again)");
    }
    vec![cancel(app)]
}

/// The fit thread answered: the best values enter the form as one undo step and the report
/// opens; an answer to a fit stopped since is dropped.
pub fn fitted(app: &mut App, answer: FitAnswer) -> Vec<Command> {
    let ours = (app.ui.fitting.as_ref()).is_some_and(|f| f.generation == answer.generation);
    if !ours {
        return Vec::new();
    }
    app.ui.fitting = None;
    let fit = match answer.result {
        Ok(fit) => fit,
        Err(why) => {
            let (crate::fit::FitError::Invalid(why) | crate::fit::FitError::NoFit(why)) = why;
            app.complain(format!("no fit: {why}"));
            return Vec::new();
        }
    };
    let keys: Vec<Key> = fit.estimates.iter().map(|e| e.key).collect();
    let values = |p: &Preset| {
        (keys.iter())
            .map(|k| format!("{} = {}", k.symbol(), form::show(p, k)))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let change = Change {
        name: "fit".into(),
        from: values(&app.doc.preset),
        to: values(&fit.preset),
    };
    let shown = app.ui.data.as_ref().map(|o| report(&fit, &o.set));
    let commands = apply(app, fit.preset.clone(), change);
    app.ui.mode = shown.map_or(Mode::Normal, |r| Mode::FitResult(Box::new(r), 0));
    app.say("fitted: the form holds the best values; u undoes them in one step");
    commands
}

/// An estimate's line: "mu = 0.29975, 95 % interval 0.2989 .. 0.3006", each number to the
/// digits the interval supports; an undetermined one says where its value comes from and what
/// fits ("k not determined by these data: kept at the preset's 1e-12 1/Pa (any k up to ...)").
fn estimate_line(e: &crate::fit::Estimate) -> String {
    let (value, [low, high]) = e.texts();
    let symbol = e.key.symbol();
    e.undetermined_words(&symbol)
        .unwrap_or_else(|| format!("{symbol} = {value}, 95 % interval {low} .. {high}"))
}

/// The report of `fit` to the data `set`, in words.
pub fn report(fit: &Fit, set: &DataSet) -> FitReport {
    let file = std::path::Path::new(&set.path)
        .file_name()
        .map_or(set.path.clone(), |f| f.to_string_lossy().into_owned());
    // the residuals' unit, when they are all of one quantity
    let unit = match set.measured.as_slice() {
        [one] => one.quantity.quantity().unit,
        _ => "",
    };
    let points = fit.degrees_of_freedom + fit.estimates.len();
    let weighting = if fit.weighted {
        "weighted by its sd columns"
    } else {
        "its noise estimated from the scatter: the file has no sd column"
    };
    let mut paragraphs = vec![format!(
        "{file}: {points} measured values, {weighting}; the best values are now in the form."
    )];
    paragraphs.push(String::new());
    for e in &fit.estimates {
        paragraphs.push(estimate_line(e));
        if let Some(why) = &e.reason {
            paragraphs.push(format!("    {why}."));
        }
    }
    paragraphs.push(String::new());
    let n = fit.residuals.len().max(1) as f64;
    let rms = (fit.residuals.iter().map(|r| r * r).sum::<f64>() / n).sqrt();
    let dof = fit.degrees_of_freedom;
    let residual = if fit.weighted {
        format!(
            "residual: rms(data - model) = {}; chi-square {:.3} for {dof} degrees of freedom \
             (reduced {:.2}: near 1 when the model fits within the sd)",
            format_si(rms, unit),
            fit.sum_of_squares,
            fit.sum_of_squares / dof as f64
        )
    } else {
        format!(
            "residual: rms(data - model) = {}; the noise estimated from it, sd {} ({dof} \
             degrees of freedom)",
            format_si(rms, unit),
            format_si(fit.residual_variance.sqrt(), unit)
        )
    };
    paragraphs.push(residual);
    paragraphs.push(
        "95 %: the range that holds the true value 95 times in 100 repeats of the measurement. \
         u undoes the fit; s saves the preset with these values."
            .into(),
    );
    FitReport {
        title: format!(
            "fit of {}",
            symbols(&fit.estimates.iter().map(|e| e.key).collect::<Vec<_>>())
        ),
        paragraphs,
    }
}
