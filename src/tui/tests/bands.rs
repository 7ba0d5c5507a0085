//! The pressure map in filled bands: edges at nice values over the range, one colour
//! (or shade) a band on the map and on the bar, and every edge labelled on the bar.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Color;

use super::*;
use crate::tui::charts::Map;
use crate::tui::charts::ticks::bands;
use crate::tui::view::heatmap;
use crate::tui::view::theme::SHADES;

fn labels(t: &crate::tui::charts::ticks::Ticks) -> Vec<&str> {
    t.ticks.iter().map(|(_, l)| l.as_str()).collect()
}

#[test]
fn band_edges_are_the_finest_nice_step_giving_at_most_the_bands_asked() {
    // worked by hand from the steps 1, 2, 2.5 and 5 times a power of ten. contact-lost's range,
    // 0 to 14.4 MPa: in steps of 2 MPa 8 bands (0 to 16), of 2.5 MPa 6 (0 to 15)
    let (t, step) = bands([0.0, 14.4e6], "p", "Pa", 6);
    assert_eq!(
        labels(&t),
        ["0", "2.5", "5.0", "7.5", "10.0", "12.5", "15.0"]
    );
    assert_eq!((step.as_str(), t.title.as_str()), ("2.5", "p [MPa]"));
    assert_eq!(t.ticks[6].0, 15e6);
    let (t, step) = bands([0.0, 14.4e6], "p", "Pa", 8);
    assert_eq!(
        labels(&t),
        ["0", "2", "4", "6", "8", "10", "12", "14", "16"]
    );
    assert_eq!(step, "2");
    // 0.31 to 1.95 MPa: in steps of 0.25 MPa 7 bands (0.25 to 2), of 0.5 MPa 4 (0 to 2)
    let (t, step) = bands([0.31e6, 1.95e6], "p", "Pa", 6);
    assert_eq!(
        (labels(&t), step.as_str()),
        (vec!["0", "0.5", "1.0", "1.5", "2.0"], "0.5")
    );
    let (t, step) = bands([0.31e6, 1.95e6], "p", "Pa", 7);
    assert_eq!(labels(&t)[..2], ["0.25", "0.50"]);
    assert_eq!((t.ticks.len(), step.as_str()), (8, "0.25"));
    // ends on multiples add no band: 0 to 10 in steps of 2 is 5 bands (of 1, 10)
    let (t, _) = bands([0.0, 10.0], "p", "", 6);
    assert_eq!(labels(&t), ["0", "2", "4", "6", "8", "10"]);
}

/// p = 10 MPa x/L on a square, 41 points a side: 0.25 MPa apart, in bands of 2 MPa (5 bands
/// of at most 6), so that the points at 2, 4, 6 and 8 MPa lie on the edges.
fn ramp() -> Map {
    let x: Vec<f64> = (0..41).map(|i| i as f64 / 40.0).collect();
    let values = (0..41).flat_map(|_| x.iter().map(|x| 10e6 * x)).collect();
    Map {
        name: "pressure",
        x: x.clone(),
        y: x,
        values,
        unit: "Pa",
        caption: "A ramp.".into(),
        empty: None,
    }
}

/// The band of a pressure [MPa] among bands whose inner edges are `inner` (as matplotlib's
/// `contourf`: a band holds its upper edge): how many inner edges lie under it.
fn band_of(p: f64, inner: &[f64]) -> usize {
    inner.iter().filter(|&&e| p > e + 1e-9).count()
}

/// The bar's labels from the top with their rows, and the column of the tick.
fn bar(buf: &Buffer, rows: u16) -> (Vec<(u16, String)>, u16) {
    let mut found = Vec::new();
    let mut tick = 0;
    for y in 0..rows {
        let line: String = (0..buf.area.width).map(|x| buf[(x, y)].symbol()).collect();
        if let Some(at) = line.chars().position(|c| c == '┤') {
            let label: String = line
                .chars()
                .skip(at + 1)
                .take_while(|c| *c != ' ')
                .collect();
            found.push((y, label));
            tick = at as u16;
        }
    }
    (found, tick)
}

