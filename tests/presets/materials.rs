//! The bundled materials table (`wearlab::materials`): its values within the preset limits and
//! equal to the table of docs/presets.md, every source resolvable in docs/references.md, the
//! wear rates against Archard (1953); `material.name` and `wear.archard_coefficient` read from a
//! preset file, refused with `path:line: reason`, and set by `--set`.

use std::path::Path;

use wearlab::materials::{MATERIALS, named};
use wearlab::physics::limits;
use wearlab::preset::parse;
use wearlab::units::parse_si;

const MM3_PER_NM: f64 = 1e-9;

fn docs(page: &str) -> String {
    std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("docs")
            .join(page),
    )
    .unwrap()
}

#[test]
fn every_material_is_within_the_limits_once_with_its_sources() {
    let references = docs("references.md")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    for (i, m) in MATERIALS.iter().enumerate() {
        assert!(
            limits::YOUNGS_MODULUS.check("E", m.youngs_modulus).is_ok(),
            "{}",
            m.name
        );
        assert!(
            limits::POISSON_RATIO.check("nu", m.poisson_ratio).is_ok(),
            "{}",
            m.name
        );
        if let Some(y) = m.strength.yield_strength {
            assert!(limits::YIELD_STRENGTH.check("Y", y).is_ok(), "{}", m.name);
        }
        if let Some(h) = m.strength.hardness {
            assert!(limits::HARDNESS.check("H", h).is_ok(), "{}", m.name);
        }
        assert!(limits::WEAR.check("k", m.wear_rate).is_ok(), "{}", m.name);
        assert!(
            limits::FRICTION.check("mu", m.friction).is_ok(),
            "{}",
            m.name
        );
        assert_eq!(
            named(&m.name.to_lowercase()),
            Some(m),
            "found by its name in any case"
        );
        assert!(
            MATERIALS[..i].iter().all(|o| o.name != m.name),
            "{} twice",
            m.name
        );
        for source in m.sources.split("; ") {
            assert!(
                references.contains(&format!("cited as {source}")),
                "{}: '{source}' is not cited in docs/references.md",
                m.name
            );
        }
    }
}

#[test]
fn the_docs_table_holds_the_librarys_values() {
    let page = docs("presets.md");
    let rows: Vec<Vec<&str>> = page
        .split("## Materials")
        .nth(1)
        .and_then(|section| section.split("\n## ").next())
        .unwrap()
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| name"))
        .map(|l| l.trim_matches('|').split(" | ").map(str::trim).collect())
        .collect();
    assert_eq!(rows.len(), MATERIALS.len());
    let si = |text: &str, unit: &str| (text != "–").then(|| parse_si(text, unit).unwrap());
    for (row, m) in rows.iter().zip(&MATERIALS) {
        assert_eq!((row[0], row[1], row[8]), (m.name, m.what, m.sources));
        assert_eq!(si(row[2], "Pa"), Some(m.youngs_modulus), "{}", m.name);
        assert_eq!(si(row[3], ""), Some(m.poisson_ratio), "{}", m.name);
        assert_eq!(si(row[4], "Pa"), m.strength.yield_strength, "{}", m.name);
        assert_eq!(si(row[5], "Pa"), m.strength.hardness, "{}", m.name);
        let k: f64 = row[6].trim_end_matches(" mm3/Nm").parse().unwrap();
        assert!(
            (k * MM3_PER_NM - m.wear_rate).abs() <= 1e-12 * m.wear_rate,
            "{}",
            m.name
        );
        assert_eq!(si(row[7], ""), Some(m.friction), "{}", m.name);
    }
}

#[test]
fn the_wear_rates_agree_with_archards_coefficients_and_hardnesses() {
    // Archard (1953), pin-on-ring, dry: K = 7e-3 for mild steel on mild steel with H = 186
    // kgf/mm^2, K = 2.5e-5 for PTFE on tool steel with H = 5 kgf/mm^2; k = K/H, and the table
    // keeps one significant figure
    let kgf_per_mm2 = 9.80665e6;
    for (name, archard, hardness) in [("mild steel", 7e-3, 186.0), ("PTFE", 2.5e-5, 5.0)] {
        let k = archard / (hardness * kgf_per_mm2);
        let m = named(name).unwrap();
        assert!(
            (m.wear_rate / k - 1.0).abs() < 0.05,
            "{name}: {} against {k:e}",
            m.wear_rate
        );
    }
}

