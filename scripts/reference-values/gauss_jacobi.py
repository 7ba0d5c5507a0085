"""Reference Gauss-Jacobi nodes and weights at 40 digits for tests/gauss_jacobi.rs.

Not needed by the Rust build or tests: run by hand (`pip install mpmath scipy`,
`python3 scripts/reference-values/gauss_jacobi.py`); the output was pasted into the test.
Produced with mpmath 1.3.0 and scipy 1.17.1.

- golub_welsch(n, a, b): eigenvalues and first eigenvector components of the Jacobi matrix
  (mpmath.eigsy at mp.dps = 40); weights mu0 v_0k^2 with mu0 = 2^(a+b+1) B(a+1, b+1).
  Independent of the Christoffel formula the Rust code uses.
- polished(n, a, b): scipy.special.roots_jacobi(n, a, b) as starts, each zero polished by
  mpmath.findroot(lambda x: mpmath.jacobi(n, a, b, x), x0, solver="secant") at 40 digits;
  weights by Szegő (15.3.5) at 40 digits with mpmath.diff for P_n'.
"""
import mpmath as mp
from scipy.special import roots_jacobi

mp.mp.dps = 40


def golub_welsch(n, a, b):
    a, b = mp.mpf(a), mp.mpf(b)
    ab = a + b
    J = mp.zeros(n, n)
    for k in range(n):
        J[k, k] = (b - a) / (ab + 2) if k == 0 else (b * b - a * a) / ((2 * k + ab) * (2 * k + ab + 2))
        if k >= 1:
            kk = mp.mpf(k)
            c = 2 * kk + ab
            if k == 1:
                off = mp.sqrt(4 * (1 + a) * (1 + b) / ((2 + ab) ** 2 * (3 + ab)))
            else:
                off = mp.sqrt(4 * kk * (kk + a) * (kk + b) * (kk + ab) / (c * c * (c + 1) * (c - 1)))
            J[k, k - 1] = off
            J[k - 1, k] = off
    E, Q = mp.eigsy(J)
    mu0 = 2 ** (ab + 1) * mp.gamma(a + 1) * mp.gamma(b + 1) / mp.gamma(ab + 2)
    return sorted((E[i], mu0 * Q[0, i] ** 2) for i in range(n))


def polished(n, a, b):
    a, b = mp.mpf(a), mp.mpf(b)
    x0, _ = roots_jacobi(n, float(a), float(b))
    P = lambda x: mp.jacobi(n, a, b, x)
    C = 2 ** (a + b + 1) * mp.gamma(n + a + 1) * mp.gamma(n + b + 1) / (mp.gamma(n + a + b + 1) * mp.factorial(n))
    out = []
    for x in x0:
        r = mp.findroot(P, mp.mpf(float(x)), solver="secant", tol=mp.mpf(10) ** -60, verify=False)
        dp = mp.diff(P, r)
        out.append((r, C / ((1 - r * r) * dp * dp)))
    return sorted(out)


CASES = [
    (golub_welsch, 7, 0.7, 0.3, None),
    (golub_welsch, 40, 0.7, 0.3, [0, 1, 19, 38, 39]),
    (golub_welsch, 41, -0.7, -0.3, [0, 1, 20, 39, 40]),
    (golub_welsch, 121, 0.95, 0.05, [0, 1, 60, 119, 120]),
    (polished, 401, 0.6, 0.4, [0, 1, 200, 399, 400]),
    (polished, 402, -0.6, -0.4, [0, 1, 201, 400, 401]),
]

for method, n, a, b, idx in CASES:
    pairs = method(n, a, b)
    print(f"// {method.__name__}(n={n}, alpha={a}, beta={b})")
    for i in idx or range(n):
        x, w = pairs[i]
        print(f"    ({i}, {mp.nstr(x, 20)}, {mp.nstr(w, 20)}),")
