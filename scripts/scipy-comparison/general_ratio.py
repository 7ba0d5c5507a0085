"""Speed of wearlab's general plane solver against the SciPy reference, as ratios measured in one run.

Not needed by the Rust build or tests. Usage (from the repository root):
    cargo build --release --example general_point
    OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 python3 scripts/scipy-comparison/general_ratio.py \
        /path/to/scipy-reference/plane-general [rounds]
The reference is the project's independent SciPy implementation of the general plane problem:
`gj.GJ(p, N).solve(P, d_guess)` (Gauss-Jacobi collocation with Newton, Brent on the half-width;
wide model, half-plane and strip, N = 64 nodes as wearlab's wide model) and `narrowg.solve(p, L_guess)`
(the Winkler ODE shot with DOP853, Brent on the trailing end); the strip kernel table is built once
beforehand, as wearlab's is. For each case and round the two are timed alternately, SciPy first, each
as the median of a few solves (`examples/general_point.rs` prints wearlab's: rules warm and, with
`cold`, built anew for every solve); the ratio is SciPy/wearlab per round, and the median over rounds
is reported with the relative differences of mu* and psi between the two. Both single-threaded
(wearlab uses one thread here; OpenBLAS is pinned to one by the environment above).
Cases (the operating points of benches/plane_general.rs): E = 1e10 Pa, nu = 0.3, mu = 0.3,
tau0 = 1e5 Pa, k m = 0.5, p0 = 1e8 Pa, P = 1e4 N/m; a power punch R = 0.05 m, n = 3 with the wear
law n = 2 and a shear cap tau_max = 2e6 Pa (the strip without the cap), and a flat punch
c = 0.1 mm with edges rounded to r = 0.05 m with the linear laws.
"""
import math
import os
import statistics
import subprocess
import sys
import time

E, NU, MU, TAU0, KM, P0, LOAD = 1e10, 0.3, 0.3, 1e5, 0.5, 1e8, 1e4
INF = math.inf
POWER = ("power", 0.05, 3.0)
FLAT = ("flat", 1e-4, 0.05)
# name, model, h [m], shape, wear exponent, tau_max [Pa]
CASES = [
    ("power_capped_half_plane", "wide", INF, POWER, 2.0, 2e6),
    ("power_capped_1mm", "wide", 1e-3, POWER, 2.0, 2e6),
    ("rounded_flat_half_plane", "wide", INF, FLAT, 1.0, INF),
    ("power_capped_narrow", "narrow", 1e-4, POWER, 2.0, 2e6),
    ("rounded_flat_narrow", "narrow", 1e-4, FLAT, 1.0, INF),
    ("power_strip_0.1mm", "strip", 1e-4, POWER, 2.0, INF),
    ("rounded_flat_strip_0.1mm", "strip", 1e-4, FLAT, 1.0, INF),
]
NODES = 64
REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TARGET = os.environ.get("CARGO_TARGET_DIR", os.path.join(REPO, "target"))
TIMER = os.path.join(TARGET, "release", "examples", "general_point")


def scipy_median(mods, case, reps):
    common, gj, narrowg = mods
    _, model, h, shape, n_w, tau_max = case
    kind, first, second = shape
    punch = common.Power(first, second) if kind == "power" else common.Flat(first, second)
    p = common.Params(E, NU, h, MU, TAU0, tau_max, KM / common.m_of(E, NU), n_w, P0, punch,
                      LOAD, model)
    times = []
    for _ in range(reps):
        start = time.perf_counter()
        if model == "narrow":
            sol = narrowg.solve(p, 1e-3)
        else:
            sol = gj.GJ(p, NODES).solve(LOAD, 1e-3)
        times.append(time.perf_counter() - start)
    width = sol["a"] + sol["b"]
    mu_star = (sol["Q1"] + sol["psi"] - TAU0 * width) / LOAD
    return statistics.median(times), sol["psi"], mu_star


def wearlab_median(case, reps, cold):
    _, model, h, shape, n_w, tau_max = case
    numbers = (E, NU, h, MU, TAU0, tau_max, KM, n_w, P0)
    args = [TIMER, model] + [repr(v) for v in numbers] + [":".join(str(v) for v in shape)]
    args += [repr(LOAD), str(reps)] + (["cold"] if cold else [])
    out = subprocess.run(args, check=True, capture_output=True, text=True)
    seconds, l_over_h, psi, mu_star = (float(v) for v in out.stdout.split())
    return seconds, l_over_h, psi, mu_star


def main():
    sys.path.insert(0, sys.argv[1])
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    import common
    import gj
    import kernels
    import narrowg
    kernels.strip_kernels(NU)
    mods = (common, gj, narrowg)
    print(f"{'case':26} (a+b)/h   SciPy [s]  wearlab warm [s]  cold [s]  ratio warm  ratio cold"
          "  mu* rel diff  psi rel diff")
    for case in CASES:
        warm_ratios, cold_ratios, rows = [], [], []
        for _ in range(rounds):
            reps = 3 if case[1] == "narrow" else 5
            t_ref, psi_ref, mu_ref = scipy_median(mods, case, reps)
            t_warm, l_h, psi_w, mu_w = wearlab_median(case, 20, cold=False)
            t_cold, _, _, _ = wearlab_median(case, 5, cold=True)
            warm_ratios.append(t_ref / t_warm)
            cold_ratios.append(t_ref / t_cold)
            rows.append((t_ref, t_warm, t_cold, l_h, abs(mu_w / mu_ref - 1), abs(psi_w / psi_ref - 1)))
        t_ref, t_warm, t_cold, l_h, dmu, dpsi = sorted(rows)[len(rows) // 2]
        print(f"{case[0]:26} {l_h:7.2f}  {t_ref:9.4f}  {t_warm:16.6f}  {t_cold:8.6f}"
              f"  {statistics.median(warm_ratios):9.1f}x  {statistics.median(cold_ratios):9.1f}x"
              f"  {dmu:12.1e}  {dpsi:12.1e}")


if __name__ == "__main__":
    main()
