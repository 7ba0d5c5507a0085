//! The loop's I/O, carried out for `update`'s commands and reported back as messages: listing
//! the presets, saving, exporting, answering a lesson's questions.

use std::io::Write;
use std::path::{Path, PathBuf};

use crate::preset::{self, BUNDLED, BUNDLED_DATA, Links, Origin, Preset, SaveTarget};

use crate::tui::app::{Msg, PickerEntry, Places};

/// The heading of the bundled presets in the picker.
pub const BUNDLED_HEADING: &str = "bundled with wearlab";

/// The picker's entries: the bundled presets, then the `.toml` files of each shared folder, then
/// those of the user's folder (each folder once, under its path), each titled by its file and
/// its name ("hertz-check.toml: Hertz check: ..."): a saved copy keeps the name it was made from.
pub fn list_presets(places: &Places) -> Msg {
    let mut out: Vec<PickerEntry> = BUNDLED
        .iter()
        .map(|b| {
            let p = b.load().map_err(|e| e.to_string());
            let mut e = entry(format!("bundled: {}", b.file), None, p, BUNDLED_HEADING);
            e.title = format!("{}: {}", b.file, e.title);
            e
        })
        .collect();
    // each folder once; the user's own is listed last, as theirs, even when also shared
    let canonical = |f: &Path| std::fs::canonicalize(f).unwrap_or_else(|_| f.to_path_buf());
    let mine = places.presets.as_deref();
    let mut seen: Vec<PathBuf> = mine.map(canonical).into_iter().collect();
    let mut folders: Vec<(&Path, String)> = Vec::new();
    for f in &places.shared {
        if !seen.contains(&canonical(f)) {
            seen.push(canonical(f));
            folders.push((f.as_path(), format!("shared: {}", f.display())));
        }
    }
    folders.extend(mine.map(|f| (f, format!("your presets: {}", f.display()))));
    for (folder, heading) in folders {
        let Ok(read) = std::fs::read_dir(folder) else {
            continue;
        };
        let mut files: Vec<PathBuf> = read
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        files.sort();
        out.extend(files.into_iter().map(|path| read_entry(&path, &heading)));
    }
    Msg::PresetsListed(out)
}

/// The data file at the first of `paths` that exists, read for `preset`; else a bundled data
/// file named `presets/<file>` among them, else the first path (to say it cannot be read).
pub fn read_data(paths: &[PathBuf], preset: &Preset) -> Msg {
    let on_disk = paths.iter().find(|p| p.exists());
    let bundled = || {
        paths.iter().find_map(|p| {
            let file = p.file_name()?.to_str()?;
            let d = BUNDLED_DATA.iter().find(|d| d.file == file)?;
            (p.parent() == Some(Path::new("presets"))).then_some((p, d.text))
        })
    };
    let read = match (on_disk, bundled()) {
        (Some(path), _) => crate::data::read(path, preset),
        (None, Some((path, text))) => crate::data::read_text(path, text, preset),
        (None, None) => match paths.first() {
            Some(path) => crate::data::read(path, preset),
            None => return Msg::DataRead(Err("no data file named".into())),
        },
    };
    Msg::DataRead(read.map(Box::new).map_err(|e| e.to_string()))
}

/// The preset file at `path`, typed in the picker.
pub fn read_preset(path: PathBuf) -> Msg {
    let folder = path
        .parent()
        .map_or_else(String::new, |f| f.display().to_string());
    Msg::PresetRead(Box::new(read_entry(&path, &folder)))
}

/// A file's entry, titled by its file and its name.
fn read_entry(path: &Path, heading: &str) -> PickerEntry {
    let p = preset::load(path).map_err(|e| e.to_string());
    let mut e = entry(
        path.display().to_string(),
        Some(path.to_path_buf()),
        p,
        heading,
    );
    let file = path.file_name().unwrap_or_default().to_string_lossy();
    e.title = format!("{file}: {}", e.title);
    e
}

/// An entry titled by its preset's name ("(unreadable)" when it cannot be read).
fn entry(
    source: String,
    path: Option<PathBuf>,
    preset: Result<Preset, String>,
    heading: &str,
) -> PickerEntry {
    PickerEntry {
        title: preset
            .as_ref()
            .map_or_else(|_| "(unreadable)".to_string(), |p| p.name.clone()),
        source,
        path,
        preset,
        folder: heading.to_string(),
    }
}

/// Saves `preset` to the target: refuses a missing folder (except the user's preset folder,
/// which is created), asks about an existing file unless `overwrite`. A symbolic link to a file
/// in one of the `shared` folders, or to a file the user may not replace, is replaced by the
/// user's own copy, and the file stays as it was.
pub fn save(
    target: SaveTarget,
    mut preset: Box<Preset>,
    overwrite: bool,
    origin: Option<Box<Origin>>,
    shared: &[PathBuf],
) -> Msg {
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
        let links = if preset::leads_into(path, shared) {
            Links::Replace
        } else {
            Links::Follow
        };
        std::fs::create_dir_all(&folder)
            .map_err(|e| format!("cannot create {}: {e}", folder.display()))
            .and_then(|()| {
                preset::save_edited(&preset, origin.as_deref(), path, links)
                    .map_err(|e| format!("{}: {e}", path.display()))
            })
            .map(|(saved, kept)| {
                *preset = saved;
                kept
            })
            .map(|kept| match kept {
                Some(original) => format!(
                    "saved {} as your own copy: it was a link to {}, which stays as it was",
                    path.display(),
                    original.display()
                ),
                None => format!("saved {}", path.display()),
            })
    };
    Msg::Saved(target, preset, result)
}

/// Writes an export atomically; asks about an existing file unless `overwrite`.
pub fn export(path: PathBuf, text: String, overwrite: bool) -> Msg {
    if !overwrite && path.exists() {
        return Msg::ExportExists(path, text);
    }
    let written = preset::write_atomically(&path, Links::Follow, |f| f.write_all(text.as_bytes()));
    let result = written.map(|_| ()).map_err(|e| e.to_string());
    // the message names the folder too: a relative name is relative to where wearlab started
    let shown = std::path::absolute(&path).unwrap_or(path);
    Msg::Exported(shown, result)
}

/// The program's answers to the preset's lesson questions, each at the question's inputs, as
/// `wearlab check` computes them (a spatial preset in partial contact runs its running-in here).
pub fn answer_lesson(preset: Preset) -> Msg {
    let values = (preset.lesson.iter())
        .flat_map(|l| &l.questions)
        .map(|q| q.solve(&preset).map_err(|e| e.to_string()))
        .collect();
    Msg::LessonAnswered(Box::new(preset), values)
}
