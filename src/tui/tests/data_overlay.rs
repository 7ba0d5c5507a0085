//! A data file over the charts (`d`): drawn on the charts whose axes it matches, named in the
//! legend, kept across edits, in both exports; a file that matches no chart says which charts
//! there are, a broken one its `path:line: reason`, and neither loses the overlay shown.

use std::path::{Path, PathBuf};

use ratatui::crossterm::event::KeyCode;

use super::*;
use crate::preset::Problem;
use crate::tui::app::Mode;
use crate::tui::charts::{Chart, Figure, PlaneChart, overlay};
use crate::tui::effects;

/// The lab's synthetic friction data (examples/lab: the wide model at mu = 0.3, k = 2e-11 1/Pa
/// with noise of sd 0.002), eight of its twenty rows (every third and the last), with that sd as a column.
const FRICTION: &str = "\
# SYNTHETIC: wearlab's wide model at mu = 0.3, k = 2e-11 1/Pa, noise sd 0.002 in mu
load [N/m],mu [-],mu sd [-]
1.00000e3,0.301851,0.002
2.06914e3,0.300433,0.002
4.28133e3,0.299741,0.002
8.85867e3,0.298902,0.002
1.83298e4,0.299965,0.002
3.79269e4,0.301262,0.002
7.84760e4,0.298737,0.002
1.00000e5,0.293633,0.002
";

/// The lab's preset (mu = 0.2 as its starting guess), solved, on the mu* chart.
fn lab() -> App {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/lab/friction-against-load.toml");
    let preset = crate::preset::load(&path).unwrap();
    let mut app = App::new(preset, Some(path), Places::default());
    app.ui.chart = Chart::Plane(PlaneChart::MuStar);
    let commands = app.start();
    settle(&mut app, commands);
    app
}

