//! A result that cannot be written is exit 1 with a message, also when stdout is closed
//! (`wearlab solve P >&-`), where Rust's runtime would give the result to /dev/null unseen; a
//! stdout that is /dev/null, however opened, takes the result (exit 0).
#![cfg(target_os = "linux")]

use std::time::Duration;

use assert_cmd::Command;

/// `wearlab ARGS REDIRECT` run by the shell.
fn run(args: &[&str], redirect: &str) -> (Option<i32>, String) {
    let out = Command::new("sh")
        .arg("-c")
        .arg(format!("exec \"$0\" \"$@\" {redirect}"))
        .arg(assert_cmd::cargo::cargo_bin!("wearlab"))
        .args(args)
        .timeout(Duration::from_secs(60))
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_closed_stdout_is_exit_1_with_the_message() {
    let sweep = [
        "sweep",
        "presets/hertz-check.toml",
        "--vary",
        "plane.load=1e3:1e4:3",
    ];
    for args in [&["solve", "presets/hertz-check.toml"][..], &sweep] {
        let (code, stderr) = run(args, ">&-");
        assert_eq!(code, Some(1), "{args:?}: {stderr}");
        assert_eq!(
            stderr,
            "error: cannot write the result to stdout: it is closed\n"
        );
        // /dev/null for writing (the shell's >) or for reading and writing (Python's DEVNULL)
        for null in [">/dev/null", "1<>/dev/null"] {
            let (code, stderr) = run(args, null);
            assert_eq!(code, Some(0), "{args:?} {null}: {stderr}");
        }
    }
}
