//! End to end: the real binary in tmux, driven by keys as a person would (the footers at 80 and
//! 120 columns, the help, the choice rows, edit a value, type garbage, resize below 80x24, Ctrl-C
//! while typing), asserting on the captured screen and on a clean exit with the terminal restored. Skipped (with a message) where tmux is not installed;
//! `.ci/run` installs it.

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

/// A tmux server of this test run's own: a new session on a server that is still shutting down
/// after an earlier run would die with it.
fn socket() -> String {
    format!("wearlab-e2e-{}", std::process::id())
}

fn tmux(args: &[&str]) -> String {
    let out = Command::new("tmux")
        .arg("-L")
        .arg(socket())
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

/// The last line of the screen (the key footer), without trailing blanks.
fn footer() -> String {
    screen().lines().last().unwrap_or("").trim_end().to_string()
}

/// Waits until the footer is `text`.
fn wait_footer(text: &str) {
    let deadline = Instant::now() + Duration::from_secs(20);
    while footer() != text {
        assert!(
            Instant::now() < deadline,
            "footer never became '{text}': {}",
            screen()
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// The main screen's footer of the plane problem at 80 columns.
const PLANE_80: &str =
    "↑↓ ←→ nudge ⏎ Tab chart p problem m x c/C f y v M D d o s e/E u i ? help q quit";

fn resize(w: &str, h: &str) {
    tmux(&["resize-window", "-t", "e2e", "-x", w, "-y", h]);
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
    // in a folder of its own, so that nothing it might write lands in the checkout
    let script = format!(
        "cd {} && TERM=xterm-256color {} {}; echo $? > {}; sleep 30",
        dir.path().display(),
        bin.display(),
        preset.display(),
        exit_file.display()
    );
    tmux(&[
        "new-session",
        "-d",
        "-s",
        "e2e",
        "-x",
        "80",
        "-y",
        "24",
        &script,
    ]);
    wait_for("valid: (a+b)/h = 0.06104");

    // the footers of both problems at 80 and 120 columns
    assert_eq!(footer(), PLANE_80);
    resize("120", "40");
    wait_for("D groups d o s e/E u i ? help q quit");
    assert_eq!(
        footer(),
        "↑↓ ←→ nudge ⏎ Tab chart p problem m x cursor c/C pin f full y log v M D groups d o s e/E u i ? help q quit"
    );
    keys(&["p"]);
    wait_for("v M D groups");
    assert_eq!(
        footer(),
        "↑↓ ←→ nudge ⏎ Tab chart p problem space +/- x cursor c/C pin f full y log v M D groups d o s e/E u i ? help q quit"
    );
    resize("80", "24");
    wait_for("space +/- x c/C");
    assert_eq!(
        footer(),
        "↑↓ ←→ nudge ⏎ Tab chart p space +/- x c/C f y v M D d o s e/E u i ? help q quit"
    );
    keys(&["u"]);
    wait_for("undo: problem spatial -> plane");
    wait_footer(PLANE_80);

    // the help names every model; Enter on a choice row lists the choices
    keys(&["?"]);
    let help = wait_for("cycle the plane model");
    assert!(
        help.contains("  m                 cycle the plane model (wide, narrow, strip)"),
        "{help}"
    );
    // (no Escape followed at once by another key: the two may read as Alt-key)
    keys(&["?"]);
    wait_footer(PLANE_80);
    // model is the twelfth row (material E nu h Y H, mu tau0 tau_max, k n, model)
    for _ in 0..11 {
        keys(&["j"]);
    }
    keys(&["Enter"]);
    let list = wait_for("model: one of wide, narrow, strip");
    assert!(list.contains("│ strip"), "{list}");
    // Enter on the current choice changes nothing
    keys(&["Enter"]);
    wait_footer(PLANE_80);
    // scale is seven rows below (shape R P, P min, P max, points, scale)
    for _ in 0..7 {
        keys(&["j"]);
    }
    keys(&["Enter"]);
    wait_for("scale: one of log, linear");
    keys(&["Enter"]);
    wait_footer(PLANE_80);

    // edit the load: P is four rows above scale
    for _ in 0..4 {
        keys(&["k"]);
    }
    keys(&["Enter"]);
    keys(&["-l", "2e4"]);
    keys(&["Enter"]);
    wait_for("20.0 kN/m");
    wait_for("valid: (a+b)/h = 0.1221; wide model holds");

    // garbage is refused with the reason; the old value stays
    keys(&["Enter"]);
    keys(&["-l", "lots"]);
    keys(&["Enter"]);
    wait_for("plane.load = 'lots' is not a number");
    keys(&["Escape"]);
    wait_for("edit cancelled");
    assert!(screen().contains("20.0 kN/m"));

    // too small, then big enough again
    resize("60", "20");
    wait_for("terminal too small");
    resize("80", "24");
    wait_for("operating point");

    // Ctrl-C while typing asks (there is an unsaved edit), and y quits
    keys(&["Enter"]);
    keys(&["-l", "3"]);
    keys(&["C-c"]);
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
    tmux(&["kill-server"]);
}
