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
