//! The explorer's speed: drawing the full screen at 120x40; a keystroke that re-solves (update,
//! the engine's stages, draw), each iteration at a load never solved before; and a load nudge on
//! the wide model through the real loop (key into the channel, the worker thread, the answer back,
//! the draw) until the new operating point is on screen, and the same for a general shape (the
//! flat pin with rounded edges on its coating, narrow model; target < 25 ms); in partial contact,
//! an edit of the mean pressure through the same loop until the first partial-contact state is on
//! screen (closed form, the start of a running-in: one contact solve, the state at t), the
//! previous running-in dropped by the key. Target: under 100 ms.

use std::hint::black_box;
use std::sync::mpsc::channel;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyModifiers};
use wearlab::engine::{Answer, Engine, Output};
use wearlab::preset::{Preset, bundled};
use wearlab::tui;

use tui::app::{App, Command, Msg, Places};
use tui::event_loop::{Loop, LoopEvent};
use tui::update::update;
use tui::view::{RenderOptions, view};

const OPTIONS: RenderOptions = RenderOptions {
    ascii: false,
    color: true,
    truecolor: false,
};

/// Solves the commands' requests stage by stage and hands every answer to `update`.
fn deliver(app: &mut App, engine: &mut Engine, commands: Vec<Command>) {
    for c in commands {
        if let Command::Solve(generation, request) = c {
            let request = std::sync::Arc::new(*request);
            let mut answers = Vec::new();
            engine.run_staged(&request, |output, complete| {
                answers.push(Answer {
                    generation,
                    request: request.clone(),
                    output,
                    complete,
                });
                true
            });
            for a in answers {
                update(app, Msg::Answer(Box::new(a)));
            }
        }
    }
}

fn app_on(file: &str, engine: &mut Engine) -> App {
    let mut app = App::new(bundled(file).unwrap().unwrap(), None, Places::default());
    let commands = app.start();
    deliver(&mut app, engine, commands);
    app
}

fn select_load(app: &mut App) {
    app.ui.selected = app
        .rows()
        .iter()
        .position(|r| r.param().key == "plane.load")
        .unwrap();
}

fn right() -> KeyEvent {
    KeyEvent::new(KeyCode::Right, KeyModifiers::NONE)
}

fn bench(c: &mut Criterion) {
    let mut engine = Engine::new();
    for file in ["polymer-coating.toml", "dispersion.toml"] {
        let app = app_on(file, &mut engine);
        let mut terminal = Terminal::new(TestBackend::new(120, 40)).unwrap();
        c.bench_function(&format!("explorer_draw_120x40/{file}"), |b| {
            b.iter(|| {
                terminal
                    .draw(|f| view(black_box(&app), OPTIONS, f))
                    .unwrap()
                    .area
            })
        });
    }

    // every iteration starts from a load never seen, so the nudge re-solves the operating point
    let mut app = app_on("polymer-coating.toml", &mut engine);
    select_load(&mut app);
    let mut terminal = Terminal::new(TestBackend::new(120, 40)).unwrap();
    let mut i = 0u64;
    c.bench_function("explorer_keystroke/plane_load_resolve", |b| {
        b.iter(|| {
            i += 1;
            app.doc.preset.plane.load = 5000.0 + i as f64 * 1e-3;
            let commands = update(&mut app, Msg::Key(right()));
            deliver(&mut app, &mut engine, commands);
            terminal.draw(|f| view(&app, OPTIONS, f)).unwrap().area
        })
    });

    // the same nudge through the loop the user runs: worker thread, channel, draw
    nudge_to_status(
        c,
        "explorer_nudge_to_status/wide_loop",
        "polymer-coating.toml",
    );
    // a general shape: the flat pin with rounded edges, narrow model (its nonlinear ODE)
    nudge_to_status(
        c,
        "explorer_nudge_to_status/flat_pin_narrow_loop",
        "flat-pin-coating.toml",
    );
}

/// A key on P through the real loop (channel, worker thread, answer, redraw) until the new
/// operating point is on screen; every iteration starts from a load never solved before.
fn nudge_to_status(c: &mut Criterion, name: &str, file: &str) {
    let (tx, rx) = channel();
    let keys = tx.clone();
    let terminal = Terminal::new(TestBackend::new(120, 40)).unwrap();
    let preset = bundled(file).unwrap().unwrap();
    let base = preset.plane.load;
    let app = App::new(preset, None, Places::default());
    let mut l = Loop::new(terminal, app, OPTIONS, tx, rx).unwrap();
    while l.app.solve.solving() {
        l.step().unwrap();
    }
    select_load(&mut l.app);
    let mut i = 0u64;
    c.bench_function(name, |b| {
        b.iter(|| {
            i += 1;
            l.app.doc.preset.plane.load = base * (1.0 + 1e-6 * i as f64);
            let before = l.app.solve.generation;
            keys.send(LoopEvent::Input(Event::Key(right()))).unwrap();
            // the key, then the answer with the new operating point
            let shown = |a: &App| a.solve.shown.as_ref().map(|s| s.generation);
            while l.app.solve.generation == before || shown(&l.app) != Some(l.app.solve.generation)
            {
                l.step().unwrap();
            }
        })
    });
}

