//! The plane presets whose descriptions were not yet checked say what the solver finds: each
//! number a description quotes is recomputed here, within half a unit of its last quoted digit
//! (the description rounds), or within the word it is quoted with ("about", "some", "~": the
//! tolerance is said beside it); each threshold it names is found by bisection where the verdict
//! changes.

use wearlab::physics::plane::strip_check::verdict;
use wearlab::physics::plane::{Model, PlaneSolution, solve};
use wearlab::preset::{self, Preset};

fn preset(file: &str) -> Preset {
    preset::bundled(file).unwrap().unwrap()
}

fn at(p: &Preset, load: f64, model: Model) -> PlaneSolution {
    solve(&p.plane_inputs().with_load(load), model).unwrap()
}

/// Within half a unit of the last digit of `said`, given as its number of decimals.
fn quoted(value: f64, said: f64, decimals: i32) -> bool {
    (value - said).abs() <= 0.5 * 10f64.powi(-decimals) * (1.0 + 1e-9)
}

/// Where `holds` turns from `lo`'s answer to the other, by bisection in log x (to 1e-4 of x).
fn turn(lo: f64, hi: f64, holds: impl Fn(f64) -> bool) -> f64 {
    let (mut lo, mut hi) = (lo.ln(), hi.ln());
    let first = holds(lo.exp());
    assert_ne!(first, holds(hi.exp()), "no turn between the ends");
    while hi - lo > 1e-4 {
        let mid = 0.5 * (lo + hi);
        if holds(mid.exp()) == first {
            lo = mid
        } else {
            hi = mid
        }
    }
    (0.5 * (lo + hi)).exp()
}

/// Where each bundled preset's description is checked against the program.
const CHECKED: [(&str, &str); 23] = [
    ("polymer-coating.toml", "presets.rs, plane_descriptions.rs"),
    ("hertz-check.toml", "plane_descriptions.rs"),
    ("friction-half-plane.toml", "plane_descriptions.rs"),
    ("wear-dominated.toml", "plane_descriptions.rs"),
    ("thin-strip-winkler.toml", "plane_descriptions.rs"),
    ("hard-coating-strip.toml", "plane_descriptions.rs"),
    ("jgh-egg-box.toml", "spatial_descriptions.rs"),
    ("wave-thick-layer.toml", "spatial_descriptions.rs"),
    ("rubber-backward-drift.toml", "spatial_descriptions.rs"),
    ("dispersion.toml", "spatial_descriptions.rs"),
    ("contact-lost.toml", "tests/explorer/engine.rs"),
    ("rubber-running-in.toml", "tests/explorer/engine.rs"),
    ("coating-thickness-sweep.toml", "plane_descriptions.rs"),
    ("friction-or-wear-map.toml", "plane_descriptions.rs"),
    ("flat-pin-coating.toml", "presets.rs, plane_descriptions.rs"),
    ("rough-thin-layer.toml", "surfaces.rs"),
    ("worn-pin-profile.toml", "general_presets.rs"),
    ("wear-law-squared.toml", "general_presets.rs"),
    ("polymer-shear-strength.toml", "general_presets.rs"),
    ("energy-split.toml", "general_presets.rs"),
    ("sharp-flat-punch.toml", "general_presets.rs"),
    ("ground-profile.toml", "surfaces.rs"),
    ("lab-friction.toml", "presets.rs"),
];

#[test]
fn every_bundled_description_is_checked_somewhere() {
    let mut bundled: Vec<&str> = preset::BUNDLED.iter().map(|b| b.file).collect();
    let mut checked: Vec<&str> = CHECKED.iter().map(|(file, _)| *file).collect();
    bundled.sort();
    checked.sort();
    assert_eq!(
        bundled, checked,
        "a new preset's description needs its test"
    );
}

#[test]
fn hertz_check_is_hertz() {
    let p = preset("hertz-check.toml");
    let s = at(&p, p.plane.load, Model::Wide);
    // "a = b = sqrt(4 R P/(pi E*)) with E* = E/(1 - nu^2)": "52.5 um at P = 1e4 N/m"
    let e_star = p.material.youngs_modulus / (1.0 - p.material.poisson_ratio.powi(2));
    let hertz = (4.0 * p.plane.radius * 1e4 / (std::f64::consts::PI * e_star)).sqrt();
    assert_eq!(p.plane.load, 1e4);
    assert!((s.a - hertz).abs() < 1e-9 * hertz && (s.b - hertz).abs() < 1e-9 * hertz);
    assert!(quoted(s.a * 1e6, 52.5, 1), "{}", s.a);
    // "q2(0) = 2P/(pi a), theta = 0, psi = 0, mu* = mu = 0"
    let peak = 2.0 * 1e4 / (std::f64::consts::PI * hertz);
    assert!((s.pressure(0.0) - peak).abs() < 1e-6 * peak);
    assert_eq!((s.theta, s.psi.abs(), s.mu_star), (Some(0.0), 0.0, 0.0));
    // "a(P) growing like sqrt(P)"
    let heavier = at(&p, 4e4, Model::Wide);
    assert!((heavier.a / s.a - 2.0).abs() < 1e-9);
}

