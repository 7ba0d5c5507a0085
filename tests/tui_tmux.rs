//! End to end: the real binary in tmux, driven by keys as a person would (edit a value, type
//! garbage, resize below 80x24, open the help, quit), asserting on the captured screen and on a
//! clean exit with the terminal restored. Skipped (with a message) where tmux is not installed;
//! `.ci/run` installs it.

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

const SOCKET: &str = "wearlab-e2e";

fn tmux(args: &[&str]) -> String {
    let out = Command::new("tmux")
        .arg("-L")
        .arg(SOCKET)
        .args(args)
        .output()
        .expect("tmux runs");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn screen() -> String {
    tmux(&["capture-pane", "-p", "-t", "e2e"])
}

fn wait_for(needle: &str) -> String {
    let deadline = Instant::now() + Duration::from_secs(20);
    loop {
        let s = screen();
        if s.contains(needle) {
            return s;
        }
        assert!(
            Instant::now() < deadline,
            "'{needle}' never appeared; screen:\n{s}"
        );
        std::thread::sleep(Duration::from_millis(50));
    }
}

fn keys(k: &[&str]) {
    let mut args = vec!["send-keys", "-t", "e2e"];
    args.extend_from_slice(k);
    tmux(&args);
}

#[test]
fn a_session_in_tmux() {
    if Command::new("tmux").arg("-V").output().is_err() {
        eprintln!("tmux is not installed: end-to-end test skipped");
        return;
    }
    let bin = assert_cmd::cargo::cargo_bin!("wearlab");
    let dir = tempfile::tempdir().unwrap();
    let exit_file = dir.path().join("exit");
    let preset = Path::new(env!("CARGO_MANIFEST_DIR")).join("presets/polymer-coating.toml");
    let script = format!(
        "TERM=xterm-256color {} {}; echo $? > {}; sleep 30",
        bin.display(),
        preset.display(),
        exit_file.display()
    );
    tmux(&["kill-session", "-t", "e2e"]);
    tmux(&[
        "new-session",
        "-d",
        "-s",
        "e2e",
        "-x",
        "100",
        "-y",
        "30",
        &script,
    ]);
    wait_for("valid: (a+b)/h = 0.061");

    // edit the load: P is the ninth row
    for _ in 0..8 {
        keys(&["j"]);
    }
    keys(&["Enter"]);
    keys(&["-l", "2e4"]);
    keys(&["Enter"]);
    let s = wait_for("20.0 kN/m");
    assert!(s.contains("(edited)"), "{s}");
    wait_for("(a+b)/h = 0.122 > 0.1: the wide-strip");

    // garbage is refused with the reason; the old value stays
    keys(&["Enter"]);
    keys(&["-l", "lots"]);
    keys(&["Enter"]);
    wait_for("P: 'lots' is not a number");
    keys(&["Escape"]);
    wait_for("edit cancelled");
    assert!(screen().contains("20.0 kN/m"));

    // too small, then big enough again
    tmux(&["resize-window", "-t", "e2e", "-x", "60", "-y", "20"]);
    wait_for("terminal too small");
    tmux(&["resize-window", "-t", "e2e", "-x", "100", "-y", "30"]);
    wait_for("operating point");

    // help and back
    keys(&["?"]);
    wait_for("help (any key closes)");
    keys(&["x"]);
    wait_for("operating point");

    // quit asks because of the unsaved edit
    keys(&["q"]);
    wait_for("unsaved edits: quit anyway? y/n");
    keys(&["y"]);
    let deadline = Instant::now() + Duration::from_secs(10);
    while !exit_file.exists() {
        assert!(Instant::now() < deadline, "the explorer did not exit");
        std::thread::sleep(Duration::from_millis(50));
    }
    std::thread::sleep(Duration::from_millis(100));
    assert_eq!(std::fs::read_to_string(&exit_file).unwrap().trim(), "0");
    // the terminal is restored: the alternate screen is gone
    assert!(!screen().contains("operating point"));
    tmux(&["kill-session", "-t", "e2e"]);
}
