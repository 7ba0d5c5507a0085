//! The explorer's thread (`engine::sweep_worker::SweepWorker`): a newer request cancels a map in
//! progress, whose end is then never delivered, and the newer one is answered to the end.

use std::sync::mpsc::channel;
use std::time::Duration;

use wearlab::engine::sweep_worker::{SweepRequest, SweepWorker};
use wearlab::physics::plane::Model;
use wearlab::preset::bundled;
use wearlab::sweeps::Opening;

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