#[test]
fn friction_half_plane_leans_back_and_mu_star_falls_like_the_root_of_the_load() {
    let p = preset("friction-half-plane.toml");
    assert_eq!((p.friction.coefficient, p.wear), (0.4, 0.0));
    let s = at(&p, p.plane.load, Model::Wide);
    // "tan(pi theta) = mu chi", "a > b", "psi is negative", "mu* below mu"
    let theta = s.theta.unwrap();
    let chi = p.material.chi();
    assert!(((std::f64::consts::PI * theta).tan() - 0.4 * chi).abs() < 1e-12);
    assert!(s.a > s.b && s.psi < 0.0 && s.mu_star < 0.4);
    // "mu - mu* grows like sqrt(P)": a decade of load multiplies it by sqrt(10), within 0.5 %
    // (measured 0.02 % from 1e2 to 0.2 % from 1e4 N/m: (4.9) is the law in Q2, and P = Q2 - phi
    // differs from it by mu psi, which grows with the load)
    let drop = |load: f64| 0.4 - at(&p, load, Model::Wide).mu_star;
    for load in [1e2, 1e3, 1e4] {
        let ratio = drop(10.0 * load) / drop(load);
        assert!((ratio / 10f64.sqrt() - 1.0).abs() < 5e-3, "{load}: {ratio}");
    }
}

#[test]
fn wear_dominated_leans_forwards() {
    let p = preset("wear-dominated.toml");
    // "k m = 2", "mu = 0.2"
    assert!(quoted(p.wear * p.material.plane_modulus(), 2.0, 0));
    assert_eq!(p.friction.coefficient, 0.2);
    // "theta < 0, b > a, psi > 0 and mu* rises above mu"; "rising with load"
    let s = at(&p, p.plane.load, Model::Wide);
    assert!(s.theta.unwrap() < 0.0 && s.b > s.a && s.psi > 0.0 && s.mu_star > 0.2);
    let mut last = 0.2;
    for i in 0..=8 {
        let m = at(&p, 10f64.powf(1.0 + i as f64 / 2.0), Model::Wide).mu_star;
        assert!(m > last, "{i}: {m}");
        last = m;
    }
}

#[test]
fn polymer_coating_wears_a_little_less_than_friction_pushes() {
    let p = preset("polymer-coating.toml");
    // "mu = 0.3", "k m = 0.11", "friction wins a little (theta > 0)", "psi is negative and mu*
    // sits just below mu", "mu*(P) falling with load"
    assert_eq!(p.friction.coefficient, 0.3);
    assert!(quoted(p.wear * p.material.plane_modulus(), 0.11, 2));
    let s = at(&p, p.plane.load, p.plane.model);
    assert!(s.theta.unwrap() > 0.0 && s.psi < 0.0 && s.mu_star < 0.3 && s.mu_star > 0.299);
    let sweep = &p.plane.sweep;
    let ends = [sweep.min, sweep.max].map(|load| at(&p, load, p.plane.model).mu_star);
    assert!(ends[1] < ends[0], "{ends:?}");
    // "mu* rises above mu at k = 3.85e-11 1/Pa (wear now dominates, a < b), a little before
    // theta changes sign at k = 4.05e-11": each sign changes within 0.5 % of the quoted k
    let with_k = |k: f64| {
        let mut q = p.clone();
        q.wear = k;
        at(&q, q.plane.load, q.plane.model)
    };
    let [below, above] = [0.995, 1.005].map(|f| with_k(3.85e-11 * f));
    assert!(below.mu_star < 0.3 && above.mu_star > 0.3 && above.a < above.b);
    let [below, above] = [0.995, 1.005].map(|f| with_k(4.05e-11 * f));
    assert!(below.theta.unwrap() > 0.0 && above.theta.unwrap() < 0.0);
}

