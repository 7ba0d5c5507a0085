//! A deterministic fuzz run of preset files: the bundled presets with random mutations (bytes
//! flipped, the file cut short, lines repeated or dropped, two values swapped, a value made huge,
//! negative, tiny, NaN or infinite), read as `wearlab` reads a file and, when they load, solved
//! through the library as `wearlab solve` solves them. Never a panic, never a non-finite number in
//! a report; an error says what is wrong in words. The work of a solve is bounded, not its time,
//! so that the run is the same on a loaded machine: a spatial solve stops after `WORK` steps (its
//! running-in's time steps, active-set iterations and mean pressures, counted by the `Stop` it
//! asks before each), a plane solve ends within its solvers' own iteration bounds; `HANG` only
//! catches a solve that never ends.
//!
//! The solves are kept small so that the run stays fast: a loaded spatial preset is solved on a
//! grid of at most `MAX_GRID` points a side and every sweep has at most `MAX_SWEEP` points (the
//! mutated values of the physics are kept; the cost of large grids is the solver benchmarks'
//! business). `PRESET_FUZZ_CASES=N` runs N cases instead of `CASES`, `PRESET_FUZZ_SEED=S` (a
//! number) another seed.

use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::Duration;

use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use wearlab::finite;
use wearlab::physics::SolveError;
use wearlab::physics::spatial::partial::running_in::Stopped;
use wearlab::physics::spatial::pipeline;
use wearlab::physics::stop::Stop;
use wearlab::preset::{BUNDLED, Preset, Problem, load, parse};
use wearlab::report::plane_report;

/// Cases of a `cargo test` run.
const CASES: u32 = 1500;
/// The seed of the run (any fixed 32 bytes: the run is the same on every machine).
const SEED: [u8; 32] = *b"wearlab preset fuzz, seed one...";
/// The most steps of a spatial solve (time steps, active-set iterations, mean pressures of its
/// sweep); a solve stopped there counts as bounded. The bundled spatial presets take at most
/// a few thousand on a `MAX_GRID` grid.
const WORK: usize = 20_000;
/// A solve without an answer after this long has hung: a hang detector only, far above the
/// bounded work (a bundled preset solves in 0.15 s).
const HANG: Duration = Duration::from_secs(120);
/// The largest grid a loaded spatial preset is solved on.
const MAX_GRID: f64 = 32.0;
/// The most points of a sweep solved.
const MAX_SWEEP: f64 = 24.0;
/// Profile points of a plane solve (`wearlab solve`'s default is 201).
const PROFILE_POINTS: usize = 101;

/// Values a mutation writes in place of a value: beyond every limit, at the edges of f64 and of
/// i64, not numbers, and text.
const VALUES: [&str; 22] = [
    "1e308",
    "-1e308",
    "-1",
    "0",
    "-0.0",
    "nan",
    "-nan",
    "inf",
    "-inf",
    "5e-324",
    "1e-300",
    "99999999999999999999",
    "9223372036854775807",
    "-9223372036854775808",
    "2001",
    "1e13",
    "0.4999999999",
    "3",
    "1.5",
    "\"nan\"",
    "\"\"",
    "{}",
];

#[derive(Clone, Debug)]
enum Mutation {
    /// Flips one bit of a byte (positions wrap around the file's length).
    Flip(usize, u8),
    /// Cuts the file at a byte.
    Truncate(usize),
    /// Repeats a line.
    Duplicate(usize),
    /// Drops a line.
    Drop(usize),
    /// Swaps the values of two assignments.
    Swap(usize, usize),
    /// Writes `VALUES[v]` as the n-th value of a line (`key = value` or inside `{ ... }`).
    Value(usize, usize, usize),
    /// Multiplies the n-th value of a line by 10^k, when it is a number.
    Scale(usize, usize, i32),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let line_value = || (any::<usize>(), 0usize..4);
    prop_oneof![
        1 => (any::<usize>(), 0u8..8).prop_map(|(at, bit)| Mutation::Flip(at, bit)),
        1 => any::<usize>().prop_map(Mutation::Truncate),
        1 => any::<usize>().prop_map(Mutation::Duplicate),
        1 => any::<usize>().prop_map(Mutation::Drop),
        1 => (any::<usize>(), any::<usize>()).prop_map(|(a, b)| Mutation::Swap(a, b)),
        2 => (line_value(), 0..VALUES.len()).prop_map(|((l, n), v)| Mutation::Value(l, n, v)),
        3 => (line_value(), -9i32..10).prop_map(|((l, n), k)| Mutation::Scale(l, n, k)),
    ]
}

