//! The `d` key (part of `update`: pure): the prompt for a data file's path, the file read by the
//! loop (`Command::ReadData`, answered by `Msg::DataRead`), and what the explorer says of it: the
//! charts it is drawn on, or the charts there are when its quantities match none of their axes,
//! or the file's `path:line: reason` (the overlay shown before stays).

use std::path::{Path, PathBuf};

use crate::data::DataSet;
use crate::sweeps::Opening;
use crate::tui::app::{App, Command, Mode};
use crate::tui::charts::overlay::{Overlay, placed};
use crate::tui::sweep_shown::wanted;
use crate::tui::text_field::TextField;

/// Opens the prompt, with the path of the file drawn now to edit or clear.
pub fn open(app: &mut App) -> Vec<Command> {
    let now = app.ui.data.as_ref().map(|o| o.set.path.clone());
    app.ui.mode = Mode::DataPath(now.map_or_else(TextField::default, TextField::proposed));
    Vec::new()
}

/// The prompt's line: what to type and, for a path typed, where it is looked for.
pub fn prompt(app: &App, typed: &str) -> String {
    let wheres: Vec<String> = candidates(app, typed.trim())
        .iter()
        .map(|p| p.display().to_string())
        .collect();
    match wheres.as_slice() {
        [] => "(a CSV path; empty takes the data away)".into(),
        [only] => format!("-> {only}"),
        many => format!("-> {}", many.join(" or ")),
    }
}

/// Where a typed path is looked for, in order: itself when absolute (or under `~`), else in
/// the preset's folder (`presets/` for a bundled preset, whose bundled data files are read
/// from the program), then where wearlab was started.
pub fn candidates(app: &App, typed: &str) -> Vec<PathBuf> {
    if typed.is_empty() {
        return Vec::new();
    }
    if let (Some(rest), Some(home)) = (typed.strip_prefix("~/"), app.places.home.as_ref()) {
        return vec![home.join(rest)];
    }
    let path = Path::new(typed);
    if path.is_absolute() {
        return vec![path.to_path_buf()];
    }
    let bundled = (app.doc.source.as_ref()).is_some_and(|s| s.starts_with("bundled: "));
    let folder = (app.doc.path.as_ref())
        .and_then(|p| p.parent())
        .or(bundled.then_some(Path::new("presets")))
        .filter(|f| !f.as_os_str().is_empty());
    let mut out: Vec<PathBuf> = folder.map(|f| f.join(path)).into_iter().collect();
    if !out.contains(&path.to_path_buf()) {
        out.push(path.to_path_buf());
    }
    out
}

/// Enter in the prompt: reads the file typed, or with nothing typed takes the overlay away.
pub fn accept(app: &mut App, typed: String) -> Vec<Command> {
    app.ui.mode = Mode::Normal;
    let paths = candidates(app, typed.trim());
    if paths.is_empty() {
        match app.ui.data.take() {
            Some(o) => app.say(format!("took away {}", o.name)),
            None => app.say("no data file is drawn (d and a path draws one)"),
        }
        return Vec::new();
    }
    vec![Command::ReadData(paths, Box::new(app.doc.preset.clone()))]
}

/// Whether the sweep view is on a sweep of one of the file's quantities against its x column.
fn on_sweep(app: &App, overlay: &Overlay) -> bool {
    let Some(Opening::Curve(spec)) = wanted(app).map(|r| r.job) else {
        return false;
    };
    let set = &overlay.set;
    !app.explore.dimensionless
        && spec.axis.key == set.x.key
        && set.measured.iter().any(|m| m.quantity == spec.quantity)
}

/// The command that reads the data file the preset's `[explore]` section names, as it opens.
pub fn of_preset(app: &App) -> Option<Command> {
    let file = app.doc.preset.explore.as_ref()?.data.as_ref()?;
    Some(Command::ReadData(
        candidates(app, file),
        Box::new(app.doc.preset.clone()),
    ))
}

/// The first clause of a file's notes, whole: its `#` lines are one text, a sentence running on
/// from one line to the next, cut at the first ". ", ": " or "; " (a message of two lines at
/// 80 columns holds it, where a line of the file would end mid-sentence); None without notes.
fn first_clause(notes: &[String]) -> Option<String> {
    let text = notes.join(" ");
    let text = text.trim();
    let end = [". ", ": ", "; "]
        .iter()
        .filter_map(|s| text.find(s))
        .min()
        .unwrap_or(text.len());
    (!text.is_empty()).then(|| text[..end].trim_end_matches('.').to_string())
}

/// The file read: drawn on the charts it matches, or why not.
pub fn read(app: &mut App, result: Result<Box<DataSet>, String>) -> Vec<Command> {
    let overlay = match result {
        Ok(set) => Overlay::new(*set),
        Err(why) => {
            let kept = app
                .ui
                .data
                .as_ref()
                .map_or(String::new(), |o| format!(" ({} stays)", o.name));
            app.complain(format!("{why}{kept}"));
            return Vec::new();
        }
    };
    let problem = app.doc.preset.problem;
    // the charts are known from an answer of the problem shown (none yet as a preset opens)
    let answered = (app.solve.shown.as_ref()).filter(|a| a.request.preset.problem == problem);
    let (mut drawn, axes) = match answered {
        Some(answer) => placed(&overlay, answer, problem),
        None => (Vec::new(), Vec::new()),
    };
    if on_sweep(app, &overlay) {
        drawn.insert(0, "the sweep".into());
    }
    let set = &overlay.set;
    let sd = if set.measured.iter().any(|m| m.sd.is_some()) {
        ", with sd"
    } else {
        ""
    };
    let what = format!(
        "{}: {}, {} points{sd}",
        overlay.name,
        overlay.measures(),
        set.len()
    );
    let note = first_clause(&set.notes).map_or(String::new(), |n| format!("; # {n}"));
    if drawn.is_empty() && answered.is_none() {
        app.say(format!(
            "{what}, drawn on the charts whose axes match{note}"
        ));
    } else if drawn.is_empty() {
        let charts = if axes.is_empty() {
            String::new()
        } else {
            format!("; the charts draw {}", axes.join(", "))
        };
        app.complain(format!(
            "{what}: no chart has these axes{charts}; v sweeps any quantity against any input \
             (kept: drawn where the axes match)"
        ));
    } else {
        app.say(format!("{what}, drawn on {}{note}", drawn.join(", ")));
    }
    app.ui.data = Some(overlay);
    Vec::new()
}
