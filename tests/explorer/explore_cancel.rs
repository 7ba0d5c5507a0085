//! The explorer's thread (`engine::sweep_worker::SweepWorker`): a newer request cancels a map in
//! progress, whose end is then never delivered, and the newer one is answered to the end; inside
//! a spatial point, the running-in stops within one time step of the newer request (counted in
//! the questions the work asks its `Stop`, not in seconds); the explorer's own running-in stops
//! inside a contact solve and goes on later with the same steps.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::channel;
use std::time::Duration;

use wearlab::engine::sweep_worker::{SweepRequest, SweepWorker};
use wearlab::engine::{CellOutput, Engine, Output, Request};
use wearlab::physics::Spacing;
use wearlab::physics::plane::Model;
use wearlab::physics::spatial::partial::running_in::Stopped;
use wearlab::physics::stop::Stop;
use wearlab::preset::{Preset, bundled};
use wearlab::sweeps::Opening;
use wearlab::sweeps::axis::Axis;
use wearlab::sweeps::map::{MapSpec, regime_map};
use wearlab::sweeps::point;
use wearlab::sweeps::quantity::QuantityKey;

fn map_request(model: Model) -> SweepRequest {
    let mut preset = bundled("friction-or-wear-map.toml").unwrap().unwrap();
    preset.plane.model = model;
    preset.material.thickness = 1e-3;
    let job = match wearlab::sweeps::opening(&preset).unwrap().unwrap() {
        Opening::Map(m) => Opening::Map(m),
        other => panic!("{other:?}"),
    };
    SweepRequest { preset, job }
}

#[test]
fn a_newer_input_cancels_a_map_in_progress() {
    let (tx, rx) = channel();
    let explorer = SweepWorker::spawn(move |a| tx.send(a).is_ok());
    // a 41 x 41 strip map takes seconds; the first pass comes, then the newer request
    explorer.submit(1, map_request(Model::Strip));
    let first = rx
        .recv_timeout(Duration::from_secs(60))
        .expect("a first pass");
    assert_eq!((first.generation, first.complete), (1, false));
    let mut newer = map_request(Model::Wide);
    newer.preset.friction.coefficient = 0.4;
    explorer.submit(2, newer);
    loop {
        let a = rx.recv_timeout(Duration::from_secs(60)).expect("an answer");
        // the older map may still deliver a pass already under way, never its end
        assert!(
            !(a.generation == 1 && a.complete),
            "the cancelled map finished"
        );
        if a.generation == 2 && a.complete {
            break;
        }
    }
}

/// A newer request that arrives at the `at`-th question of the work (its `Stop`), counting every
/// question: the work asks before every time step and every active-set iteration of a running-in.
struct Newer {
    asked: AtomicUsize,
    at: usize,
}

impl Newer {
    fn at(at: usize) -> Newer {
        Newer {
            asked: AtomicUsize::new(0),
            at,
        }
    }

    fn arrived(&self) -> bool {
        self.asked.fetch_add(1, Ordering::SeqCst) + 1 >= self.at
    }

    fn asked(&self) -> usize {
        self.asked.load(Ordering::SeqCst)
    }
}

/// "contact-lost" on 1024 nodes: partial at t = 0, its running-in takes thousands of time steps
/// (`wearlab solve` takes 5.8 s in release).
fn costly() -> Preset {
    let p = bundled("contact-lost.toml").unwrap().unwrap();
    p.with_settings(&["spatial.grid=1024"]).unwrap()
}

#[test]
fn a_newer_request_stops_a_spatial_point_within_one_time_step() {
    let newer = Newer::at(40);
    let solved = point::solve_until(&costly(), Stop::Asked(&|| newer.arrived()));
    assert!(matches!(solved, Err(Stopped::Cancelled)), "{solved:?}");
    // after the 40th question said stop, no step is taken: the stepping's loop and the
    // running-in's end ask once more each
    assert!(newer.asked() <= 42, "{} questions", newer.asked());
}

#[test]
fn a_newer_request_stops_a_map_of_running_ins_inside_its_points() {
    let p = costly();
    let axis = |key: &str, ends: [f64; 2]| {
        Axis::new(&p, p.key(key).unwrap(), ends, 5, Spacing::Linear).unwrap()
    };
    let spec = MapSpec {
        x: axis("spatial.mean_pressure", [1e6, 5e6]),
        y: axis("friction.coefficient", [0.0, 0.5]),
        quantity: QuantityKey::parse("mu_star", &p).unwrap(),
    };
    // the newer request arrives while the first pass (3 x 3 points, each a running-in) is under
    // way: between points alone, the map would ask only 9 questions and finish its pass
    let newer = Newer::at(200);
    let mut passes = 0;
    let map = regime_map(&p, &spec, Stop::Asked(&|| newer.arrived()), &mut |_| {
        passes += 1
    });
    assert!(map.is_none() && passes == 0);
    // each of the 9 points asks at most 3 more questions after it (the stepping's loop, the
    // running-in's end, the map keeping the point or not; a point not started asks once), and
    // takes no further step
    assert!(newer.asked() <= 200 + 3 * 9, "{} questions", newer.asked());
}

fn cell_of(output: &Output) -> Option<&CellOutput> {
    let Output::Spatial(Ok(out)) = output else {
        return None;
    };
    out.cell.as_ref().ok()
}

#[test]
fn the_explorers_running_in_stops_inside_a_contact_solve_and_resumes_the_same() {
    // "contact-lost" on its own 64 nodes: every step a partial-contact solve
    let mut preset = bundled("contact-lost.toml").unwrap().unwrap();
    preset.spatial.time = 30.0;
    let request = Request {
        preset: preset.clone(),
        overlays: false,
        energies: false,
    };
    // untold, the running-in asks several questions a wear step: before the step, after it (the
    // explorer's own check), and inside its contact solve (each active-set iteration and each
    // product of the linear solve but the first)
    let mut engine = Engine::new();
    let counted = Newer::at(usize::MAX);
    engine.run_stoppable(&request, Stop::Asked(&|| counted.arrived()), |_, _| true);
    let steps = engine.counts.wear_steps;
    let asked = counted.asked();
    assert!(asked > 4 * steps, "{asked} questions, {steps} steps");
    // a newer request arrives half-way through the questions: most of them inside a contact
    // solve, where the explorer used to wait for the step's end
    let mut engine = Engine::new();
    let newer = Newer::at(asked / 2);
    let mut last = None;
    engine.run_stoppable(
        &request,
        Stop::Asked(&|| newer.arrived()),
        |output, complete| {
            last = Some((cell_of(&output).map(|c| c.progress), complete));
            true
        },
    );
    // no step after it, and the work asks once more (to tell a cut step from a failed one)
    assert!(newer.asked() <= newer.at + 1, "{} questions", newer.asked());
    let cut = engine.counts.wear_steps;
    assert!(cut > 0 && cut < steps, "{cut} of {steps} steps");
    assert!(!matches!(last, Some((_, true))), "{last:?}");
    // the next request goes on from there: the same steps and the same state at t as one
    // uncut run, the cut step not counted as done
    let resumed = engine.run(&request);
    let mut fresh = Engine::new();
    let whole = fresh.run(&request);
    assert_eq!(engine.counts.running_in, 1);
    assert_eq!(engine.counts.wear_steps, fresh.counts.wear_steps);
    assert_eq!(engine.counts.wear_steps, steps);
    let state = |o: &Output| cell_of(o).unwrap().state.clone().unwrap();
    assert_eq!(state(&resumed), state(&whole));
}
