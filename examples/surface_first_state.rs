//! How long the explorer's engine takes from an edit of a height-map punch to the first state it
//! can draw, run by hand (not by `cargo test`):
//!
//!   cargo run --release --example surface_first_state -- [GRID]
//!
//! A self-affine surface of GRID x GRID nodes (256 by default: H = 0.8, rms height 1 um, roll-off
//! 250 um, cutoff 20 um over 1 mm x 1 mm) pressed on a 2 um layer at a mean pressure that leaves
//! part of it out of contact, then the seed changed twice as the explorer's form changes it (an
//! edit: the surface generated again, another running-in). For each it prints the time from the
//! edit to the engine's first delivery (what the map shows first) with its time and contact
//! fraction, then stops the engine there, as the next edit does in the explorer (the whole
//! running-in takes minutes on this grid).

use std::time::Instant;

use wearlab::engine::{Engine, Output, Request};
use wearlab::preset::parse;

fn preset_text(grid: usize, seed: u64) -> String {
    format!(
        r#"schema = 1
name = "timing"
problem = "spatial"

[material]
youngs_modulus = 1.0e9
poisson_ratio = 0.3
thickness = 2.0e-6

[friction]
coefficient = 0.3
adhesion = 0.0

[wear]
coefficient = 1.0e-13

[spatial]
mean_pressure = 2.0e6
sliding_speed = 0.1
time = 0.05
duration = 0.1
surface = {{ kind = "self-affine", hurst = 0.8, rms_height = "1 um", rolloff_wavelength = "250 um", cutoff_wavelength = "20 um", length_x = "1 mm", length_y = "1 mm", grid = {grid}, seed = {seed} }}
"#
    )
}

fn main() {
    let grid: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(256);
    let opened = match parse(&preset_text(grid, 1), std::path::Path::new("timing.toml")) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    let mut engine = Engine::new();
    let mut preset = opened.clone();
    for seed in [1, 2, 3] {
        // the edit as the form makes it: the surface generated again, then the request
        let start = Instant::now();
        if seed > 1
            && let Err(e) = preset.set_surface_key("seed", &seed.to_string())
        {
            eprintln!("{e}");
            std::process::exit(2);
        }
        let generated = start.elapsed();
        let request = Request {
            preset: preset.clone(),
            overlays: false,
            energies: false,
        };
        let mut first = None;
        let mut fraction = None;
        engine.run_staged(&request, |output, _| {
            first.get_or_insert(start.elapsed());
            if let Output::Surface(Ok(out)) = &output {
                fraction = out
                    .running_in()
                    .and_then(|c| c.state.as_ref().ok())
                    .map(|s| (s.time, s.outputs.contact_fraction));
            } else if let Output::Surface(Err(e)) = &output {
                eprintln!("{e}");
            }
            false
        });
        println!(
            "{grid} x {grid}, seed {seed}: surface generated in {:.3} s, first state after {:.3} \
             s; its (t [s], contact fraction) {fraction:?}",
            generated.as_secs_f64(),
            first.unwrap_or_default().as_secs_f64()
        );
    }
}
