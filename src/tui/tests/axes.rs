//! The x axis and the legends of every chart of every bundled preset at 80x24 and 120x40: a log
//! axis says so, every x tick drawn has its value, the last label is near the axis' end (where
//! the range ends can be read), and legends avoid the data where they can.

use ratatui::crossterm::event::KeyCode;
use ratatui::layout::Rect;

use super::*;
use crate::tui::charts::ticks::{BARE_END, Scale};
use crate::tui::charts::{Figure, range};
use crate::tui::view::chart::{Extras, draw, layout};

/// Checks the chart shown by `app` laid out in a terminal `w` x `h`; whether a legend covers
/// a data cell (a plot too small for it anywhere else).
fn check(app: &App, w: u16, h: u16, what: &str) -> bool {
    let Some(answer) = &app.solve.shown else {
        panic!("{what}: nothing solved")
    };
    let Ok(Figure::Plots(plots)) = app.ui.chart.build(answer) else {
        return false;
    };
    let frames = range::frames(&plots, &[], false);
    let areas = crate::tui::view::layout::areas(Rect::new(0, 0, w, h), false, false).unwrap();
    let inner = Rect {
        x: areas.chart.x + 1,
        y: areas.chart.y + 1,
        width: areas.chart.width - 2,
        height: areas.chart.height - 2,
    };
    let (laid, x_ticks) = layout(&frames, PLAIN, &Extras::default(), inner).unwrap();
    if matches!(frames[0].plot.x.scale, Scale::Log) {
        assert!(x_ticks.title.contains("log"), "{what}: {}", x_ticks.title);
    }
    // every data cell still shows its curve once the whole chart is drawn (no legend over it)
    let mut drawn = ratatui::buffer::Buffer::empty(inner);
    draw(&frames, PLAIN, &Extras::default(), &mut drawn, inner);
    let covers = laid.iter().any(|l| {
        let p = l.geometry.plot;
        let mut alone = ratatui::buffer::Buffer::empty(inner);
        l.raster.render(&mut alone, p);
        (0..p.width)
            .flat_map(|c| (0..p.height).map(move |r| (c, r)))
            .filter(|&(c, r)| l.raster.occupied(c, r))
            .any(|(c, r)| drawn[(p.x + c, p.y + r)].symbol() != alone[(p.x + c, p.y + r)].symbol())
    });
    // every tick drawn is labelled: the screen's label row (the title's, or the one above when
    // the title has a row of its own) holds each label
    let s = screen(app, w, h, PLAIN);
    let lines: Vec<&str> = s.lines().collect();
    let at = lines
        .iter()
        .rposition(|l| l.contains(&x_ticks.title))
        .unwrap_or_else(|| panic!("{what}: no x title {}\n{s}", x_ticks.title));
    let row = [lines[at], lines[at - 1]].into_iter().find(|l| {
        x_ticks
            .ticks
            .iter()
            .all(|(_, label)| l.contains(label.as_str()))
    });
    assert!(row.is_some(), "{what}: a tick unlabelled\n{s}");
    // where the range ends can be read: the last label within BARE_END of the axis' end; on a
    // linear axis, else no tick of its step missing before the end (7.8 um to 992 um at 80x24:
    // 200 ... 800, the next at 1000 is past the end, and a step of 100 does not fit)
    let span = frames[0].x[1] - frames[0].x[0];
    let t = &x_ticks.ticks;
    let bare = t.last().map_or(1.0, |l| (frames[0].x[1] - l.0) / span);
    let step = match t.len() {
        2.. if matches!(frames[0].plot.x.scale, Scale::Linear) => (t[1].0 - t[0].0) / span,
        _ => 0.0,
    };
    assert!(
        bare <= BARE_END + 1e-9 || bare < step,
        "{what}: the last x label {bare} of the axis from its end\n{s}"
    );
    covers
}

