//! The presets that ship inside the binary (the files of `presets/`), the default first.

use std::path::Path;

use crate::preset::{Preset, PresetError, parse};

/// A preset that ships inside the binary.
#[derive(Clone, Copy, Debug)]
pub struct Bundled {
    /// File name, e.g. "hertz-check.toml".
    pub file: &'static str,
    /// The file's text.
    pub text: &'static str,
}

macro_rules! bundled {
    ($($file:literal),* $(,)?) => {
        &[$(Bundled { file: $file, text: include_str!(concat!("../../presets/", $file)) }),*]
    };
}

/// The bundled presets, the default first.
pub const BUNDLED: &[Bundled] = bundled![
    "polymer-coating.toml",
    "hertz-check.toml",
    "friction-half-plane.toml",
    "wear-dominated.toml",
    "thin-strip-winkler.toml",
    "hard-coating-strip.toml",
    "jgh-egg-box.toml",
    "wave-thick-layer.toml",
    "rubber-backward-drift.toml",
    "dispersion.toml",
    "contact-lost.toml",
    "rubber-running-in.toml",
    "coating-thickness-sweep.toml",
    "friction-or-wear-map.toml",
    "flat-pin-coating.toml",
    "rough-thin-layer.toml",
    "worn-pin-profile.toml",
    "wear-law-squared.toml",
    "polymer-shear-strength.toml",
    "energy-split.toml",
    "sharp-flat-punch.toml",
    "ground-profile.toml",
    "lab-friction.toml",
];

/// The data files that bundled presets name (`spatial.surface.file`, `plane.shape.file`,
/// `explore.data`), built into the binary beside them.
pub const BUNDLED_DATA: &[Bundled] =
    bundled!["worn-pin.csv", "ground-profile.csv", "lab-friction.csv"];

/// The text of `file` named by the preset at `preset` when that is a bundled preset
/// (`presets/<file>`, as `Bundled::load` names it) and `file` a bundled data file.
pub(super) fn bundled_data(preset: &Path, file: &str) -> Option<&'static str> {
    let bundled = preset.parent() == Some(Path::new("presets"))
        && BUNDLED
            .iter()
            .any(|b| preset.file_name() == Some(b.file.as_ref()));
    BUNDLED_DATA
        .iter()
        .find(|d| bundled && d.file == file)
        .map(|d| d.text)
}

impl Bundled {
    /// Parses the bundled text (its path in messages is `presets/<file>`).
    pub fn load(&self) -> Result<Preset, PresetError> {
        parse(self.text, &Path::new("presets").join(self.file))
    }
}

/// The bundled preset of that file name, parsed (None for an unknown name).
pub fn bundled(file: &str) -> Option<Result<Preset, PresetError>> {
    BUNDLED.iter().find(|b| b.file == file).map(Bundled::load)
}

/// The built-in default preset (the first bundled one).
pub fn default_preset() -> Preset {
    BUNDLED[0]
        .load()
        .expect("the bundled default preset is valid (tested)")
}
