//! A monkey on every bundled preset: random keys (every key of the tables and then some, with
//! Shift and Ctrl), typed values (numbers at and beyond the limits, units, garbage, multi-byte
//! text) and resizes (from 1 x 1 to 200 x 60), through `update` and `view` as the loop runs
//! them, the engine's and the sweep thread's answers delivered (latest request first, as the
//! workers do), files written only inside a folder of the test's own. Deterministic by seed:
//! MONKEY_SEED and MONKEY_KEYS run other or longer walks. Nothing may panic; a failure prints
//! the preset, the seed and the last actions to replay it.

use std::panic::{AssertUnwindSafe, catch_unwind, resume_unwind};
use std::path::{Component, Path};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use crate::engine::Engine;
use crate::engine::sweep_worker::{SweepAnswer, SweepRequest, explore};
use crate::preset::BUNDLED;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use super::{PLAIN, answers_within};
use crate::tui::app::{App, Command, Msg, Places};
use crate::tui::effects;
use crate::tui::update::update;
use crate::tui::view::{RenderOptions, view};

/// Actions per preset by default: 2,100 in all.
const KEYS: usize = 150;
/// The seed by default.
const SEED: u64 = 23;
/// How long the monkey waits for a solve or a sweep before its next action, as a user who presses
/// another key would: the engine and the sweep thread stop their work between two of its steps (a
/// running-in on thousands of nodes takes minutes) and the engine keeps what it did for the next
/// request.
const PATIENCE: Duration = Duration::from_millis(500);

/// SplitMix64 (Steele, Lea and Flood 2014): a small generator whose walk depends on the seed only.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}

/// The characters typed as keys: every letter and sign the key tables bind, digits, and some
/// that nothing binds.
const CHARS: &str = "jkhlpmqxcCfyvMDosSeEuigdwaWrRnNtTbB?[]{}+-=_ .,/:;0123456789~!é";

const CODES: [KeyCode; 15] = [
    KeyCode::Up,
    KeyCode::Down,
    KeyCode::Left,
    KeyCode::Right,
    KeyCode::Enter,
    KeyCode::Esc,
    KeyCode::Tab,
    KeyCode::BackTab,
    KeyCode::Backspace,
    KeyCode::Delete,
    KeyCode::Home,
    KeyCode::End,
    KeyCode::PageUp,
    KeyCode::PageDown,
    KeyCode::F(1),
];

/// Values typed into a prompt, then Enter.
const TYPED: [&str; 24] = [
    "1",
    "0",
    "-1",
    "1e308",
    "-1e308",
    "5e-324",
    "1e-300",
    "nan",
    "inf",
    "-0",
    "2e4",
    "10 um",
    "3 mm3/Nm",
    "0.5 MPa",
    "abc",
    "1:10:5:log",
    "é€😀",
    "",
    "  ",
    "9999999999999999999999",
    "1e6:1:3",
    "~/x.toml",
    "../../x",
    "a/b/c.toml",
];

/// Terminal sizes a resize picks from.
const SIZES: [(u16, u16); 9] = [
    (1, 1),
    (10, 3),
    (40, 12),
    (79, 23),
    (80, 24),
    (100, 30),
    (120, 40),
    (160, 50),
    (200, 60),
];

#[derive(Clone, Debug)]
enum Act {
    Key(KeyEvent),
    Typed(&'static str),
    Resize(u16, u16),
    Tick,
}

fn act(rng: &mut Rng) -> Act {
    match rng.below(100) {
        0..=59 => {
            let chars: Vec<char> = CHARS.chars().collect();
            let c = *rng.pick(&chars);
            let modifiers = match rng.below(20) {
                0 => KeyModifiers::CONTROL,
                1 => KeyModifiers::ALT,
                _ if c.is_uppercase() => KeyModifiers::SHIFT,
                _ => KeyModifiers::NONE,
            };
            Act::Key(KeyEvent::new(KeyCode::Char(c), modifiers))
        }
        60..=84 => {
            let modifiers =
                *rng.pick(&[KeyModifiers::NONE, KeyModifiers::NONE, KeyModifiers::SHIFT]);
            Act::Key(KeyEvent::new(*rng.pick(&CODES), modifiers))
        }
        85..=91 => Act::Typed(TYPED[rng.below(TYPED.len())]),
        92..=95 => {
            let (w, h) = *rng.pick(&SIZES);
            Act::Resize(w, h)
        }
        _ => Act::Tick,
    }
}

/// The explorer's loop without threads: commands carried out at once, the newest solve and the
/// newest sweep answered after each action.
struct Monkey {
    app: App,
    terminal: Terminal<TestBackend>,
    engine: Engine,
    folder: std::path::PathBuf,
    quits: usize,
}

impl Monkey {
    fn new(file: &str, folder: &Path) -> Monkey {
        let places = Places {
            home: Some(folder.to_path_buf()),
            presets: Some(folder.join("presets")),
            shared: Vec::new(),
        };
        let app = App::new(crate::preset::bundled(file).unwrap().unwrap(), None, places);
        let mut m = Monkey {
            app,
            terminal: Terminal::new(TestBackend::new(80, 24)).unwrap(),
            engine: Engine::new(),
            folder: folder.to_path_buf(),
            quits: 0,
        };
        let commands = m.app.start();
        m.perform(commands);
        m.draw();
        m
    }

    fn draw(&mut self) {
        let size = self.terminal.size().unwrap();
        self.app.ui.screen = ratatui::layout::Rect::new(0, 0, size.width, size.height);
        let (app, render): (&App, RenderOptions) = (&self.app, PLAIN);
        self.terminal.draw(|f| view(app, render, f)).unwrap();
    }

