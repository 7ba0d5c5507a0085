//! Yield on the plane regime map: with a yield strength given, the map marks where the contact
//! yields (`LineKind::Yield`), judged from its second pass on; the line lies where the point's
//! own yield verdict (`yield_onset::judge` of the preset's model solved there) changes, and every
//! point's answer is that verdict. Without a strength, nothing is judged.

use std::sync::atomic::AtomicBool;

use wearlab::physics::Spacing;
use wearlab::physics::plane::yield_onset::{judge, peak};
use wearlab::physics::plane::{Model, solve};
use wearlab::preset::{Preset, bundled};
use wearlab::sweeps::axis::Axis;
use wearlab::sweeps::curve::solve_at;
use wearlab::sweeps::map::{LineKind, MapSpec, regime_map};
use wearlab::sweeps::point::Point;
use wearlab::sweeps::quantity::QuantityKey;

fn axis(p: &Preset, key: &str, ends: [f64; 2], n: usize, spacing: Spacing) -> Axis {
    Axis::new(p, p.key(key).unwrap(), ends, n, spacing).unwrap()
}

/// polymer-coating (wide model) with Y set to its own largest von Mises stress, so that the
/// onset passes through the preset's point; a map of load (1/10 to 10 times the preset's, log)
/// against mu (0.05 to 0.8): the stress grows with both.
fn yielding() -> (Preset, MapSpec) {
    let mut p = bundled("polymer-coating.toml").unwrap().unwrap();
    assert_eq!(p.plane.model, Model::Wide);
    let own = solve(&p.plane_inputs(), Model::Wide).unwrap();
    p.strength.yield_strength = Some(peak(&own).unwrap().stress);
    let load = p.plane.load;
    let spec = MapSpec {
        x: axis(
            &p,
            "plane.load",
            [load / 10.0, load * 10.0],
            7,
            Spacing::Log,
        ),
        y: axis(&p, "friction.coefficient", [0.05, 0.8], 7, Spacing::Linear),
        quantity: QuantityKey::parse("mu_star", &p).unwrap(),
    };
    (p, spec)
}

#[test]
fn the_yield_line_lies_where_the_points_own_yield_verdict_changes() {
    let (p, spec) = yielding();
    let mut passes = Vec::new();
    let map = regime_map(&p, &spec, &AtomicBool::new(false), &mut |m| {
        passes.push(m.samples.iter().flatten().any(|s| s.yields.is_some()))
    })
    .unwrap();
    // the first pass goes without yield (its cost), the later ones judge
    assert!(passes.len() >= 2, "{passes:?}");
    assert!(
        !passes[0] && passes[1..].iter().all(|&judged| judged),
        "{passes:?}"
    );
    let yields = |x: f64, y: f64| match solve_at(&p, &[spec.x, spec.y], &[x, y], None).unwrap() {
        Point::Plane(pp) => judge(&pp.solution, p.strength).unwrap().yields.unwrap(),
        Point::Spatial(_) => unreachable!(),
    };
    // every point's answer is its own verdict, both sides present
    for (k, s) in map.samples.iter().enumerate() {
        let (x, y) = (map.x[k % 7], map.y[k / 7]);
        assert_eq!(s.as_ref().unwrap().yields, Some(yields(x, y)), "({x}, {y})");
    }
    let segments = &map
        .lines
        .iter()
        .find(|l| l.kind == LineKind::Yield)
        .unwrap()
        .segments;
    assert!(segments.len() >= 3, "{}", segments.len());
    // each end lies on a grid edge, located to 2^-12 of it (an edge is a factor 100^(1/6) in
    // load, 0.125 in mu): a step of 1e-3 relative in load or 1e-4 in mu either way crosses the
    // verdict
    for [x, y] in segments.iter().flatten().copied() {
        let across_x = yields(x * (1.0 - 1e-3), y) != yields(x * (1.0 + 1e-3), y);
        let across_y = yields(x, y - 1e-4) != yields(x, y + 1e-4);
        assert!(across_x || across_y, "yield line at ({x}, {y})");
    }
}

#[test]
fn without_a_strength_the_map_judges_no_yield() {
    let (mut p, spec) = yielding();
    p.strength.yield_strength = None;
    let map = regime_map(&p, &spec, &AtomicBool::new(false), &mut |_| {}).unwrap();
    assert!(map.samples.iter().flatten().all(|s| s.yields.is_none()));
    let line = map
        .lines
        .iter()
        .find(|l| l.kind == LineKind::Yield)
        .unwrap();
    assert!(line.segments.is_empty());
}