#[test]
fn each_cell_shows_the_colour_of_its_band_and_the_bar_labels_every_edge() {
    let map = ramp();
    let area = Rect::new(0, 0, 60, 24);
    // the map: 46 x 23 cells with the words under it (fit, 60 - 8 - 1 columns); the bar right
    // of it, its ticks and labels right of the bar
    let (w, h) = (46u16, 23u16);
    let bx = w + 1;
    let colours = COLOUR.bands(5);
    for i in 0..5 {
        assert!(!colours[i + 1..].contains(&colours[i]), "{colours:?}");
    }
    // in colour 5 bands of 2 MPa; without colour the 4 shades but the blank take 4 of 2.5 MPa,
    // the lightest but the blank for the lowest
    let cases = [
        (
            COLOUR,
            &[2.0, 4.0, 6.0, 8.0][..],
            &["10", "8", "6", "4", "2", "0"][..],
            "2",
        ),
        (
            PLAIN,
            &[2.5, 5.0, 7.5],
            &["10.0", "7.5", "5.0", "2.5", "0"],
            "2.5",
        ),
    ];
    for (style, inner, labels, step) in cases {
        let n = inner.len() + 1;
        let mut buf = Buffer::empty(area);
        heatmap::draw(&map, None, None, style, &mut buf, area);
        for col in 0..w {
            // the grid point the column shows
            let p = 10.0 * ((col as usize * 41) / w as usize) as f64 / 40.0;
            let band = band_of(p, inner);
            for row in 0..h {
                let cell = &buf[(col, row)];
                if style.color {
                    let shown = match cell.symbol() {
                        " " => cell.bg,
                        "█" => cell.fg,
                        other => panic!("{other} at {col}, {row}"),
                    };
                    assert_eq!(shown, colours[band], "p = {p} MPa at {col}, {row}");
                } else {
                    assert_eq!(cell.symbol(), SHADES[band + 1].to_string(), "p = {p} MPa");
                }
            }
        }
        let (found, tick) = bar(&buf, h);
        let texts: Vec<&str> = found.iter().map(|(_, l)| l.as_str()).collect();
        assert_eq!((texts.as_slice(), tick), (labels, bx + 1), "{style:?}");
        assert_eq!((found[0].0, found[n].0), (0, h - 1));
        // between two edges' rows the bar shows the band between them; in colour an edge
        // splits its row between the bands above and below it, without colour it is blank
        for (k, pair) in found.windows(2).enumerate() {
            let band = n - 1 - k;
            for y in pair[0].0 + 1..pair[1].0 {
                let cell = &buf[(bx, y)];
                if style.color {
                    assert_eq!((cell.symbol(), cell.bg), (" ", colours[band]));
                } else {
                    assert_eq!(cell.symbol(), SHADES[band + 1].to_string());
                }
            }
            let edge = &buf[(bx, pair[0].0)];
            if !style.color {
                assert_eq!(edge.symbol(), " ");
            } else if k > 0 {
                let (above, below) = (colours[band + 1], colours[band]);
                assert_eq!((edge.symbol(), edge.fg, edge.bg), ("▀", above, below));
            }
        }
        let words: String = (0..area.width).map(|x| buf[(x, h)].symbol()).collect();
        let says = format!("p [MPa] in bands of {step}. A ramp.");
        assert!(words.starts_with(&says), "{words}");
    }
    // the rows of the lowest and highest edge: half a row of band colour
    let mut buf = Buffer::empty(area);
    heatmap::draw(&map, None, None, COLOUR, &mut buf, area);
    let (top, bottom) = (&buf[(bx, 0)], &buf[(bx, h - 1)]);
    assert_eq!(
        (top.symbol(), top.fg, top.bg),
        ("▄", colours[4], Color::Reset)
    );
    assert_eq!((bottom.symbol(), bottom.fg), ("▀", colours[0]));
}
