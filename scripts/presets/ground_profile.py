"""Writes presets/ground-profile.csv, the measured-like profile of the bundled preset
ground-profile.toml: a 2 mm trace along the sliding direction, 1024 points (dx = 1.953 um), as a
stylus profilometer exports a ground steel surface after its finishing pass.

Procedure (plain Python, no packages; run: python3 scripts/presets/ground_profile.py):
1. A self-affine profile as docs/physics/spatial-surface.md section 4 defines it: the profile PSD
   C1(q) ~ q^-(1 + 2H) with H = 0.7, flat below the roll-off q_r = 2 pi/200 um, zero above the
   cutoff q_s = 2 pi/15 um and at q = 0; amplitudes exactly sqrt(C1), phases 2 pi u from
   SplitMix64 (Steele, Lea & Flood (2014)) seeded with 2026, one per mode m = 1 .. N/2 - 1 in
   order; heights by the inverse DFT, scaled to an rms of 0.3 um.
2. The finishing pass: every height above +1 rms is cut to +1 rms (the plateaus a finishing pass
   leaves on the peaks; heights point toward the layer), so the profile is skewed negative.
3. The mean removed, and each height rounded to the instrument's 1 nm resolution.
The profile is periodic over the 2 mm (the trace is one period of the cell).
"""

import math
import os

N = 1024
LENGTH = 2e-3
HURST = 0.7
ROLLOFF = 200e-6
CUTOFF = 15e-6
RMS = 0.3e-6
SEED = 2026
MASK = (1 << 64) - 1


def splitmix64(seed):
    state = seed
    while True:
        state = (state + 0x9E3779B97F4A7C15) & MASK
        z = state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        yield z ^ (z >> 31)


def profile():
    q_r, q_s = 2 * math.pi / ROLLOFF, 2 * math.pi / CUTOFF
    random = splitmix64(SEED)
    modes = []
    for m in range(1, N // 2):
        q = 2 * math.pi * m / LENGTH
        phase = 2 * math.pi * (next(random) >> 11) / float(1 << 53)
        c1 = 0.0 if q > q_s else max(q, q_r) ** -(1 + 2 * HURST)
        if c1 > 0.0:
            modes.append((m, math.sqrt(c1), phase))
    heights = [
        sum(2 * a * math.cos(2 * math.pi * m * i / N + phase) for m, a, phase in modes)
        for i in range(N)
    ]
    rms = math.sqrt(sum(h * h for h in heights) / N)
    heights = [min(h * RMS / rms, RMS) for h in heights]
    mean = sum(heights) / N
    return [round((h - mean) * 1e9) for h in heights]


def main():
    nanometres = profile()
    path = os.path.join(os.path.dirname(__file__), "..", "..", "presets", "ground-profile.csv")
    with open(path, "w") as out:
        out.write(
            "# A ground steel surface, 2 mm along the sliding direction, 1024 points\n"
            "# (dx = 1.953 um), heights in metres toward the layer, 1 nm resolution.\n"
            "# Made by scripts/presets/ground_profile.py (self-affine H = 0.7, roll-off\n"
            "# 200 um, cutoff 15 um, seed 2026, rms 0.3 um; peaks above +1 rms cut flat).\n"
        )
        out.write(",".join(f"{k}e-9" for k in nanometres) + "\n")


if __name__ == "__main__":
    main()
