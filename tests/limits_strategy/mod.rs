//! Strategies that draw a parameter across its whole allowed range (`physics::limits`): both
//! ends, 0 and inf where allowed, and log-uniform values in between (down to 1e-300 for ranges
//! that start at 0).
#![allow(dead_code)]

use proptest::prelude::*;
use wearlab::physics::limits::Limit;

fn log_between(lo: f64, hi: f64) -> BoxedStrategy<f64> {
    (lo.ln()..=hi.ln())
        .prop_map(move |l| l.exp().clamp(lo, hi))
        .boxed()
}

/// A value `limit` accepts, corners weighted up.
pub fn across(limit: &Limit) -> BoxedStrategy<f64> {
    let (min, max) = (limit.min, limit.max);
    let mut options: Vec<(u32, BoxedStrategy<f64>)> = vec![(1, Just(max).boxed())];
    if min > 0.0 {
        options.push((1, Just(min).boxed()));
        options.push((6, log_between(min, max)));
    } else if min == 0.0 {
        options.push((1, Just(0.0).boxed()));
        options.push((1, log_between(1e-300, max)));
        options.push((5, log_between(max * 1e-12, max)));
    } else {
        options.push((1, Just(min).boxed()));
        options.push((6, (min..=max).boxed()));
    }
    if limit.accepts(0.0) && min > 0.0 {
        options.push((1, Just(0.0).boxed()));
    }
    if limit.accepts(f64::INFINITY) {
        options.push((2, Just(f64::INFINITY).boxed()));
    }
    let strategy = proptest::strategy::Union::new_weighted(options);
    let limit = *limit;
    strategy
        .prop_filter("allowed", move |v| limit.accepts(*v))
        .boxed()
}

/// Poisson's ratio: 0, the largest double below 1/2, and uniform in between.
pub fn poisson() -> BoxedStrategy<f64> {
    prop_oneof![
        1 => Just(0.0),
        1 => Just(0.499_999_999_999_999_94),
        6 => 0.0f64..0.5,
    ]
    .boxed()
}
