//! The messages `update` takes (keys, time, what the loop's I/O and the workers report) and the
//! commands it gives the loop (the I/O and the solving happen there).

use std::path::PathBuf;

use ratatui::crossterm::event::KeyEvent;

use crate::data::DataSet;
use crate::engine::fit_worker::{FitAnswer, FitJob};
use crate::engine::sweep_worker::{SweepAnswer, SweepRequest};
use crate::engine::{Answer, Request};
use crate::preset::{Origin, Preset, SaveTarget};
use crate::tui::picker_entry::PickerEntry;

/// Input to `update`: keys, time, and what the loop's I/O and the worker report.
#[derive(Clone, Debug)]
pub enum Msg {
    /// A key press.
    Key(KeyEvent),
    /// Time passes while playing (spatial).
    Tick,
    /// The worker answered (a stage of) a request.
    Answer(Box<Answer>),
    /// The presets to offer in the picker.
    PresetsListed(Vec<PickerEntry>),
    /// A preset file named by a path typed in the picker, read.
    PresetRead(Box<PickerEntry>),
    /// A save needs confirmation: the file exists.
    SaveExists(SaveTarget),
    /// A save finished: the preset written and what to say of it, or why not.
    Saved(SaveTarget, Box<Preset>, Result<String, String>),
    /// An export needs confirmation: the file exists (the file, the text to write).
    ExportExists(PathBuf, String),
    /// An export finished: the file, or why not.
    Exported(PathBuf, Result<(), String>),
    /// The explorer's thread answered (a pass of) a sweep or a map.
    Explored(Box<SweepAnswer>),
    /// The program's answers to the lesson's questions at these inputs (each SI, or why not).
    LessonAnswered(Box<Preset>, Vec<Result<f64, String>>),
    /// A data file read for the overlay, or why not (`path:line: reason`).
    DataRead(Result<Box<DataSet>, String>),
    /// The fit thread finished a fit.
    Fitted(Box<FitAnswer>),
}

/// What the loop must do after an update (the I/O and the solving happen there).
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    /// Solve this request (generation number attached).
    Solve(u64, Box<Request>),
    /// List the bundled presets, the shared folders and the user's folder, answered by
    /// `PresetsListed`.
    ListPresets,
    /// Read the preset file at this path, answered by `PresetRead`.
    ReadPreset(PathBuf),
    /// Write the preset; refuse an existing file unless `overwrite`. Answered by `Saved` or
    /// `SaveExists`.
    Save {
        /// Where.
        target: SaveTarget,
        /// What.
        preset: Box<Preset>,
        /// Replace an existing file.
        overwrite: bool,
        /// The file it was opened from or last saved to, whose text the save keeps.
        origin: Option<Box<Origin>>,
    },
    /// Write this text to this file; refuse an existing file unless `overwrite`. Answered by
    /// `Exported` or `ExportExists`.
    Export {
        /// Where.
        path: PathBuf,
        /// What.
        text: String,
        /// Replace an existing file.
        overwrite: bool,
    },
    /// Compute this sweep or map on the explorer's thread (cancelling older work), answered
    /// by `SweepResult`.
    Explore(u64, Box<SweepRequest>),
    /// Answer the lesson's questions at these inputs, answered by `LessonAnswered`.
    AnswerLesson(Box<Preset>),
    /// Read the data file at the first of these paths that exists, for this preset, answered
    /// by `DataRead`.
    ReadData(Vec<PathBuf>, Box<Preset>),
    /// Fit on the fit thread (generation attached), or stop the running fit; a fit is
    /// answered by `Fitted`.
    Fit(u64, Box<FitJob>),
    /// Leave.
    Quit,
}
