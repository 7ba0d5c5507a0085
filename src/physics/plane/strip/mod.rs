//! The strip of any thickness (docs/physics/plane.md section 6): the wear-contact equation with the exact
//! kernels (3.7),
//!   gamma q2 + (1/m) p.v. int q2/(s-x) ds + (1/(m h)) int q2(s) [R2(z) + mu chi B12(z)] ds
//!     = -x/R - (tau0/m) [pi chi + chi l12((b-x)/h) + chi l12((a+x)/h)],    z = (s-x)/h,
//! solved by Gauss–Jacobi collocation at a given contact width (`collocation`), then for the load
//! by a secant on ln P(ln L): first with about 16 + 2 L/h nodes (P(L) within 1e-3), then with
//! N = 40 + 4 L/h (rounded up to a multiple of 16) and one factorization reused by refinement at
//! every width tried; a bracket and Brent's method where the secant fails. The node count grows
//! with L/h because the kernels vary on the scale h; beyond MAX_NODES the model says so instead of
//! answering.

mod by_width;
pub mod collocation;
mod factors;
mod jacobi_transforms;
pub mod kernel_table;
mod kernels;
mod rules;
mod two_grid;
pub use by_width::sweep_by_width;

use std::cell::RefCell;
use std::rc::Rc;
use std::sync::Arc;

use crate::physics::SolveError;
use crate::physics::plane::narrow::{self, winkler_beta};
use crate::physics::plane::strip::collocation::{Rules, System};
use crate::physics::plane::{Found, Model, PlaneInputs, PlaneSolution, PressureLaw, exponent};
use crate::physics::roots::{bracket, brent_to, secant_log};

pub use crate::physics::plane::strip::collocation::Collocation;
pub use crate::physics::plane::strip::kernels::{ColumnKernel, Kernels, WideLimit, kernels_for};

/// The largest node count the strip model uses ((a+b)/h up to 242): beyond it the model returns
/// `SolveError::NoSolution` rather than an unresolved answer.
pub const MAX_NODES: usize = 1008;

/// The fine node count from which an operating point is solved by two-grid refinement from the
/// coarse search's factors (`two_grid`) instead of a factorization of its own: with fewer nodes
/// the factorization costs less than the five to ten two-grid steps (thread CPU, allocator
/// page faults kept out: two-grid 8 % slower at N = 128, 3 % at 160 and 192, 6 % faster at 240,
/// 10-13 % at 336 and 400).
const TWO_GRID_FROM: usize = 224;

/// Relative accuracy of the linear solves by refinement at an operating point (the width is
/// found to 1e-15) and along a sweep (whose loads are those of the solutions).
const POINT_TOLERANCE: f64 = 1e-14;
const SWEEP_TOLERANCE: f64 = 1e-13;

/// The number of nodes that resolves the strip: 40 + 4 L/h (docs/physics/plane.md suggests 60 + 5 L/h for
/// 1e-11; this keeps N against 1.5 N within 1e-8 up to nu = 0.499, tested).
pub fn nodes_for(l_over_h: f64) -> usize {
    (40.0 + 4.0 * l_over_h).ceil() as usize
}

/// The node count used at L/h: `nodes_for` rounded up to a multiple of 16, so that neighbouring
/// widths share rules and factorizations; None beyond MAX_NODES.
fn node_count(l_over_h: f64) -> Option<usize> {
    let n = nodes_for(l_over_h).div_ceil(16) * 16;
    (n <= MAX_NODES).then_some(n)
}

/// The coarse search's node count at L/h: 16 + 2 L/h rounded up to a multiple of 8 (P(L) within
/// about 1e-3 of the converged value up to nu = 0.499).
fn coarse_count(l_over_h: f64) -> usize {
    ((16.0 + 2.0 * l_over_h).ceil() as usize).div_ceil(8) * 8
}

/// The widest contact the model resolves [m]: (a+b)/h = (MAX_NODES - 40)/4.
pub fn widest(inputs: &PlaneInputs) -> f64 {
    (MAX_NODES - 40) as f64 / 4.0 * inputs.material.thickness
}

/// The regular kernel over columns for the inputs' mu, shared by the systems of one solve.
fn columns<'a>(inputs: &PlaneInputs, kernels: &'a dyn Kernels) -> Rc<ColumnKernel<'a>> {
    Rc::new(kernels.regular_columns(inputs.friction.coefficient))
}

fn singular(l: f64, h: f64) -> SolveError {
    SolveError::NoSolution(format!(
        "the strip collocation system is singular at (a+b)/h = {:.3}",
        l / h
    ))
}

/// Solves the collocation system at contact width `l` with `n` nodes (one factorization).
pub fn collocate(
    inputs: &PlaneInputs,
    kernels: &dyn Kernels,
    l: f64,
    n: usize,
) -> Result<Collocation, SolveError> {
    let (_, _, theta) = exponent(inputs);
    let regular = columns(inputs, kernels);
    System::new(
        inputs,
        kernels,
        &regular,
        Rules::cached(theta, n),
        POINT_TOLERANCE,
    )
    .at(l)
    .ok_or_else(|| singular(l, inputs.material.thickness))
}

