//! `--max-seconds`: the work itself stops when the bound passes (it asks a `Stop` between its
//! steps and inside every contact solve), nothing is left running, and output cut short never
//! reads as a whole answer.

use std::time::Instant;

use crate::common::sixty_four_preset;
use crate::run::wearlab;

/// Runs `wearlab ARGS --max-seconds 1`: the exit code, stdout, stderr and the wall-clock time.
fn bounded(args: &[&str]) -> (i32, String, String, f64) {
    let start = Instant::now();
    let mut all = args.to_vec();
    all.extend(["--max-seconds", "1"]);
    let (code, stdout, stderr) = wearlab(&all);
    (code, stdout, stderr, start.elapsed().as_secs_f64())
}

#[test]
fn a_partial_contact_of_64_harmonics_on_a_big_grid_stops_inside_its_contact_solve() {
    // 64 harmonics in partial contact on 256 x 256 nodes: 170 s of CPU to the end of the
    // running-in (issue report); one linear-solve product is a few FFTs of 65,536 nodes
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("sixty-four.toml");
    std::fs::write(&path, sixty_four_preset(256)).unwrap();
    let path = path.to_str().unwrap();
    for args in [
        vec!["solve", path],
        vec!["solve", path, "--format", "csv"],
        vec!["solve", path, "--output", "mu_star"],
    ] {
        let (code, stdout, stderr, took) = bounded(&args);
        assert_eq!(code, 3, "{args:?}: {stderr}");
        assert!(
            stderr.starts_with("error: stopped after ")
                && stderr.contains(" s (--max-seconds): the solve had not finished"),
            "{stderr}"
        );
        assert!(stdout.is_empty(), "{args:?} printed {stdout}");
        // the bound, then at most one product and the start-up; 4 s leaves room for a loaded
        // machine (a debug build under a load average of 11 took 1.2 s)
        assert!(took < 4.0, "{args:?} took {took:.1} s");
    }
}

#[test]
fn a_stopped_sweep_says_how_many_rows_it_wrote_and_its_json_is_left_open() {
    // four million plane points: the rows written before the bound stay, cut where it fell
    let sweep = [
        "sweep",
        "presets/polymer-coating.toml",
        "--vary",
        "plane.load=1:1e6:2000:log",
        "--vary",
        "friction.coefficient=0:1:2000",
    ];
    for format in ["csv", "json"] {
        let mut args = sweep.to_vec();
        args.extend(["--format", format]);
        let (code, stdout, stderr, took) = bounded(&args);
        assert_eq!(code, 3, "{stderr}");
        assert!(took < 4.0, "took {took:.1} s");
        let done: usize = stderr
            .strip_prefix("error: stopped after ")
            .and_then(|s| s.split_once(" s (--max-seconds): "))
            .and_then(|(_, rest)| rest.strip_suffix(" of 4000000 points done\n"))
            .and_then(|n| n.parse().ok())
            .unwrap_or_else(|| panic!("{stderr}"));
        // every row handed on was written whole, and nothing after the stop
        let rows = match format {
            "csv" => stdout.lines().count() - 1,
            _ => stdout.matches("\"status\":").count(),
        };
        assert_eq!(rows, done, "{format}");
        assert!(stdout.ends_with('\n') || format == "json");
        if format == "json" {
            assert!(serde_json::from_str::<serde_json::Value>(&stdout).is_err());
        }
    }
}

#[test]
fn a_spatial_sweep_stops_inside_its_first_point() {
    // each point a 64-harmonic running-in on 128 x 128 nodes (tens of seconds in a debug build)
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("sixty-four.toml");
    std::fs::write(&path, sixty_four_preset(128)).unwrap();
    let args = [
        "sweep",
        path.to_str().unwrap(),
        "--vary",
        "spatial.mean_pressure=2e7:3e7:3",
        "--format",
        "csv",
    ];
    let (code, stdout, stderr, took) = bounded(&args);
    assert_eq!(code, 3, "{stderr}");
    assert!(stderr.ends_with(": 0 of 3 points done\n"), "{stderr}");
    // the header alone: no row of a point the bound cut
    assert_eq!(stdout.lines().count(), 1, "{stdout}");
    assert!(took < 4.0, "took {took:.1} s");
}