/// Writes `text` as `name` in `dir`.
fn file(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// `d`, the path typed, Enter, and the file read as the loop reads it.
fn draw_data(app: &mut App, typed: &str) {
    press(app, KeyCode::Char('d'));
    assert!(matches!(app.ui.mode, Mode::DataPath(_)));
    // the prompt proposes the file drawn now: cleared first
    for _ in 0..200 {
        press(app, KeyCode::Backspace);
    }
    type_text(app, typed);
    let cmds = press(app, KeyCode::Enter);
    match cmds.as_slice() {
        [Command::ReadData(paths, preset)] => {
            update(app, effects::read_data(paths, preset));
        }
        // nothing typed: nothing to read
        [] => assert!(typed.is_empty()),
        _ => panic!("{cmds:?}"),
    }
}

fn message(app: &App) -> String {
    app.ui
        .message
        .as_ref()
        .map(|m| m.text.clone())
        .unwrap_or_default()
}

#[test]
fn a_data_file_is_drawn_on_the_chart_of_its_axes_with_its_error_bars() {
    let dir = tempfile::tempdir().unwrap();
    let path = file(dir.path(), "friction.csv", FRICTION);
    let mut app = lab();
    draw_data(&mut app, path.to_str().unwrap());
    let said = message(&app);
    assert!(
        said.starts_with("data: friction.csv: mu* against P, 8 points, with sd, drawn on mu* against load; # SYNTHETIC"),
        "{said}"
    );
    let answer = app.solve.shown.as_ref().unwrap();
    let Ok(Figure::Plots(plots)) = overlay::figure(app.ui.chart, answer, app.ui.data.as_ref())
    else {
        panic!("plots")
    };
    let [d] = plots[0].data.as_slice() else {
        panic!("one data set")
    };
    assert_eq!(d.name, "data: friction.csv");
    assert_eq!(d.points[0], (1.0e3, 0.301851));
    assert_eq!(
        d.bars()[0],
        [(1.0e3, 0.301851 - 0.002), (1.0e3, 0.301851 + 0.002)]
    );
    // the other plane charts draw other axes: nothing added to them
    for chart in Chart::all(Problem::Plane) {
        if let Ok(Figure::Plots(ps)) = overlay::figure(chart, answer, app.ui.data.as_ref()) {
            let with = ps.iter().any(|p| !p.data.is_empty());
            assert_eq!(with, chart == Chart::Plane(PlaneChart::MuStar), "{chart:?}");
        }
    }
}

#[test]
fn the_data_stay_across_edits_and_go_into_both_exports() {
    let dir = tempfile::tempdir().unwrap();
    let path = file(dir.path(), "friction.csv", FRICTION);
    let mut app = lab();
    draw_data(&mut app, path.to_str().unwrap());
    select(&mut app, "mu", None);
    let cmds = press(&mut app, KeyCode::Right);
    settle(&mut app, cmds);
    assert!(app.ui.data.is_some());
    let cmds = press(&mut app, KeyCode::Char('e'));
    let (_, text) = exported(&cmds);
    assert!(text.contains("# measured points from "), "{text}");
    assert!(
        text.contains("#   SYNTHETIC: wearlab's wide model"),
        "{text}"
    );
    let header = text.lines().find(|l| !l.starts_with('#')).unwrap();
    assert_eq!(header, "curve,P [N/m],mu* [-],mu* sd [-]");
    let rows: Vec<&str> = (text.lines())
        .filter(|l| l.starts_with("data: friction.csv,"))
        .collect();
    assert_eq!(rows.len(), 8);
    assert_eq!(rows[0], "data: friction.csv,1e3,3.01851e-1,2e-3");
    let cmds = press(&mut app, KeyCode::Char('E'));
    let (_, svg) = exported(&cmds);
    assert!(
        svg.contains("data: friction.csv"),
        "the SVG's legend names the data"
    );
    assert!(svg.contains("bars: one standard deviation"));
}

#[test]
fn a_broken_file_says_where_and_keeps_the_data_drawn() {
    let dir = tempfile::tempdir().unwrap();
    let good = file(dir.path(), "friction.csv", FRICTION);
    let bad = file(
        dir.path(),
        "ragged.csv",
        "load [N/m],mu [-]\n1e3,0.3\n2e3,0.3,0.1\n",
    );
    let mut app = lab();
    draw_data(&mut app, good.to_str().unwrap());
    draw_data(&mut app, bad.to_str().unwrap());
    let m = app.ui.message.clone().unwrap();
    assert!(m.error);
    assert_eq!(
        m.text,
        format!(
            "{}:3: 3 values, but the header names 2 columns (data: friction.csv stays)",
            bad.display()
        )
    );
    assert_eq!(app.ui.data.as_ref().unwrap().name, "data: friction.csv");
    // a file that is not there says so, and an empty path takes the data away
    draw_data(&mut app, "no-such-file.csv");
    assert!(
        message(&app).contains("no-such-file.csv: cannot be read"),
        "{}",
        message(&app)
    );
    draw_data(&mut app, "");
    assert_eq!(message(&app), "took away data: friction.csv");
    assert!(app.ui.data.is_none());
}

#[test]
fn a_file_no_chart_draws_says_which_charts_there_are() {
    let dir = tempfile::tempdir().unwrap();
    let path = file(
        dir.path(),
        "width.csv",
        "load [N/m],contact width [um]\n1e3,120\n1e4,400\n",
    );
    let mut app = lab();
    draw_data(&mut app, path.to_str().unwrap());
    let m = app.ui.message.clone().unwrap();
    assert!(m.error);
    assert!(
        m.text.starts_with(
            "data: width.csv: a+b against P, 2 points: no chart has these axes; the charts draw \
             stress against x, wear/pass against x,"
        ),
        "{}",
        m.text
    );
    assert!(m.text.contains("mu* against P"), "{}", m.text);
    assert!(
        m.text.ends_with(
            "v sweeps any quantity against any input (kept: drawn where the axes match)"
        ),
        "{}",
        m.text
    );
}

#[test]
fn a_relative_path_is_looked_for_beside_the_preset_then_where_wearlab_started() {
    let mut app = lab();
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/lab");
    assert_eq!(
        crate::tui::data_keys::candidates(&app, "friction-against-load.csv"),
        [
            folder.join("friction-against-load.csv"),
            PathBuf::from("friction-against-load.csv")
        ]
    );
    draw_data(&mut app, "friction-against-load.csv");
    assert!(
        message(&app).contains("20 points, drawn on mu* against load"),
        "{}",
        message(&app)
    );
}

#[test]
fn the_mu_star_chart_with_data_on_screen() {
    let dir = tempfile::tempdir().unwrap();
    let path = file(dir.path(), "friction.csv", FRICTION);
    let mut app = lab();
    draw_data(&mut app, path.to_str().unwrap());
    insta::assert_snapshot!("data_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("data_120x40", screen(&app, 120, 40, PLAIN));
    insta::assert_snapshot!("data_120x40_ascii", screen(&app, 120, 40, ASCII));
}

#[test]
fn the_lab_preset_opens_on_the_sweep_of_its_data() {
    let mut app = app("lab-friction.toml");
    app.doc.source = Some("bundled: lab-friction.toml".into());
    let cmds = app.start();
    assert_eq!(app.explore.view, Some(crate::tui::sweep_state::View::Sweep));
    let Some(Command::ReadData(paths, preset)) =
        cmds.iter().find(|c| matches!(c, Command::ReadData(..)))
    else {
        panic!("{cmds:?}")
    };
    // read from the program where presets/ is not on disk
    assert_eq!(paths[0], PathBuf::from("presets/lab-friction.csv"));
    update(&mut app, effects::read_data(paths, preset));
    let said = message(&app);
    assert!(
        said.starts_with(
            "data: lab-friction.csv: mu* against P, 20 points, with sd, drawn on the sweep; # \
             SYNTHETIC data, not a measurement"
        ),
        "{said}"
    );
    settle(&mut app, cmds.clone());
    super::explore::explored(&mut app, &cmds);
    let plots = crate::tui::view::sweep::sweep_plots(&app).unwrap();
    assert_eq!(plots[0].data[0].points.len(), 20);
    insta::assert_snapshot!("lab_sweep_80x24", screen(&app, 80, 24, PLAIN));
    insta::assert_snapshot!("lab_sweep_120x40", screen(&app, 120, 40, COLOUR));
}
