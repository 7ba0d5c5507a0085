//! The explorer's model (The Elm Architecture): the document being edited, the solve bookkeeping
//! and the UI state; the messages `update` takes and the commands it gives the loop.

use std::path::PathBuf;

pub use crate::tui::messages::{Command, Msg};
pub use crate::tui::picker_entry::{PickerEntry, found};
use crate::tui::text_field::TextField;

use crate::engine::{Answer, Request};
use crate::preset::{Origin, Preset, Problem, SaveTarget};

use crate::tui::charts::export::Format;
use crate::tui::charts::overlay::Overlay;
use crate::tui::charts::{Chart, Plot};
use crate::tui::fit_state::{FitForm, FitReport, Fitting};
use crate::tui::form::{self, Change, Row};
use crate::tui::lesson_state::{LessonState, Quiz, invitation};
use crate::tui::sweep_state::Explore;
use crate::tui::sweep_state::SweepForm;

/// The preset being edited and its history.
#[derive(Clone, Debug)]
pub struct Document {
    /// The preset (always valid).
    pub preset: Preset,
    /// The file it came from or was saved to.
    pub path: Option<PathBuf>,
    /// Where it was read, as `i` says it: its file, or "bundled: <file>" (None: not known).
    pub source: Option<String>,
    /// Edited since the last save or load (`Document::edited`).
    pub dirty: bool,
    /// The preset as last opened or saved: what `dirty` and a saved copy's provenance compare
    /// with.
    pub opened: Preset,
    /// Earlier presets with the change that left each, newest last.
    pub undo: Vec<(Preset, Change)>,
}

impl Document {
    /// The file it was opened from or last saved to, with the preset it held.
    pub fn origin(&self) -> Option<Box<Origin>> {
        self.path.as_ref().map(|path| {
            Box::new(Origin {
                path: path.clone(),
                preset: self.opened.clone(),
            })
        })
    }

    /// Whether the inputs differ from those opened or saved, the time apart: the time shown (t,
    /// and playing it) is where one looks, not an edit.
    pub fn edited(&self) -> bool {
        let mut then = self.opened.clone();
        then.spatial.time = self.preset.spatial.time;
        then != self.preset
    }
}

/// The smallest terminal the explorer draws in (and the screen assumed before the first draw).
pub const MIN_SIZE: (u16, u16) = (80, 24);

/// Undo keeps this many steps.
pub const UNDO_DEPTH: usize = 200;

/// What has been asked of the worker and what came back.
#[derive(Clone, Debug, Default)]
pub struct Solve {
    /// The generation of the newest request.
    pub generation: u64,
    /// Whether the newest request asked for the overlays.
    pub overlays: bool,
    /// Whether the newest request asked for the energy losses along the load sweep.
    pub energies: bool,
    /// The newest answer received (it carries the request it answers).
    pub shown: Option<Answer>,
}

impl Solve {
    /// True until the newest request is completely answered.
    pub fn solving(&self) -> bool {
        self.shown
            .as_ref()
            .is_none_or(|a| a.generation != self.generation || !a.complete)
    }
}

/// A message for the user.
#[derive(Clone, Debug, PartialEq)]
pub struct Message {
    /// The text.
    pub text: String,
    /// True for an error (drawn in red or bold).
    pub error: bool,
}

/// What the keyboard is doing.
#[derive(Clone, Debug, PartialEq)]
pub enum Mode {
    /// The main screen.
    Normal,
    /// Typing a value for the selected row.
    Editing(TextField),
    /// Picking one of the selected row's choices.
    Choosing(usize),
    /// Reading the help, scrolled by this many lines.
    Help(u16),
    /// Reading the preset's name and whole description (`i`), scrolled by this many lines.
    About(u16),
    /// Choosing a preset to open.
    Picker {
        /// The presets offered.
        entries: Vec<PickerEntry>,
        /// The highlighted one (an index of `entries`, one that matches `filter`).
        selected: usize,
        /// Lines of its description scrolled off the top (PgUp/PgDn).
        scroll: u16,
        /// The text typed: the list shows the entries it matches (`PickerEntry::matches`); a
        /// path to a file opens that file.
        filter: String,
    },
    /// Typing a file name to save to.
    SaveAs(TextField),
    /// Typing the x the chart's cursor goes to (`g`).
    GoTo(TextField),
    /// Typing the path of a data file to draw over the charts (`d`).
    DataPath(TextField),
    /// The file exists: overwrite?
    ConfirmOverwrite(SaveTarget),
    /// The export's file exists: overwrite? (the file, the text to write)
    ConfirmExport(Box<(PathBuf, String)>),
    /// Unsaved edits: open this preset anyway?
    ConfirmOpen(Box<PickerEntry>),
    /// Unsaved edits: quit anyway? (No goes back to the mode it was asked from.)
    ConfirmQuit(Box<Mode>),
    /// Choosing the axes and the quantity of a sweep or a map (`v`, `M`).
    Form(Box<SweepForm>),
    /// Answering the lesson's questions (`a`).
    Questions(Quiz),
    /// Choosing the inputs a fit frees (`F`).
    FitForm(FitForm),
    /// Reading a fit's result, scrolled by this many lines.
    FitResult(Box<FitReport>, u16),
}

