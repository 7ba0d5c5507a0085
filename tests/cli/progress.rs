//! A long `wearlab solve` shows a spinner with the time so far on stderr when stderr is a
//! terminal (a pty of the test's own here), for a punch of harmonics and for a height map, with
//! and without `--output`; never in a pipe. Each solve is ended by `--max-seconds 2`.
#![cfg(target_os = "linux")]

use std::fs::File;
use std::io::Read;
use std::os::fd::{FromRawFd, OwnedFd};
use std::process::{Command, Stdio};

use crate::common::sixty_four_preset;
use crate::run::SURFACE_PRESET;

/// What `wearlab solve ARGS --max-seconds 2` writes on stderr, a pty when `terminal`, and its
/// exit code.
fn stderr_of(args: &[&str], terminal: bool) -> (String, Option<i32>) {
    let mut command = Command::new(assert_cmd::cargo::cargo_bin!("wearlab"));
    command
        .arg("solve")
        .args(args)
        .args(["--max-seconds", "2"])
        .stdin(Stdio::null())
        .stdout(Stdio::null());
    if !terminal {
        let out = command.output().unwrap();
        return (
            String::from_utf8_lossy(&out.stderr).into(),
            out.status.code(),
        );
    }
    let (mut master, mut slave) = (-1, -1);
    // SAFETY: openpty writes two descriptors; the name, termios and window size may be null.
    let done = unsafe {
        libc::openpty(
            &mut master,
            &mut slave,
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null(),
        )
    };
    assert_eq!(done, 0);
    // SAFETY: both descriptors were just opened and are owned by nothing else.
    let (master, slave) = unsafe { (OwnedFd::from_raw_fd(master), OwnedFd::from_raw_fd(slave)) };
    command.stderr(Stdio::from(slave));
    let mut child = command.spawn().unwrap();
    // the slave's last copy outside the child goes with the command: reading ends at its exit
    drop(command);
    let mut text = Vec::new();
    let mut file = File::from(master);
    let mut chunk = [0u8; 4096];
    while let Ok(n) = file.read(&mut chunk) {
        if n == 0 {
            break;
        }
        text.extend_from_slice(&chunk[..n]);
    }
    let status = child.wait().unwrap();
    (String::from_utf8_lossy(&text).into(), status.code())
}

#[test]
fn a_long_solve_shows_its_time_on_a_terminal_only() {
    let dir = tempfile::tempdir().unwrap();
    let harmonics = dir.path().join("sixty-four.toml");
    std::fs::write(&harmonics, sixty_four_preset(256)).unwrap();
    let map = dir.path().join("rough.toml");
    std::fs::write(
        &map,
        format!(
            "{SURFACE_PRESET}surface = {{ kind = \"self-affine\", hurst = 0.8, rms_slope = 0.05, \
             rolloff_wavelength = \"250 um\", cutoff_wavelength = \"20 um\", length_x = \"1 mm\", \
             length_y = \"1 mm\", grid = 256, seed = 3 }}\n"
        ),
    )
    .unwrap();
    for preset in [&harmonics, &map] {
        let path = preset.to_str().unwrap();
        for args in [vec![path], vec![path, "--output", "mu_star"]] {
            let (shown, code) = stderr_of(&args, true);
            assert_eq!(code, Some(3), "{args:?}: {shown}");
            assert!(
                shown.contains("solving, ") && shown.contains("s so far"),
                "{args:?}: {shown:?}"
            );
            assert!(shown.contains("(--max-seconds)"), "{shown:?}");
            let (piped, _) = stderr_of(&args, false);
            assert!(!piped.contains("solving"), "{args:?}: {piped:?}");
        }
    }
}
