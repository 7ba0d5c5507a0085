//! The whole validity study of the wide and narrow models (src/physics/plane/criteria.rs; the
//! machinery in `tests/plane/validity_study.rs`): every case of the study's grid that a model
//! flags as holding must be within 2 % in contact width and 5 % in mu* - mu of the strip model
//! (it panics, naming the case, where one is not), and the worst case of each model is printed.
//! Run with `cargo run --release --example validity_study` (about 3 minutes of CPU).

#[path = "../tests/common/mod.rs"]
mod common;
#[path = "../tests/plane/validity_study.rs"]
mod validity_study;

use validity_study::{grid, run};
use wearlab::physics::plane::Model;

fn main() {
    let nus = [
        0.0, 0.1, 0.2, 0.25, 0.3, 0.35, 0.4, 0.42, 0.44, 0.45, 0.46, 0.47, 0.48, 0.485, 0.49,
        0.495, 0.499,
    ];
    let mus = [0.0, 0.1, 0.3, 0.6, 1.0];
    let kms = [0.0, 0.01, 0.05, 0.2, 0.5, 1.0, 3.0];
    let wide_widths: Vec<f64> = (0..115).map(|i| 0.05 * 1.03f64.powi(i)).collect();
    let narrow_widths = [
        10.0, 14.0, 20.0, 28.0, 40.0, 56.0, 80.0, 113.0, 160.0, 240.0,
    ];
    for (model, widths) in [
        (Model::Wide, wide_widths.as_slice()),
        (Model::Narrow, narrow_widths.as_slice()),
    ] {
        let cases = grid(&nus, &mus, &kms, widths);
        let (holds, width, mu) = run(&cases, model);
        println!(
            "{}: {} of {} cases flagged as holding; worst contact width {:.2} % at {}; worst \
             mu* - mu {:.2} % at {}",
            model.name(),
            holds,
            cases.len(),
            100.0 * width.0,
            width.1,
            100.0 * mu.0,
            mu.1
        );
    }
}