/// The UI state.
#[derive(Clone, Debug)]
pub struct Ui {
    /// Selected form row.
    pub selected: usize,
    /// Keyboard mode.
    pub mode: Mode,
    /// The visible chart.
    pub chart: Chart,
    /// The last message for the user.
    pub message: Option<Message>,
    /// Time is playing (spatial).
    pub playing: bool,
    /// A chart waiting for its current result to be exported, and how.
    pub export_waiting: Option<(Chart, Format)>,
    /// The cursor of the readout, as a fraction of the chart's x range (None: off).
    pub cursor: Option<f64>,
    /// The pressure map's cursor (grid column, row; `map_cursor`), when on.
    pub map_cell: Option<(usize, usize)>,
    /// Curves pinned for comparison, oldest first.
    pub pins: Vec<Pin>,
    /// The data file drawn over the charts whose axes it matches, kept across edits.
    pub data: Option<Overlay>,
    /// The fit running on the fit thread, if any.
    pub fitting: Option<Fitting>,
    /// The fit thread's requests so far (the generation of the newest).
    pub fit_runs: u64,
    /// The chart has the whole screen but the status.
    pub expanded: bool,
    /// The charts whose y axis is toggled (log, symmetric log, or back to linear).
    pub log_y: Vec<Chart>,
    /// The pressure map's colour scale over the times seen of one set of inputs.
    pub heat_scale: Option<HeatScale>,
    /// The screen as last drawn (80x24 before the first draw): the help's scrolling stops at
    /// its end.
    pub screen: ratatui::layout::Rect,
}

/// A colour scale kept while only the time changes, so that a decay shows as fading colours.
#[derive(Clone, Debug, PartialEq)]
pub struct HeatScale {
    /// The inputs it belongs to, at t = 0.
    pub inputs: Preset,
    /// The lowest and highest pressure seen [Pa].
    pub range: [f64; 2],
}

impl Ui {
    /// The kept colour scale of the map drawn for these inputs, if it is theirs.
    pub fn heat_scale_for(&self, preset: &Preset) -> Option<[f64; 2]> {
        let s = self.heat_scale.as_ref()?;
        let mut at_zero = preset.clone();
        at_zero.spatial.time = 0.0;
        (s.inputs == at_zero).then_some(s.range)
    }

    /// The pins of a chart, oldest first.
    pub fn pins_of(&self, chart: Chart) -> Vec<&Pin> {
        self.pins.iter().filter(|p| p.chart == chart).collect()
    }
}

/// The curves of a chart kept to compare with later results.
#[derive(Clone, Debug, PartialEq)]
pub struct Pin {
    /// The chart they were drawn on.
    pub chart: Chart,
    /// The inputs they answer.
    pub preset: Preset,
    /// The plots.
    pub plots: Vec<Plot>,
}

