//! Where a name typed in the explorer's save prompt goes: the file it names, resolved without
//! touching the file system, or why it names none.

use std::path::{Path, PathBuf};

/// Where a name typed in the explorer's save prompt goes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SaveTarget {
    /// The file.
    pub path: PathBuf,
    /// True when the folder may be created if missing: only the user's preset folder; any other
    /// folder must exist (a mistyped path is refused, not created).
    pub create_folder: bool,
}

/// Resolves a typed save name to a file, without touching the file system:
/// - `~` at the start followed by `/` is the home folder (`~/x` -> `$HOME/x.toml`);
/// - the file name gets `.toml` unless it ends in it (`x` and `x.` -> `x.toml`, `a.b` -> `a.b.toml`);
/// - a bare name goes to the user's preset folder (`preset_dir`, or the current folder without
///   one); a name with a folder stays as typed (relative to the current folder).
pub fn resolve_save_path(
    typed: &str,
    home: Option<&Path>,
    preset_dir: Option<&Path>,
) -> Result<SaveTarget, String> {
    let typed = typed.trim();
    if typed.is_empty() {
        return Err("type a file name".into());
    }
    let expanded = match typed.strip_prefix("~/") {
        Some(rest) => home
            .ok_or("~ stands for the home folder, which is unknown here: type a full path")?
            .join(rest),
        None if typed == "~" => {
            return Err("~ is a folder: type a file name, e.g. ~/lab.toml".into());
        }
        None => PathBuf::from(typed),
    };
    if let Some(c) = typed.chars().find(|c| c.is_control()) {
        return Err(format!(
            "a file name holds no {}: type the name without it",
            if c == '\t' {
                "tab"
            } else {
                "control character"
            }
        ));
    }
    // the last part as typed: `Path` reads "x/." as "x"
    let last = typed.rsplit('/').next().unwrap_or(typed);
    let before = &typed[..typed.len() - last.len()];
    let folder = match last {
        "" => Some(("it ends in /", format!("{typed}lab.toml"))),
        "." => Some(("'.' is the folder itself", format!("{before}lab.toml"))),
        ".." => Some(("'..' is the folder above", format!("{typed}/lab.toml"))),
        _ => None,
    };
    if let Some((why, example)) = folder {
        return Err(format!(
            "'{typed}' is a folder ({why}): type a file name, e.g. {example}"
        ));
    }
    let Some(name) = expanded.file_name().and_then(|n| n.to_str()) else {
        return Err(format!(
            "'{typed}' is not a file name: type one, e.g. lab.toml"
        ));
    };
    let stem = name.trim_end_matches('.');
    if stem.is_empty() {
        return Err(format!("'{typed}' has no file name: type one"));
    }
    let file = if stem.to_ascii_lowercase().ends_with(".toml") {
        stem.to_string()
    } else {
        format!("{stem}.toml")
    };
    // `file` ends in the ASCII ".toml", so the cut is at a character boundary
    if file[..file.len() - ".toml".len()]
        .trim_matches('.')
        .is_empty()
    {
        return Err(format!(
            "'{typed}' has no name before .toml (the file would be hidden): type one, e.g. \
             lab.toml"
        ));
    }
    let bare = !typed.contains('/');
    Ok(match (bare, preset_dir) {
        (true, Some(dir)) => SaveTarget {
            path: dir.join(file),
            create_folder: true,
        },
        _ => SaveTarget {
            path: expanded.with_file_name(file),
            create_folder: false,
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn resolve(typed: &str) -> Result<SaveTarget, String> {
        resolve_save_path(
            typed,
            Some(Path::new("/home/ana")),
            Some(Path::new("/data/presets")),
        )
    }

    fn path(typed: &str) -> PathBuf {
        resolve(typed).unwrap().path
    }

    #[test]
    fn a_bare_name_goes_to_the_preset_folder_with_toml() {
        assert_eq!(
            resolve("my lab 1"),
            Ok(SaveTarget {
                path: "/data/presets/my lab 1.toml".into(),
                create_folder: true
            })
        );
        assert_eq!(path("x."), PathBuf::from("/data/presets/x.toml"));
        assert_eq!(path("x.toml"), PathBuf::from("/data/presets/x.toml"));
        assert_eq!(path(" lab.v2 "), PathBuf::from("/data/presets/lab.v2.toml"));
        let here = resolve_save_path("x", None, None).unwrap();
        assert_eq!((here.path, here.create_folder), ("x.toml".into(), false));
    }

    #[test]
    fn the_home_folder_expands_and_other_folders_must_exist() {
        assert_eq!(
            resolve("~/x"),
            Ok(SaveTarget {
                path: "/home/ana/x.toml".into(),
                create_folder: false
            })
        );
        assert_eq!(path("~/labs/a."), PathBuf::from("/home/ana/labs/a.toml"));
        assert_eq!(path("/tmp/nowhere/x"), PathBuf::from("/tmp/nowhere/x.toml"));
        assert!(!resolve("/tmp/nowhere/x").unwrap().create_folder);
        assert_eq!(path("sub/x"), PathBuf::from("sub/x.toml"));
        assert!(
            resolve_save_path("~/x", None, None)
                .unwrap_err()
                .contains("full path")
        );
    }

    #[test]
    fn folders_and_empty_names_are_refused() {
        assert_eq!(resolve("  "), Err("type a file name".into()));
        assert!(resolve("~").unwrap_err().contains("is a folder"));
        assert!(resolve("/tmp/").unwrap_err().contains("is a folder"));
        assert!(resolve("..").unwrap_err().contains("file name"));
        assert!(resolve("...").unwrap_err().contains("no file name"));
    }

    #[test]
    fn every_refused_name_says_why() {
        let cases = [
            (
                ".",
                "'.' is a folder ('.' is the folder itself): type a file name, e.g. lab.toml",
            ),
            (
                "labs/.",
                "'labs/.' is a folder ('.' is the folder itself): type a file name, e.g. \
                 labs/lab.toml",
            ),
            (
                "..",
                "'..' is a folder ('..' is the folder above): type a file name, e.g. ../lab.toml",
            ),
            (
                "labs/",
                "'labs/' is a folder (it ends in /): type a file name, e.g. labs/lab.toml",
            ),
            (
                ".toml",
                "'.toml' has no name before .toml (the file would be hidden): type one, e.g. \
                 lab.toml",
            ),
            (
                "~/..TOML",
                "'~/..TOML' has no name before .toml (the file would be hidden): type one, e.g. \
                 lab.toml",
            ),
            ("a\tb", "a file name holds no tab: type the name without it"),
            (
                "a\u{7}b",
                "a file name holds no control character: type the name without it",
            ),
        ];
        for (typed, why) in cases {
            assert_eq!(resolve(typed), Err(why.to_string()), "{typed:?}");
        }
        // a name that starts with a dot is the user's choice
        assert_eq!(path(".lab"), PathBuf::from("/data/presets/.lab.toml"));
    }
}
