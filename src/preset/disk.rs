//! Preset files on disk, read and written defensively: only regular files of at most
//! `MAX_PRESET_BYTES` are read (a FIFO or a device is refused before it is opened, and the open
//! cannot block), text must be UTF-8; a save replaces the file atomically, writes through a
//! symbolic link to a target the user may write (a link to a file they cannot write, such as a
//! teacher's shared preset, is replaced by their own copy and the file stays as it was), keeps
//! the mode of the file it replaces, and removes the temporary files an interrupted save of ours
//! left behind.

use std::fs::{self, File, OpenOptions};
use std::io::{self, Read, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, SystemTime};

use crate::preset::PresetError;

/// The largest preset file read [bytes]: a preset with 64 harmonics is about 12 kB.
pub const MAX_PRESET_BYTES: u64 = 256 * 1024;
/// The prefix of the temporary files of a save.
const TEMP_PREFIX: &str = ".wearlab-save-";
/// A temporary file of ours this old is left over from an interrupted save.
const STALE_AFTER: Duration = Duration::from_secs(10);
/// The most symbolic links followed from a saved path to its target.
const MAX_LINKS: usize = 40;

fn refused(path: &Path, line: Option<usize>, reason: String) -> PresetError {
    PresetError {
        path: path.to_path_buf(),
        line,
        reason,
    }
}

/// What a non-regular file is, in words.
fn kind(meta: &fs::Metadata) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        let t = meta.file_type();
        if t.is_fifo() {
            return "a named pipe (FIFO)";
        }
        if t.is_char_device() || t.is_block_device() {
            return "a device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if meta.is_dir() {
        "a folder"
    } else {
        "not a regular file"
    }
}

fn open_without_blocking(path: &Path) -> io::Result<File> {
    let mut options = OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        // a FIFO swapped in after the check must not block the open
        options.custom_flags(libc::O_NONBLOCK);
    }
    options.open(path)
}

/// The text of a preset file: a regular file (checked before and after opening) of at most
/// `MAX_PRESET_BYTES`, in UTF-8 (else `path:line: reason` at the first bad byte).
pub fn read_text(path: &Path) -> Result<String, PresetError> {
    let cannot = |e: io::Error| refused(path, None, format!("cannot read the file: {e}"));
    let check = |meta: &fs::Metadata| {
        if !meta.is_file() {
            return Err(refused(
                path,
                None,
                format!(
                    "not a preset file: it is {}, and wearlab reads only regular files",
                    kind(meta)
                ),
            ));
        }
        if meta.len() > MAX_PRESET_BYTES {
            return Err(too_large(path));
        }
        Ok(())
    };
    check(&fs::metadata(path).map_err(cannot)?)?;
    let file = open_without_blocking(path).map_err(cannot)?;
    check(&file.metadata().map_err(cannot)?)?;
    let mut bytes = Vec::new();
    file.take(MAX_PRESET_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    if bytes.len() as u64 > MAX_PRESET_BYTES {
        return Err(too_large(path));
    }
    String::from_utf8(bytes).map_err(|e| {
        let good = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        let line = 1 + good.iter().filter(|&&b| b == b'\n').count();
        let column = 1 + good.iter().rev().take_while(|&&b| b != b'\n').count();
        refused(
            path,
            Some(line),
            format!(
                "the file is not UTF-8 text (byte 0x{:02x} at column {column}); a preset is a \
                 TOML text file",
                e.as_bytes()[good.len()]
            ),
        )
    })
}

fn too_large(path: &Path) -> PresetError {
    refused(
        path,
        None,
        format!(
            "the file is larger than {} kB, the most a preset file may be",
            MAX_PRESET_BYTES / 1024
        ),
    )
}

/// What a save does with a symbolic link at the path it writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Links {
    /// Writes the file the link leads to, when the user may replace it (else as `Replace`).
    Follow,
    /// Replaces the link by the saved file: the file it led to stays as it was.
    Replace,
}

/// The file a save to `path` writes: `path` itself, or with `Links::Follow` the target its
/// symbolic links lead to (a relative link is relative to the link's folder) when the user may
/// replace it; and the file a link led to that the save leaves as it was (the link replaced by
/// the saved file), if any.
fn save_target(path: &Path, links: Links) -> io::Result<(PathBuf, Option<PathBuf>)> {
    let target = match links {
        Links::Follow => link_target(path)?,
        Links::Replace => match link_target(path) {
            Ok(target) => target,
            Err(_) => return Ok((path.to_path_buf(), None)),
        },
    };
    if target == path || (links == Links::Follow && writable(&target)) {
        return Ok((target, None));
    }
    let kept = target.exists().then_some(target);
    Ok((path.to_path_buf(), kept))
}

