//! The terminal explorer: terminal setup and restore, the event loop, and the effects that
//! `update` asks for (solve on the worker, save, export).

pub mod app;
pub mod form;
pub mod view;

#[cfg(test)]
mod tests;

use std::io;
use std::path::{Path, PathBuf};
use std::time::Duration;

use ratatui::crossterm::event::{
    self, DisableMouseCapture, EnableMouseCapture, Event, KeyEventKind,
};
use ratatui::crossterm::execute;
use wearlab::engine::{Answer, Output, Request, Worker};
use wearlab::preset::{self, Preset};

use app::{App, Command, Msg, update};
use view::{RenderOptions, view};

/// Options of the explorer from the command line and the environment.
#[derive(Clone, Copy, Debug)]
pub struct Options {
    /// Draw charts with ASCII dots instead of Braille.
    pub ascii: bool,
    /// Capture the mouse.
    pub mouse: bool,
}

/// Where the user's presets live: $XDG_DATA_HOME/wearlab/presets (or the platform's data dir).
pub fn user_preset_dir() -> Option<PathBuf> {
    dirs::data_dir().map(|d| d.join("wearlab").join("presets"))
}

/// Runs the explorer until the user quits. The terminal is restored on every exit path,
/// including a panic (ratatui's init installs a hook that restores it first).
pub fn run(preset: Preset, path: Option<PathBuf>, options: Options) -> io::Result<()> {
    let render = RenderOptions {
        ascii: options.ascii,
        color: std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty()),
    };
    let mut terminal = ratatui::init();
    if options.mouse {
        execute!(io::stdout(), EnableMouseCapture)?;
    }
    let result = event_loop(
        &mut terminal,
        App::new(preset, path, user_preset_dir()),
        render,
    );
    if options.mouse {
        let _ = execute!(io::stdout(), DisableMouseCapture);
    }
    ratatui::restore();
    result
}

fn event_loop(
    terminal: &mut ratatui::DefaultTerminal,
    mut app: App,
    render: RenderOptions,
) -> io::Result<()> {
    let (answers, results) = std::sync::mpsc::channel::<Answer>();
    let worker = Worker::spawn(move |a| answers.send(a).is_ok());
    let mut commands = app.start();
    let mut redraw = true;
    loop {
        for cmd in commands.drain(..) {
            match cmd {
                Command::Solve(generation, preset) => worker.submit(
                    generation,
                    Request {
                        preset: *preset,
                        overlays: true,
                    },
                ),
                Command::Save(path, preset) => save(&mut app, &path, &preset),
                Command::Export => export(&mut app),
                Command::Quit => return Ok(()),
            }
            redraw = true;
        }
        if redraw {
            terminal.draw(|f| view(&app, render, f))?;
            redraw = false;
        }
        let timeout = if app.playing {
            Duration::from_millis(100)
        } else {
            Duration::from_millis(50)
        };
        if event::poll(timeout)? {
            match event::read()? {
                Event::Key(key) if key.kind != KeyEventKind::Release => {
                    commands = update(&mut app, Msg::Key(key));
                    redraw = true;
                }
                Event::Resize(..) => redraw = true,
                _ => {}
            }
        } else if app.playing {
            commands = update(&mut app, Msg::Tick);
        }
        while let Ok(answer) = results.try_recv() {
            commands.extend(update(
                &mut app,
                Msg::Solved(answer.generation, Box::new(answer.output)),
            ));
            redraw = true;
        }
    }
}

fn save(app: &mut App, path: &Path, preset: &Preset) {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty())
        && let Err(e) = std::fs::create_dir_all(dir)
    {
        app.message = Some((format!("cannot create {}: {e}", dir.display()), true));
        return;
    }
    match preset::save(preset, path) {
        Ok(()) => {
            app.path = Some(path.to_path_buf());
            app.dirty = false;
            app.message = Some((format!("saved {}", path.display()), false));
        }
        Err(e) => app.message = Some((format!("not saved: {}: {e}", path.display()), true)),
    }
}

/// The visible chart's data as CSV text and a file-name stem.
pub fn chart_csv(app: &App) -> Option<(String, String)> {
    let title = app::chart_titles(app.preset.problem)[app.chart];
    let stem = title
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
        .collect::<Vec<_>>()
        .join("-");
    match app.output.as_ref()? {
        Output::Spatial(Ok(out)) if app.chart == 0 => {
            let f = &out.state.field;
            let mut text = String::from("x,y,pressure\n");
            for (j, y) in f.y.iter().enumerate() {
                for (i, x) in f.x.iter().enumerate() {
                    text.push_str(&format!("{x:e},{y:e},{:e}\n", f.pressure[j * f.n + i]));
                }
            }
            Some((stem, text))
        }
        output => {
            let specs = match output {
                Output::Plane(out) => view::plane_charts(app, out).ok()?,
                Output::Spatial(Ok(out)) => view::spatial_charts(app, out),
                Output::Spatial(Err(_)) => return None,
            };
            let mut text = String::from("curve,x,y\n");
            for spec in &specs {
                for c in &spec.curves {
                    for (x, y) in &c.points {
                        let x = if spec.log_x { 10f64.powf(*x) } else { *x };
                        text.push_str(&format!(
                            "{} [{} / {}],{x:e},{y:e}\n",
                            c.name, spec.x_label, spec.y_unit
                        ));
                    }
                }
            }
            Some((stem, text))
        }
    }
}

fn export(app: &mut App) {
    let Some((stem, text)) = chart_csv(app) else {
        app.message = Some(("nothing to export: the chart has no data".into(), true));
        return;
    };
    let path = PathBuf::from(format!("wearlab-{stem}.csv"));
    let written = preset::write_atomically(&path, |f| io::Write::write_all(f, text.as_bytes()));
    app.message = Some(match written {
        Ok(()) => (format!("exported the chart to {}", path.display()), false),
        Err(e) => (format!("export failed: {}: {e}", path.display()), true),
    });
}
