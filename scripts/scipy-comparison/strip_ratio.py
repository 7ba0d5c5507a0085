"""Speed of wearlab's strip model against the SciPy reference, as ratios measured in one run.

Not needed by the Rust build or tests. Usage (from the repository root):
    cargo build --release --example strip_point
    OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 python3 scripts/scipy-comparison/strip_ratio.py \
        /path/to/scipy-reference/plane [rounds]
The reference is `general_solve(P, R, E, nu, h, mu, kW, tau0)` of the project's independent SciPy
implementation (kernel table built once beforehand, as wearlab's is). For each case and round the
two are timed alternately, SciPy first, each as the median of a few solves (`examples/strip_point.rs`
prints wearlab's, rules warm and, with `cold`, rebuilt for every solve); the ratio is
SciPy/wearlab per round, and the median over rounds is reported. Both single-threaded (wearlab uses
one thread; OpenBLAS is pinned to one by the environment above).
Case: E = 1e10 Pa, nu = 0.3, h = 1e-5 m, R = 0.05 m, mu = 0.3, k m = 0.5; P chosen for
(a+b)/h of about 1, 5, 20, 56 and 86 (56 is the strip preset at P = 1e5 N/m).
"""
import os
import statistics
import subprocess
import sys
import time

E, NU, H, R, MU, KM = 1e10, 0.3, 1e-5, 0.05, 0.3, 0.5
LOADS = [5.5, 300.0, 1.05e4, 1e5, 2.4e5]
REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TIMER = os.path.join(REPO, "target", "release", "examples", "strip_point")


def scipy_median(general, kernels, load, reps):
    m = kernels.m_of(E, NU)
    times = []
    for _ in range(reps):
        start = time.perf_counter()
        sol = general.general_solve(load, R, E, NU, H, MU, KM / m, 0.0)
        times.append(time.perf_counter() - start)
    return statistics.median(times), sol["L"] / H, sol["mu_star"]


def wearlab_median(load, reps, cold):
    args = [TIMER] + [repr(v) for v in (E, NU, H, R, MU, KM, load)] + [str(reps)]
    out = subprocess.run(args + (["cold"] if cold else []), check=True, capture_output=True, text=True)
    seconds, l_over_h, mu_star = (float(v) for v in out.stdout.split())
    return seconds, l_over_h, mu_star


def main():
    sys.path.insert(0, sys.argv[1])
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    import general
    import kernels
    kernels.strip_kernels(NU)
    print("(a+b)/h   SciPy [s]   wearlab warm [s]  cold [s]   ratio warm  ratio cold   |mu* diff|")
    for load in LOADS:
        warm_ratios, cold_ratios, rows = [], [], []
        for _ in range(rounds):
            reps = 3 if load > 5e4 else 5
            t_ref, l_ref, mu_ref = scipy_median(general, kernels, load, reps)
            t_warm, l_w, mu_w = wearlab_median(load, 20, cold=False)
            t_cold, _, _ = wearlab_median(load, 5, cold=True)
            warm_ratios.append(t_ref / t_warm)
            cold_ratios.append(t_ref / t_cold)
            rows.append((t_ref, t_warm, t_cold, l_w, abs(mu_w - mu_ref)))
        t_ref, t_warm, t_cold, l_w, dmu = rows[len(rows) // 2]
        print(f"{l_w:7.2f}   {t_ref:9.4f}   {t_warm:14.5f}  {t_cold:8.5f}   {statistics.median(warm_ratios):9.1f}x"
              f"  {statistics.median(cold_ratios):9.1f}x   {dmu:.1e}")


if __name__ == "__main__":
    main()