/// True when the answer on screen is the newest request's and holds its partial-contact state.
fn partial_on_screen(app: &App) -> bool {
    let Some(shown) = &app.solve.shown else {
        return false;
    };
    let Output::Spatial(Ok(out)) = &shown.output else {
        return false;
    };
    shown.generation == app.solve.generation
        && out
            .cell
            .as_ref()
            .is_ok_and(|c| c.state.as_ref().is_ok_and(|s| !s.outputs.complete))
}

/// Each iteration starts from a mean pressure never solved before, so nothing is cached.
fn edit_to_first_partial_state(c: &mut Criterion, name: &str, preset: Preset) {
    let (tx, rx) = channel();
    let keys = tx.clone();
    let terminal = Terminal::new(TestBackend::new(120, 40)).unwrap();
    let base = preset.spatial.mean_pressure;
    let app = App::new(preset, None, Places::default());
    let mut l = Loop::new(terminal, app, OPTIONS, tx, rx).unwrap();
    while !partial_on_screen(&l.app) {
        l.step().unwrap();
    }
    l.app.ui.selected = l
        .app
        .rows()
        .iter()
        .position(|r| r.param().key == "spatial.mean_pressure")
        .unwrap();
    let mut i = 0u64;
    c.bench_function(name, |b| {
        b.iter(|| {
            i += 1;
            l.app.doc.preset.spatial.mean_pressure = base * (1.0 + 1e-9 * i as f64);
            let before = l.app.solve.generation;
            keys.send(LoopEvent::Input(Event::Key(right()))).unwrap();
            while l.app.solve.generation == before || !partial_on_screen(&l.app) {
                l.step().unwrap();
            }
        })
    });
}

fn partial(c: &mut Criterion) {
    let lost = bundled("contact-lost.toml").unwrap().unwrap();
    edit_to_first_partial_state(c, "explorer_edit_to_partial/contact_lost_64x1", lost);
    // the egg-box at a quarter of its complete-contact load, with friction, on a layer
    let mut egg = bundled("jgh-egg-box.toml").unwrap().unwrap();
    egg.spatial.mean_pressure = 2.5e7;
    egg.friction.coefficient = 0.3;
    egg.material.thickness = 5e-4;
    for grid in [64, 128] {
        egg.spatial.grid = grid;
        let name = format!("explorer_edit_to_partial/egg_box_{grid}x{grid}");
        edit_to_first_partial_state(c, &name, egg.clone());
    }
}

/// True when the map on screen answers the newest sweep/map request (a coarse pass or more).
fn map_on_screen(app: &App) -> bool {
    app.explore
        .shown
        .as_ref()
        .is_some_and(|a| a.generation == app.explore.generation)
}

/// An edit of the load on the regime map of the strip model (friction-or-wear-map.toml on a
/// 1 mm layer, 41 x 41): from the key to the first coarse pass of the new map drawn, through the
/// real loop (the explorer's thread cancels the previous map). Each iteration's load is new.
fn map_first_pass(c: &mut Criterion) {
    let mut preset = bundled("friction-or-wear-map.toml").unwrap().unwrap();
    preset.plane.model = wearlab::physics::plane::Model::Strip;
    preset.material.thickness = 1e-3;
    let (tx, rx) = channel();
    let keys = tx.clone();
    let terminal = Terminal::new(TestBackend::new(120, 40)).unwrap();
    let app = App::new(preset, None, Places::default());
    let mut l = Loop::new(terminal, app, OPTIONS, tx, rx).unwrap();
    while !map_on_screen(&l.app) {
        l.step().unwrap();
    }
    select_load(&mut l.app);
    let mut i = 0u64;
    c.bench_function("explorer_edit_to_map_first_pass/strip_41x41", |b| {
        b.iter(|| {
            i += 1;
            l.app.doc.preset.plane.load = 5000.0 * (1.0 + 1e-6 * i as f64);
            let before = l.app.explore.generation;
            keys.send(LoopEvent::Input(Event::Key(right()))).unwrap();
            while l.app.explore.generation == before || !map_on_screen(&l.app) {
                l.step().unwrap();
            }
        })
    });
}

criterion_group!(benches, bench);
criterion_group! {
    name = regime_map;
    config = Criterion::default().sample_size(20).measurement_time(Duration::from_secs(4));
    targets = map_first_pass
}
criterion_group! {
    name = partial_contact;
    config = Criterion::default().sample_size(20).measurement_time(Duration::from_secs(4));
    targets = partial
}
criterion_main!(benches, partial_contact, regime_map);
