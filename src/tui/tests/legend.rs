//! Legend placement: never on a data cell while there is an empty corner or room elsewhere.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;

use super::*;
use crate::tui::charts::range::frames;
use crate::tui::charts::{Chart, Figure};
use crate::tui::view::chart::{Extras, draw, layout};
use crate::tui::view::layout::areas;
use crate::tui::view::legend::{Entry, Place, corner};
use crate::tui::view::raster::{Ink, Raster};

fn entries(n: usize, width: usize) -> Vec<Entry> {
    (0..n)
        .map(|i| Entry {
            sample: "**".into(),
            style: Style::default(),
            text: format!("{i}{}", "n".repeat(width)),
        })
        .collect()
}

const INK: Ink = Ink {
    glyph: '*',
    solid: false,
    second: None,
    style: Style::new(),
};

#[test]
fn the_legend_goes_to_an_empty_corner_and_nowhere_else_without_one() {
    let plot = Rect::new(0, 0, 40, 10);
    // a curve rising to the top right (the leading-edge peak of wear-dominated.toml)
    let mut r = Raster::new(40, 10, true);
    r.line(&[(0.0, 0.0), (0.6, 0.2), (1.0, 1.0)], INK);
    let legend = entries(3, 10);
    assert_eq!(corner(&r, plot, &legend, false), Some(Place::Corner(0, 0)));
    // data in all four corners: no empty one; the fallback takes the emptiest
    r.line(&[(0.0, 1.0), (0.1, 1.0)], INK);
    r.line(&[(0.9, 0.0), (1.0, 0.0)], INK);
    assert_eq!(corner(&r, plot, &legend, false), None);
    let Some(Place::Corner(x, y)) = corner(&r, plot, &legend, true) else {
        panic!()
    };
    let (w, h) = crate::tui::view::legend::box_size(&legend);
    let covered = r.count(Rect::new(x, y, w, h));
    for (cx, cy) in [(0, 0), (40 - w, 0), (0, 10 - h), (40 - w, 10 - h)] {
        assert!(covered <= r.count(Rect::new(cx, cy, w, h)));
    }
    // a box larger than the plot has no corner
    assert_eq!(corner(&r, plot, &entries(11, 2), true), None);
}

/// Every data cell of every plot still shows its curve after the whole chart is drawn.
fn no_data_cell_covered(app: &App, w: u16, h: u16, style: RenderOptions) {
    let Some((answer, _)) = crate::tui::on_screen::on_screen(app).answer() else {
        panic!("no answer")
    };
    let Ok(Figure::Plots(plots)) = app.ui.chart.build(answer) else {
        return;
    };
    let chart = areas(Rect::new(0, 0, w, h), false, false).unwrap().chart;
    let inner = Rect::new(chart.x + 1, chart.y + 1, chart.width - 2, chart.height - 2);
    let frames = frames(&plots, &[], false);
    let extras = Extras::default();
    let mut buf = Buffer::empty(Rect::new(0, 0, w, h));
    draw(&frames, style, &extras, &mut buf, inner);
    let (laid, _) = layout(&frames, style, &extras, inner).unwrap();
    for l in &laid {
        let mut alone = Buffer::empty(Rect::new(0, 0, w, h));
        l.raster.render(&mut alone, l.geometry.plot);
        let p = l.geometry.plot;
        for row in 0..p.height {
            for col in 0..p.width {
                if l.raster.occupied(col, row) {
                    let at = (p.x + col, p.y + row);
                    assert_eq!(
                        buf[at].symbol(),
                        alone[at].symbol(),
                        "{:?} {w}x{h}: data at {at:?} covered",
                        app.ui.chart
                    );
                }
            }
        }
    }
}

#[test]
fn no_legend_or_label_covers_a_curve_on_any_bundled_chart() {
    for file in [
        "wear-dominated.toml",
        "polymer-coating.toml",
        "hard-coating-strip.toml",
        "hertz-check.toml",
        "dispersion.toml",
        "wave-thick-layer.toml",
        "rubber-backward-drift.toml",
    ] {
        let mut app = solved(file);
        for chart in Chart::all(app.doc.preset.problem) {
            app.ui.chart = chart;
            let cmds = app.start();
            settle(&mut app, cmds);
            for (w, h) in [(80, 24), (120, 40)] {
                for style in [
                    PLAIN,
                    RenderOptions {
                        ascii: false,
                        color: true,
                        truecolor: false,
                    },
                ] {
                    no_data_cell_covered(&app, w, h, style);
                }
            }
        }
    }
}

#[test]
fn a_legend_that_does_not_fit_is_folded_into_a_count_never_cut() {
    use crate::tui::view::legend::{fold, lines_needed};
    // six entries of 22 columns ("** 0nnnnnnnnnnnnnnnnnn"): beside a 43-column title one, then
    // two to a 48-column line
    let all = entries(6, 18);
    assert_eq!(lines_needed(&all, 43, 48), 4);
    let texts = |e: Vec<Entry>| e.into_iter().map(|e| e.text).collect::<Vec<_>>();
    assert_eq!(texts(fold(&all, 43, 48, 4)), texts(all.clone()));
    // in two lines: two entries whole and the count of the four left out, with the key
    let two = fold(&all, 43, 48, 2);
    assert!(lines_needed(&two, 43, 48) <= 2);
    assert_eq!(
        texts(two),
        [
            all[0].text.clone(),
            all[1].text.clone(),
            "+4 more: i".into()
        ]
    );
    // an entry wider than a line is counted rather than cut
    assert_eq!(texts(fold(&entries(1, 60), 43, 48, 2)), ["+1 more: i"]);
}

#[test]
fn a_crowded_chart_counts_its_legend_and_i_lists_it_whole() {
    use ratatui::crossterm::event::KeyCode;
    // hard-coating-strip's mu* chart (three models, a failing one, a gap) pinned, then drawn at
    // twice mu: at 80x24 the pin's three curves do not fit beside the others'
    let mut app = app("hard-coating-strip.toml");
    app.ui.chart = Chart::Plane(crate::tui::charts::PlaneChart::MuStar);
    let cmds = app.start();
    settle(&mut app, cmds);
    press(&mut app, KeyCode::Char('c'));
    select(&mut app, "mu", None);
    let cmds = press(&mut app, KeyCode::Char('L'));
    settle(&mut app, cmds);
    app.ui.screen = Rect::new(0, 0, 80, 24);
    let s = screen(&app, 80, 24, PLAIN);
    let chart: Vec<&str> = (s.lines())
        .take_while(|l| !l.contains("operating point"))
        .collect();
    assert!(chart.iter().any(|l| l.contains(" more: i")), "{s}");
    // every entry whole: none ends cut at the chart's border
    let full = crate::tui::view::legend_full::in_full(&app, PLAIN);
    for name in ["mu* strip", "mu* wide", "mu* narrow", "pin: mu = 0.3"] {
        assert!(full.iter().any(|e| e.contains(name)), "{name}: {full:?}");
    }
    let about: Vec<String> = crate::tui::view::popups::about_lines(&app, PLAIN, 78)
        .iter()
        .map(|l| l.to_string())
        .collect();
    let heading = about
        .iter()
        .position(|l| l == "the chart's legend in full:");
    let listed = &about[heading.expect("the heading") + 1..];
    assert!(full.iter().all(|e| listed.contains(e)), "{about:?}");
    insta::assert_snapshot!("folded_legend_80x24", s);
}
