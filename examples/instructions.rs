//! The bodies of the `plane_refresh` and `sweeps` benches, run a given number of times in one
//! process, for counting instructions under callgrind (docs/performance.md, "Instructions against
//! the code before the reshaping"): the count of 2N runs less that of N is N runs' work without the
//! process's start. Usage: `instructions WORKLOAD N`, WORKLOAD one of refresh_wide,
//! refresh_narrow, curve_wide, curve_with_narrow, map_wide.

use std::hint::black_box;
use std::sync::atomic::AtomicBool;

use wearlab::physics::plane::profile::profile;
use wearlab::physics::plane::sweep::sweep;
use wearlab::physics::plane::{Model, solve};
use wearlab::physics::{Spacing, SweepRange};
use wearlab::preset::{Preset, bundled};
use wearlab::sweeps::axis::Axis;
use wearlab::sweeps::curve::{CurveSpec, curve};
use wearlab::sweeps::map::{MapSpec, regime_map};
use wearlab::sweeps::quantity::QuantityKey;

fn axis(p: &Preset, key: &str, ends: [f64; 2], n: usize) -> Axis {
    Axis::new(p, p.key(key).unwrap(), ends, n, Spacing::Log).unwrap()
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (Some(workload), Some(count)) = (
        args.get(1),
        args.get(2).and_then(|n| n.parse::<usize>().ok()),
    ) else {
        eprintln!("usage: instructions WORKLOAD N");
        std::process::exit(2);
    };
    let never = AtomicBool::new(false);
    for (file, model, name) in [
        ("polymer-coating.toml", Model::Wide, "refresh_wide"),
        ("thin-strip-winkler.toml", Model::Narrow, "refresh_narrow"),
    ] {
        if workload != name {
            continue;
        }
        let preset = bundled(file).unwrap().unwrap();
        let inputs = preset.plane_inputs();
        let loads = SweepRange {
            points: 200,
            spacing: Spacing::Log,
            ..preset.plane.sweep
        };
        for _ in 0..count {
            let sol = solve(black_box(&inputs), model).unwrap();
            black_box((profile(&sol, 201), sweep(&inputs, model, &loads)));
        }
    }
    let p = bundled("polymer-coating.toml").unwrap().unwrap();
    let mu_star = QuantityKey::parse("mu_star", &p).unwrap();
    let spec = CurveSpec {
        axis: axis(&p, "material.thickness", [1e-4, 1e-1], 200),
        quantity: mu_star,
        models: vec![Model::Wide],
    };
    let overlays = CurveSpec {
        models: vec![Model::Wide, Model::Narrow],
        ..spec.clone()
    };
    let map = MapSpec {
        x: axis(&p, "plane.load", [1e2, 1e7], 64),
        y: axis(&p, "material.thickness", [1e-5, 1e-1], 64),
        quantity: mu_star,
    };
    for _ in 0..count {
        match workload.as_str() {
            "curve_wide" => drop(black_box(curve(&p, &spec, &never))),
            "curve_with_narrow" => drop(black_box(curve(&p, &overlays, &never))),
            "map_wide" => drop(black_box(regime_map(&p, &map, &never, &mut |_| {}))),
            _ => {}
        }
    }
}
