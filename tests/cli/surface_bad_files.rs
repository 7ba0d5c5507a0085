//! The bad height-map files of the verification list, as `wearlab solve` meets them beside a
//! preset: each refused with exit 2 and `file:line: reason` (the whole file's reason for an empty
//! or oversized one), never a panic, a hang or the memory of the whole file; the reader's own
//! cases are in tests/spatial/surface.rs.

use crate::run::SURFACE_PRESET as PRESET;
use std::io::Write;
use std::path::Path;
use std::time::{Duration, Instant};

use assert_cmd::Command;

/// `wearlab solve p.toml` in `dir` with the surface file `name`: (exit code, stderr).
fn solve_file(dir: &Path, name: &str) -> (Option<i32>, String) {
    std::fs::write(
        dir.join("p.toml"),
        format!("{PRESET}surface = {{ file = \"{name}\", length_x = 1e-3, length_y = 1e-3 }}\n"),
    )
    .unwrap();
    let out = Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .timeout(Duration::from_secs(60))
        .current_dir(dir)
        .args(["solve", "p.toml"])
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).to_string(),
    )
}

fn refused(dir: &Path, name: &str, says: &str) {
    let (code, err) = solve_file(dir, name);
    assert_eq!(code, Some(2), "{name}: {err}");
    assert!(err.contains(says), "{name}: {err}");
    assert!(!err.contains("panicked"), "{name}: {err}");
}

#[test]
fn each_bad_file_says_its_line_and_its_reason() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| std::fs::write(dir.path().join(name), text).unwrap();
    write("ragged.csv", "1e-7,2e-7,3e-7\n1e-7,2e-7\n");
    refused(
        dir.path(),
        "ragged.csv",
        "ragged.csv:2: this row has 2 values and the first row 3",
    );
    write("text.csv", "# heights\n1e-7,2e-7\n1e-7,high\n");
    refused(dir.path(), "text.csv", "text.csv:3: 'high' is not a number");
    write("nan.csv", "1e-7,NaN\n1e-7,2e-7\n");
    refused(dir.path(), "nan.csv", "nan.csv:1: NaN");
    write("empty.csv", "");
    refused(dir.path(), "empty.csv", "empty.csv: no heights");
    write("one.csv", "# a single height\n1e-7\n");
    refused(
        dir.path(),
        "one.csv",
        "one.csv:2: a surface needs at least 2 nodes along x",
    );
    // 1 km: far beyond the 1 cm of MAX_HEIGHT; the cell is quoted as written
    write("km.csv", "1e-7,2e-7\n1e-7,1e3\n");
    refused(dir.path(), "km.csv", "km.csv:2: 1e3: heights beyond 0.01 m");
}

#[test]
fn a_grid_of_4097_rows_is_refused_at_its_second_row() {
    // 4097 x 4097 heights: the reader stops at the second row of 4097 values (more than 1024 x
    // 1024), before the rest is read or held; the rows after it are never reached
    let dir = tempfile::tempdir().unwrap();
    let row = format!("{}\n", vec!["1e-7"; 4097].join(","));
    let mut out =
        std::io::BufWriter::new(std::fs::File::create(dir.path().join("huge.csv")).unwrap());
    for _ in 0..4097 {
        out.write_all(row.as_bytes()).unwrap();
    }
    out.flush().unwrap();
    drop(out);
    refused(
        dir.path(),
        "huge.csv",
        "huge.csv:2: a map larger than 1024 x 1024 (rows of 4097 values, 2 rows so far)",
    );
}

#[test]
fn a_file_of_1_gb_is_refused_from_its_size_without_being_read() {
    let dir = tempfile::tempdir().unwrap();
    let big = dir.path().join("big.csv");
    // sparse: 1 GiB of length, no block written
    std::fs::File::create(&big)
        .unwrap()
        .set_len(1 << 30)
        .unwrap();
    let start = Instant::now();
    refused(
        dir.path(),
        "big.csv",
        "big.csv: the file is 1073741824 bytes, more than the 134217728",
    );
    // reading 1 GiB of zeros would take seconds; the size alone takes none
    assert!(start.elapsed() < Duration::from_secs(20));
}

#[test]
fn a_generated_grid_of_4097_is_refused_before_it_is_made() {
    // the generator checks the grid before it allocates the 4097^2 spectrum
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("p.toml"),
        format!(
            "{PRESET}surface = {{ kind = \"self-affine\", hurst = 0.8, rms_height = 1e-7, \
             rolloff_wavelength = 1e-4, cutoff_wavelength = 1e-5, length_x = 1e-3, \
             length_y = 1e-3, grid = 64, seed = 1 }}\n"
        ),
    )
    .unwrap();
    let out = Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .timeout(Duration::from_secs(60))
        .current_dir(dir.path())
        .args(["solve", "p.toml", "--set", "spatial.surface.grid=4097"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("a 4097 x 4097 map is more than the 1024 x 1024 the solvers take"),
        "{err}"
    );
}