#[test]
fn every_x_tick_has_its_value_a_log_axis_says_so_and_legends_avoid_data() {
    let mut covering = Vec::new();
    for b in crate::preset::BUNDLED {
        let mut app = app(b.file);
        let cmds = app.start();
        settle(&mut app, cmds);
        if app.explore.view.is_some() {
            press(&mut app, KeyCode::Tab);
        }
        for _ in 0..2 {
            let (_, charts) = app.ui.chart.position();
            for _ in 0..charts {
                for (w, h) in [(80, 24), (120, 40)] {
                    let what = format!("{} {} at {w}x{h}", b.file, app.ui.chart.title());
                    if check(&app, w, h, &what) {
                        covering.push(what);
                    }
                }
                let cmds = press(&mut app, KeyCode::Tab);
                settle(&mut app, cmds);
            }
            let cmds = press(&mut app, KeyCode::Char('p'));
            settle(&mut app, cmds);
        }
    }
    // jgh-egg-box's dispersion chart at 80x24, a plot of four rows: the legend goes on empty
    // rows across the plot, not over the curve
    assert!(
        !covering.iter().any(|c| c.starts_with("jgh-egg-box")),
        "{covering:#?}"
    );
    eprintln!("legends over data (no room elsewhere): {covering:#?}");
}

#[test]
fn a_legend_says_why_a_curve_it_names_cannot_be_seen() {
    // thin-strip-winkler's sweep: the wide model fails over the whole range (all of it drawn in
    // its dim mark), so "++ mu* wide" alone would name a curve that cannot be seen; hertz-check's b lies under a (mu = 0)
    let mut app = solved("thin-strip-winkler.toml");
    press(&mut app, KeyCode::Char('v'));
    let cmds = press(&mut app, KeyCode::Enter);
    super::explore::explored(&mut app, &cmds);
    for (w, h) in [(80, 24), (120, 40)] {
        let s = screen(&app, w, h, PLAIN);
        assert!(s.contains(",, mu* wide: fails over the whole range"), "{s}");
        assert!(
            !s.contains("++ mu* wide") && !s.contains(",, wide fails"),
            "{s}"
        );
    }
    let mut app = solved("hertz-check.toml");
    while app.ui.chart.title() != "contact edges against load" {
        let cmds = press(&mut app, KeyCode::Tab);
        settle(&mut app, cmds);
    }
    let s = screen(&app, 80, 24, PLAIN);
    assert!(s.contains("++ b (leading): under a (trailing)"), "{s}");
}

#[test]
fn the_sweep_cursor_reads_each_mu_star_alike_and_tags_a_failing_model() {
    // thin-strip-winkler's sweep cursor: every mu* with six significant digits (not
    // 'mu* strip = 0.30406'), and the wide model's value tagged, as its legend says it fails
    // over the whole range; twenty points left of the operating point, at P = 1 kN/m, where the
    // wide model still has its contact about the punch tip
    let mut app = solved("thin-strip-winkler.toml");
    press(&mut app, KeyCode::Char('v'));
    let cmds = press(&mut app, KeyCode::Enter);
    super::explore::explored(&mut app, &cmds);
    press(&mut app, KeyCode::Char('x'));
    let s = screen(&app, 120, 40, PLAIN);
    assert!(s.contains("mu* wide: no value here"), "{s}");
    press(&mut app, KeyCode::Char('{'));
    press(&mut app, KeyCode::Char('{'));
    let s = screen(&app, 120, 40, PLAIN);
    let text = s.replace(['│', '"'], " ");
    let words: Vec<&str> = text.split_whitespace().collect();
    let values: Vec<(&str, &str)> = (words.windows(4))
        .filter(|w| w[0] == "mu*" && w[2] == "=")
        .map(|w| (w[1], w[3]))
        .collect();
    assert!(values.len() >= 3, "{s}");
    for (model, v) in &values {
        let decimals = v.split('.').nth(1).map_or(0, str::len);
        assert_eq!(decimals, 6, "mu* {model} = {v}\n{s}");
    }
    assert!(s.contains("(fails)"), "{s}");
}

#[test]
fn a_reference_line_under_a_curve_says_so() {
    // jgh-egg-box's charts: the curve lies on the line '┈┈ mu = 0' (and '┈┈ c = 0') over its
    // whole width, so that the line shows nowhere and its legend says so
    let mut app = solved("jgh-egg-box.toml");
    let mut seen = 0;
    for _ in 0..5 {
        let s = screen(&app, 120, 40, PLAIN);
        for line in ["┈┈ mu = 0", "┈┈ c = 0"] {
            if s.contains(line) {
                assert!(s.contains(&format!("{line}: under ")), "{s}");
                seen += 1;
            }
        }
        let cmds = press(&mut app, KeyCode::Tab);
        settle(&mut app, cmds);
    }
    assert!(seen >= 2, "{seen}");
}
