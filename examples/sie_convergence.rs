//! The FFT active-set solver's convergence in the number of nodes N on the 1-D half-plane with
//! friction (docs/physics/spatial-partial.md section 6, route 6), against the singular integral
//! equation of `tests/spatial/sie_reference.rs`: for mu = 0.2, 0.5 and 1 under a 1 um, 1 mm wave,
//! the errors of the contact fraction (absolute), p_max, psi and the mean gap (relative) at
//! N = 256 ... 65536. Run with `cargo run --release --example sie_convergence` (a few seconds).

#[path = "../tests/common/mod.rs"]
mod common;
#[path = "../tests/spatial/sie_reference.rs"]
mod sie_reference;

use sie_reference::{fft, solve_sie, wave};

fn main() {
    for mu in [0.2, 0.5, 1.0] {
        let wv = wave(mu);
        let sie = solve_sie(&wv, 0.2 * wv.l, 40);
        let exact = sie.outputs(&wv);
        println!(
            "mu = {mu}: c/l = {:.6e}, pbar = {:.6e} Pa, psi = {:.6e} Pa, mean gap = {:.6e} m",
            sie.c / wv.l,
            sie.pbar,
            exact[2],
            exact[3]
        );
        for n in [256, 1024, 4096, 16384, 65536] {
            let got = fft(&wv, sie.pbar, n);
            println!(
                "  N = {n:6}: fraction {:+.2e}, p_max {:+.2e}, psi {:+.2e}, mean gap {:+.2e}",
                got[0] - exact[0],
                got[1] / exact[1] - 1.0,
                got[2] / exact[2] - 1.0,
                got[3] / exact[3] - 1.0
            );
        }
    }
}
