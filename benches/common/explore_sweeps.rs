//! The explore sweeps of `polymer-coating` that `benches/sweeps.rs` and
//! `examples/instructions.rs` measure: a 200-point curve of mu* against h with the wide model
//! alone and with the narrow overlay, and a 64 x 64 map of mu* over (P, h) that crosses both
//! models' validity boundaries (every point solves the wide and narrow models).

use wearlab::physics::Spacing;
use wearlab::physics::plane::Model;
use wearlab::preset::{Preset, bundled};
use wearlab::sweeps::axis::Axis;
use wearlab::sweeps::curve::CurveSpec;
use wearlab::sweeps::map::MapSpec;
use wearlab::sweeps::quantity::QuantityKey;

/// The preset and the three sweeps' specifications.
pub struct ExploreSweeps {
    /// `polymer-coating`.
    pub preset: Preset,
    /// mu* against h from 0.1 to 100 mm, 200 points, the wide model.
    pub wide: CurveSpec,
    /// The same with the narrow model's curve.
    pub with_narrow: CurveSpec,
    /// mu* over P from 1e2 to 1e7 N/m and h from 10 um to 100 mm, 64 x 64.
    pub map: MapSpec,
}

/// An axis of `n` points spaced evenly in the logarithm.
pub fn axis(p: &Preset, key: &str, ends: [f64; 2], n: usize) -> Axis {
    Axis::new(p, p.key(key).unwrap(), ends, n, Spacing::Log).unwrap()
}

/// The sweeps on `polymer-coating`.
pub fn explore_sweeps() -> ExploreSweeps {
    let preset = bundled("polymer-coating.toml").unwrap().unwrap();
    let mu_star = QuantityKey::parse("mu_star", &preset).unwrap();
    let wide = CurveSpec {
        axis: axis(&preset, "material.thickness", [1e-4, 1e-1], 200),
        quantity: mu_star,
        models: vec![Model::Wide],
    };
    let with_narrow = CurveSpec {
        models: vec![Model::Wide, Model::Narrow],
        ..wide.clone()
    };
    let map = MapSpec {
        x: axis(&preset, "plane.load", [1e2, 1e7], 64),
        y: axis(&preset, "material.thickness", [1e-5, 1e-1], 64),
        quantity: mu_star,
    };
    ExploreSweeps {
        preset,
        wide,
        with_narrow,
        map,
    }
}
