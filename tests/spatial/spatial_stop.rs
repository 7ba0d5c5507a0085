//! A contact solve told to stop ends within one product of its linear solve (counted in the
//! questions it asks its `Stop`, not in seconds): the work inside one active-set iteration of a
//! big grid is what `--max-seconds` and the explorer must not wait for.

use std::sync::atomic::{AtomicUsize, Ordering};

use wearlab::physics::SolveError;
use wearlab::physics::spatial::partial::Setup;
use wearlab::physics::spatial::partial::running_in::{Stopped, run_in_until};
use wearlab::physics::stop::{STOPPED, Stop};

use crate::common::{layer, sixty_four_harmonics, spatial};

/// Says stop from the `at`-th question on (never when `at` is 0), counting every question.
struct Counted {
    asked: AtomicUsize,
    at: usize,
}

impl Counted {
    fn at(at: usize) -> Counted {
        Counted {
            asked: AtomicUsize::new(0),
            at,
        }
    }

    fn now(&self) -> bool {
        let n = self.asked.fetch_add(1, Ordering::SeqCst) + 1;
        self.at > 0 && n >= self.at
    }

    fn asked(&self) -> usize {
        self.asked.load(Ordering::SeqCst)
    }
}

/// The 64 harmonics of `benches/partial_harmonics.rs` in partial contact on 128 x 128 nodes.
fn sixty_four() -> Setup {
    let inputs = spatial(
        layer(2e11, 0.3, 5e-4),
        0.3,
        0.0,
        1e-16,
        2.5e7,
        sixty_four_harmonics(),
    );
    Setup::new(&inputs, 128).unwrap()
}

#[test]
fn a_contact_solve_ends_within_one_product_of_being_told() {
    let setup = sixty_four();
    let solve = |stop: Stop| {
        let shape = setup.initial_shape.clone();
        setup.state(&mut setup.operator(), shape, 0.0, None, stop)
    };
    // untold, the solve asks before each active-set iteration and each product but the first
    let counted = Counted::at(0);
    let state = solve(Stop::Asked(&|| counted.now())).unwrap();
    let work = state.work;
    assert!(!state.outputs.complete);
    assert!(
        counted.asked() >= work.linear_iterations,
        "{} questions, {work:?}",
        counted.asked()
    );
    // told at the 5th question (inside the first linear solve), it asks nothing more
    for at in [1, 5, counted.asked() / 2] {
        let told = Counted::at(at);
        let stopped = solve(Stop::Asked(&|| told.now()));
        assert_eq!(
            stopped,
            Err(SolveError::NoSolution(STOPPED.into())),
            "at {at}"
        );
        assert_eq!(told.asked(), at);
    }
}

#[test]
fn a_running_in_told_inside_its_first_contact_solve_is_cancelled() {
    let setup = sixty_four();
    let told = Counted::at(3);
    let run = run_in_until(&setup, 1e-6, Stop::Asked(&|| told.now()));
    assert!(matches!(run, Err(Stopped::Cancelled)), "{run:?}");
    // the first solve's question, then the running-in's own reading of it
    assert_eq!(told.asked(), 4);
}