#[test]
fn the_flat_pins_wear_is_of_order_two_in_lambda_l() {
    let p = preset("flat-pin-coating.toml");
    // "lambda L ~ 2": lambda = k/beta of the Winkler solution, L = a + b ("~": within 1 to 3)
    let s = at(&p, p.plane.load, Model::Narrow);
    let beta = wearlab::physics::plane::narrow::winkler_beta(&p.plane_inputs());
    let lambda_l = p.wear / beta * s.contact_width();
    assert!((1.0..3.0).contains(&lambda_l), "{lambda_l}");
    assert_eq!(p.wear, 1e-11);
}

#[test]
fn the_friction_or_wear_map_has_its_theta_zero_line_where_it_says() {
    let p = preset("friction-or-wear-map.toml");
    // "k m = pi mu chi, here k = 1.35e-10 mu"
    let slope = std::f64::consts::PI * p.material.chi() / p.material.plane_modulus();
    assert!(quoted(slope * 1e10, 1.35, 2), "{slope}");
    // on the line: "Hertz's symmetric one, psi = 0 and mu* = mu exactly" (to round-off)
    let mut on = p.clone();
    on.wear = slope * on.friction.coefficient;
    let s = at(&on, on.plane.load, Model::Wide);
    assert!(s.theta.unwrap().abs() < 1e-12 && (s.a - s.b).abs() < 1e-9 * s.a);
    assert!((s.mu_star - 0.3).abs() < 1e-12 && s.psi.abs() < 1e-9 * on.plane.load);
    // "the preset's own point (mu = 0.3, k = 2e-11) lies on the friction side": a > b, mu* < mu
    assert_eq!((p.friction.coefficient, p.wear), (0.3, 2e-11));
    let own = at(&p, p.plane.load, Model::Wide);
    assert!(own.a > own.b && own.mu_star < 0.3 && own.theta.unwrap() > 0.0);
    // "(mu 0 to 1) and (k 0 to 2e-10 1/Pa)"; "R = 50 mm, P = 5e3 N/m", "E = 3 GPa, nu = 0.35"
    let x = &p.explore.as_ref().unwrap().axes;
    let ranges: Vec<(f64, f64)> = x.iter().map(|a| (a.range.min, a.range.max)).collect();
    assert_eq!(ranges, [(0.0, 1.0), (0.0, 2e-10)]);
    assert_eq!((p.plane.radius, p.plane.load), (0.05, 5e3));
    assert_eq!(
        (p.material.youngs_modulus, p.material.poisson_ratio),
        (3e9, 0.35)
    );
}

#[test]
fn the_hard_coating_strip_is_between_the_two_asymptotes() {
    let p = preset("hard-coating-strip.toml");
    // "k m = 0.5"; "at P = 1e3 N/m the contact is about 8 coating thicknesses wide" (about: 7.5
    // to 8.5)
    assert!(quoted(p.wear * p.material.plane_modulus(), 0.5, 1));
    let s = at(&p, 1e3, Model::Strip);
    let lambda = s.contact_width() / p.material.thickness;
    assert!((7.5..8.5).contains(&lambda), "{lambda}");
    // "too wide for the wide-strip model and too narrow for Winkler": both verdicts fail there
    for model in [Model::Wide, Model::Narrow] {
        assert!(!verdict(&at(&p, 1e3, model)).ok, "{model:?}");
    }
    // "runs from the wide curve at light loads to the Winkler curve at heavy ones": at the ends
    // of the preset's sweep the strip's mu* - mu is nearer the one model, then the other
    // (at the heaviest the wide model has no answer: its contact leaves the punch's tip)
    let sweep = &p.plane.sweep;
    let gap = |load: f64, model: Model| {
        let strip = at(&p, load, Model::Strip).mu_star;
        solve(&p.plane_inputs().with_load(load), model)
            .map_or(f64::INFINITY, |s| (strip - s.mu_star).abs())
    };
    assert!(gap(sweep.min, Model::Wide) < gap(sweep.min, Model::Narrow));
    assert!(gap(sweep.max, Model::Narrow) < gap(sweep.max, Model::Wide));
}

