//! Gauss–Jacobi rules against 40-digit reference values.
//!
//! Source of every number below: `scripts/reference-values/gauss_jacobi.py` (mpmath 1.3.0,
//! scipy 1.17.1), run once by hand. `golub_welsch(n, a, b)`: `mpmath.eigsy` of the Jacobi matrix
//! at mp.dps = 40, weights mu0 v_0k^2 (independent of the Christoffel formula the library uses);
//! `polished(n, a, b)`: `scipy.special.roots_jacobi(n, a, b)` polished by `mpmath.findroot(lambda x:
//! mpmath.jacobi(n, a, b, x), x0, solver="secant")` at 40 digits, weights by Szegő (15.3.5) at 40
//! digits. Each entry is (index in increasing order, node, weight).

use wearlab::physics::quadrature::{gauss_jacobi, jacobi_zeros};

type Case = (usize, f64, f64, &'static [(usize, f64, f64)]);

const CASES: [Case; 6] = [
    // golub_welsch(n=7, alpha=0.7, beta=0.3)
    (
        7,
        0.7,
        0.3,
        &[
            (0, -0.9369866027204428, 0.09432302884676307),
            (1, -0.7330057177618419, 0.2636794622890484),
            (2, -0.41723521764511745, 0.38726863404872214),
            (3, -0.037714907308807825, 0.3982046276379242),
            (4, 0.3477804779917926, 0.2988433383918294),
            (5, 0.6805597790851485, 0.15162425585665365),
            (6, 0.9099355216926022, 0.037009925458451),
        ],
    ),
    // golub_welsch(n=40, alpha=0.7, beta=0.3)
    (
        40,
        0.7,
        0.3,
        &[
            (0, -0.9975779868897658, 0.0014080339048579487),
            (1, -0.9893740274625169, 0.004602500760744422),
            (19, -0.0458993988775997, 0.07788130797650993),
            (38, 0.9871523446474065, 0.0007156587800542046),
            (39, 0.996519215481669, 0.00015088543330868387),
        ],
    ),
    // golub_welsch(n=41, alpha=-0.7, beta=-0.3): the collocation points' exponents
    (
        41,
        -0.7,
        -0.3,
        &[
            (0, -0.9989004186391091, 0.016794117373136165),
            (1, -0.9924474386939311, 0.02505065635252079),
            (20, 0.00772191777984273, 0.07686220557185243),
            (39, 0.9943216115909798, 0.24890953779429487),
            (40, 0.9995918511690283, 0.4435542540303038),
        ],
    ),
    // golub_welsch(n=121, alpha=0.95, beta=0.05): theta = 0.45, near the end of its range
    (
        121,
        0.95,
        0.05,
        &[
            (0, -0.9997931368308419, 0.000650946583671474),
            (1, -0.998947410475317, 0.0016127200162935449),
            (60, -0.005778811087079263, 0.025884347129009125),
            (119, 0.9983808528525999, 3.4080086941622744e-06),
            (120, 0.9995240574789648, 5.862511469761462e-07),
        ],
    ),
    // polished(n=401, alpha=0.6, beta=0.4)
    (
        401,
        0.6,
        0.4,
        &[
            (0, -0.9999721756399453, 1.3247094581880845e-06),
            (1, -0.999883612833631, 4.817737411976376e-06),
            (200, -0.0003904359592540353, 0.007815516415956314),
            (399, 0.9998720103421186, 7.625658089760918e-07),
            (400, 0.9999666621965859, 1.7420953525965414e-07),
        ],
    ),
    // polished(n=402, alpha=-0.6, beta=-0.4)
    (
        402,
        -0.6,
        -0.4,
        &[
            (0, -0.9999905141263046, 0.002268402921831374),
            (1, -0.9999263643545275, 0.002810315669786011),
            (201, 0.004298495200456116, 0.007821628749192374),
            (400, 0.9999361314885684, 0.02205902668762778),
            (401, 0.9999941134689555, 0.02849299543541365),
        ],
    ),
];

#[test]
fn nodes_and_weights_match_the_40_digit_references() {
    for (n, alpha, beta, expected) in CASES {
        let rule = gauss_jacobi(n, alpha, beta);
        assert_eq!(rule.nodes, jacobi_zeros(n, alpha, beta));
        for &(i, x, w) in expected {
            let (got_x, got_w) = (rule.nodes[i], rule.weights[i]);
            assert!(
                (got_x - x).abs() < 1e-13,
                "n={n} ({alpha}, {beta}) node {i}: {got_x:e} vs {x:e}"
            );
            // A node is an f64 within an ulp (2.2e-16) of the zero; the weight formula moves with
            // it by d ln w/dx = 2[(beta - alpha) - (alpha + beta + 1) x]/(1 - x^2) (the Jacobi
            // equation at a zero), which near +-1 at n = 400 exceeds 1e-13 per ulp: allow that.
            let slope = 2.0 * ((beta - alpha) - (alpha + beta + 1.0) * x) / (1.0 - x * x);
            let allowed = 1e-13 + slope.abs() * 2.3e-16;
            assert!(
                (got_w - w).abs() < allowed * w,
                "n={n} ({alpha}, {beta}) weight {i}: {got_w:e} vs {w:e}"
            );
        }
    }
}
