"""The frictionless half-space cases of benches/partial_harmonics.rs solved by Tamaas (a public
Westergaard boundary-element code, Polonsky & Keer's conjugate-gradient solver, Frerot et al.,
JOSS 2020), for a second answer and a time to compare with.

The punch shape U = sum A sin(wx x + rx) sin(wy y + ry) on the 1 mm cell (docs/physics/
spatial-partial.md section 1), sampled at x_i = i L/N as wearlab's grid samples it; the contact is
where U is highest, as for Tamaas's surface heights. Steel (E = 200 GPa, nu = 0.3), pbar = 25 MPa.

Run: OMP_NUM_THREADS=1 /work/venv-tamaas/bin/python scripts/tamaas-comparison/partial_harmonics.py
Prints, per case: contact fraction, p_max [Pa], mean gap [m] (<gap> = mean of the gap field), and
the median wall time of REPEATS cold solves [ms].
"""

import math
import statistics
import time

import numpy as np
import tamaas as tm

L = 1e-3
E, NU = 2.0e11, 0.3
PBAR = 2.5e7
DELTA = 1e-7
REPEATS = 3


def egg_box():
    """The egg-box of presets/jgh-egg-box.toml: Delta sin(k x + pi/2) sin(k y + pi/2)."""
    k = 2 * math.pi / L
    return [(DELTA, k, k, math.pi / 2, math.pi / 2)]


def sixty_four():
    """The 64 harmonics of benches/partial_harmonics.rs: (i, j) k0, amplitudes 1/(i^2 + j^2)
    scaled to the egg-box's rms height, phases spread by the golden ratio."""
    k0 = 2 * math.pi / L
    golden = 0.5 * (math.sqrt(5) - 1)
    out = []
    n = 0
    for i in range(1, 9):
        for j in range(1, 9):
            out.append([
                1.0 / (i * i + j * j),
                i * k0,
                j * k0,
                2 * math.pi * (((2 * n + 1) * golden) % 1.0),
                2 * math.pi * (((2 * n + 2) * golden) % 1.0),
            ])
            n += 1
    scale = DELTA / math.sqrt(sum(h[0] ** 2 for h in out))
    return [(a * scale, wx, wy, px, py) for a, wx, wy, px, py in out]


def surface(harmonics, n):
    x = np.arange(n) * L / n
    xx, yy = np.meshgrid(x, x, indexing="ij")
    u = np.zeros((n, n))
    for a, wx, wy, px, py in harmonics:
        u += a * np.sin(wx * xx + px) * np.sin(wy * yy + py)
    return u


def solve(u, n):
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [L, L], [n, n])
    model.E, model.nu = E, NU
    solver = tm.PolonskyKeerRey(model, u, 1e-12)
    solver.max_iter = 10000
    start = time.perf_counter()
    solver.solve(PBAR)
    took = time.perf_counter() - start
    p = np.array(model.traction)
    gap = np.array(model.displacement) - u
    gap -= gap[p > 0].mean()
    return took, p, gap


def main():
    tm.set_log_level(tm.LogLevel.error)
    for name, harmonics in [("1", egg_box()), ("64", sixty_four())]:
        for n in [64, 128, 256]:
            if name == "64" and n < 128:
                # wearlab needs 16 nodes per wavelength of the 8th harmonic
                continue
            u = surface(harmonics, n)
            times = []
            for _ in range(REPEATS):
                took, p, gap = solve(u, n)
                times.append(took)
            print(
                f"tamaas/{name}/{n}x{n}: contact {np.mean(p > 0):.4f}, p_max {p.max():.6e} Pa, "
                f"mean p {p.mean():.6e} Pa, mean gap {gap.mean():.6e} m, "
                f"median {1e3 * statistics.median(times):.2f} ms"
            )


if __name__ == "__main__":
    main()
