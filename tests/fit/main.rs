//! Fits against an independent route: data made by the model itself with a known noise
//! (`fit::synthetic`, seeded), read back through the data-file reader, fitted, and the estimates,
//! intervals and verdicts compared with the values the data were made with.

mod coverage;
mod identifiability;
mod lab_data;
mod running_in;
mod saved;

use std::io::Write;

use wearlab::data::{self, DataSet};
use wearlab::fit::synthetic;
use wearlab::preset::{Preset, default_preset};
use wearlab::sweeps::QuantityKey;

/// The default preset (a steel cylinder on a 10 mm polymer coating, wide model) with settings.
pub fn preset(settings: &[&str]) -> Preset {
    default_preset().with_settings(settings).unwrap()
}

/// `points` loads from 1 kN/m to 100 kN/m, evenly on a log scale.
pub fn loads(points: usize) -> Vec<f64> {
    (0..points)
        .map(|i| 1e3 * 100f64.powf(i as f64 / (points - 1) as f64))
        .collect()
}

/// A data file of `quantity` against the load, made by the model of `truth` with noise `sd`
/// (seed `seed`), written with 17 significant digits and read back; with an sd column when
/// `with_sd`.
pub fn measured(
    truth: &Preset,
    quantity: &str,
    unit: &str,
    sd: f64,
    seed: u64,
    with_sd: bool,
) -> (DataSet, tempfile::NamedTempFile) {
    let xs = loads(20);
    let key = truth.key("plane.load").unwrap();
    let q = QuantityKey::parse(quantity, truth).unwrap();
    let ys = synthetic::measure(truth, key, &xs, q, sd, seed).unwrap();
    let mut file = tempfile::NamedTempFile::new().unwrap();
    let sd_head = if with_sd {
        format!(",{quantity} sd [{unit}]")
    } else {
        String::new()
    };
    writeln!(file, "# synthetic, seed {seed}").unwrap();
    writeln!(file, "load [N/m],{quantity} [{unit}]{sd_head}").unwrap();
    for (x, y) in xs.iter().zip(&ys) {
        let sd_cell = if with_sd {
            format!(",{sd:e}")
        } else {
            String::new()
        };
        writeln!(file, "{x:e},{y:e}{sd_cell}").unwrap();
    }
    file.flush().unwrap();
    let set = data::read(file.path(), truth).unwrap();
    (set, file)
}
