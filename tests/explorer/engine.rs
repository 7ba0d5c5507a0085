//! The engine's stages: an edit recomputes only what it touches (`docs/performance.md`, "The engine's stages").

use std::sync::mpsc::channel;
use std::time::Duration;

use wearlab::engine::{Answer, Engine, Output, Request, StageCounts, Worker};
use wearlab::preset::Preset;

fn full(preset: &Preset) -> Request {
    Request {
        preset: preset.clone(),
        overlays: true,
        energies: false,
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
            strip_check: 1,
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
        energies: false,
    };
    engine.run_staged(&request, |output, complete| {
        let Output::Plane(out) = output else { panic!() };
        stages.push((
            out.point.is_ok(),
            out.strip_check.is_some(),
            out.sweep.map(|s| s.judged),
            out.overlays.len(),
            complete,
        ));
        true
    });
    // the status first (point, no sweep yet), then its check against the strip model, then the
    // strip's own sweep's curve, then the curve with its verdicts; no overlays asked
    assert_eq!(
        stages,
        [
            (true, false, None, 0, false),
            (true, true, None, 0, false),
            (true, true, Some(false), 0, false),
            (true, true, Some(true), 0, true)
        ]
    );
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

// --- the period cell: partial contact and the running-in ---

use std::cell::Cell;

use wearlab::engine::{CellOutput, Progress};

/// The cell output of a spatial answer.
fn cell(output: &Output) -> &CellOutput {
    let Output::Spatial(Ok(out)) = output else {
        panic!("a spatial answer")
    };
    out.cell.as_ref().expect("solved on the period cell")
}

#[test]
fn a_time_step_replays_the_cached_running_in() {
    let mut engine = Engine::new();
    let mut preset = bundled("contact-lost.toml");
    let out = engine.run(&full(&preset));
    let c = cell(&out);
    let state = c.state.as_ref().unwrap();
    // the preset's premise: half the cell touches at t = 0 (its description)
    assert!(!state.outputs.complete && (0.4..0.6).contains(&state.outputs.contact_fraction));
    assert!(matches!(c.progress, Progress::Done { .. }));
    let t_cc = c.history.as_ref().unwrap().time_to_complete.unwrap();
    let steps = engine.counts.wear_steps;
    assert_eq!(
        (engine.counts.running_in, engine.counts.contact_state),
        (1, 1)
    );
    assert!(steps > 10, "{steps} wear steps");
    // the time only replays the running-in: no new running-in, no new wear step
    for t in [10.0, 0.5 * t_cc, t_cc + 1.0, 90.0] {
        preset.spatial.time = t;
        let out = engine.run(&full(&preset));
        let state = cell(&out).state.as_ref().unwrap();
        assert_eq!(state.time, t);
        assert_eq!(state.outputs.complete, t > t_cc, "t = {t}");
    }
    assert_eq!(
        (
            engine.counts.running_in,
            engine.counts.wear_steps,
            engine.counts.contact_state
        ),
        (1, steps, 5)
    );
    // the physics starts another
    preset.spatial.mean_pressure *= 1.1;
    engine.run(&full(&preset));
    assert_eq!(engine.counts.running_in, 2);
}

#[test]
fn an_input_change_cancels_the_running_in_and_a_time_change_resumes_it() {
    let mut engine = Engine::new();
    let mut preset = bundled("contact-lost.toml");
    preset.spatial.time = 30.0;
    // a newer request arrives during the fourth wear step: the request stops after it,
    // unanswered to the end
    let calls = Cell::new(0);
    let after_three = || {
        calls.set(calls.get() + 1);
        calls.get() > 3
    };
    let mut last = None;
    engine.run_cancellable(&full(&preset), &after_three, |output, complete| {
        last = Some((cell(&output).progress, complete));
        true
    });
    assert_eq!(engine.counts.wear_steps, 4);
    let Some((Progress::Running { towards, .. }, false)) = last else {
        panic!("{last:?}")
    };
    assert_eq!(towards, Some(30.0), "still on the way to t");
    // the newer request changes only the time: it goes on from the fourth step, to the same end
    preset.spatial.time = 40.0;
    let out = engine.run(&full(&preset));
    assert_eq!(cell(&out).state.as_ref().unwrap().time, 40.0);
    let resumed = engine.counts.wear_steps;
    let mut fresh = Engine::new();
    fresh.run(&full(&preset));
    assert_eq!(engine.counts.running_in, 1);
    assert_eq!(resumed, fresh.counts.wear_steps, "no step done twice");
    // a request that changes the physics starts afresh and leaves the other kept
    preset.friction.coefficient = 0.5;
    calls.set(0);
    engine.run_cancellable(&full(&preset), &after_three, |_, _| true);
    assert_eq!(
        (engine.counts.running_in, engine.counts.wear_steps),
        (2, resumed + 4)
    );
}

#[test]
fn the_running_in_reports_its_progress() {
    let mut engine = Engine::new();
    engine.progress_every = Duration::ZERO;
    let mut preset = bundled("contact-lost.toml");
    preset.spatial.time = 30.0;
    let mut seen = Vec::new();
    engine.run_staged(&full(&preset), |output, complete| {
        let c = cell(&output);
        let time = c.state.as_ref().unwrap().time;
        seen.push((c.progress, time, complete));
        true
    });
    // first the state at t = 0 (t not reached yet), then every step towards t with the last
    // stepped state, then the state at t while the stepping goes on to complete contact
    assert_eq!(
        seen[0],
        (
            Progress::Running {
                reached: 0.0,
                towards: Some(30.0)
            },
            0.0,
            false
        )
    );
    let (mut before, mut at_t) = (0.0, false);
    for (progress, time, complete) in &seen[1..seen.len() - 1] {
        assert!(!complete);
        match progress {
            Progress::Running {
                reached,
                towards: Some(t),
            } => {
                assert!(!at_t && *t == 30.0 && *reached > before && *time == *reached);
                before = *reached;
            }
            Progress::Running {
                reached,
                towards: None,
            } => {
                at_t = true;
                assert!(*reached >= 30.0 && *time == 30.0, "{seen:?}");
            }
            Progress::Done { .. } => assert_eq!(*time, 30.0),
        }
    }
    assert!(at_t, "{seen:?}");
    let (progress, time, complete) = *seen.last().unwrap();
    assert!(matches!(progress, Progress::Done { .. }) && time == 30.0 && complete);
    // one delivery per step but the two that end a part (t reached, contact complete), one
    // after each part, the first, and the last with mu*(pbar)
    assert_eq!(seen.len(), engine.counts.wear_steps + 2, "{seen:?}");
}

#[test]
fn the_worker_drops_a_running_in_when_a_newer_request_arrives() {
    // an egg-box at an eighth of its complete-contact load, with friction, on 128 x 128 nodes:
    // its running-in takes a few hundred wear steps of ~20 ms (`docs/performance.md`, "Benchmarks")
    let mut slow = bundled("jgh-egg-box.toml");
    slow.spatial.mean_pressure = 1.2e7;
    slow.friction.coefficient = 0.3;
    slow.material.thickness = 5e-4;
    slow.spatial.grid = 128;
    let (tx, rx) = channel::<Answer>();
    let worker = Worker::spawn(move |a| tx.send(a).is_ok());
    worker.submit(1, full(&slow));
    let first = rx.recv_timeout(Duration::from_secs(20)).unwrap();
    assert_eq!((first.generation, first.complete), (1, false));
    assert!(!cell(&first.output).state.as_ref().unwrap().outputs.complete);
    // the newer request, while the first one is stepping its wear
    worker.submit(2, full(&bundled("contact-lost.toml")));
    loop {
        let answer = rx.recv_timeout(Duration::from_secs(20)).unwrap();
        assert!(
            answer.generation == 2 || !answer.complete,
            "the first request is dropped before its end"
        );
        if answer.generation == 2 && answer.complete {
            assert!(matches!(
                cell(&answer.output).progress,
                Progress::Done { .. }
            ));
            break;
        }
    }
}

/// Where a sampled curve peaks: the x [m] of its largest value.
fn crest(x: &[f64], v: &[f64]) -> f64 {
    let i = (0..v.len()).max_by(|&a, &b| v[a].total_cmp(&v[b])).unwrap();
    x[i]
}

#[test]
fn the_running_in_lessons_say_what_the_solver_finds() {
    // the numbers each description quotes (presets/contact-lost.toml, rubber-running-in.toml)
    let mut engine = Engine::new();
    let close = |a: f64, b: f64, tol: f64| (a - b).abs() <= tol * b.abs();
    let lost = bundled("contact-lost.toml");
    let out = engine.run(&full(&lost));
    let Output::Spatial(Ok(sp)) = &out else {
        panic!()
    };
    let c = cell(&out);
    let o = c.state.as_ref().unwrap().outputs;
    let curve = c.load_curve.as_ref().unwrap().as_ref().unwrap();
    let t_cc = c.history.as_ref().unwrap().time_to_complete.unwrap();
    assert_eq!(o.contact_fraction, 0.5, "half the cell");
    assert!(close(t_cc, 62.6, 1e-3), "{t_cc}");
    let formal = sp.state.contact.complete_after.unwrap();
    assert!(close(formal, 35.0, 0.01), "{formal}");
    assert!(close(curve.complete_mean_pressure, 10.3e6, 3e-3));
    // the thin rubber: reversed coupling, a crest drifting backwards while the contact spreads
    let mut rubber = bundled("rubber-running-in.toml");
    let out = engine.run(&full(&rubber));
    let Output::Spatial(Ok(sp)) = &out else {
        panic!()
    };
    let c = cell(&out);
    let s0 = c.state.as_ref().unwrap().clone();
    let t_cc = c.history.as_ref().unwrap().time_to_complete.unwrap();
    assert_eq!((s0.outputs.contact_fraction * 100.0).floor(), 37.0);
    assert!(s0.outputs.psi > 0.0 && s0.outputs.mu_star > 1.0);
    assert!(close(t_cc, 4.31e3, 1e-3), "{t_cc}");
    let formal = sp.state.contact.complete_after.unwrap();
    assert!(close(formal, 2.1e3, 0.01), "{formal}");
    let h = rubber.material.thickness;
    let kh = rubber.spatial.harmonics[0].wavenumber_x * h;
    assert!(close(kh, 1.26, 3e-3), "{kh}");
    let curve = c.load_curve.as_ref().unwrap().as_ref().unwrap();
    assert!(close(curve.complete_mean_pressure, 180e3, 3e-3));
    let x = s0.grid.xs();
    assert_eq!(crest(&x, &s0.shape), 1.25e-3);
    assert!(
        crest(&x, &s0.pressure) > 1.25e-3,
        "the pressure crest is ahead"
    );
    rubber.spatial.time = 3000.0;
    let out = engine.run(&full(&rubber));
    let s = cell(&out).state.as_ref().unwrap().clone();
    // the legend's crest is the parabola's vertex (334 um), the node's within half a spacing
    let moved = crest(&x, &s.shape);
    assert!((moved - 334e-6).abs() <= 0.5 * x[1], "{moved}");
    assert!(crest(&x, &s.pressure) > moved && !s.outputs.complete);
}
