//! The event loop. It sleeps on one channel fed by the input thread and by the solver's worker,
//! so it wakes on a key and on a result alike (and on the frame clock while time plays); it
//! carries out `update`'s commands (solving, files) and reports back with messages.

use std::io;
use std::sync::mpsc::{Receiver, RecvTimeoutError, Sender};
use std::time::{Duration, Instant};

use crate::engine::fit_worker::{FitAnswer, FitWorker};
use crate::engine::sweep_worker::{SweepAnswer, SweepWorker};
use crate::engine::{Answer, Worker};
use ratatui::Terminal;
use ratatui::backend::Backend;
use ratatui::crossterm::event::{Event, KeyEventKind};

use crate::tui::app::{App, Command, Msg};
use crate::tui::effects;
use crate::tui::update::update;
use crate::tui::view::{RenderOptions, view};

/// How often time advances while playing: five frames a second, so that the pressure map
/// writes well under 60 KB/s to a terminal over SSH (`docs/performance.md`, "Bytes to the terminal"; tests/bytes.rs).
pub const FRAME: Duration = Duration::from_millis(200);

/// What wakes the loop.
#[derive(Debug)]
pub enum LoopEvent {
    /// A terminal event from the input thread.
    Input(Event),
    /// An answer from the worker.
    Answer(Box<Answer>),
    /// An answer from the explorer's thread (a sweep, a pass of a map).
    Explored(Box<SweepAnswer>),
    /// A fit done on the fit thread.
    Fitted(Box<FitAnswer>),
    /// A signal that ends the explorer (its number; `signals.rs`).
    Signal(i32),
}

/// How the loop ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ending {
    /// The user quit (or the channel closed).
    Quit,
    /// A signal arrived (its number).
    Signal(i32),
}

/// The event loop over any backend (a real terminal, or a test buffer).
pub struct Loop<B: Backend> {
    /// The terminal drawn on.
    pub terminal: Terminal<B>,
    /// The model.
    pub app: App,
    render: RenderOptions,
    wake: Receiver<LoopEvent>,
    worker: Worker,
    explorer: SweepWorker,
    fitter: FitWorker,
    next_frame: Instant,
    ending: Ending,
}

impl<B: Backend> Loop<B> {
    /// Starts the worker (answering into `tx`), asks for the first solve and draws.
    pub fn new(
        terminal: Terminal<B>,
        app: App,
        render: RenderOptions,
        tx: Sender<LoopEvent>,
        rx: Receiver<LoopEvent>,
    ) -> io::Result<Loop<B>> {
        let explored = tx.clone();
        let explorer =
            SweepWorker::spawn(move |a| explored.send(LoopEvent::Explored(Box::new(a))).is_ok());
        let fitted = tx.clone();
        let fitter = FitWorker::spawn(move |a| fitted.send(LoopEvent::Fitted(Box::new(a))).is_ok());
        let worker = Worker::spawn(move |a| tx.send(LoopEvent::Answer(Box::new(a))).is_ok());
        let mut l = Loop {
            terminal,
            app,
            render,
            wake: rx,
            worker,
            explorer,
            fitter,
            next_frame: Instant::now() + FRAME,
            ending: Ending::Quit,
        };
        let commands = l.app.start();
        l.perform(commands);
        l.draw()?;
        Ok(l)
    }

    /// Runs until the user quits or a signal ends it.
    pub fn run(&mut self) -> io::Result<Ending> {
        while self.step()? {}
        Ok(self.ending)
    }

    /// Sleeps until a key, a result or the next frame of playing time; handles it and whatever
    /// else has arrived meanwhile, then redraws once. False when the user quit or a signal
    /// arrived (which ends the loop before anything that came with it is handled).
    pub fn step(&mut self) -> io::Result<bool> {
        let first = if self.app.ui.playing {
            let wait = self.next_frame.saturating_duration_since(Instant::now());
            match self.wake.recv_timeout(wait) {
                Ok(w) => Some(w),
                Err(RecvTimeoutError::Timeout) => None,
                Err(RecvTimeoutError::Disconnected) => return Ok(false),
            }
        } else {
            match self.wake.recv() {
                Ok(w) => Some(w),
                Err(_) => return Ok(false),
            }
        };
        let mut wakes: Vec<LoopEvent> = first.into_iter().collect();
        wakes.extend(self.wake.try_iter());
        if let Some(signal) = wakes.iter().find_map(|w| match w {
            LoopEvent::Signal(s) => Some(*s),
            _ => None,
        }) {
            self.ending = Ending::Signal(signal);
            return Ok(false);
        }
        let mut messages: Vec<Msg> = wakes.into_iter().filter_map(message).collect();
        let now = Instant::now();
        if self.app.ui.playing && now >= self.next_frame {
            messages.push(Msg::Tick);
            self.next_frame = now + FRAME;
        }
        for msg in messages {
            let commands = update(&mut self.app, msg);
            if !self.perform(commands) {
                return Ok(false);
            }
        }
        self.draw()?;
        Ok(true)
    }

    fn draw(&mut self) -> io::Result<()> {
        let size = self
            .terminal
            .size()
            .map_err(|e| io::Error::other(e.to_string()))?;
        self.app.ui.screen = ratatui::layout::Rect::new(0, 0, size.width, size.height);
        let (app, render) = (&self.app, self.render);
        match self.terminal.draw(|f| view(app, render, f)) {
            Ok(_) => Ok(()),
            Err(e) => Err(io::Error::other(e.to_string())),
        }
    }

    /// Carries out commands, and the commands of the messages they report; false on Quit.
    fn perform(&mut self, mut commands: Vec<Command>) -> bool {
        while !commands.is_empty() {
            let mut reports = Vec::new();
            for cmd in commands {
                let report = match cmd {
                    Command::Solve(generation, request) => {
                        self.worker.submit(generation, *request);
                        continue;
                    }
                    Command::Explore(generation, request) => {
                        self.explorer.submit(generation, *request);
                        continue;
                    }
                    Command::Fit(generation, job) => {
                        self.fitter.submit(generation, *job);
                        continue;
                    }
                    Command::ListPresets => effects::list_presets(&self.app.places),
                    Command::ReadPreset(path) => effects::read_preset(path),
                    Command::Save {
                        target,
                        preset,
                        overwrite,
                        origin,
                    } => effects::save(target, preset, overwrite, origin, &self.app.places.shared),
                    Command::Export {
                        path,
                        text,
                        overwrite,
                    } => effects::export(path, text, overwrite),
                    Command::AnswerLesson(preset) => effects::answer_lesson(*preset),
                    Command::ReadData(paths, preset) => effects::read_data(&paths, &preset),
                    Command::Quit => return false,
                };
                reports.push(report);
            }
            commands = reports
                .into_iter()
                .flat_map(|m| update(&mut self.app, m))
                .collect();
        }
        true
    }
}

/// The message of a wake-up (key releases, mouse events and signals are none).
fn message(wake: LoopEvent) -> Option<Msg> {
    match wake {
        LoopEvent::Input(Event::Key(key)) if key.kind != KeyEventKind::Release => {
            Some(Msg::Key(key))
        }
        LoopEvent::Input(_) | LoopEvent::Signal(_) => None,
        LoopEvent::Answer(answer) => Some(Msg::Answer(answer)),
        LoopEvent::Explored(answer) => Some(Msg::Explored(answer)),
        LoopEvent::Fitted(answer) => Some(Msg::Fitted(answer)),
    }
}
