//! The hostile corpus: files and arguments that could hang, panic or print nonsense with exit 0,
//! each with the exit code and the message it must give. The files are in tests/hostile/ (each
//! says in its first line what it probes); FIFOs, devices and oversized
//! files are made at test time.

use std::io::Read;
use std::process::{Command as Process, Stdio};
use std::time::Duration;

use assert_cmd::Command;
use serde_json::Value;

fn wearlab() -> Command {
    let mut cmd = Command::new(assert_cmd::cargo::cargo_bin!("wearlab"));
    cmd.timeout(Duration::from_secs(60));
    cmd
}

/// Runs `wearlab solve ARGS`, checks the exit code and that stderr holds `message`, and that no
/// Rust internals leak (panics, type names).
fn expect(args: &[&str], code: i32, message: &str) -> String {
    let out = wearlab().arg("solve").args(args).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(code), "{args:?}: {stderr}");
    assert!(stderr.contains(message), "{args:?}: {stderr}");
    for leak in [
        "panicked",
        "struct File",
        "wanted string or table",
        "f64",
        "i64",
        "NaN",
    ] {
        assert!(!stderr.contains(leak), "{args:?} leaks {leak:?}: {stderr}");
    }
    String::from_utf8_lossy(&out.stdout).to_string()
}

#[test]
fn the_corpus_gives_its_exit_codes_and_messages() {
    let cases: [(&str, i32, &str); 12] = [
        (
            "huge-modulus.toml",
            2,
            "huge-modulus.toml:14: youngs_modulus = 1e308 is out of range: allowed 1e2 <= E <= 1e13 (Pa)",
        ),
        (
            "overflowing-sweep.toml",
            2,
            "overflowing-sweep.toml:29: load_min = 1e-300 is out of range",
        ),
        (
            "strip-heavy-load.toml",
            3,
            "at P = 1.0000e8 N/m the contact is wider than the strip model resolves",
        ),
        (
            "huge-friction.toml",
            2,
            "coefficient = 1e200 is out of range: allowed 0 <= mu <= 10",
        ),
        (
            "huge-wavenumber.toml",
            2,
            "wavenumber_x = 1e151 is out of range: allowed 0, or 1e-3 <= w <= 1e10 (rad/m)",
        ),
        (
            "wide-overload.toml",
            3,
            "the wide-strip model has no contact at P = 1.0000e10 N/m: it carries at most P = 4.",
        ),
        (
            "near-commensurate.toml",
            3,
            "complete contact not certified: the lower bound pbar - sum A/M = -10.6 MPa is not \
             positive, and the cell minimum is unknown: no common period along x was found",
        ),
        (
            "wear-not-a-table.toml",
            2,
            "wear-not-a-table.toml:12: wear: expected the section [wear] (coefficient), found the \
             whole number 3",
        ),
        (
            "problem-a-number.toml",
            2,
            "problem-a-number.toml:11: problem: expected \"plane\" or \"spatial\"",
        ),
        (
            "modulus-as-text.toml",
            2,
            "modulus-as-text.toml:14: youngs_modulus = \"3 GigaPa\": '3 GigaPa': unknown unit; \
             write a plain number or a prefixed Pa (e.g. kPa, MPa); e.g. youngs_modulus = \"1 GPa\" \
             or 1e9",
        ),
        (
            "too-many-harmonics.toml",
            2,
            "the number of harmonics = 65 is out of range: allowed a whole number from 1 to 64",
        ),
        (
            "latin1.toml",
            2,
            "latin1.toml:3: the file is not UTF-8 text (byte 0xe9 at column 12)",
        ),
    ];
    for (file, code, message) in cases {
        expect(&[&format!("tests/hostile/{file}")], code, message);
    }
}

#[test]
fn the_strip_sweep_holds_numbers_only() {
    // the widths whose collocation fails the checks are left out: no null, no NaN in `load`
    let out = expect(&["tests/hostile/strip-sweep-to-heavy-loads.toml"], 0, "");
    let v: Value = serde_json::from_str(&out).unwrap();
    for key in ["load", "mu_star", "a", "b", "normal_force"] {
        let values = v["sweep"][key].as_array().unwrap();
        assert!(
            values.len() >= 2 && values.iter().all(Value::is_number),
            "{key}"
        );
    }
}

#[test]
fn special_files_are_refused_without_blocking() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("pipe.toml");
    let made = Process::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    expect(
        &[fifo.to_str().unwrap()],
        2,
        "not a preset file: it is a named pipe (FIFO)",
    );
    for device in ["/dev/zero", "/dev/urandom"] {
        expect(&[device], 2, "not a preset file: it is a device");
    }
    expect(&["tests"], 2, "not a preset file: it is a folder");
    let big = dir.path().join("big.toml");
    std::fs::write(&big, "# ".repeat(200_000)).unwrap();
    expect(
        &[big.to_str().unwrap()],
        2,
        "the file is larger than 256 kB, the most a preset file may be",
    );
}

