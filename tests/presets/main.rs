//! Preset files: the bundled ones, the parameter registry, the `[explore]` section, broken and
//! fuzzed files, and saving.

mod explore_section;
mod general_presets;
mod hostile_save;
mod kept_text;
mod materials;
mod params;
mod plane_descriptions;
mod preset_fuzz;
mod preset_multibyte;
mod presets;
mod spatial_descriptions;
mod surfaces;
