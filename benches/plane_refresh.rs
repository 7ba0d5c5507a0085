//! A full plane refresh: what the screen draws first (the operating point, a 201-point profile
//! and a 200-point load sweep's curve), the sweep's verdicts that follow it, and the energy
//! identity of the operating point.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;

#[path = "common/refresh.rs"]
mod refresh;

fn refresh(c: &mut Criterion) {
    for r in refresh::refreshes() {
        c.bench_function(&format!("plane_refresh/{}", r.name), |b| {
            b.iter(|| black_box(r.curve()))
        });
        let solved = r.solved();
        c.bench_function(&format!("plane_sweep_verdicts/{}", r.name), |b| {
            b.iter(|| black_box(black_box(&solved).clone().judged()))
        });
        c.bench_function(&format!("plane_energy/{}", r.name), |b| {
            let sol = r.point();
            b.iter(|| black_box(wearlab::physics::plane::energy::energy(black_box(&sol))))
        });
    }
}

criterion_group!(benches, refresh);
criterion_main!(benches);
