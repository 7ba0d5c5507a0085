//! Exports keep what the student did: the CSV of a chart holds every curve drawn, the pinned
//! ones included, and the SVG names every curve its y range cuts (the terminal's "off scale")
//! and each pinned curve in its legend.

use ratatui::crossterm::event::KeyCode;

use super::charts::texts;
use super::*;
use crate::preset::Problem;
use crate::tui::charts::svg::{Page, svg};
use crate::tui::charts::{Axis, Chart, Figure, Plot, Scale, Series};

#[test]
fn the_csv_of_a_chart_with_a_pin_holds_the_pinned_curves() {
    // hertz-check's contact edges, pinned, then R from 50 mm to 55 mm: the CSV has the curves
    // of now and, after them, those of the pin with the pin's name, each of its points a row
    let mut app = solved("hertz-check.toml");
    app.ui.chart = Chart::all(Problem::Plane)[3];
    let cmds = app.start();
    settle(&mut app, cmds);
    press(&mut app, KeyCode::Char('c'));
    select(&mut app, "R", None);
    let cmds = press(&mut app, KeyCode::Right);
    settle(&mut app, cmds);
    let cmds = press(&mut app, KeyCode::Char('e'));
    let (path, text) = exported(&cmds);
    assert_eq!(
        path.to_str(),
        Some("wearlab-contact-edges-against-load.csv")
    );
    let pins = app.ui.pins_of(app.ui.chart);
    let [pin] = pins.as_slice() else {
        panic!("one pin")
    };
    let name = pin.name(&app.doc.preset);
    assert_eq!(name, "pin: R = 50.0 mm");
    let rows: Vec<&str> = text.lines().filter(|l| !l.starts_with('#')).collect();
    for s in &pin.plots[0].series {
        let curve = format!("{name}: {}", s.name);
        let own: Vec<&&str> = rows
            .iter()
            .filter(|r| r.starts_with(&format!("{curve},")))
            .collect();
        assert_eq!(own.len(), s.points.len(), "{curve} in {text}");
        // the first point as drawn: x and y in the curve's columns
        let fields: Vec<f64> = own[0]
            .split(',')
            .skip(1)
            .filter_map(|f| f.parse().ok())
            .collect();
        assert_eq!(fields, [s.points[0].0, s.points[0].1], "{curve}");
    }
    // the curves of now are there too, named as before
    let answer = app.solve.shown.as_ref().unwrap();
    let Ok(Figure::Plots(plots)) = app.ui.chart.build(answer) else {
        panic!("plots")
    };
    for s in &plots[0].series {
        assert!(rows.iter().any(|r| r.starts_with(&format!("{},", s.name))));
    }
    assert!(
        text.contains("# pinned curves (dashed in the figure)"),
        "{text}"
    );
}

fn curve(name: &str, ys: &[f64]) -> Series {
    Series {
        name: name.into(),
        points: ys.iter().enumerate().map(|(i, &y)| (i as f64, y)).collect(),
    }
}

#[test]
fn the_svg_names_every_curve_its_y_range_cuts_its_pins_too() {
    // the first curve sets the y range (0..1); the overlay reaches 5 (partly off scale); the
    // pin's overlay lies wholly above (off scale); the curves inside are named alone
    let axis = |label: &str| Axis {
        label: label.into(),
        unit: "",
        scale: Scale::Linear,
    };
    let mut now = Plot::new(
        axis("x"),
        axis("y"),
        vec![
            curve("focus", &[0.0, 0.5, 1.0]),
            curve("overlay", &[0.2, 5.0, 0.4]),
            curve("inside", &[0.1, 0.2, 0.3]),
        ],
    );
    now.focus = 1;
    let mut pinned = now.clone();
    pinned.series = vec![
        curve("focus", &[0.0, 0.4, 0.8]),
        curve("overlay", &[7.0, 8.0, 9.0]),
    ];
    let pins = [pinned];
    let page = Page {
        title: "test",
        caption: Vec::new(),
        pins: vec![(&pins[..], "pin: mu = 0.2".into())],
        toggled: false,
        scale: None,
    };
    let t = texts(&svg(&Figure::Plots(vec![now]), &page).unwrap());
    let at = |s: &str| {
        t.iter()
            .position(|x| x == s)
            .unwrap_or_else(|| panic!("{s} in {t:?}"))
    };
    assert!(
        t[at("overlay") + 1].starts_with("partly off scale, "),
        "{t:?}"
    );
    assert_eq!(t[at("focus") + 1], "overlay");
    // one entry per pinned curve, as the terminal's legend has them: the first with the pin's
    // name, each cut one with its range under it
    let pin = at("inside") + 1;
    assert_eq!(
        t[pin..pin + 2],
        ["pin: mu = 0.2, focus", "overlay"],
        "{t:?}"
    );
    assert!(t[pin + 2].starts_with("off scale, 7"), "{t:?}");
}
