//! What every symbol of the status panel means, with its unit and sign convention (shown by `?`).

use std::sync::LazyLock;

use crate::preset::Problem;
use crate::sweeps::quantity::{by_name, problem_groups};

/// One symbol: how the status writes it, its unit, what it is.
pub type Entry = (&'static str, &'static str, &'static str);

/// The plane problem's status symbols.
#[rustfmt::skip]
pub const PLANE: [Entry; 10] = [
    ("a, b", "m", "contact zone [-a, b] around the punch tip; b is the leading edge (the punch moves to +x)"),
    ("theta", "-", "exponent shift of the pressure at the contact edges (wide and strip models; eq. 4.5), from gamma = pi chi mu/m - k: > 0 where friction shifts the edges more than wear, < 0 where wear does. On a half-plane without adhesion its sign is which effect dominates; on a strip of finite thickness the line 'mu* - mu = ..., a < b: ...' says it"),
    ("Q2", "N/m", "normal contact force, the integral of the pressure q2 over the contact"),
    ("psi", "N/m", "deformation component of friction, the integral of q2 g'(x) (eq. 2.2); > 0 adds to friction"),
    ("mu*", "-", "total friction coefficient (T - tau0 (a+b))/P = mu + [(1 + mu^2) psi + mu Delta_g tau0]/P (eq. 3.13): the friction force T less the adhesive part tau0 (a+b), over the load P (T/P only without adhesion)"),
    ("mu", "-", "the sliding friction coefficient of the preset, for comparison with mu*"),
    ("I-J residual", "-", "|I - J| over the gross work: how well the solution meets the energy identity I = J (eq. 2.9); small is good"),
    ("(a+b)/h", "-", "contact width over strip thickness: wide model for << 1, narrow (Winkler) for >> 1, strip for any"),
    ("mu* - mu = ..., a < b: wear dominates", "-", "which effect dominates, read from the solution: wear tilts the pressure forwards (a < b, mu* > mu), friction backwards (a > b, mu* < mu); 'not wear (k = 0)' where it leans forwards without wear (the friction of a thin strip, or the punch's shape), 'the two signs disagree' where mu* - mu and a - b point different ways, 'neither dominates' where mu* = mu and a = b (to 1e-9); under a flat punch with sharp corners the contact is the face at every load (mu* = mu, a = b: 'contact fixed by the corners'), and theta's sign names the corner whose pressure singularity is the stronger (> 0: the trailing one, q2 ~ r^(-1/2-theta) there)"),
    ("valid / !", "", "whether the model holds at this operating point, or why not"),
];

/// The spatial problem's status symbols.
#[rustfmt::skip]
pub const SPATIAL: [Entry; 16] = [
    ("t", "s", "the instant shown (space plays time)"),
    ("partial contact (fraction f)", "-", "the contact, solved on the nodes of the period cell, is partial: the fraction f of the cell touches (p > 0), four digits as the running-in chart's cursor reads it; 'complete contact' when all of it does"),
    ("p_max", "Pa", "largest contact pressure in the cell (p_min (nodes): the smallest, once contact is complete)"),
    ("running in", "s", "the wear of the punch is being simulated, step by step: the simulated time reached and the time asked for; until t is reached the state shown is the last one reached"),
    ("complete after t (simulated)", "s", "when the simulated running-in makes the contact complete; wear concentrates on the crests that touch, so the closed-form bound (formal bound: complete contact assumed all along) can be far off"),
    ("time-step error", "-", "how far the simulated running-in may be from the exact one because time advances in finite steps, relative to the values shown (an estimate); spatial.time_tolerance in the preset sets it: smaller means more steps"),
    ("after complete contact", "", "the harmonics' closed-form rates below (1/beta, c, phi) hold once the contact is complete, not while it is partial"),
    ("mu*", "-", "total friction coefficient mu + (1 + mu^2) psi/P at time t"),
    ("psi", "Pa", "deformation component of friction per unit area, psi = -<p dg/dx>; > 0 adds to friction"),
    ("p_min", "Pa", "smallest contact pressure in the cell: the certified minimum (with the lower bound pbar - sum A_n/M_n beside it), or only the bound when the wavenumbers do not share a period"),
    ("n", "", "one row per harmonic, numbered as in the form; '+N more' counts those that do not fit (select a harmonic's row in the form to see it)"),
    ("kh", "-", "wavenumber k = |(wx, wy)| times the layer thickness (k [rad/m] itself for a half-space)"),
    ("1/beta", "s", "decay time of the harmonic's amplitude by wear, A(t) = A(0) exp(-beta t); inf without wear"),
    ("c", "m/s", "drift velocity of the wave pattern, > 0 along +x (with the friction force on the layer, against its motion)"),
    ("phi", "rad", "phase lead of the pressure harmonic over the shape harmonic (psi goes with -sin phi)"),
    ("mu", "-", "the sliding friction coefficient of the preset, for comparison with mu*"),
];

/// The symbols of a problem's status, then those of its dimensionless view.
pub fn of(problem: Problem) -> &'static [Entry] {
    match problem {
        Problem::Plane => &PLANE_ALL,
        Problem::Spatial => &SPATIAL_ALL,
    }
}

static PLANE_ALL: LazyLock<Vec<Entry>> = LazyLock::new(|| with_groups(&PLANE, Problem::Plane));
static SPATIAL_ALL: LazyLock<Vec<Entry>> =
    LazyLock::new(|| with_groups(&SPATIAL, Problem::Spatial));

/// What heads the groups' entries.
const GROUPS_HEAD: Entry = (
    "D (groups)",
    "",
    "the dimensionless view: the status shows the problem's dimensionless groups instead of dimensional values, its title says 'in dimensionless groups'; the sweep chart's x axis is the swept input's group ((a+b)/h for h, P/(m R) for P, k m for k, mu chi for mu, (a+b)/R for R, kh1 for the spatial h), the cursor also reading the input with its unit; other inputs keep their unit, '(dimensional: no group)'; D again goes back. The groups not defined above:",
);

/// The spatial view's one group that is not a quantity of its own.
const PRESSURE_SUM: Entry = (
    "sum A/(M pbar)",
    "",
    "the harmonics' A/(M pbar) summed, 1 - (pbar - sum A/M)/pbar: the contact is surely complete while it is below 1",
);

/// A status's entries, then the groups of the dimensionless view and mu* - mu that they do not
/// define, from the quantity table (symbol and description).
fn with_groups(status: &[Entry], problem: Problem) -> Vec<Entry> {
    let mut entries = status.to_vec();
    entries.push(GROUPS_HEAD);
    entries.extend(
        problem_groups(problem)
            .chain(by_name(problem, "mu_star_minus_mu"))
            .filter(|q| !status.iter().any(|(symbol, _, _)| *symbol == q.symbol))
            .map(|q| (q.symbol, "-", q.description)),
    );
    if problem == Problem::Spatial {
        entries.push(PRESSURE_SUM);
    }
    entries
}
