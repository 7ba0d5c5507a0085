//! What the data determine and what they do not, said in words.

use wearlab::fit::{self, FitError};

use crate::{measured, preset};

/// The case: a tribometer's mu*(P) with noise 0.002 determines mu but not k. On this
/// coating the wear coefficient shifts mu* by less than the noise across two decades of k.
#[test]
fn mu_is_recovered_and_k_is_reported_undetermined_from_friction_against_load() {
    let truth = preset(&["wear.coefficient=2e-11"]);
    let (data, _file) = measured(&truth, "mu_star", "-", 0.002, 1, false);
    let start = preset(&["friction.coefficient=0.2", "wear.coefficient=1e-12"]);
    let keys = [
        start.key("friction.coefficient").unwrap(),
        start.key("wear.coefficient").unwrap(),
    ];
    let f = fit::fit(&start, &data, &keys).unwrap();
    let (mu, k) = (&f.estimates[0], &f.estimates[1]);
    assert!(mu.determined, "{mu:?}");
    assert!((mu.value - 0.3).abs() < 0.002, "mu = {}", mu.value);
    assert!(
        mu.interval[0] < 0.3 && 0.3 < mu.interval[1],
        "{:?}",
        mu.interval
    );
    assert!(mu.interval[1] - mu.interval[0] < 0.005, "{:?}", mu.interval);
    assert!(!k.determined, "{k:?}");
    let why = k.reason.as_deref().unwrap();
    assert!(
        why.starts_with("k is not determined by these data: "),
        "{why}"
    );
    assert!(why.contains("within the noise"), "{why}");
    assert!(why.contains("wear depth against sliding distance"), "{why}");
    // the range that fits holds the truth and spans decades
    assert!(
        k.interval[0] <= 2e-11 && 2e-11 <= k.interval[1],
        "{:?}",
        k.interval
    );
    assert!(k.interval[1] / k.interval[0] > 100.0, "{:?}", k.interval);
}

/// The contact width against load determines Young's modulus (a+b grows like sqrt(P/E)): not
/// reported undetermined, and recovered within its interval.
#[test]
fn a_determined_parameter_is_reported_determined() {
    let truth = preset(&[]);
    let (data, _file) = measured(&truth, "contact_width", "m", 2e-6, 3, true);
    let start = preset(&["material.youngs_modulus=1GPa"]);
    let keys = [start.key("material.youngs_modulus").unwrap()];
    let f = fit::fit(&start, &data, &keys).unwrap();
    let e = &f.estimates[0];
    assert!(e.determined, "{e:?}");
    assert!(e.reason.is_none());
    assert!(
        e.interval[0] < 3e9 && 3e9 < e.interval[1],
        "{:?}",
        e.interval
    );
    assert!((e.value / 3e9 - 1.0).abs() < 0.05, "E = {}", e.value);
    assert!(f.weighted);
    assert_eq!(f.residuals.len(), 20);
}

/// A free parameter the quantity does not depend on at all (the end of the preset's own load
/// sweep, which no point of the data solves): rank-deficient, said so.
#[test]
fn a_parameter_without_effect_is_rank_deficient() {
    let truth = preset(&[]);
    let (data, _file) = measured(&truth, "contact_width", "m", 2e-6, 4, true);
    let keys = [
        truth.key("material.youngs_modulus").unwrap(),
        truth.key("plane.sweep.load_max").unwrap(),
    ];
    let f = fit::fit(&truth, &data, &keys).unwrap();
    assert!(f.estimates[0].determined, "{:?}", f.estimates[0]);
    let k = &f.estimates[1];
    assert!(!k.determined);
    assert!(
        k.reason.as_deref().unwrap().contains("rank-deficient"),
        "{k:?}"
    );
}

#[test]
fn requests_that_make_no_sense_are_refused() {
    let truth = preset(&[]);
    let (data, _file) = measured(&truth, "mu_star", "-", 0.002, 5, false);
    let load = truth.key("plane.load").unwrap();
    let mu = truth.key("friction.coefficient").unwrap();
    let invalid = |keys: &[_]| match fit::fit(&truth, &data, keys) {
        Err(FitError::Invalid(why)) => why,
        other => panic!("{other:?}"),
    };
    assert!(invalid(&[load]).contains("the data's x axis"));
    assert!(invalid(&[mu, mu]).contains("named twice"));
    assert!(invalid(&[]).contains("no free parameter"));
    let model = truth.key("plane.model").unwrap();
    assert!(invalid(&[model]).contains("not a number a fit can vary"));
}
