//! The engine's stages: an edit recomputes only what it touches (design.md, "Incremental re-solve").

use wearlab::engine::{Engine, Output, StageCounts};

fn bundled(file: &str) -> wearlab::preset::Preset {
    wearlab::preset::bundled(file).unwrap().unwrap()
}

#[test]
fn nudging_the_load_does_not_recompute_the_sweep() {
    let mut engine = Engine::new();
    let mut preset = bundled("polymer-coating.toml");
    engine.run(&preset);
    // the preset's model and the two others overlaid on mu*(P)
    assert_eq!(
        engine.counts,
        StageCounts {
            operating_point: 1,
            load_sweep: 3,
            ..StageCounts::default()
        }
    );
    preset.plane.load *= 1.1;
    let out = engine.run(&preset);
    assert_eq!(engine.counts.operating_point, 2);
    assert_eq!(engine.counts.load_sweep, 3, "the sweeps do not depend on P");
    let Output::Plane(out) = out else { panic!() };
    assert!((out.point.unwrap().solution.inputs.load - 5500.0).abs() < 1e-9);
    // a parameter the sweep depends on recomputes it
    preset.friction.coefficient = 0.31;
    engine.run(&preset);
    assert_eq!(engine.counts.load_sweep, 6);
}

#[test]
fn stepping_time_does_not_recompute_the_harmonic_responses() {
    let mut engine = Engine::new();
    let mut preset = bundled("dispersion.toml");
    engine.run(&preset);
    assert_eq!(
        (
            engine.counts.responses,
            engine.counts.history,
            engine.counts.state
        ),
        (1, 1, 1)
    );
    for step in 1..=5 {
        preset.spatial.time = 10.0 * step as f64;
        engine.run(&preset);
    }
    assert_eq!(
        (
            engine.counts.responses,
            engine.counts.history,
            engine.counts.state
        ),
        (1, 1, 6)
    );
    // the amplitude changes the history but not the responses
    preset.spatial.harmonics[0].amplitude *= 2.0;
    engine.run(&preset);
    assert_eq!((engine.counts.responses, engine.counts.history), (1, 2));
    // the thickness changes the responses
    preset.material.thickness *= 2.0;
    engine.run(&preset);
    assert_eq!(engine.counts.responses, 2);
}

#[test]
fn the_worker_answers_the_newest_request() {
    let worker = wearlab::engine::Worker::spawn();
    let preset = bundled("polymer-coating.toml");
    for generation in 1..=20 {
        let mut p = preset.clone();
        p.plane.load = 1000.0 * generation as f64;
        worker.submit(generation, p);
    }
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(20);
    let mut last = 0;
    while last != 20 {
        assert!(
            std::time::Instant::now() < deadline,
            "no answer for generation 20"
        );
        if let Some((generation, out)) = worker.try_recv() {
            assert!(
                generation > last,
                "answers arrive in order and older pending ones are dropped"
            );
            last = generation;
            if generation == 20 {
                let Output::Plane(out) = out else { panic!() };
                assert_eq!(out.point.unwrap().solution.inputs.load, 20000.0);
            }
        } else {
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
    }
}
