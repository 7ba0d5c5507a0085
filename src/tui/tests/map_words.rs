//! The regime map's cell cursor says which effect dominates at its cell in the status's words
//! (`plane::dominance`: the signs of mu* - mu and a - b of the preset's model solved there),
//! so that a map of mu* - mu reads without the help.

use ratatui::crossterm::event::KeyCode;

use super::explore::explored;
use super::*;
use crate::physics::plane::dominance::Dominance;
use crate::sweeps::curve::solve_at;
use crate::sweeps::point::Point;

#[test]
fn the_map_cursor_names_the_dominant_effect_as_the_status_does() {
    let mut preset = bundled("friction-or-wear-map.toml");
    for axis in &mut preset.explore.as_mut().unwrap().axes {
        axis.range.points = 5;
    }
    let mut app = App::new(preset.clone(), None, Places::default());
    let cmds = app.start();
    settle(&mut app, cmds.clone());
    explored(&mut app, &cmds);
    press(&mut app, KeyCode::Char('x'));
    // two cells: the cursor's first, then the top right corner (mu = 1, k = 2e-10: wear's side
    // of the theta = 0 line k = 1.35e-10 mu, friction-or-wear-map.toml)
    for moves in [0, 8] {
        for _ in 0..moves {
            press(&mut app, KeyCode::Char(']'));
            press(&mut app, KeyCode::Char('}'));
        }
        let (i, j) = app.explore.cell.unwrap();
        let section = preset.explore.as_ref().unwrap();
        let axes = section.axes.clone();
        let at = [axes[0].values()[i], axes[1].values()[j]];
        let Point::Plane(p) = solve_at(&preset, &axes, &at, None).unwrap() else {
            panic!("a plane point")
        };
        let words = Dominance::of(&p.solution).describe().to_string();
        let items: Vec<String> = (crate::tui::view::sweep::readout(&app).unwrap().iter())
            .map(ToString::to_string)
            .collect();
        assert!(items.contains(&words), "{words} not in {items:?}");
        if moves > 0 {
            assert!(words.ends_with("wear dominates"), "{words}");
        }
    }
}