/// Whether `path` is a symbolic link (possibly through others) to a file in one of `folders`.
pub fn leads_into(path: &Path, folders: &[PathBuf]) -> bool {
    let canonical = |p: &Path| fs::canonicalize(p).ok();
    let Some(target) = link_target(path).ok().filter(|t| t != path) else {
        return false;
    };
    let Some(dir) = target.parent().and_then(canonical) else {
        return false;
    };
    folders
        .iter()
        .any(|f| canonical(f).is_some_and(|f| dir.starts_with(f)))
}

/// Whether the user may replace the file at `path`: write it and write in its folder (where the
/// saved file is renamed over it).
fn writable(path: &Path) -> bool {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    #[cfg(unix)]
    {
        use std::os::unix::ffi::OsStrExt;
        let may_write = |p: &Path| {
            std::ffi::CString::new(p.as_os_str().as_bytes())
                // SAFETY: access only reads the NUL-terminated path it is given
                .is_ok_and(|c| unsafe { libc::access(c.as_ptr(), libc::W_OK) } == 0)
        };
        (!path.exists() || may_write(path)) && may_write(dir)
    }
    #[cfg(not(unix))]
    {
        fs::metadata(path).map_or(true, |m| !m.permissions().readonly())
            && fs::metadata(dir).is_ok_and(|m| !m.permissions().readonly())
    }
}

/// The file `path`'s symbolic links lead to (`path` itself when it is none).
fn link_target(path: &Path) -> io::Result<PathBuf> {
    let mut at = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        match fs::symlink_metadata(&at) {
            Ok(meta) if meta.file_type().is_symlink() => {
                let next = fs::read_link(&at)?;
                at = match at.parent() {
                    Some(dir) if next.is_relative() => dir.join(next),
                    _ => next,
                };
            }
            _ => return Ok(at),
        }
    }
    Err(io::Error::other(format!(
        "more than {MAX_LINKS} symbolic links lead from {}",
        path.display()
    )))
}

/// Removes the temporary files of ours (same prefix, same owner as `fresh`, a regular file) that
/// an interrupted save left in `dir`: those last modified more than `STALE_AFTER` ago. A save in
/// progress writes its file continually, so it is never that old. Failures are ignored: the
/// cleanup must not stop a save.
fn remove_stale(dir: &Path, fresh: &fs::Metadata, keep: &Path) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    let now = SystemTime::now();
    for entry in entries.flatten() {
        let path = entry.path();
        let ours = entry
            .file_name()
            .to_str()
            .is_some_and(|n| n.starts_with(TEMP_PREFIX));
        let Ok(meta) = entry.metadata() else {
            continue;
        };
        let stale = meta
            .modified()
            .ok()
            .and_then(|m| now.duration_since(m).ok())
            .is_some_and(|age| age > STALE_AFTER);
        if ours && stale && meta.is_file() && same_owner(&meta, fresh) && path != keep {
            let _ = fs::remove_file(&path);
        }
    }
}

fn same_owner(a: &fs::Metadata, b: &fs::Metadata) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        a.uid() == b.uid()
    }
    #[cfg(not(unix))]
    {
        let _ = (a, b);
        true
    }
}

/// Writes `path` atomically: the bytes go to a temporary file in the folder of the file that is
/// replaced (the target of `path`'s links, as `links` says), which gets that file's mode, is
/// synced and then renamed over it. If `write` fails, the old file is untouched and the
/// temporary file removed. Ok holds the file a link led to that the save left as it was.
pub fn write_atomically(
    path: &Path,
    links: Links,
    write: impl FnOnce(&mut File) -> io::Result<()>,
) -> io::Result<Option<PathBuf>> {
    let (target, kept) = save_target(path, links)?;
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut builder = tempfile::Builder::new();
    builder.prefix(TEMP_PREFIX);
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        // a new file gets the usual mode (0666 less the umask), not the 0600 of a temporary file
        builder.permissions(fs::Permissions::from_mode(0o666));
    }
    // the temporary file is ours, not the user's: a failure names the folder it was made in
    let mut tmp = builder.tempfile_in(dir).map_err(|e| {
        io::Error::new(
            e.kind(),
            format!(
                "cannot write in the folder {}: {}",
                dir.display(),
                io::Error::from(e.kind())
            ),
        )
    })?;
    remove_stale(dir, &tmp.as_file().metadata()?, tmp.path());
    if let Ok(old) = fs::metadata(&target) {
        tmp.as_file().set_permissions(old.permissions())?;
    }
    write(tmp.as_file_mut())?;
    tmp.as_file_mut().flush()?;
    tmp.as_file().sync_all()?;
    tmp.persist(&target).map_err(|e| e.error)?;
    Ok(kept)
}
