//! The spatial status under a wear law n != 1 says what `wearlab solve` says
//! (tests/cli/wear_law_cli.rs): the minimum of the simulated shape, and neither the linear law's
//! closed-form lower bound nor its time of complete contact.

use super::*;

#[test]
fn under_a_nonlinear_wear_law_the_status_gives_no_closed_form_bound_or_time() {
    // the wave of wave-thick-layer (complete contact) under n = 2, p0 = pbar, at t = 10 s
    let mut preset = bundled("wave-thick-layer.toml");
    preset.wear_exponent = 2.0;
    preset.reference_pressure = Some(2e7);
    preset.spatial.time = 10.0;
    let mut app = App::new(preset, None, Places::default());
    let cmds = app.start();
    settle(&mut app, cmds);
    for (w, h) in [(80, 24), (120, 40)] {
        let s = screen(&app, w, h, PLAIN);
        assert!(!s.contains("lower bound"), "{s}");
        assert!(!s.contains("formal bound"), "{s}");
    }
}
