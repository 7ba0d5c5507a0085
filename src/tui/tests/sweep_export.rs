//! `E` in the sweep and map views: the figure the view draws as SVG (parsed as XML), with its
//! axes' titles in the inputs' units (log where the sweep is log), the ticks, the legend, the
//! colour bar's range and the parameters it came from; and it waits for a view still computing.

use ratatui::crossterm::event::KeyCode;

use super::charts::texts;
use super::explore::explored;
use super::*;
use crate::physics::Spacing;
use crate::sweeps::map::LineKind;
use crate::tui::charts::Scale;
use crate::tui::charts::map_lines::line_key;
use crate::tui::charts::range::frames;
use crate::tui::charts::ticks::ticks;
use crate::tui::view::sweep::sweep_plots;

/// Whether `t` holds the text `s`, else the texts.
fn has(t: &[String], s: &str) {
    assert!(t.iter().any(|x| x == s), "no {s:?} in {t:?}");
}

#[test]
fn e_in_the_sweep_view_writes_the_sweep_with_its_log_axis_legend_and_parameters() {
    let mut app = app("coating-thickness-sweep.toml");
    let cmds = app.start();
    settle(&mut app, cmds.clone());
    explored(&mut app, &cmds);
    let cmds = press(&mut app, KeyCode::Char('E'));
    let (path, text) = exported(&cmds);
    assert_eq!(path.to_str(), Some("wearlab-sweep-mu-mu-against-h.svg"));
    let t = texts(text);
    has(&t, "sweep: mu*-mu against h");
    has(&t, &format!("{} (plane problem)", app.doc.preset.name));
    assert!(t.iter().any(|x| x.starts_with("E = 10.0 GPa")), "{t:?}");
    let plots = sweep_plots(&app).unwrap();
    for f in frames(&plots, &[], false) {
        let p = f.plot;
        // h swept from 1 um to 10 mm on a log axis (coating-thickness-sweep.toml)
        assert_eq!(p.x.scale, Scale::Log);
        let x = ticks(f.x, p.x.scale, &p.x.label, p.x.unit, 9);
        let y = ticks(f.y, f.y_scale, &p.y.label, p.y.unit, 7);
        assert!(
            x.title.starts_with("h [") && x.title.ends_with("(log)"),
            "{x:?}"
        );
        has(&t, &x.title);
        has(&t, &y.title);
        for (_, label) in x.ticks.iter().chain(&y.ticks) {
            has(&t, label);
        }
        // every model's curve, the failing parts, the marks on the x axis and the zero line
        for s in &p.series {
            let at = t.iter().position(|x| x == &s.name);
            let at = at.unwrap_or_else(|| panic!("{} in {t:?}", s.name));
            // a curve the y range cuts (the wide model's, beyond its own range) says so
            let cut = (s.points.iter()).any(|&(_, y)| !(f.y[0]..=f.y[1]).contains(&y));
            assert_eq!(t[at + 1].contains("off scale, "), cut, "{}: {t:?}", s.name);
        }
        has(&t, &p.dim_label);
        for m in p.x_marks.iter().chain(&p.y_marks) {
            has(&t, &m.label);
        }
    }
}

/// friction-or-wear-map with `points` a side and its wear coefficient on a log axis from 1e-12
/// to 1e-10 1/Pa.
fn log_map(points: usize) -> App {
    let mut preset = bundled("friction-or-wear-map.toml");
    let section = preset.explore.as_mut().unwrap();
    for axis in &mut section.axes {
        axis.range.points = points;
    }
    let k = &mut section.axes[1].range;
    (k.min, k.max, k.spacing) = (1e-12, 1e-10, Spacing::Log);
    App::new(preset, None, Places::default())
}

#[test]
fn e_in_the_map_view_writes_the_map_with_its_axes_bar_range_lines_and_point() {
    let mut app = log_map(9);
    let cmds = app.start();
    settle(&mut app, cmds.clone());
    explored(&mut app, &cmds);
    let cmds = press(&mut app, KeyCode::Char('E'));
    let (path, text) = exported(&cmds);
    assert_eq!(
        path.to_str(),
        Some("wearlab-regime-map-mu-mu-over-mu-and-k.svg")
    );
    let t = texts(text);
    has(&t, "regime map: mu*-mu over mu and k");
    has(&t, &format!("{} (plane problem)", app.doc.preset.name));
    // mu from 0 to 1 linear, k from 1e-12 to 1e-10 1/Pa on log10 plot coordinates
    let mu = ticks([0.0, 1.0], Scale::Linear, "mu", "", 6);
    let k = ticks([-12.0, -10.0], Scale::Log, "k", "1/Pa", 6);
    assert_eq!(k.title, "k [1/Pa] (log)");
    has(&t, &mu.title);
    has(&t, &k.title);
    for (_, label) in mu.ticks.iter().chain(&k.ticks) {
        has(&t, label);
    }
    // the colour bar: its title, and its range as the view's (every computed value)
    let (answer, _) = crate::tui::sweep_shown::shown(&app).unwrap();
    let crate::engine::sweep_worker::SweepResult::Map(map) = &answer.explored else {
        panic!("a map")
    };
    let values: Vec<f64> = (map.samples.iter().flatten())
        .filter_map(|s| s.value.as_ref().ok().copied())
        .collect();
    let [lo, hi] = crate::tui::charts::range::bounds(values.iter().copied());
    let bar = ticks([lo, hi], Scale::Linear, "mu*-mu", "", 8);
    has(&t, &bar.title);
    for (_, label) in &bar.ticks {
        has(&t, label);
    }
    let range = format!(
        "colour: mu*-mu from {} to {}",
        crate::units::format_si(lo, ""),
        crate::units::format_si(hi, "")
    );
    has(&t, &range);
    // the theta = 0 line crosses this map: drawn with its letter and named
    let theta = map.lines.iter().find(|l| l.kind == LineKind::ThetaZero);
    assert!(theta.is_some_and(|l| !l.segments.is_empty()));
    let (glyph, meaning) = line_key(LineKind::ThetaZero);
    has(&t, &glyph.to_string());
    has(&t, &format!("{glyph}  {meaning}"));
    has(&t, "+  now: the preset's own point");
}

#[test]
fn e_waits_for_a_map_still_computing_and_writes_it_when_whole() {
    let mut app = log_map(5);
    let cmds = app.start();
    settle(&mut app, cmds.clone());
    assert!(press(&mut app, KeyCode::Char('E')).is_empty());
    let said = app.ui.message.clone().unwrap().text;
    assert!(said.contains("waits"), "{said}");
    let delivered = explored(&mut app, &cmds);
    let (path, text) = exported(&delivered);
    assert!(path.to_str().unwrap().starts_with("wearlab-regime-map-"));
    // the whole map: no word of a coarse one
    assert!(!texts(text).iter().any(|x| x.contains("coarse")));
}