#[test]
fn the_thin_strip_is_winklers_above_4e3_n_per_m() {
    let p = preset("thin-strip-winkler.toml");
    let s = at(&p, p.plane.load, Model::Narrow);
    // "some 16 strip thicknesses wide" ("some": within 15.5 to 17.5); "lambda L ~ 1" (0.5 to 2)
    let lambda = s.contact_width() / p.material.thickness;
    assert!((15.5..17.5).contains(&lambda), "{lambda}");
    let beta = wearlab::physics::plane::narrow::winkler_beta(&p.plane_inputs());
    let lambda_l = p.wear / beta * s.contact_width();
    assert!((0.5..2.0).contains(&lambda_l), "{lambda_l}");
    // "the pressure maximum ahead of the tip"; "mu* exceeds mu"; "without wear ... mu* = mu"
    let x = |i: usize| -s.a + s.contact_width() * i as f64 / 1000.0;
    let top = (0..=1000).max_by(|&i, &j| s.pressure(x(i)).total_cmp(&s.pressure(x(j))));
    assert!(x(top.unwrap()) > 0.0 && s.mu_star > p.friction.coefficient);
    let mut no_wear = p.clone();
    no_wear.wear = 0.0;
    assert_eq!(
        at(&no_wear, 1e4, Model::Narrow).mu_star,
        p.friction.coefficient
    );
    // "mu* - mu grows about 4.6 times (10^(2/3))" a decade of load ("about": 4.4 to 4.8)
    let excess = |load: f64| at(&p, load, Model::Narrow).mu_star - p.friction.coefficient;
    let per_decade = excess(1e5) / excess(1e4);
    assert!((4.4..4.8).contains(&per_decade), "{per_decade}");
    // "warns below P ~ 4e3 N/m: there (a+b)/h < 12 and Winkler's contact width is more than 2 %
    // off the exact strip solution (measured against it)" ("~": 3.5e3 to 4.5e3)
    let turn_at = turn(1e3, 1e4, |load| verdict(&at(&p, load, Model::Narrow)).ok);
    assert!((3.5e3..4.5e3).contains(&turn_at), "{turn_at}");
    let below = verdict(&at(&p, turn_at / 1.001, Model::Narrow));
    let width = below.contact_width_over_thickness;
    assert!(!below.ok && quoted(width, 12.0, 0), "{width}");
    let measured = below.measured_error.unwrap();
    assert!(measured.contact_width > 0.02 && measured.mu_star_minus_mu < 0.05);
}

#[test]
fn the_coating_thickness_sweep_changes_sign_where_it_says() {
    let p = preset("coating-thickness-sweep.toml");
    let on = |h: f64, model: Model| {
        let mut q = p.clone();
        q.material.thickness = h;
        at(&q, q.plane.load, model)
    };
    // "theta = +0.017", the same at every thickness
    let theta = on(1e-3, Model::Strip).theta.unwrap();
    assert!(quoted(theta, 0.017, 3) && on(1e-5, Model::Strip).theta == Some(theta));
    // "k m = 0.1"
    assert!(quoted(p.wear * p.material.plane_modulus(), 0.1, 1));
    // "mu* - mu changes sign near h = 125 um" ("near": 120 to 130 um), "(a+b)/h = 1.1"; friction
    // wins on a thick coating (mu* < mu), wear on a thin one
    let mu = p.friction.coefficient;
    let sign = turn(1e-6, 1e-2, |h| on(h, Model::Strip).mu_star > mu);
    assert!((120e-6..130e-6).contains(&sign), "{sign}");
    assert!(on(1e-6, Model::Strip).mu_star > mu && on(1e-2, Model::Strip).mu_star < mu);
    assert!(quoted(
        on(sign, Model::Strip).contact_width() / sign,
        1.1,
        1
    ));
    // "At h = 10 mm ((a+b)/h = 0.015) it meets the wide model, at h = 1 um ((a+b)/h = 37) the
    // Winkler model": each model's own (a+b)/h
    assert!(quoted(
        on(1e-2, Model::Wide).contact_width() / 1e-2,
        0.015,
        3
    ));
    assert!(quoted(
        on(1e-6, Model::Narrow).contact_width() / 1e-6,
        37.0,
        0
    ));
    // "wide above about 0.35 mm, (a+b)/h below 0.43; Winkler below about 5 um, (a+b)/h above 12"
    // ("about": within 5 % of the thickness where the verdict turns)
    let holds = |h: f64, model: Model| verdict(&on(h, model)).ok;
    let wide = turn(1e-4, 1e-3, |h| holds(h, Model::Wide));
    assert!((wide / 0.35e-3 - 1.0).abs() < 0.05, "{wide}");
    assert!(holds(1.01 * wide, Model::Wide) && !holds(0.99 * wide, Model::Wide));
    assert!(quoted(
        on(wide, Model::Wide).contact_width() / wide,
        0.43,
        2
    ));
    let narrow = turn(1e-6, 2e-5, |h| holds(h, Model::Narrow));
    assert!((narrow / 5e-6 - 1.0).abs() < 0.05, "{narrow}");
    assert!(holds(0.99 * narrow, Model::Narrow) && !holds(1.01 * narrow, Model::Narrow));
    assert!(quoted(
        on(narrow, Model::Narrow).contact_width() / narrow,
        12.0,
        0
    ));
}