    /// Inside the test's folder, with no way out of it.
    fn inside(&self, path: &Path) -> bool {
        path.starts_with(&self.folder) && path.components().all(|c| c != Component::ParentDir)
    }

    fn send(&mut self, msg: Msg) {
        let commands = update(&mut self.app, msg);
        self.perform(commands);
    }

    /// Carries out commands and the commands of their reports, solves and sweeps last (only
    /// the newest of each, as the workers drop a request a newer one replaces).
    fn perform(&mut self, mut commands: Vec<Command>) {
        let (mut solve, mut sweep) = (None, None);
        for _ in 0..100 {
            if commands.is_empty() {
                let work: Vec<Command> = solve.take().into_iter().chain(sweep.take()).collect();
                if work.is_empty() {
                    return;
                }
                for a in answers_within(&mut self.engine, &work, PATIENCE) {
                    commands.extend(update(&mut self.app, Msg::Answer(Box::new(a))));
                }
                for c in work {
                    if let Command::Explore(generation, request) = c {
                        commands.extend(self.explore(generation, *request));
                    }
                }
                continue;
            }
            let mut reports = Vec::new();
            for c in std::mem::take(&mut commands) {
                match c {
                    Command::Solve(..) => solve = Some(c),
                    Command::Explore(..) => sweep = Some(c),
                    Command::ListPresets => {
                        reports.push(effects::list_presets(&self.app.places));
                    }
                    Command::ReadPreset(path) => reports.push(effects::read_preset(path)),
                    Command::Save {
                        target,
                        preset,
                        overwrite,
                        origin,
                    } => reports.push(if self.inside(&target.path) {
                        effects::save(target, preset, overwrite, origin, &[])
                    } else {
                        Msg::Saved(target, preset, Err("outside the monkey's folder".into()))
                    }),
                    Command::Export {
                        path,
                        text,
                        overwrite,
                    } => reports.push(if self.inside(&path) {
                        effects::export(path, text, overwrite)
                    } else {
                        Msg::Exported(path, Err("outside the monkey's folder".into()))
                    }),
                    Command::AnswerLesson(preset) => {
                        reports.push(effects::answer_lesson(*preset));
                    }
                    Command::ReadData(paths, preset) => {
                        reports.push(effects::read_data(&paths, &preset));
                    }
                    // a walk leaves its fits running: the fit thread's answers are tested in fit.rs
                    Command::Fit(..) => {}
                    Command::Quit => self.quits += 1,
                }
            }
            for r in reports {
                commands.extend(update(&mut self.app, r));
            }
        }
        panic!("commands kept coming after 100 rounds");
    }

    fn explore(&mut self, generation: u64, request: SweepRequest) -> Vec<Command> {
        let request = std::sync::Arc::new(request);
        let mut passes = Vec::new();
        let (stop, finished) = (AtomicBool::new(false), AtomicBool::new(false));
        let done = std::thread::scope(|s| {
            s.spawn(|| {
                let start = Instant::now();
                while !finished.load(Ordering::Relaxed) && start.elapsed() < PATIENCE {
                    std::thread::sleep(Duration::from_millis(10));
                }
                stop.store(true, Ordering::Relaxed);
            });
            let done = explore(&request, &stop, &mut |pass| passes.push(pass));
            finished.store(true, Ordering::Relaxed);
            done
        });
        let mut commands = Vec::new();
        let last = done.into_iter().map(|e| (e, true));
        for (explored, complete) in passes.into_iter().map(|e| (e, false)).chain(last) {
            let answer = SweepAnswer {
                generation,
                request: request.clone(),
                explored,
                complete,
            };
            commands.extend(update(&mut self.app, Msg::Explored(Box::new(answer))));
        }
        commands
    }

    fn act(&mut self, act: &Act) {
        match act {
            Act::Key(k) => self.send(Msg::Key(*k)),
            Act::Typed(text) => {
                for c in text.chars() {
                    self.send(Msg::Key(KeyEvent::new(
                        KeyCode::Char(c),
                        KeyModifiers::NONE,
                    )));
                }
                self.send(Msg::Key(KeyEvent::new(KeyCode::Enter, KeyModifiers::NONE)));
            }
            Act::Resize(w, h) => self.terminal.backend_mut().resize(*w, *h),
            Act::Tick => self.send(Msg::Tick),
        }
        self.draw();
    }
}

fn setting(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

#[test]
fn a_monkey_on_every_bundled_preset_breaks_nothing() {
    let seed = setting("MONKEY_SEED", SEED);
    let keys = setting("MONKEY_KEYS", KEYS as u64) as usize;
    let folder = tempfile::tempdir().unwrap();
    let start = Instant::now();
    let mut quits = 0;
    for (i, b) in BUNDLED.iter().enumerate() {
        let mut rng = Rng(seed.wrapping_mul(1000).wrapping_add(i as u64));
        let acts: Vec<Act> = (0..keys).map(|_| act(&mut rng)).collect();
        let mut done: usize = 0;
        let run = catch_unwind(AssertUnwindSafe(|| {
            let mut m = Monkey::new(b.file, folder.path());
            for a in &acts {
                m.act(a);
                done += 1;
                // a quit starts the explorer again on the same preset, as a user would
                if m.quits > 0 {
                    quits += m.quits;
                    m = Monkey::new(b.file, folder.path());
                }
            }
        }));
        if let Err(panic) = run {
            let recent = &acts[done.saturating_sub(20)..=done.min(acts.len() - 1)];
            eprintln!(
                "monkey on {} (MONKEY_SEED={seed}) panicked at action {done}; the last: {recent:?}",
                b.file
            );
            resume_unwind(panic);
        }
    }
    eprintln!(
        "monkey: {} presets x {keys} actions, {quits} quits, {:.1} s",
        BUNDLED.len(),
        start.elapsed().as_secs_f64()
    );
}