#[test]
fn negative_numbers_are_values_and_flags_of_the_other_problem_are_refused() {
    let out = expect(
        &[
            "presets/dispersion.toml",
            "--probe",
            "-1e-4,0",
            "--time",
            "2",
        ],
        0,
        "",
    );
    let v: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["probes"][0]["x"], -1e-4);
    expect(
        &["presets/dispersion.toml", "--time", "-1"],
        2,
        "--time = -1 is out of range: allowed 0 <= t <= 1e12 (s)",
    );
    expect(
        &["presets/dispersion.toml", "--probe", "-1e300,0"],
        2,
        "x = -1e300 is out of range: allowed -1e6 <= x, y <= 1e6 (m)",
    );
    expect(
        &["presets/hertz-check.toml", "--time", "3"],
        2,
        "--time applies to spatial presets only; this preset solves problem = \"plane\"",
    );
    expect(
        &["presets/hertz-check.toml", "--probe", "0,0"],
        2,
        "--probe applies to spatial presets only",
    );
    expect(
        &["presets/dispersion.toml", "--points", "5"],
        2,
        "--points applies to plane presets only; this preset solves problem = \"spatial\"",
    );
}

#[test]
fn a_closed_pipe_or_a_full_disk_is_an_error_not_a_panic() {
    // `wearlab solve presets/dispersion.toml --format csv | head -c 10`: the field CSV (~300 kB)
    // outgrows the pipe; the reader takes 10 bytes and closes it.
    let mut child = Process::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .args(["solve", "presets/dispersion.toml", "--format", "csv"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut head = [0u8; 10];
    child.stdout.take().unwrap().read_exact(&mut head).unwrap();
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("cannot write the result to stdout"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");

    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let out = Process::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .args(["solve", "presets/hertz-check.toml"])
        .stdout(full)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("No space left on device"), "{stderr}");
}

#[test]
fn the_explorer_needs_a_terminal() {
    // `setsid wearlab < /dev/null`: no terminal on stdin or stdout
    let out = Process::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        "error: wearlab needs a terminal; use `wearlab solve` for scripts\n"
    );
}

/// Runs `wearlab ARGS --max-seconds 1` on work that takes far longer: exit 3 soon after the
/// second, with the reason.
fn stopped_after_a_second(args: &[&str], reason: &str) {
    let start = std::time::Instant::now();
    let out = wearlab()
        .args(args)
        .args(["--max-seconds", "1"])
        .output()
        .unwrap();
    let took = start.elapsed().as_secs_f64();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{stderr}");
    assert!(
        stderr.contains("error: stopped after 1.") && stderr.contains(reason),
        "{stderr}"
    );
    // a second of work and the start-up; 4 s leaves room for a loaded machine
    assert!(took < 4.0, "took {took:.1} s");
}

#[test]
fn max_seconds_stops_a_long_solve_and_a_long_sweep_with_exit_3() {
    // the egg-box at a long wavelength and a low pressure: the partial-contact solver works
    // for about a minute before it gives up
    stopped_after_a_second(
        &[
            "solve",
            "presets/jgh-egg-box.toml",
            "--set",
            "spatial.harmonics.0.wavenumber_x=0.0665",
            "--set",
            "spatial.mean_pressure=2195",
        ],
        "(--max-seconds): the solve had not finished",
    );
    // four million points
    stopped_after_a_second(
        &[
            "sweep",
            "presets/polymer-coating.toml",
            "--vary",
            "plane.load=1:1e6:2000:log",
            "--vary",
            "friction.coefficient=0:1:2000",
        ],
        "of 4000000 points done",
    );
    // a bound that is not a positive number is invalid input
    let out = wearlab()
        .args(["solve", "presets/hertz-check.toml", "--max-seconds", "0"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn a_contact_off_the_punch_tip_is_exit_3() {
    // a 5 um coating under the polymer preset's load: the wide model's contact [1.49, 2.10] mm
    // lies wholly ahead of the tip; a 10 GPa adhesion carries the load on the punch's slope
    for (set, hint) in [
        (
            "material.thickness=5um",
            "try the strip model (plane.model=strip)",
        ),
        ("friction.adhesion=1e10", "try a smaller tau0"),
    ] {
        expect(
            &["presets/polymer-coating.toml", "--set", set],
            3,
            "does not contain the punch tip x = 0",
        );
        expect(&["presets/polymer-coating.toml", "--set", set], 3, hint);
    }
    // the hint holds: the strip model answers the 5 um coating
    let out = wearlab()
        .args(["solve", "presets/polymer-coating.toml"])
        .args([
            "--set",
            "material.thickness=5um",
            "--set",
            "plane.model=strip",
        ])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