/// Where the width search starts: the smaller of the half-plane width (4.6) and the narrow
/// (Winkler) model's width with the inputs' friction and wear (section 5; the frictionless
/// (12 beta R P)^(1/3) where it finds none). The first is right at small L/h, the second within 1 %
/// at large L/h for nu <= 0.45 (0.3 % at (a+b)/h = 86 with nu = 0.3, k m = 0.5); for nu -> 1/2 the
/// layer is softer than Winkler's and the search grows it.
fn start_width(inputs: &PlaneInputs, p: f64) -> f64 {
    let (m, _, theta) = exponent(inputs);
    let half_plane = (8.0 * inputs.radius() * p / ((1.0 - 4.0 * theta * theta) * m)).sqrt();
    let winkler = narrow::solve(&inputs.with_load(p)).map_or_else(
        |_| (12.0 * winkler_beta(inputs) * inputs.radius() * p).cbrt(),
        |s| s.contact_width(),
    );
    half_plane.min(winkler).min(widest(inputs))
}

/// `f` evaluated once per distinct argument (the root finders revisit their end points).
fn memoized(f: impl Fn(f64) -> f64) -> impl Fn(f64) -> f64 {
    let seen = RefCell::new(Vec::<(f64, f64)>::new());
    move |x| {
        let known = seen
            .borrow()
            .iter()
            .find(|(y, _)| y.to_bits() == x.to_bits())
            .map(|s| s.1);
        known.unwrap_or_else(|| {
            let v = f(x);
            seen.borrow_mut().push((x, v));
            v
        })
    }
}

/// Why a width search failed.
enum Missed {
    /// The width is beyond what MAX_NODES resolve.
    Beyond(SolveError),
    /// Any other reason.
    Failed(SolveError),
}

impl From<Missed> for SolveError {
    fn from(missed: Missed) -> SolveError {
        match missed {
            Missed::Beyond(e) | Missed::Failed(e) => e,
        }
    }
}

/// The contact width at which the load is `p` to relative accuracy `rtol`, with the system that
/// found it (its factors are those of a nearby width; its solutions by refinement accurate to
/// `tolerance`). Stages of fixed node count: a secant on
/// ln P(ln L) (P grows like L^2 to L^3) from the start width, coarse (P within 1e-3) until the
/// width found needs no more coarse nodes than were used, then fine likewise; each fine stage
/// factors once and refines at every width it tries. Where the secant fails (P(L) not increasing
/// like a power), a bracket and Brent's method take over.
fn search<'a>(
    inputs: &PlaneInputs,
    kernels: &'a dyn Kernels,
    regular: &Rc<ColumnKernel<'a>>,
    p: f64,
    (rtol, tolerance): (f64, f64),
    two_grid: bool,
) -> Result<(f64, System<'a>), Missed> {
    const STAGES: usize = 4;
    const SECANT_EVALS: usize = 20;
    let h = inputs.material.thickness;
    let (_, _, theta) = exponent(inputs);
    let widest = widest(inputs);
    let no_width = || {
        Missed::Failed(SolveError::NoSolution(format!(
            "the strip model finds no contact width for P = {p:.4e} N/m"
        )))
    };
    let beyond = || {
        Missed::Beyond(SolveError::NoSolution(format!(
            "at P = {p:.4e} N/m the contact is wider than the strip model resolves ((a+b)/h > \
             {:.0} with at most {MAX_NODES} nodes); the narrow (Winkler) model is its limit there",
            widest / h
        )))
    };
    // refinement to 1e-10 suffices for the coarse stages (P within 1e-3)
    let system = |n: usize, tolerance: f64| {
        RefCell::new(System::new(
            inputs,
            kernels,
            regular,
            Rules::cached(theta, n),
            tolerance,
        ))
    };
    let load = |sys: &RefCell<System>, l: f64| sys.borrow_mut().at(l).map(|c| c.load);
    let (mut l, mut slope) = (start_width(inputs, p), 2.5);
    let mut coarse_done = false;
    // the last coarse system, whose factors a two-grid fine solve uses
    let mut coarse = None;
    for _ in 0..STAGES {
        let n = coarse_count(1.1 * l.min(widest) / h);
        let sys = system(n, 1e-10);
        let within = |l: f64| (l <= widest).then(|| load(&sys, l)).flatten();
        let Some((root, s)) = secant_log(within, p, l, slope, 1e-4, SECANT_EVALS) else {
            break;
        };
        (l, slope) = (root, s);
        coarse = Some(sys);
        if coarse_count(l / h) <= n {
            coarse_done = true;
            break;
        }
    }
    // kept only where a fine system will use it (its memory freed as early as before otherwise)
    let fine_nodes = node_count(1.01 * l / h).unwrap_or(0);
    let coarse = coarse
        .filter(|_| coarse_done && two_grid && fine_nodes >= TWO_GRID_FROM)
        .and_then(|sys| sys.into_inner().into_coarse())
        .map(Rc::new);
    if !coarse_done {
        // one coarse system per width tried; wider than the model resolves counts as too wide
        let coarse = memoized(|l: f64| {
            if l > widest {
                return f64::INFINITY;
            }
            load(&system(coarse_count(l / h), 1e-10), l).map_or(f64::NAN, |v| v - p)
        });
        let start = start_width(inputs, p);
        let (lo, hi) = bracket(start, (0.5, 60), (1.5, 60), &coarse).ok_or_else(no_width)?;
        if hi > widest {
            return Err(beyond());
        }
        l = brent_to(lo, hi, 1e-4, &coarse).ok_or_else(no_width)?;
    }
    if l >= widest * (1.0 - 1e-3) {
        return Err(beyond());
    }
    for _ in 0..STAGES {
        let n = node_count(1.01 * l / h).ok_or_else(beyond)?;
        let sys = system(n, tolerance);
        if let Some(coarse) = coarse.as_ref().filter(|_| n >= TWO_GRID_FROM) {
            sys.borrow_mut().set_coarse(Rc::clone(coarse));
        }
        let found = secant_log(|l| load(&sys, l), p, l, slope, rtol, SECANT_EVALS);
        (l, slope) = match found {
            Some(found) => found,
            None => {
                let fine = memoized(|l: f64| load(&sys, l).map_or(f64::NAN, |v| v - p));
                let (lo, hi) = bracket(l, (0.995, 60), (1.005, 60), &fine).ok_or_else(no_width)?;
                let root = brent_to(lo, hi, rtol, &fine).ok_or_else(|| {
                    Missed::Failed(SolveError::NoSolution(format!(
                        "the contact width did not converge at P = {p:.4e} N/m"
                    )))
                })?;
                (root, slope)
            }
        };
        if node_count(l / h).is_some_and(|needed| needed <= n) {
            return Ok((l, sys.into_inner()));
        }
    }
    Err(no_width())
}

