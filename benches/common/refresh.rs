//! The plane refresh that `benches/plane_refresh.rs` and `examples/instructions.rs` measure, on
//! `polymer-coating` (wide model) and `thin-strip-winkler` (narrow): what the screen draws first
//! (the operating point, a 201-point profile and the 200-point load sweep's curve) and the
//! sweep's verdicts, which the explorer delivers after the curve.

use std::hint::black_box;

use wearlab::physics::plane::profile::profile;
use wearlab::physics::plane::sweep::{self, Solved, Sweep};
use wearlab::physics::plane::{Model, PlaneInputs, PlaneSolution, solve};
use wearlab::physics::{Spacing, SweepRange};
use wearlab::preset::bundled;

/// One bundled preset's refresh.
pub struct Refresh {
    /// The model's name: "wide" or "narrow".
    pub name: &'static str,
    inputs: PlaneInputs,
    model: Model,
    loads: SweepRange,
}

/// The wide model's refresh on `polymer-coating` and the narrow model's on `thin-strip-winkler`.
pub fn refreshes() -> [Refresh; 2] {
    [
        ("polymer-coating.toml", Model::Wide),
        ("thin-strip-winkler.toml", Model::Narrow),
    ]
    .map(|(file, model)| {
        let preset = bundled(file).unwrap().unwrap();
        Refresh {
            name: model.name(),
            inputs: preset.plane_inputs(),
            model,
            loads: SweepRange {
                points: 200,
                spacing: Spacing::Log,
                ..preset.plane.sweep
            },
        }
    })
}

impl Refresh {
    /// The operating point, its 201-point profile and the load sweep's curve without its
    /// verdicts.
    pub fn curve(&self) -> Sweep {
        black_box(profile(&self.point(), 201));
        self.solved().unjudged()
    }

    /// The operating point.
    pub fn point(&self) -> PlaneSolution {
        solve(black_box(&self.inputs), self.model).unwrap()
    }

    /// The load sweep's solutions, whose verdicts `Solved::judged` measures.
    pub fn solved(&self) -> Solved {
        sweep::solve(&self.inputs, self.model, &self.loads)
    }
}
