//! The verdict along a load sweep (`sweep_verdicts::holds_along`, which measures the doubted
//! points on a grid and reads the points between from the interpolated deviations) against the
//! verdict of every point solved on its own (`strip_check::verdict`, a strip solve at every
//! doubted point): equal at every point of every bundled plane preset's load sweep, for the wide
//! and the narrow model, and along a thickness sweep that crosses both models' limits.

use wearlab::physics::plane::strip_check::verdict;
use wearlab::physics::plane::sweep::sweep;
use wearlab::physics::plane::sweep_verdicts::holds_along;
use wearlab::physics::plane::{Model, PlaneInputs, solve};
use wearlab::physics::{Spacing, SweepRange};
use wearlab::preset::{BUNDLED, Problem, bundled};

/// Each point's verdict solved on its own.
fn one_by_one(inputs: &[PlaneInputs], model: Model) -> Vec<Option<bool>> {
    inputs
        .iter()
        .map(|at| solve(at, model).ok().map(|s| verdict(&s).ok))
        .collect()
}

#[test]
fn the_sweep_verdicts_are_each_points_own_on_every_bundled_plane_preset() {
    let mut measured_runs = 0;
    for b in BUNDLED {
        let preset = bundled(b.file).unwrap().unwrap();
        if preset.problem != Problem::Plane {
            continue;
        }
        let inputs = preset.plane_inputs();
        // the preset's own range, widened to 1e2..1e6 N/m where it is narrower
        let loads = SweepRange {
            min: preset.plane.sweep.min.min(1e2),
            max: preset.plane.sweep.max.max(1e6),
            points: 60,
            spacing: Spacing::Log,
        };
        for model in [Model::Wide, Model::Narrow] {
            let swept = sweep(&inputs, model, &loads);
            let each: Vec<PlaneInputs> = swept.load.iter().map(|&p| inputs.with_load(p)).collect();
            let own = one_by_one(&each, model);
            assert_eq!(swept.valid, own, "{} {}", b.file, model.name());
            measured_runs += usize::from(own.contains(&Some(true)) && own.contains(&Some(false)));
        }
    }
    // the comparison means something only where some verdicts turn along the sweep
    assert!(
        measured_runs >= 5,
        "{measured_runs} sweeps where the verdict turns"
    );
}

#[test]
fn the_verdicts_along_a_thickness_sweep_are_each_points_own() {
    for (file, model) in [
        ("polymer-coating.toml", Model::Wide),
        ("polymer-coating.toml", Model::Narrow),
        ("thin-strip-winkler.toml", Model::Narrow),
    ] {
        let inputs = bundled(file).unwrap().unwrap().plane_inputs();
        let each: Vec<PlaneInputs> = (0..80)
            .map(|i| {
                let mut at = inputs.clone();
                at.material.thickness = 1e-5 * 10f64.powf(4.0 * i as f64 / 79.0);
                at
            })
            .collect();
        let solutions: Vec<_> = each.iter().map(|at| solve(at, model).ok()).collect();
        assert_eq!(
            holds_along(&solutions),
            one_by_one(&each, model),
            "{file} {model:?}"
        );
    }
}

/// The premise of `verdict_table`: at the same (a+b)/h and groups the deviations from the strip
/// model are the same. (P, h, R) -> (2P, 2h, 2R) keeps (a+b)/h, nu, mu, gamma m and tau0 R/(m h)
/// (q2 scales as m h/R, so P as m h^2/R), and must keep the measured deviations to the solvers'
/// accuracy.
#[test]
fn the_deviation_from_the_strip_model_depends_on_the_width_over_the_thickness_alone() {
    use wearlab::physics::plane::strip_check::against_strip;
    for (file, model, load) in [
        ("polymer-coating.toml", Model::Wide, 3e5),
        ("thin-strip-winkler.toml", Model::Narrow, 3e3),
    ] {
        let inputs = bundled(file)
            .unwrap()
            .unwrap()
            .plane_inputs()
            .with_load(load);
        let mut scaled = inputs.with_load(2.0 * load);
        scaled.material.thickness *= 2.0;
        scaled.shape = wearlab::physics::plane::Shape::Parabola {
            radius: 2.0 * inputs.radius(),
        };
        let (a, b) = (
            solve(&inputs, model).unwrap(),
            solve(&scaled, model).unwrap(),
        );
        let lambda = |s: &wearlab::physics::plane::PlaneSolution| {
            s.contact_width() / s.inputs.material.thickness
        };
        assert!((lambda(&a) / lambda(&b) - 1.0).abs() < 1e-12, "{file}");
        let (da, db) = (against_strip(&a).unwrap(), against_strip(&b).unwrap());
        for (x, y) in [
            (da.contact_width, db.contact_width),
            (da.mu_star_minus_mu, db.mu_star_minus_mu),
        ] {
            assert!(
                (x - y).abs() <= 1e-9 * x.abs().max(1e-3),
                "{file}: {x} against {y}"
            );
        }
    }
}

/// A regime map over (P, h) reads most verdicts from its shared table (`verdict_table`): every
/// sample's wide and narrow verdict must still be the point's own.
#[test]
fn the_verdicts_of_a_load_thickness_map_are_each_points_own() {
    use std::sync::atomic::AtomicBool;
    use wearlab::sweeps::axis::Axis;
    use wearlab::sweeps::map::{MapSpec, regime_map};
    use wearlab::sweeps::quantity::QuantityKey;
    let p = bundled("polymer-coating.toml").unwrap().unwrap();
    let axis = |key: &str, ends: [f64; 2]| {
        Axis::new(&p, p.key(key).unwrap(), ends, 17, Spacing::Log).unwrap()
    };
    let spec = MapSpec {
        x: axis("plane.load", [1e2, 1e7]),
        y: axis("material.thickness", [1e-5, 1e-1]),
        quantity: QuantityKey::parse("mu_star", &p).unwrap(),
    };
    let map = regime_map(&p, &spec, &AtomicBool::new(false), &mut |_| {}).unwrap();
    let inputs = p.plane_inputs();
    let (mut turns, mut compared) = ([0usize; 2], 0);
    for (j, &h) in map.y.iter().enumerate() {
        for (i, &load) in map.x.iter().enumerate() {
            let sample = map.sample(i, j).unwrap();
            let mut at = inputs.with_load(load);
            at.material.thickness = h;
            for (k, (model, shown)) in [
                (Model::Wide, sample.wide_holds),
                (Model::Narrow, sample.narrow_holds),
            ]
            .into_iter()
            .enumerate()
            {
                let own = solve(&at, model).ok().map(|s| verdict(&s).ok);
                assert_eq!(shown, own, "{model:?} at P = {load:e} N/m, h = {h:e} m");
                turns[k] += usize::from(own == Some(true));
                compared += 1;
            }
        }
    }
    // both models hold somewhere and fail somewhere on this map
    assert!(
        turns.iter().all(|&t| t > 0 && t < 17 * 17),
        "{turns:?} of {compared}"
    );
}
