//! Running the wearlab binary as a script does, and the preset text the height-map tests
//! complete with their `surface` line.

/// Runs the wearlab binary with `args`: its exit code, stdout and stderr.
pub fn wearlab(args: &[&str]) -> (i32, String, String) {
    let out = assert_cmd::Command::new(assert_cmd::cargo::cargo_bin!("wearlab"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// A spatial preset on a steel half-space without a punch: the height-map tests add their
/// `surface = ...` line under `[spatial]`.
pub const SURFACE_PRESET: &str = "schema = 1
problem = \"spatial\"
[material]
youngs_modulus = 2.0e11
poisson_ratio = 0.3
thickness = inf
[wear]
coefficient = 1.0e-12
[spatial]
mean_pressure = 1.0e9
sliding_speed = 1.0
";
