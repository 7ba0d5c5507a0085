//! Saving a preset that was opened from a file: the author's text kept, only the values that
//! changed rewritten (`text_edit`), and the data files it names (a measured profile, a height
//! map; relative to the preset's folder) named so that the saved file finds them from its own
//! folder.

use std::io::Write;
use std::path::{Component, Path, PathBuf};
use std::sync::Arc;

use crate::physics::plane::Shape;
use crate::physics::plane::shape::Table;
use crate::physics::spatial::surface::{SurfaceShape, SurfaceSource};
use crate::preset::{Preset, Problem, disk, parse, text_edit, to_toml};

/// The file a preset was opened from (or last saved to) and the preset it read as.
#[derive(Clone, Debug, PartialEq)]
pub struct Origin {
    /// The file.
    pub path: PathBuf,
    /// The preset it held.
    pub preset: Preset,
}

/// Saves `preset` atomically to `path` (doing `links` with a symbolic link there). With an
/// origin whose file still reads as its preset, the file's text is kept and only the values
/// that changed are rewritten; else the preset is written as `to_toml` writes it. Ok holds the
/// preset as saved (its data files named from `path`'s folder) and the file a link led to that
/// the save left as it was.
pub fn save_edited(
    preset: &Preset,
    origin: Option<&Origin>,
    path: &Path,
    links: disk::Links,
) -> std::io::Result<(Preset, Option<PathBuf>)> {
    let (text, saved) = saved_text(preset, origin, path);
    let kept = disk::write_atomically(path, links, |f| f.write_all(text.as_bytes()))?;
    Ok((saved, kept))
}

/// The text a save of `preset` to `path` writes, and the preset it reads as.
pub fn saved_text(preset: &Preset, origin: Option<&Origin>, path: &Path) -> (String, Preset) {
    let Some(origin) = origin else {
        return (to_toml(preset), preset.clone());
    };
    let after = data_files_moved(preset, folder(&origin.path), folder(path));
    let text = (disk::read_text(&origin.path).ok())
        .filter(|t| parse(t, &origin.path).is_ok_and(|p| p == origin.preset));
    if let Some(mut text) = text {
        let mut before = origin.preset.clone();
        // a key the file leaves to a default that follows other values (the duration follows
        // the wear) is written on the second pass, where the first one read differently
        for _ in 0..2 {
            let Some(next) = text_edit::edited(&text, &before, &after) else {
                break;
            };
            match parse(&next, path) {
                Ok(read) if reads_as(&read, &after) => return (next, after),
                Ok(read) => (text, before) = (next, read),
                Err(_) => break,
            }
        }
    }
    (to_toml(&after), after)
}

/// Whether a saved file that reads as `read` holds `preset`: the same inputs, the spatial
/// duration apart in a plane preset (a file without a `[spatial]` section gets the default
/// duration of its wear, which the plane problem does not use).
fn reads_as(read: &Preset, preset: &Preset) -> bool {
    let mut expected = preset.clone();
    if preset.problem == Problem::Plane {
        expected.spatial.duration = read.spatial.duration;
    }
    *read == expected
}

/// `preset` with the names of its data files taken from `saved` (the same preset as saved
/// elsewhere, its data files named from the new folder).
pub fn with_data_files_of(preset: &Preset, saved: &Preset) -> Preset {
    let mut out = preset.clone();
    if let (Some(Shape::Table(mine)), Some(Shape::Table(theirs))) =
        (&preset.plane.shape, &saved.plane.shape)
        && mine.spline == theirs.spline
    {
        out.plane.shape = Some(Shape::Table(Arc::clone(theirs)));
    }
    if let (Some(mine), Some(theirs)) = (&preset.plane.measured, &saved.plane.measured)
        && mine.spline == theirs.spline
    {
        out.plane.measured = Some(Arc::clone(theirs));
    }
    if let (Some(mine), Some(theirs)) = (&preset.spatial.surface, &saved.spatial.surface)
        && mine.surface == theirs.surface
        && matches!(mine.source, SurfaceSource::File { .. })
    {
        out.spatial.surface = Some(Arc::clone(theirs));
    }
    out
}

/// The folder of a file ("." for a bare name).
fn folder(path: &Path) -> &Path {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    }
}

/// `preset` with its data files, named relative to the folder `from`, named from `to`.
fn data_files_moved(preset: &Preset, from: &Path, to: &Path) -> Preset {
    let mut out = preset.clone();
    let table_moved = |t: &Arc<Table>| {
        Arc::new(Table {
            file: moved(&t.file, from, to),
            spline: t.spline.clone(),
        })
    };
    if let Some(Shape::Table(t)) = &preset.plane.shape {
        out.plane.shape = Some(Shape::Table(table_moved(t)));
    }
    // the profile the form can return to is named from the new folder too
    out.plane.measured = preset.plane.measured.as_ref().map(table_moved);
    if let Some(s) = &preset.spatial.surface
        && let SurfaceSource::File {
            file,
            length_x,
            length_y,
        } = &s.source
    {
        out.spatial.surface = Some(Arc::new(SurfaceShape {
            source: SurfaceSource::File {
                file: moved(file, from, to),
                length_x: *length_x,
                length_y: *length_y,
            },
            surface: s.surface.clone(),
        }));
    }
    out
}

/// `file`, named relative to the folder `from`, as named from the folder `to`: as it is when it
/// is absolute or the folders are one; else relative to `to`, or absolute where no relative
/// path leads (another drive).
pub(super) fn moved(file: &str, from: &Path, to: &Path) -> String {
    let named = Path::new(file);
    let (Ok(from), Ok(to)) = (std::fs::canonicalize(from), std::fs::canonicalize(to)) else {
        return file.to_string();
    };
    if named.is_absolute() || from == to {
        return file.to_string();
    }
    let target =
        std::fs::canonicalize(from.join(named)).unwrap_or_else(|_| lexical(&from.join(named)));
    let (t, f): (Vec<Component>, Vec<Component>) =
        (target.components().collect(), to.components().collect());
    let common = t.iter().zip(&f).take_while(|(a, b)| a == b).count();
    let out: PathBuf = if common == 0 {
        target.clone()
    } else {
        (f[common..].iter().map(|_| Component::ParentDir))
            .chain(t[common..].iter().copied())
            .collect()
    };
    out.to_str()
        .map_or_else(|| file.to_string(), str::to_string)
}

/// A path with its `.` and `..` parts resolved by their names (for a file that does not exist).
fn lexical(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for part in path.components() {
        match part {
            Component::CurDir => {}
            Component::ParentDir => {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out
}
