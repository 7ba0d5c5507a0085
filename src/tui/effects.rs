//! The loop's I/O, carried out for `update`'s commands and reported back as messages: listing
//! the presets, saving, exporting.

use std::io::Write;
use std::path::{Path, PathBuf};

use crate::preset::{self, BUNDLED, Preset, SaveTarget};

use crate::tui::app::{Msg, PickerEntry};

/// The picker's entries: the bundled presets, then the `.toml` files of the user's folder, each
/// titled by its file and its name ("my lab.toml: Hertz check: ...").
pub fn list_presets(user_dir: Option<&Path>) -> Msg {
    let entry = |title_if_broken: &str, source, path, preset: Result<Preset, String>| PickerEntry {
        title: preset
            .as_ref()
            .map_or_else(|_| title_if_broken.to_string(), |p| p.name.clone()),
        source,
        path,
        preset,
    };
    let mut out: Vec<PickerEntry> = BUNDLED
        .iter()
        .map(|b| {
            let p = b.load().map_err(|e| e.to_string());
            entry(b.file, format!("bundled: {}", b.file), None, p)
        })
        .collect();
    if let Some(Ok(read)) = user_dir.map(std::fs::read_dir) {
        let mut files: Vec<PathBuf> = read
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        files.sort();
        for path in files {
            let p = preset::load(&path).map_err(|e| e.to_string());
            let source = path.display().to_string();
            let mut e = entry("(unreadable)", source, Some(path.clone()), p);
            // the file first: a saved copy of a bundled preset keeps its name
            let file = path.file_name().unwrap_or_default().to_string_lossy();
            e.title = format!("{file}: {}", e.title);
            out.push(e);
        }
    }
    Msg::PresetsListed(out)
}

/// Saves `preset` to the target: refuses a missing folder (except the user's preset folder,
/// which is created), asks about an existing file unless `overwrite`.
pub fn save(target: SaveTarget, preset: Box<Preset>, overwrite: bool) -> Msg {
    let path = &target.path;
    let folder = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let result = if !folder.is_dir() && !target.create_folder {
        Err(format!(
            "the folder {} does not exist (wearlab creates only its own preset folder)",
            folder.display()
        ))
    } else if path.is_dir() {
        Err(format!("{} is a folder", path.display()))
    } else if path.exists() && !overwrite {
        return Msg::SaveExists(target);
    } else {
        std::fs::create_dir_all(&folder)
            .map_err(|e| format!("cannot create {}: {e}", folder.display()))
            .and_then(|()| {
                preset::save(&preset, path).map_err(|e| format!("{}: {e}", path.display()))
            })
    };
    Msg::Saved(target, preset, result)
}

/// Writes an export atomically; asks about an existing file unless `overwrite`.
pub fn export(path: PathBuf, text: String, overwrite: bool) -> Msg {
    if !overwrite && path.exists() {
        return Msg::ExportExists(path, text);
    }
    let written = preset::write_atomically(&path, |f| f.write_all(text.as_bytes()));
    let result = written.map_err(|e| e.to_string());
    Msg::Exported(path, result)
}
