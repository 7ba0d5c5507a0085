"""The rough-surface cases of benches/spatial_surface.rs solved by other codes, for a second
answer and a time to compare with:

- rough-256: the frictionless partial contact of a self-affine 256 x 256 map on a steel
  half-space, by Tamaas (Polonsky & Keer's conjugate gradients, Frerot et al., JOSS 2020) to
  1e-12 as in partial_harmonics.py;
- rough-1024-complete: the complete-contact state at t of a 1024 x 1024 map on a 10 um layer
  with mu = 0.3, which Tamaas cannot compute (no layer, no friction coupling, no wear): every
  Fourier mode by the closed form (docs/physics/spatial.md section 3), with the layer functions
  A(k), B(k) of the independent SciPy reference (/work/shared/scipy-reference/spatial/
  wavywear.py) on numpy's FFT: U^(q, t) = U^(q, 0) exp(-k_w t/(A - i mu sx B)) and
  p^(q) = U^(q, t)/(A - i mu sx B), with sx = qx/|q|.

The maps are the ones wearlab generates: `wearlab solve PRESET --time 0 --write-surface` writes
them (the same seed gives the same surface bit for bit).

Run: OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 /work/venv-tamaas/bin/python \
     scripts/tamaas-comparison/rough_surface.py target/release/wearlab [REPEATS]
Prints per case the answers and the median wall time of REPEATS cold solves [ms].
"""

import os
import statistics
import subprocess
import sys
import tempfile
import time
import tomllib

import numpy as np

sys.path.insert(0, "/work/shared/scipy-reference/spatial")
import wavywear  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.path.join(HERE, "..", "..", "benches", "reference")


def case(wearlab, name):
    """The preset of benches/reference/NAME.toml and its map at t = 0 [m], rows along y."""
    path = os.path.join(REFERENCE, name + ".toml")
    with open(path, "rb") as f:
        preset = tomllib.load(f)
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "map.csv")
        subprocess.run(
            [wearlab, "solve", path, "--time", "0", "--write-surface", out],
            check=True,
            stdout=subprocess.DEVNULL,
        )
        heights = np.loadtxt(out, delimiter=",", comments="#", ndmin=2)
    return preset, heights


def tamaas_partial(preset, u, repeats):
    import tamaas as tm

    tm.set_log_level(tm.LogLevel.error)
    material, spatial = preset["material"], preset["spatial"]
    ny, nx = u.shape
    length = 1e-3
    times = []
    for _ in range(repeats):
        model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [length, length], [ny, nx])
        model.E, model.nu = material["youngs_modulus"], material["poisson_ratio"]
        solver = tm.PolonskyKeerRey(model, u, 1e-12)
        solver.max_iter = 10000
        start = time.perf_counter()
        solver.solve(spatial["mean_pressure"])
        times.append(time.perf_counter() - start)
    p = np.array(model.traction)
    gap = np.array(model.displacement) - u
    gap -= gap[p > 0].mean()
    print(
        f"tamaas/rough_partial/{nx}x{ny}: contact {np.mean(p > 0):.6f}, p_max {p.max():.9e} Pa, "
        f"mean gap {gap.mean():.9e} m, median {1e3 * statistics.median(times):.1f} ms"
    )


def closed_form_state(preset, u0):
    """p [Pa] and U [m] at the preset's time, every mode by its closed form."""
    material, spatial = preset["material"], preset["spatial"]
    e, nu, h = material["youngs_modulus"], material["poisson_ratio"], material["thickness"]
    g = e / (2 * (1 + nu))
    mu = preset["friction"]["coefficient"]
    kw = preset["wear"]["coefficient"] * spatial["sliding_speed"]
    t = spatial["time"]
    ny, nx = u0.shape
    length = 1e-3
    qx = 2 * np.pi * np.fft.fftfreq(nx, length / nx)
    qy = 2 * np.pi * np.fft.fftfreq(ny, length / ny)
    qx, qy = np.meshgrid(qx, qy)
    k = np.hypot(qx, qy)
    k[0, 0] = 1.0
    m = wavywear.A(k, h, g, nu) - 1j * mu * (qx / k) * wavywear.B(k, h, g, nu)
    m[0, 0] = 1.0
    ut = np.fft.fft2(u0) * np.exp(-kw * t / m)
    ut[0, 0] = 0.0
    p = spatial["mean_pressure"] + np.fft.ifft2(ut / m).real
    return p, np.fft.ifft2(ut).real


def reference_complete(preset, u0, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        p, u = closed_form_state(preset, u0)
        times.append(time.perf_counter() - start)
    ny, nx = u0.shape
    print(
        f"numpy/rough_complete_state/{nx}x{ny} at t = {preset['spatial']['time']} s: p from "
        f"{p.min():.9e} to {p.max():.9e} Pa, rms height {np.sqrt(np.mean(u * u)):.9e} m, "
        f"median {1e3 * statistics.median(times):.1f} ms"
    )


def main():
    wearlab = sys.argv[1]
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    preset, u = case(wearlab, "rough-256")
    tamaas_partial(preset, u, repeats)
    preset, u = case(wearlab, "rough-1024-complete")
    reference_complete(preset, u, repeats)


if __name__ == "__main__":
    main()
