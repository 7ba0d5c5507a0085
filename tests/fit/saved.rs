//! The fitted preset saved and read again gives the same curve: `preset::save_edited`, the save
//! of `wearlab fit --write` and of the explorer, keeps every digit the fit found, also for a
//! value written in another unit than SI.

use std::path::Path;

use wearlab::data::{self, DataSet};
use wearlab::fit;
use wearlab::preset::{self, Links, Origin, Preset};
use wearlab::sweeps::point;

const PRESET: &str = "examples/lab/friction-against-load.toml";
const DATA: &str = "examples/lab/friction-against-load.csv";

/// The model's value of each measured quantity at each row of `data`, from `preset`.
fn curve(preset: &Preset, data: &DataSet) -> Vec<f64> {
    let mut out = Vec::new();
    for x in &data.x.values {
        let mut at = preset.clone();
        at.set(data.x.key, *x).unwrap();
        let p = point::solve(&at).unwrap();
        for m in &data.measured {
            out.push(m.quantity.value(&p).unwrap());
        }
    }
    out
}

/// Fits mu and k of the preset file `source` to the lab data, saves the fitted preset over a
/// copy of `source`'s text, reads it back and compares: the values bit for bit where the unit
/// is SI, and the curve at every data point to 1e-12 relative, against the fitted preset's and
/// against the fit's own model (data minus residual).
fn saved_and_read_again(source: &Path) {
    let read = preset::load(source).unwrap();
    let data = data::read(Path::new(DATA), &read).unwrap();
    let keys = [
        read.key("friction.coefficient").unwrap(),
        read.key("wear.coefficient").unwrap(),
    ];
    let fitted = fit::fit(&read, &data, &keys).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("fitted.toml");
    let origin = Origin {
        path: source.to_path_buf(),
        preset: read,
    };
    preset::save_edited(&fitted.preset, Some(&origin), &out, Links::Follow).unwrap();
    let again = preset::load(&out).unwrap();
    for e in &fitted.estimates {
        let v = again.get(e.key).unwrap();
        assert!(
            (v - e.value).abs() <= 1e-15 * e.value.abs(),
            "{}: {v} read again against {} fitted",
            e.key,
            e.value
        );
    }
    let observed: Vec<f64> = (0..data.len())
        .flat_map(|i| data.measured.iter().map(move |m| m.values[i]))
        .collect();
    let model: Vec<f64> = observed
        .iter()
        .zip(&fitted.residuals)
        .map(|(o, r)| o - r)
        .collect();
    let before = curve(&fitted.preset, &data);
    let after = curve(&again, &data);
    assert_eq!(after.len(), data.len());
    for (i, ((a, b), m)) in after.iter().zip(&before).zip(&model).enumerate() {
        assert!(
            (a - b).abs() <= 1e-12 * b.abs(),
            "row {i}: {a} read again against {b}"
        );
        assert!(
            (a - m).abs() <= 1e-12 * m.abs(),
            "row {i}: {a} read again against the fit's {m}"
        );
    }
}

#[test]
fn the_fitted_preset_saved_and_read_again_gives_the_same_curve() {
    saved_and_read_again(Path::new(PRESET));
}

/// k written in mm3/Nm (1e-3 mm3/Nm = 1e-12 1/Pa) is written back in mm3/Nm: the conversion
/// keeps the curve to 1e-12.
#[test]
fn a_value_written_in_another_unit_keeps_the_curve() {
    let text = std::fs::read_to_string(PRESET).unwrap();
    let old = "[wear]\ncoefficient = 1.0e-12\n";
    assert!(text.contains(old), "{PRESET} changed: {text}");
    let dir = tempfile::tempdir().unwrap();
    let source = dir.path().join("lab.toml");
    let units = text.replace(old, "[wear]\ncoefficient = \"1e-3 mm3/Nm\"\n");
    std::fs::write(&source, units).unwrap();
    saved_and_read_again(&source);
}
