//! The bodies of the `plane_refresh` and `sweeps` benches, run a given number of times in one
//! process, for counting instructions under callgrind (docs/performance.md, "Instructions against
//! the code before the reshaping"): the count of 2N runs less that of N is N runs' work without the
//! process's start. Usage: `instructions WORKLOAD N`, WORKLOAD one of refresh_wide,
//! refresh_narrow, verdicts_wide, verdicts_narrow, curve_wide, curve_with_narrow, judged_wide,
//! judged_with_narrow, map_wide.

use std::hint::black_box;
use std::sync::atomic::AtomicBool;

use wearlab::sweeps::curve::{curve, solve};
use wearlab::sweeps::map::regime_map;

#[path = "../benches/common/explore_sweeps.rs"]
mod explore_sweeps;
#[path = "../benches/common/refresh.rs"]
mod refresh;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (Some(workload), Some(count)) = (
        args.get(1),
        args.get(2).and_then(|n| n.parse::<usize>().ok()),
    ) else {
        eprintln!("usage: instructions WORKLOAD N");
        std::process::exit(2);
    };
    let never = AtomicBool::new(false);
    for r in refresh::refreshes() {
        if *workload == format!("refresh_{}", r.name) {
            (0..count).for_each(|_| drop(black_box(r.curve())));
        }
        if *workload == format!("verdicts_{}", r.name) {
            let solved = r.solved();
            (0..count).for_each(|_| drop(black_box(solved.clone().judged())));
        }
    }
    let s = explore_sweeps::explore_sweeps();
    let unjudged = |spec| solve(&s.preset, spec, (&never).into()).map(|c| c.unjudged());
    for _ in 0..count {
        match workload.as_str() {
            "curve_wide" => drop(black_box(unjudged(&s.wide))),
            "curve_with_narrow" => drop(black_box(unjudged(&s.with_narrow))),
            "judged_wide" => drop(black_box(curve(&s.preset, &s.wide, &never))),
            "judged_with_narrow" => drop(black_box(curve(&s.preset, &s.with_narrow, &never))),
            "map_wide" => drop(black_box(regime_map(
                &s.preset,
                &s.map,
                &never,
                &mut |_| {},
            ))),
            _ => {}
        }
    }
}