const HEAD: &str = "schema = 1\nproblem = \"plane\"\n";
/// After the sections a test writes, so that their lines count from `HEAD`.
const PLANE: &str = "[plane]\nmodel = \"wide\"\nradius = 0.01\nload = 1e4\n";

#[test]
fn a_named_material_fills_what_the_file_does_not_write() {
    let ptfe = named("PTFE").unwrap();
    let p = parse(
        &format!("{HEAD}[material]\nname = \"PTFE\"\nthickness = \"2 mm\"\n{PLANE}"),
        Path::new("a.toml"),
    )
    .unwrap();
    assert_eq!(p.material.youngs_modulus, ptfe.youngs_modulus);
    assert_eq!(p.material.poisson_ratio, ptfe.poisson_ratio);
    assert_eq!(p.strength, ptfe.strength);
    // a value written beside the name overrides the table's; a written strength replaces both
    let p = parse(
        &format!(
            "{HEAD}[material]\nname = \"ptfe\"\nyoungs_modulus = \"1 GPa\"\nthickness = 1e-3\n\
             hardness = \"0.1 GPa\"\n{PLANE}"
        ),
        Path::new("a.toml"),
    )
    .unwrap();
    assert_eq!(p.material.youngs_modulus, 1e9);
    assert_eq!(p.material.poisson_ratio, ptfe.poisson_ratio);
    assert_eq!(
        (p.strength.yield_strength, p.strength.hardness),
        (None, Some(1e8))
    );
}

#[test]
fn a_name_not_in_the_table_or_a_missing_modulus_is_refused_at_its_line() {
    let err = parse(
        &format!("{HEAD}[material]\nname = \"unobtainium\"\nthickness = 1e-3\n{PLANE}"),
        Path::new("a.toml"),
    )
    .unwrap_err()
    .to_string();
    assert!(
        err.starts_with("a.toml:4: material.name = \"unobtainium\" is not in"),
        "{err}"
    );
    assert!(err.contains("\"PTFE\""), "{err}");
    let err = parse(
        &format!("{HEAD}[material]\npoisson_ratio = 0.3\nthickness = 1e-3\n{PLANE}"),
        Path::new("a.toml"),
    )
    .unwrap_err()
    .to_string();
    assert!(
        err.contains("[material] needs material.youngs_modulus"),
        "{err}"
    );
    assert!(err.starts_with("a.toml:"), "{err}");
}

#[test]
fn archards_coefficient_is_k_times_the_hardness() {
    let material = "[material]\nyoungs_modulus = 1e9\npoisson_ratio = 0.3\nthickness = 1e-3\n";
    let with = |wear: &str, hardness: &str| {
        parse(
            &format!("{HEAD}{material}{hardness}[wear]\n{wear}\n{PLANE}"),
            Path::new("a.toml"),
        )
    };
    // k = K/H: 1e-4 / 1 GPa = 1e-13 1/Pa = 1e-4 mm3/Nm
    let p = with("archard_coefficient = 1e-4", "hardness = \"1 GPa\"\n").unwrap();
    assert!((p.wear - 1e-13).abs() < 1e-28, "{}", p.wear);
    let err = with("archard_coefficient = 1e-4", "")
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("a.toml:8: wear.archard_coefficient is K = k H"),
        "{err}"
    );
    let err = with(
        "coefficient = 1e-13\narchard_coefficient = 1e-4",
        "hardness = 1e9\n",
    )
    .unwrap_err()
    .to_string();
    assert!(err.contains("give the wear coefficient once"), "{err}");
    // the registry's K row reads and sets the same law
    let p = p
        .with_settings(&["wear.archard_coefficient=2e-4", "material.name=PEEK"])
        .unwrap();
    let peek = named("PEEK").unwrap();
    assert_eq!(p.material.youngs_modulus, peek.youngs_modulus);
    assert!((p.wear - 2e-13).abs() < 1e-28, "{}", p.wear);
    let bare = with("coefficient = 1e-13", "").unwrap();
    let err = bare
        .with_settings(&["wear.archard_coefficient=1e-4"])
        .unwrap_err();
    assert!(
        err.contains("needs") || err.contains("give material.hardness"),
        "{err}"
    );
}
