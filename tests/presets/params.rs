//! The parameter registry (`preset::params`): its keys are the preset file's keys, its getters
//! read what the file says, its setters refuse what the file checker refuses.

use wearlab::physics::limits;
use wearlab::preset::{BUNDLED, Key, PARAMS, Preset, Problem, bundled};
use wearlab::units::parse_si;

/// The value at a dotted key in the TOML text itself (an independent route: the file as data, not
/// the preset's fields); `spatial.harmonics.N.x` indexes the array of tables.
fn toml_value(text: &str, key: &str) -> Option<toml::Value> {
    let mut v: toml::Value = toml::from_str(text).unwrap();
    for part in key.split('.') {
        v = match part.parse::<usize>() {
            Ok(n) => v.as_array()?.get(n)?.clone(),
            Err(_) => v.get(part)?.clone(),
        };
    }
    Some(v)
}

#[test]
fn every_key_reads_what_the_preset_file_says() {
    let mut compared = 0;
    for b in BUNDLED {
        let preset = b.load().unwrap();
        // a measured profile's file and range are shown, not read as numbers
        for key in Key::all(&preset)
            .into_iter()
            .filter(|k| k.param().fixed().is_none())
        {
            let Some(file) = toml_value(b.text, &key.to_string()) else {
                continue; // a default: the file does not say
            };
            // a measured surface's keys are its file's (read-only), not numbers set here
            let measured = toml_value(b.text, "spatial.surface.file").is_some();
            if measured && key.to_string().starts_with("spatial.surface.") {
                continue;
            }
            let got = preset.get(key).unwrap();
            match key.param().choices() {
                Some(names) => assert_eq!(Some(names[got as usize]), file.as_str(), "{key}"),
                None => {
                    // a number in SI units, or a string with its unit ("20 nm")
                    let unit = key.param().unit;
                    let want = file
                        .as_float()
                        .or(file.as_integer().map(|i| i as f64))
                        .or_else(|| file.as_str().and_then(|t| parse_si(t, unit).ok()))
                        .unwrap_or_else(|| panic!("{} {key}: {file}", b.file));
                    assert_eq!(got.to_bits(), want.to_bits(), "{} {key}", b.file);
                }
            }
            compared += 1;
        }
    }
    // 11 bundled presets, each with at least its material, friction and wear keys
    assert!(compared > 11 * 6, "{compared}");
}

#[test]
fn the_keys_of_each_problem_cover_the_sections_it_solves() {
    let plane = bundled("hertz-check.toml").unwrap().unwrap();
    let spatial = bundled("dispersion.toml").unwrap().unwrap();
    let names = |p: &Preset| {
        Key::all(p)
            .iter()
            .map(|k| k.to_string())
            .collect::<Vec<_>>()
    };
    let plane_keys = names(&plane);
    assert!(plane_keys.iter().all(|k| !k.starts_with("spatial.")));
    assert!(plane_keys.contains(&"plane.sweep.scale".to_string()));
    let spatial_keys = names(&spatial);
    // dispersion.toml has four harmonics, five keys each
    assert_eq!(
        spatial_keys
            .iter()
            .filter(|k| k.starts_with("spatial.harmonics."))
            .count(),
        20
    );
    assert!(spatial_keys.contains(&"spatial.harmonics.3.phase_y".to_string()));
    for key in Key::all(&spatial) {
        assert_eq!(Key::parse(&key.to_string()), Ok(key));
    }
    // 41 plane and harmonic keys, and the height map's ten: file, hurst, rms_height, rms_slope,
    // rolloff_wavelength, cutoff_wavelength, length_x, length_y, grid, seed
    assert_eq!(PARAMS.len(), 51);
}

#[test]
fn a_value_out_of_range_is_refused_naming_key_value_and_range_and_leaves_the_preset() {
    let mut p = bundled("polymer-coating.toml").unwrap().unwrap();
    let before = p.clone();
    let key = p.key("material.thickness").unwrap();
    let err = p.set(key, 1e4).unwrap_err();
    assert_eq!(
        err,
        format!(
            "material.thickness = 10000 is out of range: allowed {}",
            limits::THICKNESS.allowed
        )
    );
    assert_eq!(p, before);
    p.set(key, f64::INFINITY).unwrap();
    assert!(p.material.is_half_space());
}

#[test]
fn text_takes_units_and_choices_by_name() {
    let p = bundled("polymer-coating.toml").unwrap().unwrap();
    let q = p
        .with_settings(&[
            "material.thickness=10um",
            "material.youngs_modulus=3 GPa",
            "plane.model=strip",
            "plane.sweep.scale=linear",
            "plane.sweep.points=7",
        ])
        .unwrap();
    // parse_si divides for negative powers, so 10 um is exactly 10/1e6
    assert_eq!(q.material.thickness, 10.0 / 1e6);
    assert_eq!(q.material.youngs_modulus, 3e9);
    assert_eq!(q.plane.model.name(), "strip");
    assert_eq!(q.plane.sweep.points, 7);
    let err = p.with_settings(&["plane.model=thin"]).unwrap_err();
    assert_eq!(
        err,
        "plane.model=thin: plane.model = 'thin' is not a choice: allowed one of wide, narrow, strip"
    );
    let err = p.with_settings(&["plane.sweep.points=2.5"]).unwrap_err();
    assert!(err.contains("a whole number from 2 to 2000"), "{err}");
    let err = p.with_settings(&["friction.coefficient=lots"]).unwrap_err();
    assert!(err.contains("'lots' is not a number") && err.contains("0 <= mu <= 10"));
}

#[test]
fn the_rules_between_fields_are_checked_after_all_settings() {
    let p = bundled("polymer-coating.toml").unwrap().unwrap();
    // both ends of the load sweep move past each other: fine together, wrong one at a time
    let q = p
        .with_settings(&["plane.sweep.load_min=1e6", "plane.sweep.load_max=1e7"])
        .unwrap();
    assert_eq!((q.plane.sweep.min, q.plane.sweep.max), (1e6, 1e7));
    let err = p.with_settings(&["plane.sweep.load_min=1e6"]).unwrap_err();
    assert!(
        err.contains("plane.sweep.load_max = 100000 must be larger"),
        "{err}"
    );
    let err = p
        .with_settings(&["material.thickness=inf", "plane.model=narrow"])
        .unwrap_err();
    assert!(err.contains("needs a finite material.thickness"), "{err}");
}

#[test]
fn keys_of_the_other_problem_and_missing_harmonics_are_refused() {
    let plane = bundled("polymer-coating.toml").unwrap().unwrap();
    assert_eq!(plane.problem, Problem::Plane);
    let err = plane.key("spatial.mean_pressure").unwrap_err();
    assert!(err.contains("applies to spatial presets only"), "{err}");
    let err = plane.key("material.thicknes").unwrap_err();
    assert!(err.starts_with("unknown key 'material.thicknes': the keys of a plane preset are"));
    assert!(!err.contains("spatial."));
    let spatial = bundled("wave-thick-layer.toml").unwrap().unwrap();
    let err = spatial.key("spatial.harmonics.1.amplitude").unwrap_err();
    assert!(err.contains("there is no harmonic 1"), "{err}");
    let err = spatial
        .with_settings(&[
            "spatial.harmonics.0.wavenumber_x=0",
            "spatial.harmonics.0.wavenumber_y=0",
        ])
        .unwrap_err();
    assert!(err.contains("wave vector is zero"), "{err}");
}