/// The byte ranges of a line's values: after each `=`, up to the next `,` or `}` or the end.
fn values_of(line: &[u8]) -> Vec<(usize, usize)> {
    (0..line.len())
        .filter(|&i| line[i] == b'=')
        .map(|i| {
            let start = i + 1;
            let end = (start..line.len())
                .find(|&j| matches!(line[j], b',' | b'}'))
                .unwrap_or(line.len());
            (start, end)
        })
        .collect()
}

/// Applies a mutation to the file's bytes (lines are split at `\n`; a flipped byte may leave
/// text that is not UTF-8, which the later mutations keep as it is).
fn apply(bytes: &mut Vec<u8>, m: &Mutation) {
    if bytes.is_empty() {
        return;
    }
    let mut lines: Vec<Vec<u8>> = bytes.split(|&b| b == b'\n').map(<[u8]>::to_vec).collect();
    let count = lines.len();
    match *m {
        Mutation::Flip(at, bit) => {
            let at = at % bytes.len();
            bytes[at] ^= 1 << bit;
            return;
        }
        Mutation::Truncate(at) => {
            bytes.truncate(at % (bytes.len() + 1));
            return;
        }
        Mutation::Duplicate(l) => {
            let line = lines[l % count].clone();
            lines.insert(l % count, line);
        }
        Mutation::Drop(l) => {
            lines.remove(l % count);
        }
        Mutation::Swap(a, b) => {
            let assigned: Vec<usize> = (0..count)
                .filter(|&i| !values_of(&lines[i]).is_empty())
                .collect();
            if assigned.len() < 2 {
                return;
            }
            let (a, b) = (assigned[a % assigned.len()], assigned[b % assigned.len()]);
            let (sa, ea) = values_of(&lines[a])[0];
            let (sb, eb) = values_of(&lines[b])[0];
            let va = lines[a][sa..ea].to_vec();
            let vb = lines[b][sb..eb].to_vec();
            lines[a].splice(sa..ea, vb);
            lines[b].splice(sb..eb, va);
        }
        Mutation::Value(l, n, v) => {
            let line = &mut lines[l % count];
            let values = values_of(line);
            if let Some(&(start, end)) = values.get(n % values.len().max(1)) {
                line.splice(start..end, format!(" {} ", VALUES[v]).into_bytes());
            }
        }
        Mutation::Scale(l, n, k) => {
            let line = &mut lines[l % count];
            let values = values_of(line);
            let Some(&(start, end)) = values.get(n % values.len().max(1)) else {
                return;
            };
            let number = std::str::from_utf8(&line[start..end])
                .ok()
                .and_then(|t| t.trim().parse::<f64>().ok());
            if let Some(x) = number {
                let scaled = format!(" {:e} ", x * 10f64.powi(k));
                line.splice(start..end, scaled.into_bytes());
            }
        }
    }
    *bytes = lines.join(&b'\n');
}

/// The preset made cheap to solve (a smaller grid, shorter sweeps), or None when the smaller
/// grid does not resolve its harmonics.
fn small(preset: &Preset) -> Option<Preset> {
    let mut settings = Vec::new();
    let mut cap = |key: &str, max: f64| {
        // a key of the other problem is not the preset's to set
        let value = preset.key(key).and_then(|k| preset.get(k));
        if value.is_ok_and(|v| v > max) {
            settings.push(format!("{key}={max}"));
        }
    };
    cap("spatial.grid", MAX_GRID);
    cap("plane.sweep.points", MAX_SWEEP);
    cap("spatial.sweep.points", MAX_SWEEP);
    preset.with_settings(&settings).ok()
}

/// Solves as `wearlab solve` does (`spatial_report`: the state at t and mu* against pbar), a
/// spatial solve within `WORK` steps; Err holds the solver's refusal in words, or
/// `Stopped::Cancelled` at the bound. Also returns the steps a spatial solve took.
fn solve(preset: Preset) -> (Result<Result<(), finite::NonFinite>, Stopped>, usize) {
    let steps = AtomicUsize::new(0);
    let bounded = || steps.fetch_add(1, Ordering::Relaxed) >= WORK;
    let answer = match preset.problem {
        Problem::Plane => plane_report(&preset, PROFILE_POINTS)
            .map(|r| finite::check(&r))
            .map_err(Stopped::from),
        Problem::Spatial => {
            let (inputs, at) = (preset.spatial_inputs(), preset.spatial_state_at());
            pipeline::solve_until(&inputs, &at, &[], true, Stop::Asked(&bounded))
                .map(|r| finite::check(&r))
        }
    };
    (answer, steps.load(Ordering::Relaxed))
}