impl Pin {
    /// The pin's legend name against the inputs shown now: what differs ("pin: k = 2e-11 1/Pa,
    /// mu = 0.2"), the first three of it.
    pub fn name(&self, now: &Preset) -> String {
        let (ours, theirs) = (&self.preset.spatial.harmonics, &now.spatial.harmonics);
        let mut differ: Vec<String> = form::rows(&self.preset)
            .iter()
            .filter(|r| r.harmonic_index().is_none_or(|n| n < theirs.len()))
            .filter(|r| form::show(&self.preset, r) != form::show(now, r))
            .map(|r| format!("{} = {}", r.symbol(), form::show(&self.preset, r)))
            .collect();
        if self.preset.problem == Problem::Spatial && ours.len() != theirs.len() {
            differ.push(format!("{} harmonics", ours.len()));
        }
        match differ.len() {
            0 if self.preset.name != now.name => format!("pin: \"{}\"", self.preset.name),
            0 => "pin: the same inputs".into(),
            1..=3 => format!("pin: {}", differ.join(", ")),
            n => format!("pin: {}, +{} more", differ[..3].join(", "), n - 3),
        }
    }
}

/// Where files go: read once at start, so that `update` stays a pure function.
#[derive(Clone, Debug, Default)]
pub struct Places {
    /// The home folder (`~` in the save prompt).
    pub home: Option<PathBuf>,
    /// The user's preset folder (bare names are saved there; the picker lists it).
    pub presets: Option<PathBuf>,
    /// Folders of presets shared with the user, listed by the picker after the bundled ones:
    /// those of `WEARLAB_PRESETS`, then the folder of the file the explorer was started on.
    pub shared: Vec<PathBuf>,
}

/// The whole model.
#[derive(Clone, Debug)]
pub struct App {
    /// The preset and its history.
    pub doc: Document,
    /// Where files go.
    pub places: Places,
    /// The solve bookkeeping.
    pub solve: Solve,
    /// The UI state.
    pub ui: Ui,
    /// The sweep chart and the regime map.
    pub explore: Explore,
    /// The preset's lesson: its questions' answers.
    pub lesson: LessonState,
}

impl App {
    /// A new app on a preset; the first solve is asked by `start` (update.rs).
    pub fn new(preset: Preset, path: Option<PathBuf>, places: Places) -> App {
        App {
            places,
            explore: Explore::opened(&preset),
            lesson: LessonState::opened(&preset),
            ui: Ui {
                selected: 0,
                mode: Mode::Normal,
                chart: Chart::opening(&preset),
                // a value that looks like a unit mistake first: the lesson can wait
                message: (crate::tui::warned::said(&preset)
                    .map(|text| Message { text, error: true }))
                .or_else(|| invitation(&preset).map(|text| Message { text, error: false })),
                playing: false,
                export_waiting: None,
                cursor: None,
                map_cell: None,
                pins: Vec::new(),
                data: None,
                fitting: None,
                fit_runs: 0,
                expanded: false,
                log_y: Vec::new(),
                heat_scale: None,
                screen: ratatui::layout::Rect::new(0, 0, MIN_SIZE.0, MIN_SIZE.1),
            },
            doc: Document {
                opened: preset.clone(),
                preset,
                source: path.as_ref().map(|p| p.display().to_string()),
                path,
                dirty: false,
                undo: Vec::new(),
            },
            solve: Solve::default(),
        }
    }

    /// A new request for the current preset and chart.
    pub fn request(&mut self) -> Command {
        self.solve.generation += 1;
        self.solve.overlays = self.ui.chart.draws_overlays();
        self.solve.energies = self.ui.chart.draws_energies();
        Command::Solve(
            self.solve.generation,
            Box::new(Request {
                preset: self.doc.preset.clone(),
                overlays: self.solve.overlays,
                energies: self.solve.energies,
            }),
        )
    }

    /// Says something to the user.
    pub fn say(&mut self, text: impl Into<String>) {
        self.ui.message = Some(Message {
            text: text.into(),
            error: false,
        });
    }

    /// Says what went wrong.
    pub fn complain(&mut self, text: impl Into<String>) {
        self.ui.message = Some(Message {
            text: text.into(),
            error: true,
        });
    }

    /// The form's rows for the current problem.
    pub fn rows(&self) -> Vec<Row> {
        form::rows(&self.doc.preset)
    }

    /// The selected row.
    pub fn row(&self) -> Row {
        let rows = self.rows();
        rows[self.ui.selected.min(rows.len() - 1)]
    }

    /// Keeps the selected row and the chart inside what the current problem has.
    pub fn fit(&mut self) {
        let rows = self.rows().len();
        self.ui.selected = self.ui.selected.min(rows.saturating_sub(1));
        if self.ui.chart.problem() != self.doc.preset.problem {
            self.ui.chart = Chart::first(self.doc.preset.problem);
        }
    }
}
