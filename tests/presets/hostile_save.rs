//! Saving a preset (the library's part): atomic, through symbolic links, keeping
//! the mode of the file it replaces, cleaning up after interrupted saves, creating no folders.
#![cfg(unix)]

use std::fs::{self, File, FileTimes};
use std::os::unix::fs::{PermissionsExt, symlink};
use std::path::Path;
use std::time::{Duration, SystemTime};

use wearlab::preset::{self, default_preset, load, save};

fn mode(path: &Path) -> u32 {
    fs::metadata(path).unwrap().permissions().mode() & 0o777
}

#[test]
fn an_overwritten_file_keeps_its_mode_and_a_new_one_gets_the_usual_mode() {
    let dir = tempfile::tempdir().unwrap();
    for kept in [0o644, 0o600, 0o640] {
        let path = dir.path().join(format!("lab-{kept:o}.toml"));
        fs::write(&path, "old").unwrap();
        fs::set_permissions(&path, fs::Permissions::from_mode(kept)).unwrap();
        save(&default_preset(), &path).unwrap();
        assert_eq!(mode(&path), kept);
        assert_eq!(load(&path).unwrap(), default_preset());
    }
    // a new file: what File::create gives under the same umask (0666 less the umask), not 0600
    let reference = dir.path().join("reference");
    File::create(&reference).unwrap();
    let fresh = dir.path().join("fresh.toml");
    save(&default_preset(), &fresh).unwrap();
    assert_eq!(mode(&fresh), mode(&reference));
}

#[test]
fn saving_over_a_link_writes_its_target_and_keeps_the_link() {
    let dir = tempfile::tempdir().unwrap();
    fs::create_dir(dir.path().join("real")).unwrap();
    let target = dir.path().join("real/lab.toml");
    fs::write(&target, "old").unwrap();
    let link = dir.path().join("lab.toml");
    symlink("real/lab.toml", &link).unwrap();
    let chain = dir.path().join("chain.toml");
    symlink("lab.toml", &chain).unwrap();
    save(&default_preset(), &chain).unwrap();
    for l in [&link, &chain] {
        assert!(fs::symlink_metadata(l).unwrap().file_type().is_symlink());
    }
    assert_eq!(load(&target).unwrap(), default_preset());
    // no temporary file left next to the link or the target
    for folder in [dir.path(), &dir.path().join("real")] {
        let names: Vec<_> = fs::read_dir(folder)
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .collect();
        assert!(
            names.iter().all(|n| !n.starts_with(".wearlab-save-")),
            "{names:?}"
        );
    }
}

#[test]
fn stale_temporary_files_of_an_interrupted_save_are_removed() {
    let dir = tempfile::tempdir().unwrap();
    let old = SystemTime::now() - Duration::from_secs(3600);
    let age = |path: &Path, when: SystemTime| {
        File::options()
            .write(true)
            .open(path)
            .unwrap()
            .set_times(FileTimes::new().set_modified(when))
            .unwrap();
    };
    let stale = dir.path().join(".wearlab-save-a1B2c3");
    let fresh = dir.path().join(".wearlab-save-x9Y8z7");
    let other = dir.path().join(".other-save-a1B2c3");
    let folder = dir.path().join(".wearlab-save-folder");
    for f in [&stale, &fresh, &other] {
        fs::write(f, "partial").unwrap();
    }
    fs::create_dir(&folder).unwrap();
    age(&stale, old);
    age(&other, old);
    save(&default_preset(), &dir.path().join("lab.toml")).unwrap();
    assert!(
        !stale.exists(),
        "an hour-old temporary file of ours is removed"
    );
    assert!(fresh.exists(), "a temporary file being written now stays");
    assert!(other.exists() && folder.exists(), "only our own files");
}

#[test]
fn a_save_creates_no_folder() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("no/such/folder/lab.toml");
    assert!(save(&default_preset(), &missing).is_err());
    assert!(!dir.path().join("no").exists());
    assert!(preset::write_atomically(&missing, preset::Links::Follow, |_| Ok(())).is_err());
}

#[test]
fn a_failed_write_leaves_the_old_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("lab.toml");
    fs::write(&path, "old").unwrap();
    let failed = preset::write_atomically(&path, preset::Links::Follow, |_| {
        Err(std::io::Error::other("disk full"))
    });
    assert!(failed.is_err());
    assert_eq!(fs::read_to_string(&path).unwrap(), "old");
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);
}

#[test]
fn a_folder_that_cannot_be_written_is_named_not_the_temporary_file() {
    // a read-only folder, or where the modes do not stop this user (root), /sys
    let dir = tempfile::tempdir().unwrap();
    let ro = dir.path().join("read-only");
    fs::create_dir(&ro).unwrap();
    fs::set_permissions(&ro, fs::Permissions::from_mode(0o555)).unwrap();
    let Some(folder) = [ro, "/sys".into()]
        .into_iter()
        .find(|d| d.is_dir() && File::create(d.join("probe.toml")).is_err())
    else {
        eprintln!("skipped: every folder here can be written");
        return;
    };
    let why = save(&default_preset(), &folder.join("lab.toml"))
        .unwrap_err()
        .to_string();
    assert_eq!(
        why,
        format!(
            "cannot write in the folder {}: permission denied",
            folder.display()
        )
    );
}