/// Solves on a thread of its own, so that a solve that hangs fails the test after `HANG`
/// instead of stalling it; Ok(false) when the work bound stopped it.
fn solve_bounded(preset: Preset, case: &str, most: &Cell<usize>) -> Result<bool, SolveError> {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(solve(preset));
    });
    match rx.recv_timeout(HANG) {
        Ok((answer, steps)) => {
            most.set(most.get().max(steps));
            match answer {
                Ok(Ok(())) => Ok(true),
                Ok(Err(nan)) => panic!("{case}: {nan}"),
                Err(Stopped::Cancelled) => Ok(false),
                Err(Stopped::Failed(e)) => Err(e),
            }
        }
        Err(mpsc::RecvTimeoutError::Timeout) => panic!("{case}: no answer within {HANG:?}"),
        Err(mpsc::RecvTimeoutError::Disconnected) => panic!("{case}: the solver panicked"),
    }
}

#[derive(Default)]
struct Counts {
    refused: Cell<usize>,
    solved: Cell<usize>,
    unsolvable: Cell<usize>,
    bounded: Cell<usize>,
    most_steps: Cell<usize>,
}

fn bump(c: &Cell<usize>) {
    c.set(c.get() + 1);
}

fn env_number(name: &str) -> Option<u64> {
    std::env::var(name).ok().and_then(|n| n.parse().ok())
}

#[test]
fn mutated_presets_load_or_say_why_and_solve_or_say_why() {
    let cases = env_number("PRESET_FUZZ_CASES").map_or(CASES, |n| n as u32);
    let config = Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    };
    let mut seed = SEED;
    if let Some(s) = env_number("PRESET_FUZZ_SEED") {
        seed[..8].copy_from_slice(&s.to_le_bytes());
    }
    let mut runner =
        TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &seed));
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("fuzzed.toml");
    // the data files a bundled preset reads lie beside it, as in presets/
    for d in wearlab::preset::BUNDLED_DATA {
        std::fs::write(dir.path().join(d.file), d.text).unwrap();
    }
    let counts = Counts::default();
    let strategy = (0..BUNDLED.len(), prop::collection::vec(mutation(), 1..4));
    runner
        .run(&strategy, |(file, mutations)| {
            let mut bytes = BUNDLED[file].text.as_bytes().to_vec();
            for m in &mutations {
                apply(&mut bytes, m);
            }
            let case = format!("{} {mutations:?}", BUNDLED[file].file);
            let loaded = match std::str::from_utf8(&bytes) {
                Ok(text) => parse(text, &path),
                Err(_) => {
                    std::fs::write(&path, &bytes).unwrap();
                    load(&path)
                }
            };
            let preset = match loaded {
                Ok(p) => p,
                Err(e) => {
                    let shown = e.to_string();
                    assert!(
                        shown.starts_with(&path.display().to_string()),
                        "{case}: {shown}"
                    );
                    assert!(!e.reason.trim().is_empty(), "{case}: {shown}");
                    assert!(!shown.contains("panicked"), "{case}: {shown}");
                    bump(&counts.refused);
                    return Ok(());
                }
            };
            let Some(preset) = small(&preset) else {
                bump(&counts.refused);
                return Ok(());
            };
            match solve_bounded(preset, &case, &counts.most_steps) {
                Ok(true) => bump(&counts.solved),
                Ok(false) => bump(&counts.bounded),
                Err(e) => {
                    assert!(!e.to_string().trim().is_empty(), "{case}");
                    bump(&counts.unsolvable);
                }
            }
            Ok(())
        })
        .unwrap();
    let (refused, solved, unsolvable, bounded) = (
        counts.refused.get(),
        counts.solved.get(),
        counts.unsolvable.get(),
        counts.bounded.get(),
    );
    eprintln!(
        "{cases} cases: {refused} refused, {solved} solved, {unsolvable} unsolvable, {bounded} \
         stopped at {WORK} steps; the most steps of a spatial solve {}",
        counts.most_steps.get()
    );
    // a run that solves nothing tests only the reader
    assert!(solved * 5 >= cases as usize, "{solved} of {cases} solved");
}
