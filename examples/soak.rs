//! A soak of the explorer's engine, run by hand (not by `cargo test`):
//!
//!   cargo run --release --example soak -- [MINUTES] [PRESET]
//!
//! (10 minutes of `presets/dispersion.toml` by default). For MINUTES it drives the explorer's two
//! background workers as a user at the keyboard does: an edit of the preset every 150 ms (the
//! mean pressure, into partial contact and out again, so the period cell is solved and worn; the
//! friction coefficient; the time; the grid), each submitted to the solve worker with the charts'
//! overlays, and every 2 s a sweep or a regime map of the sweep worker, a newer request always
//! replacing the older one. Every 10 s it prints the process's resident memory (VmRSS of
//! /proc/self/status), and at the end its start, largest and end. The edits come from a fixed
//! seed: every run asks the same things.

use std::sync::mpsc;
use std::time::{Duration, Instant};

use wearlab::engine::sweep_worker::{SweepRequest, SweepWorker};
use wearlab::engine::{Request, Worker};
use wearlab::physics::Spacing;
use wearlab::preset::{Preset, load};
use wearlab::sweeps::Opening;
use wearlab::sweeps::axis::Axis;
use wearlab::sweeps::curve::CurveSpec;
use wearlab::sweeps::map::MapSpec;
use wearlab::sweeps::quantity::QuantityKey;

/// The resident memory of this process [MB], from /proc/self/status (0 where it cannot be read).
fn rss_mb() -> f64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find_map(|l| l.strip_prefix("VmRSS:"))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse::<f64>().ok())
        .map_or(0.0, |kb| kb / 1024.0)
}

/// A 64-bit linear congruential generator (Knuth's MMIX constants): the same edits every run.
struct Lcg(u64);

impl Lcg {
    /// A number in [0, 1).
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// One of `options`.
    fn pick<'a, T>(&mut self, options: &'a [T]) -> &'a T {
        &options[((self.next() * options.len() as f64) as usize).min(options.len() - 1)]
    }
}

/// The preset with one random edit.
fn edit(base: &Preset, rng: &mut Lcg) -> Preset {
    let pbar = base.spatial.mean_pressure;
    let setting = match (rng.next() * 4.0) as usize {
        // from a tenth (partial contact, the cell worn) to twice the preset's
        0 => format!("spatial.mean_pressure={}", pbar * (0.1 + 1.9 * rng.next())),
        1 => format!("friction.coefficient={}", rng.next()),
        2 => format!("spatial.time={}", base.spatial.duration * rng.next()),
        _ => format!("spatial.grid={}", rng.pick(&[32, 64, 128])),
    };
    base.with_settings(&[setting])
        .unwrap_or_else(|_| base.clone())
}

/// A sweep or a map of the preset, over the mean pressure and the friction coefficient.
fn exploration(preset: &Preset, rng: &mut Lcg) -> Option<SweepRequest> {
    let pbar = preset.spatial.mean_pressure;
    let axis = |key: &str, ends: [f64; 2], n: usize, spacing: Spacing| {
        Axis::new(preset, preset.key(key).ok()?, ends, n, spacing).ok()
    };
    let pressures = axis(
        "spatial.mean_pressure",
        [0.05 * pbar, 2.0 * pbar],
        *rng.pick(&[20, 40]),
        Spacing::Log,
    )?;
    let quantity = QuantityKey::parse(rng.pick::<&str>(&["mu_star", "load"]), preset).ok()?;
    let job = if rng.next() < 0.5 {
        Opening::Curve(CurveSpec {
            axis: pressures,
            quantity,
            models: Vec::new(),
        })
    } else {
        Opening::Map(MapSpec {
            x: pressures,
            y: axis("friction.coefficient", [0.0, 1.0], 16, Spacing::Linear)?,
            quantity,
        })
    };
    Some(SweepRequest {
        preset: preset.clone(),
        job,
    })
}

fn main() {
    let mut args = std::env::args().skip(1);
    let minutes: f64 = args.next().and_then(|m| m.parse().ok()).unwrap_or(10.0);
    let file = args
        .next()
        .unwrap_or_else(|| "presets/dispersion.toml".into());
    let base = load(std::path::Path::new(&file)).expect("a readable preset");
    let (answers, answered) = mpsc::channel();
    let solved = answers.clone();
    let worker = Worker::spawn(move |a| solved.send(a.complete).is_ok());
    let sweeps = SweepWorker::spawn(move |a| answers.send(a.complete).is_ok());
    let mut rng = Lcg(0x5eed);
    let (start, length) = (Instant::now(), Duration::from_secs_f64(minutes * 60.0));
    let (first, mut largest) = (rss_mb(), 0.0f64);
    let (mut generation, mut complete, mut edits, mut explorations) = (0u64, 0usize, 0usize, 0);
    let mut next_report = Duration::ZERO;
    let mut next_exploration = Duration::from_secs(2);
    println!("time [s], RSS [MB], edits, sweeps and maps asked, answers complete");
    while start.elapsed() < length {
        let now = start.elapsed();
        generation += 1;
        let preset = edit(&base, &mut rng);
        if now >= next_exploration {
            next_exploration += Duration::from_secs(2);
            if let Some(request) = exploration(&preset, &mut rng) {
                sweeps.submit(generation, request);
                explorations += 1;
            }
        }
        worker.submit(
            generation,
            Request {
                preset,
                overlays: true,
                energies: false,
            },
        );
        edits += 1;
        std::thread::sleep(Duration::from_millis(150));
        complete += answered.try_iter().filter(|c| *c).count();
        let rss = rss_mb();
        largest = largest.max(rss);
        if now >= next_report {
            next_report += Duration::from_secs(10);
            println!(
                "{:7.1}, {rss:7.1}, {edits}, {explorations}, {complete}",
                now.as_secs_f64()
            );
        }
    }
    let end = rss_mb();
    println!(
        "RSS over {minutes} min of {file}: start {first:.1} MB, largest {largest:.1} MB, end \
         {end:.1} MB ({edits} edits, {explorations} sweeps and maps, {complete} complete answers)"
    );
}