/// The solution from a converged collocation.
pub fn solution(inputs: &PlaneInputs, col: Collocation, model: Model) -> PlaneSolution {
    let (_, gamma, _) = exponent(inputs);
    let found = Found {
        a: 0.5 * col.l - col.c,
        b: 0.5 * col.l + col.c,
        width: col.l,
        q2: col.q2,
        psi: col.psi,
        delta_g: col.delta_g,
        theta: Some(col.theta),
        gamma: Some(gamma),
        friction_integrals: None,
    };
    PlaneSolution::assemble(model, inputs, found, PressureLaw::Strip(Arc::new(col)))
}

/// Solves the strip model at the inputs' load (finite thickness only).
pub fn solve(inputs: &PlaneInputs) -> Result<PlaneSolution, SolveError> {
    solve_at_accuracy(inputs, (1e-15, POINT_TOLERANCE))
}

/// Relative accuracy of the contact width and of the linear solves of a strip solution that
/// only measures another model's deviation (`strip_check`): a million times finer than the
/// tolerances the deviation is judged against (2 % in contact width, 5 % in mu* - mu), so a
/// verdict moves only where a deviation lies within 1e-7 of its tolerance.
const CHECK_ACCURACY: (f64, f64) = (1e-9, 1e-10);

/// As `solve`, to the accuracy a measurement of another model's deviation needs
/// (`CHECK_ACCURACY`).
pub fn solve_to_check(inputs: &PlaneInputs) -> Result<PlaneSolution, SolveError> {
    solve_at_accuracy(inputs, CHECK_ACCURACY)
}

/// `solve` with the contact width to relative accuracy `rtol` and the linear solves to
/// `tolerance`.
fn solve_at_accuracy(
    inputs: &PlaneInputs,
    accuracy: (f64, f64),
) -> Result<PlaneSolution, SolveError> {
    if inputs.material.is_half_space() {
        return Err(SolveError::InvalidInput(
            "the strip model needs a finite thickness h; for a half-plane use the wide model (it is exact there)".into(),
        ));
    }
    let kernels = kernels_for(inputs.material.poisson_ratio);
    solve_to(inputs, kernels.as_ref(), accuracy)
}

/// As `solve`, with the kernels given.
pub fn solve_with(
    inputs: &PlaneInputs,
    kernels: &dyn Kernels,
) -> Result<PlaneSolution, SolveError> {
    solve_to(inputs, kernels, (1e-15, POINT_TOLERANCE))
}

/// The strip solution at the inputs' load, its contact width to relative accuracy `rtol` and its
/// linear solves to `tolerance`.
fn solve_to(
    inputs: &PlaneInputs,
    kernels: &dyn Kernels,
    (rtol, tolerance): (f64, f64),
) -> Result<PlaneSolution, SolveError> {
    let regular = columns(inputs, kernels);
    let (l, mut system) = search(
        inputs,
        kernels,
        &regular,
        inputs.load,
        (rtol, tolerance),
        true,
    )?;
    // the secant stops when its next step is below rtol: the last width it solved is as good
    // an answer as the one it predicts, and costs no further assembly
    let last = system
        .last()
        .filter(|c| (c.l - l).abs() <= rtol * l)
        .cloned();
    let col = match last {
        Some(col) => col,
        None => system
            .at(l)
            .ok_or_else(|| singular(l, inputs.material.thickness))?,
    };
    Ok(solution(inputs, col, Model::Strip))
}
