//! The engine's stages: an edit recomputes only what it touches (design.md, "Incremental re-solve").

use std::sync::mpsc::channel;
use std::time::Duration;

use wearlab::engine::{Answer, Engine, Output, Request, StageCounts, Worker};
use wearlab::preset::Preset;

fn full(preset: &Preset) -> Request {
    Request {
        preset: preset.clone(),
        overlays: true,
    }
}

fn bundled(file: &str) -> wearlab::preset::Preset {
    wearlab::preset::bundled(file).unwrap().unwrap()
}

#[test]
fn nudging_the_load_does_not_recompute_the_sweep() {
    let mut engine = Engine::new();
    let mut preset = bundled("polymer-coating.toml");
    engine.run(&full(&preset));
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
    let out = engine.run(&full(&preset));
    assert_eq!(engine.counts.operating_point, 2);
    assert_eq!(engine.counts.load_sweep, 3, "the sweeps do not depend on P");
    let Output::Plane(out) = out else { panic!() };
    assert!((out.point.unwrap().solution.inputs.load - 5500.0).abs() < 1e-9);
    // a parameter the sweep depends on recomputes it
    preset.friction.coefficient = 0.31;
    engine.run(&full(&preset));
    assert_eq!(engine.counts.load_sweep, 6);
}

#[test]
fn stepping_time_does_not_recompute_the_harmonic_responses() {
    let mut engine = Engine::new();
    let mut preset = bundled("dispersion.toml");
    engine.run(&full(&preset));
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
        engine.run(&full(&preset));
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
    engine.run(&full(&preset));
    assert_eq!((engine.counts.responses, engine.counts.history), (1, 2));
    // the thickness changes the responses
    preset.material.thickness *= 2.0;
    engine.run(&full(&preset));
    assert_eq!(engine.counts.responses, 2);
}

#[test]
fn the_worker_answers_the_newest_request() {
    let (tx, rx) = channel::<Answer>();
    let worker = Worker::spawn(move |a| tx.send(a).is_ok());
    let preset = bundled("polymer-coating.toml");
    for generation in 1..=20 {
        let mut p = preset.clone();
        p.plane.load = 1000.0 * generation as f64;
        worker.submit(generation, full(&p));
    }
    let mut last = 0;
    loop {
        let answer = rx
            .recv_timeout(Duration::from_secs(20))
            .expect("an answer for generation 20");
        assert!(
            answer.generation >= last,
            "answers arrive in order and older pending ones are dropped"
        );
        last = answer.generation;
        let Output::Plane(out) = &answer.output else {
            panic!()
        };
        let load = out.point.as_ref().unwrap().solution.inputs.load;
        assert_eq!(
            load, answer.request.preset.plane.load,
            "an answer carries its request"
        );
        if answer.generation == 20 && answer.complete {
            assert_eq!(load, 20000.0);
            assert_eq!(out.overlays.len(), 2);
            break;
        }
    }
}

#[test]
fn the_operating_point_comes_first_and_overlays_only_when_asked() {
    let mut engine = Engine::new();
    let preset = bundled("hard-coating-strip.toml");
    let mut stages = Vec::new();
    let request = Request {
        preset: preset.clone(),
        overlays: false,
    };
    engine.run_staged(&request, |output, complete| {
        let Output::Plane(out) = output else { panic!() };
        stages.push((
            out.point.is_ok(),
            out.sweep.is_some(),
            out.overlays.len(),
            complete,
        ));
        true
    });
    // the status first (point, no sweep yet), then the strip's own sweep; no overlays asked
    assert_eq!(stages, [(true, false, 0, false), (true, true, 0, true)]);
    assert_eq!(engine.counts.load_sweep, 1);
    // a stage that is told to stop stops: the point is delivered, the sweeps are skipped
    let mut other = preset.clone();
    other.plane.load *= 1.1;
    other.friction.coefficient += 0.01;
    let mut deliveries = 0;
    engine.run_staged(&full(&other), |_, _| {
        deliveries += 1;
        false
    });
    assert_eq!((deliveries, engine.counts.load_sweep), (1, 1));
    // everything cached: one complete delivery
    let mut deliveries = Vec::new();
    engine.run_staged(&request, |_, complete| {
        deliveries.push(complete);
        true
    });
    assert_eq!(deliveries, [true]);
}

#[test]
fn the_cache_keeps_the_latest_eight_operating_points() {
    let mut engine = Engine::new();
    let mut preset = bundled("polymer-coating.toml");
    let loads: Vec<f64> = (0..9).map(|i| 1000.0 * (i + 1) as f64).collect();
    for load in &loads[..8] {
        preset.plane.load = *load;
        engine.run(&full(&preset));
    }
    assert_eq!(engine.counts.operating_point, 8);
    preset.plane.load = loads[0];
    engine.run(&full(&preset));
    assert_eq!(engine.counts.operating_point, 8, "the first is still kept");
    preset.plane.load = loads[8];
    engine.run(&full(&preset));
    assert_eq!(engine.counts.operating_point, 9);
    // the least recently used one (2 kN/m) went out; 1 kN/m was used again and stays
    preset.plane.load = loads[0];
    engine.run(&full(&preset));
    assert_eq!(engine.counts.operating_point, 9);
    preset.plane.load = loads[1];
    engine.run(&full(&preset));
    assert_eq!(engine.counts.operating_point, 10);
}
