//! The explorer's speed: drawing the full screen at 120x40, and a keystroke on a plane preset
//! (update, re-solve of the changed stages, draw), as the user sees it.

use criterion::{Criterion, criterion_group, criterion_main};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::hint::black_box;
use wearlab::engine::{Engine, Request};
use wearlab::preset::bundled;

// The explorer lives in the binary; the bench compiles the same model, form and view modules
// (not the event loop). Parts the bench does not call are allowed to be unused here.
#[allow(dead_code)]
#[path = "../src/tui"]
mod tui {
    pub mod app;
    pub mod form;
    pub mod view;
}

use tui::app::{App, Command, Msg, update};
use tui::view::{RenderOptions, view};

fn app_on(file: &str, engine: &mut Engine) -> App {
    let preset = bundled(file).unwrap().unwrap();
    let mut app = App::new(preset, None, None);
    for cmd in app.start() {
        if let Command::Solve(g, p) = cmd {
            update(&mut app, Msg::Solved(g, Box::new(engine.run(&full(*p)))));
        }
    }
    app
}

fn bench(c: &mut Criterion) {
    let options = RenderOptions {
        ascii: false,
        color: true,
    };
    let mut engine = Engine::new();
    for file in ["polymer-coating.toml", "dispersion.toml"] {
        let app = app_on(file, &mut engine);
        let mut terminal = Terminal::new(TestBackend::new(120, 40)).unwrap();
        c.bench_function(&format!("explorer_draw_120x40/{file}"), |b| {
            b.iter(|| {
                terminal
                    .draw(|f| view(black_box(&app), options, f))
                    .unwrap()
                    .area
            })
        });
    }
    let mut app = app_on("polymer-coating.toml", &mut engine);
    // select the load
    app.selected = 8;
    let mut terminal = Terminal::new(TestBackend::new(120, 40)).unwrap();
    let mut dir = KeyCode::Right;
    c.bench_function("explorer_keystroke/plane_load", |b| {
        b.iter(|| {
            dir = if dir == KeyCode::Right {
                KeyCode::Left
            } else {
                KeyCode::Right
            };
            for cmd in update(&mut app, Msg::Key(KeyEvent::new(dir, KeyModifiers::NONE))) {
                if let Command::Solve(g, p) = cmd {
                    update(&mut app, Msg::Solved(g, Box::new(engine.run(&full(*p)))));
                }
            }
            terminal.draw(|f| view(&app, options, f)).unwrap().area
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);

fn full(preset: wearlab::preset::Preset) -> Request {
    Request {
        preset,
        overlays: true,
    }
}
