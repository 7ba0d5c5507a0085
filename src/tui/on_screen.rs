//! The answer on screen and how it relates to the form's inputs (a query on the model, read by
//! the drawing and by the keys that work on what is drawn).

use crate::engine::Answer;
use crate::preset::{Preset, Problem};
use crate::tui::app::App;

/// How the shown result relates to the form.
#[derive(Clone, Debug)]
pub enum OnScreen<'a> {
    /// Nothing has arrived yet, or only a result of the other problem.
    Nothing,
    /// The result of the form's inputs; `solving` while more of it (or a newer one) is coming.
    Current(&'a Answer, bool),
    /// A result of other inputs, named by `label`, while the form's are solving.
    Previous(&'a Answer, String),
}

impl<'a> OnScreen<'a> {
    /// The answer to draw, and whether to dim it (it answers other inputs than the form's).
    pub fn answer(&self) -> Option<(&'a Answer, bool)> {
        match self {
            OnScreen::Nothing => None,
            OnScreen::Current(a, _) => Some((*a, false)),
            OnScreen::Previous(a, _) => Some((*a, true)),
        }
    }
}

/// What the screen shows of the newest answer, compared with the form's preset.
pub fn on_screen(app: &App) -> OnScreen<'_> {
    let Some(answer) = &app.solve.shown else {
        return OnScreen::Nothing;
    };
    let theirs = &answer.request.preset;
    let ours = &app.doc.preset;
    if theirs.problem != ours.problem {
        return OnScreen::Nothing;
    }
    // while time plays, each frame is a new request: a result a few frames old is labelled
    // by the t it shows, not dimmed; a name or description (a save marks an edited copy in
    // both) changes no result
    let same = |a: &Preset, b: &Preset| {
        let mut a = a.clone();
        if app.ui.playing {
            a.spatial.time = b.spatial.time;
        }
        a.name.clone_from(&b.name);
        a.description.clone_from(&b.description);
        a == *b
    };
    if same(theirs, ours) {
        return OnScreen::Current(answer, app.solve.solving());
    }
    let label = if theirs.name != ours.name {
        format!("\"{}\"", theirs.name)
    } else if ours.problem == Problem::Plane && theirs.plane.model != ours.plane.model {
        format!("{} model", theirs.plane.model.name())
    } else {
        "previous inputs".to_string()
    };
    OnScreen::Previous(answer, label)
}
