//! `--set` on a key a lesson locks: refused (exit 2) naming the lock and the value the
//! questions are asked at, unless `--unlock` (the instructor's check of another value); a value
//! it already has, other keys and `--vary` stay free, as in the explorer.

use super::run::wearlab as run;

const LESSON: &str = "presets/friction-half-plane.toml";

#[test]
fn a_locked_key_is_refused_unless_unlocked() {
    let (code, out, err) = run(&["solve", LESSON, "--set", "friction.coefficient=0.5"]);
    assert_eq!((code, out.as_str()), (2, ""), "{err}");
    assert_eq!(
        err.trim(),
        "error: --set friction.coefficient: friction.coefficient is locked by the lesson of \
         presets/friction-half-plane.toml, whose questions are asked at mu = 0.4; add --unlock \
         to set it anyway (the instructor's check of another value)"
    );
    let (code, _, err) = run(&["sweep", LESSON, "--set", "material.thickness=1mm"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("material.thickness is locked by the lesson"),
        "{err}"
    );
    // the instructor's check
    let unlocked = [
        "--set",
        "friction.coefficient=0.5",
        "--unlock",
        "--output",
        "mu_star",
    ];
    let (code, out, err) = run(&[&["solve", LESSON][..], &unlocked].concat());
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("mu_star = "), "{out}");
}

#[test]
fn free_keys_the_same_value_and_sweeps_stay_allowed() {
    for args in [
        &[
            "solve",
            LESSON,
            "--set",
            "plane.load=2kN/m",
            "--output",
            "mu_star",
        ][..],
        &[
            "solve",
            LESSON,
            "--set",
            "friction.coefficient=0.4",
            "--output",
            "mu_star",
        ],
        &[
            "sweep",
            LESSON,
            "--vary",
            "friction.coefficient=0.1:0.5:3",
            "--output",
            "mu_star",
        ],
    ] {
        let (code, _, err) = run(args);
        assert_eq!(code, 0, "{args:?}: {err}");
    }
}
