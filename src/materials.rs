//! The bundled materials table: typical properties of common strip and coating materials, each
//! with its sources (docs/references.md, "Materials"), that presets name (`material.name`) and the
//! explorer's form offers on its material row. Elastic constants and strengths are handbook
//! values at room temperature; the wear rates and friction coefficients against steel are one
//! significant figure for dry sliding and vary tenfold with the conditions (speed, temperature,
//! humidity, counterface roughness): a starting point to be replaced by a measurement.

use crate::physics::plane::yield_onset::Strength;

/// One entry of the table. All values SI.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MaterialEntry {
    /// The name presets use (`material.name = "PTFE"`), unique in the table.
    pub name: &'static str,
    /// What it is, in a few words.
    pub what: &'static str,
    /// Young's modulus E [Pa].
    pub youngs_modulus: f64,
    /// Poisson's ratio nu [-].
    pub poisson_ratio: f64,
    /// Yield strength in tension and indentation hardness [Pa], where the material has them (an
    /// elastomer has neither: it does not yield).
    pub strength: Strength,
    /// Typical specific wear rate against steel, dry, k [1/Pa] (= m^3/(N m); 1 mm^3/(N m) =
    /// 1e-9 1/Pa).
    pub wear_rate: f64,
    /// Typical friction coefficient against steel, dry, mu [-].
    pub friction: f64,
    /// Where the values come from, as cited in docs/references.md.
    pub sources: &'static str,
}

const GPA: f64 = 1e9;
const MPA: f64 = 1e6;
/// 1 mm^3/(N m) in 1/Pa.
pub const MM3_PER_NM: f64 = 1e-9;

const fn entry(
    [name, what, sources]: [&'static str; 3],
    [youngs_modulus, poisson_ratio]: [f64; 2],
    [yield_strength, hardness]: [Option<f64>; 2],
    [wear_rate, friction]: [f64; 2],
) -> MaterialEntry {
    MaterialEntry {
        name,
        what,
        youngs_modulus,
        poisson_ratio,
        strength: Strength {
            yield_strength,
            hardness,
        },
        wear_rate,
        friction,
        sources,
    }
}

/// Entries in the table.
pub const COUNT: usize = 9;

/// The table.
#[rustfmt::skip]
pub const MATERIALS: [MaterialEntry; COUNT] = [
    entry(["AISI 52100", "hardened bearing steel (~60 HRC)", "Ashby (2011); Hutchings & Shipway (2017)"],
        [210.0 * GPA, 0.30], [None, Some(7.5 * GPA)], [1e-6 * MM3_PER_NM, 0.6]),
    entry(["mild steel", "low-carbon steel, as rolled", "Archard (1953); Ashby (2011)"],
        [205.0 * GPA, 0.29], [None, Some(1.8 * GPA)], [4e-3 * MM3_PER_NM, 0.6]),
    entry(["phosphor bronze", "CuSn8 bearing bronze", "Ashby (2011); Hutchings & Shipway (2017)"],
        [110.0 * GPA, 0.34], [None, Some(1.2 * GPA)], [1e-5 * MM3_PER_NM, 0.3]),
    entry(["PTFE", "unfilled polytetrafluoroethylene", "Archard (1953); Ashby (2011); Blanchet & Kennedy (1992)"],
        [0.5 * GPA, 0.46], [Some(12.0 * MPA), Some(0.05 * GPA)], [5e-4 * MM3_PER_NM, 0.1]),
    entry(["UHMWPE", "ultra-high molecular weight polyethylene", "Ashby (2011); Hutchings & Shipway (2017)"],
        [0.7 * GPA, 0.46], [Some(21.0 * MPA), Some(0.06 * GPA)], [1e-6 * MM3_PER_NM, 0.15]),
    entry(["PEEK", "unfilled polyetheretherketone", "Ashby (2011); Hutchings & Shipway (2017)"],
        [3.6 * GPA, 0.40], [Some(95.0 * MPA), Some(0.27 * GPA)], [1e-5 * MM3_PER_NM, 0.35]),
    entry(["PA66", "polyamide 66, dry as moulded", "Ashby (2011); Hutchings & Shipway (2017)"],
        [2.8 * GPA, 0.40], [Some(80.0 * MPA), Some(0.15 * GPA)], [1e-5 * MM3_PER_NM, 0.4]),
    entry(["NBR", "nitrile rubber, ~70 Shore A (no yield)", "Ashby (2011); Hutchings & Shipway (2017)"],
        [5.0 * MPA, 0.49], [None, None], [1e-3 * MM3_PER_NM, 1.0]),
    entry(["DLC", "hydrogenated amorphous carbon coating (a-C:H)", "Robertson (2002); Erdemir & Donnet (2006)"],
        [150.0 * GPA, 0.25], [None, Some(15.0 * GPA)], [1e-7 * MM3_PER_NM, 0.1]),
];

/// The names a form offers: "custom" (the values typed in the form or written in the preset, not
/// a material's of the table) first, then the table's.
pub const CHOICES: [&str; COUNT + 1] = {
    let mut names = [CUSTOM; COUNT + 1];
    let mut i = 0;
    while i < COUNT {
        names[i + 1] = MATERIALS[i].name;
        i += 1;
    }
    names
};

/// The choice of values that are not a material's of the table.
pub const CUSTOM: &str = "custom";

/// The entry named `name` (any case), or None.
pub fn named(name: &str) -> Option<&'static MaterialEntry> {
    MATERIALS
        .iter()
        .find(|m| m.name.eq_ignore_ascii_case(name.trim()))
}

/// The entry whose elastic constants and strengths are exactly these, or None (values typed or
/// edited since a material was chosen).
pub fn matching(youngs_modulus: f64, poisson_ratio: f64, strength: Strength) -> Option<usize> {
    MATERIALS.iter().position(|m| {
        m.youngs_modulus == youngs_modulus
            && m.poisson_ratio == poisson_ratio
            && m.strength == strength
    })
}

/// The table's names, for messages: `"AISI 52100", "mild steel", ...`.
pub fn names() -> String {
    MATERIALS
        .iter()
        .map(|m| format!("\"{}\"", m.name))
        .collect::<Vec<_>>()
        .join(", ")
}
