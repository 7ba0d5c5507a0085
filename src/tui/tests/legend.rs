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
