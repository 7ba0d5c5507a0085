//! The synthetic lab dataset of `examples/lab/` is what its notes say: wearlab's wide model at
//! mu = 0.3, k = 2e-11 1/Pa with noise 0.002 from seed 25, at the loads of the file.
//! `WEARLAB_WRITE_LAB=1 cargo test --test fit lab` writes it anew.

use wearlab::data;
use wearlab::fit::synthetic;
use wearlab::sweeps::QuantityKey;

use crate::{loads, preset};

const FILE: &str = "examples/lab/friction-against-load.csv";
const SEED: u64 = 25;
const NOISE: f64 = 0.002;

fn made(xs: &[f64]) -> Vec<f64> {
    let truth = preset(&["friction.coefficient=0.3", "wear.coefficient=2e-11"]);
    let key = truth.key("plane.load").unwrap();
    let q = QuantityKey::parse("mu_star", &truth).unwrap();
    synthetic::measure(&truth, key, xs, q, NOISE, SEED).unwrap()
}

#[test]
fn the_lab_dataset_is_the_model_with_its_stated_noise() {
    if std::env::var("WEARLAB_WRITE_LAB").is_ok() {
        // the loads to 6 digits, as written, then the model at exactly those loads
        let xs: Vec<f64> = loads(20)
            .iter()
            .map(|x| format!("{x:.5e}").parse().unwrap())
            .collect();
        let mut text = String::from(
            "# SYNTHETIC data, not a measurement: wearlab's wide model (preset\n\
             # friction-against-load.toml at mu = 0.3, k = 2e-11 1/Pa) plus Gaussian noise of\n\
             # sd 0.002 in mu, seed 25 (wearlab::fit::synthetic), at 20 loads from 1 to 100 kN/m.\n\
             load [N/m],mu [-]\n",
        );
        for (x, y) in xs.iter().zip(made(&xs)) {
            text += &format!("{x:.5e},{y:.6}\n");
        }
        std::fs::write(FILE, text).unwrap();
    }
    let base = preset(&[]);
    let set = data::read(std::path::Path::new(FILE), &base).unwrap();
    assert_eq!(set.len(), 20);
    assert!(set.notes[0].starts_with("SYNTHETIC"), "{:?}", set.notes);
    let again = made(&set.x.values);
    for (y, m) in set.measured[0].values.iter().zip(&again) {
        // written to 6 decimals
        assert!((y - m).abs() <= 5e-7, "{y} against {m}");
    }
}
