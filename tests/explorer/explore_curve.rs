//! The sweep worker's curve comes in two deliveries: the curve as soon as its points are solved,
//! then the same curve with the verdict at every point and where it changes (strip solves where
//! the study's estimate doubts a plane model, a bisection at each change).

use std::sync::atomic::AtomicBool;

use wearlab::engine::sweep_worker::{SweepRequest, SweepResult, explore};
use wearlab::physics::Spacing;
use wearlab::physics::plane::Model;
use wearlab::preset::bundled;
use wearlab::sweeps::Opening;
use wearlab::sweeps::axis::Axis;
use wearlab::sweeps::curve::CurveSpec;
use wearlab::sweeps::quantity::QuantityKey;

#[test]
fn a_curve_is_drawn_before_its_verdicts_and_they_do_not_change_it() {
    let preset = bundled("polymer-coating.toml").unwrap().unwrap();
    // mu* against h from 0.1 to 100 mm: the wide model fails on the thin coatings and holds on
    // the thick ones (one change), the narrow model fails throughout
    let axis = Axis::new(
        &preset,
        preset.key("material.thickness").unwrap(),
        [1e-4, 1e-1],
        24,
        Spacing::Log,
    )
    .unwrap();
    let spec = CurveSpec {
        axis,
        quantity: QuantityKey::parse("mu_star", &preset).unwrap(),
        models: vec![Model::Wide, Model::Narrow],
    };
    let request = SweepRequest {
        preset,
        job: Opening::Curve(spec),
    };
    let mut passes = Vec::new();
    let done = explore(&request, &AtomicBool::new(false), &mut |p| passes.push(p)).unwrap();
    let ([SweepResult::Curve(first)], SweepResult::Curve(done)) = (&passes[..], done) else {
        panic!("one pass before the curve, both curves")
    };
    let wide = &done.series[0];
    assert_eq!((wide.holds[0], wide.holds[23]), (Some(false), Some(true)));
    assert_eq!(wide.changes.len(), 1);
    assert!(!first.judged && done.judged);
    assert_eq!((&first.x, first.current), (&done.x, done.current));
    for (f, d) in first.series.iter().zip(&done.series) {
        assert_eq!((f.model, &f.y, &f.group), (d.model, &d.y, &d.group));
        assert!(f.holds.iter().all(Option::is_none) && f.changes.is_empty());
        assert!(d.holds.iter().all(Option::is_some));
    }
}
