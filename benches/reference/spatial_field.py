"""Times the spatial field (pressure, shape and wear on an n x n grid over the cell) with plain
numpy, one matrix product per field, for the ratio against wearlab's `spatial_field` bench:
"fresh" allocates the three results anew at every call (as `field` does; both pay the first-touch
page faults of new multi-MB arrays), "reused" writes them into arrays allocated once (`out=`, as
`field_into` does). CPU time of this process (time.process_time), best of 7 repeats.

Usage: OPENBLAS_NUM_THREADS=1 python3 benches/reference/spatial_field.py SCIPY_REFERENCE_DIR
Prefix it and the bench with MALLOC_MMAP_THRESHOLD_=33554432 MALLOC_TRIM_THRESHOLD_=268435456 for
glibc to keep freed memory: fresh results then cost no page faults in either (README, Speed).
The cases are those of benches/spatial_field.rs (8 harmonics on 128 x 128, 32 on 512 x 512).
Not used by the Rust build or tests."""
import sys, time, timeit
import numpy as np

sys.path.insert(0, sys.argv[1] + "/spatial")
import wavywear as ww

def case(count, n):
    w = 2 * np.pi / 4e-3
    E, nu, h, mu, k, V, pbar = 1e7, 0.45, 5e-4, 0.8, 1e-12, 0.1, 2e6
    harm = [(1e-6 / (i + 1), w * (1 + i % 4), w * (i // 2), 0.3 * i, 1.0 + 0.2 * i) for i in range(count)]
    if count > 8:  # as benches/spatial_field.rs: more directions for the larger case
        harm = [(1e-6 / (i + 1), w * (1 + i % 8), w * (i // 8), 0.3 * i, 1.0 + 0.2 * i) for i in range(count)]
    G = E / (2 * (1 + nu))
    prob = ww.Problem(h, G, nu, mu, k * V, harm, pbar)
    t = 10.0
    lx = 2 * np.pi / w
    ly = lx
    xs = (np.arange(n) + 0.5) * lx / n
    ys = (np.arange(n) + 0.5) * ly / n
    state = prob.amp_phase(t)
    wx = np.array([hh[1] for hh in prob.harm]); wy = np.array([hh[2] for hh in prob.harm])
    A0 = np.array([hh[0] for hh in prob.harm]); rx0 = np.array([hh[3] for hh in prob.harm])
    A = np.array([s[0] for s in state]); rx = np.array([s[1] for s in state]); ry = np.array([s[2] for s in state])
    ratio = np.array([inf["ratio"] for inf in prob.info]); phi = np.array([inf["phi"] for inf in prob.info])
    mean_wear = k * V * pbar * t

    def fields():
        sy = np.sin(np.outer(wy, ys) + ry[:, None])              # H x n
        px = (A * ratio)[:, None] * np.sin(np.outer(wx, xs) + (rx + phi)[:, None])
        ux = A[:, None] * np.sin(np.outer(wx, xs) + rx[:, None])
        u0 = A0[:, None] * np.sin(np.outer(wx, xs) + rx0[:, None])
        p = pbar + sy.T @ px                                       # rows y, columns x
        u = sy.T @ ux
        wear = mean_wear + sy.T @ u0 - u
        return p, u, wear

    p, u, wear = (np.empty((n, n)) for _ in range(3))

    def fields_into():
        sy = np.sin(np.outer(wy, ys) + ry[:, None])
        px = (A * ratio)[:, None] * np.sin(np.outer(wx, xs) + (rx + phi)[:, None])
        ux = A[:, None] * np.sin(np.outer(wx, xs) + rx[:, None])
        u0 = A0[:, None] * np.sin(np.outer(wx, xs) + rx0[:, None])
        np.matmul(sy.T, px, out=p)
        np.add(p, pbar, out=p)
        np.matmul(sy.T, ux, out=u)
        np.matmul(sy.T, u0, out=wear)
        np.subtract(wear, u, out=wear)
        np.add(wear, mean_wear, out=wear)

    reps = 2000 if n <= 128 else 50
    time_of = lambda f: min(timeit.repeat(f, number=reps, repeat=7, timer=time.process_time)) / reps
    return time_of(fields), time_of(fields_into)

for count, n in [(8, 128), (32, 512)]:
    fresh, reused = case(count, n)
    print(f"numpy {n}x{n}x{count}: fresh {fresh * 1e3:.4f} ms, reused {reused * 1e3:.4f} ms")
