//! The validity study's machinery (src/physics/plane/criteria.rs): the strip model of any
//! thickness at a chosen contact width, a model's deviation from it as the study measures it, and
//! a run over a grid of cases that asserts every case flagged "holds" is within tolerance. Used by
//! the plane tests and by `examples/validity_study.rs`, which reruns the whole study.

use crate::common;

use common::plane;
use wearlab::physics::elastic::plane_modulus;
use wearlab::physics::plane::criteria::MU_STAR_FLOOR;
use wearlab::physics::plane::strip::{collocate, kernels_for, nodes_for, solution};
use wearlab::physics::plane::validity::{Deviation, estimate};
use wearlab::physics::plane::{Model, PlaneInputs, PlaneSolution, solve};

pub const E: f64 = 1e10;
pub const H: f64 = 1e-5;
pub const R: f64 = 0.05;

/// The strip solution whose contact width is lambda h, and the inputs at its load.
pub fn strip_at_width(nu: f64, mu: f64, km: f64, lambda: f64) -> (PlaneInputs, PlaneSolution) {
    let base = plane(E, nu, H, mu, 0.0, km / plane_modulus(E, nu), R, 1.0);
    let n = nodes_for(lambda).div_ceil(16) * 16;
    let col = collocate(&base, kernels_for(nu).as_ref(), lambda * H, n).unwrap();
    let inputs = base.with_load(col.load);
    let sol = solution(&inputs, col, Model::Strip);
    (inputs, sol)
}

/// A model's deviation from the strip solution, as the study measures it.
pub fn deviation(model: &PlaneSolution, strip: &PlaneSolution) -> Deviation {
    let mu = strip.inputs.friction.coefficient;
    let floor = MU_STAR_FLOOR * strip.contact_width() / R;
    Deviation {
        contact_width: (model.contact_width() / strip.contact_width() - 1.0).abs(),
        mu_star_minus_mu: (model.mu_star - strip.mu_star).abs()
            / (strip.mu_star - mu).abs().max(floor),
    }
}

/// For every case: if the model is flagged as holding, it must be within tolerance. Returns how
/// many were flagged and the worst deviation among them (width, mu* - mu), with its case.
pub fn run(cases: &[(f64, f64, f64, f64)], model: Model) -> (usize, (f64, String), (f64, String)) {
    let (mut holds, mut worst_width, mut worst_mu) =
        (0, (0.0, String::new()), (0.0, String::new()));
    for &(nu, mu, km, lambda) in cases {
        let (inputs, strip) = strip_at_width(nu, mu, km, lambda);
        let Ok(sol) = solve(&inputs, model) else {
            continue;
        };
        let validity = estimate(&sol);
        if !validity.failed_criteria.is_empty() {
            continue;
        }
        holds += 1;
        let d = deviation(&sol, &strip);
        let case = format!("nu = {nu}, mu = {mu}, k m = {km}, (a+b)/h = {lambda}");
        assert!(
            d.within_tolerance(),
            "{} flagged as holding but off by {d:?} at {case}",
            model.name()
        );
        if d.contact_width > worst_width.0 {
            worst_width = (d.contact_width, case.clone());
        }
        if d.mu_star_minus_mu > worst_mu.0 {
            worst_mu = (d.mu_star_minus_mu, case);
        }
    }
    (holds, worst_width, worst_mu)
}

pub fn grid(nus: &[f64], mus: &[f64], kms: &[f64], lambdas: &[f64]) -> Vec<(f64, f64, f64, f64)> {
    let mut cases = Vec::new();
    for &nu in nus {
        for &mu in mus {
            for &km in kms {
                for &lambda in lambdas {
                    cases.push((nu, mu, km, lambda));
                }
            }
        }
    }
    cases
}
