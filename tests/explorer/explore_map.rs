//! The explorer's curve and map (`sweeps::curve`, `sweeps::map`): their lines agree with the
//! solver's own verdicts and with the closed forms where there is one; the strip model's sweep
//! over the thickness meets the wide model and Winkler as `docs/physics/plane.md` says; a map is
//! coarse first, the same numbers as a sweep, and stops when cancelled.

use std::sync::atomic::{AtomicBool, Ordering};

use wearlab::physics::Spacing;
use wearlab::physics::plane::Model;
use wearlab::preset::{Preset, bundled};
use wearlab::sweeps::axis::Axis;
use wearlab::sweeps::curve::{CurveSpec, curve, holds, solve_at};
use wearlab::sweeps::map::{LineKind, Map, MapSpec, regime_map};
use wearlab::sweeps::point::Point;
use wearlab::sweeps::quantity::QuantityKey;
use wearlab::sweeps::sweep;

fn preset(file: &str) -> Preset {
    bundled(file).unwrap().unwrap()
}

fn axis(p: &Preset, key: &str, ends: [f64; 2], n: usize, spacing: Spacing) -> Axis {
    Axis::new(p, p.key(key).unwrap(), ends, n, spacing).unwrap()
}

fn map_of(p: &Preset, spec: &MapSpec) -> Map {
    regime_map(p, spec, &AtomicBool::new(false), &mut |_| {}).unwrap()
}

fn line(map: &Map, kind: LineKind) -> &[[[f64; 2]; 2]] {
    &map.lines.iter().find(|l| l.kind == kind).unwrap().segments
}

#[test]
fn the_theta_line_is_k_m_equal_pi_mu_chi_and_splits_the_solvers_signs() {
    let p = preset("friction-or-wear-map.toml");
    let spec = MapSpec {
        x: axis(&p, "friction.coefficient", [0.0, 1.0], 12, Spacing::Linear),
        y: axis(&p, "wear.coefficient", [0.0, 2e-10], 12, Spacing::Linear),
        quantity: QuantityKey::parse("mu_star_minus_mu", &p).unwrap(),
    };
    let map = map_of(&p, &spec);
    let segments = line(&map, LineKind::ThetaZero);
    assert!(segments.len() >= 8, "{}", segments.len());
    // (4.3), (4.5): theta = 0 where gamma = pi chi mu/m - k = 0
    let (m, chi) = (p.material.plane_modulus(), p.material.chi());
    let theta_sign = |mu: f64, k: f64| {
        let at = solve_at(&p, &[spec.x, spec.y], &[mu, k], Some(Model::Wide)).unwrap();
        match at {
            Point::Plane(pp) => pp.solution.theta.unwrap() > 0.0,
            Point::Spatial(_) => unreachable!(),
        }
    };
    for s in segments {
        for [mu, k] in s {
            let k_line = std::f64::consts::PI * chi * mu / m;
            // located to 2^-20 of an edge: within 1e-6 of the map's k range of the line
            assert!((k - k_line).abs() < 1e-6 * 2e-10, "{mu} {k} vs {k_line}");
        }
        // across the middle of each segment the solver's theta changes sign
        let mid = [0.5 * (s[0][0] + s[1][0]), 0.5 * (s[0][1] + s[1][1])];
        assert!(theta_sign(mid[0], mid[1] * 0.99));
        assert!(!theta_sign(mid[0], mid[1] * 1.01 + 1e-14));
    }
    // the wide model's validity holds everywhere here and the half-plane has no narrow model
    assert!(line(&map, LineKind::Validity(Model::Wide)).is_empty());
    assert!(line(&map, LineKind::Validity(Model::Narrow)).is_empty());
}

#[test]
fn validity_lines_lie_where_the_models_own_verdict_changes() {
    let p = preset("polymer-coating.toml");
    let spec = MapSpec {
        x: axis(&p, "plane.load", [1e2, 1e7], 10, Spacing::Log),
        y: axis(&p, "material.thickness", [1e-5, 1e-1], 10, Spacing::Log),
        quantity: QuantityKey::parse("mu_star", &p).unwrap(),
    };
    let map = map_of(&p, &spec);
    for model in [Model::Wide, Model::Narrow] {
        let segments = line(&map, LineKind::Validity(model));
        assert!(segments.len() >= 5, "{model:?}: {}", segments.len());
        let verdict =
            |x: f64, y: f64| holds(&solve_at(&p, &[spec.x, spec.y], &[x, y], Some(model)).unwrap());
        // each end lies on a grid edge, located to 2^-30 of it: a step of 1e-6 (relative) either
        // way along x or along y crosses the model's own verdict
        for [x, y] in segments.iter().flatten().copied() {
            let (lo, hi) = (1.0 - 1e-6, 1.0 + 1e-6);
            let crosses = verdict(x * lo, y) != verdict(x * hi, y)
                || verdict(x, y * lo) != verdict(x, y * hi);
            assert!(crosses, "{model:?} at ({x}, {y})");
        }
    }
    // every computed point's verdicts are the models' own
    for (k, s) in map.samples.iter().enumerate() {
        let s = s.as_ref().unwrap();
        let (x, y) = (map.x[k % 10], map.y[k / 10]);
        let solved = solve_at(&p, &[spec.x, spec.y], &[x, y], Some(Model::Narrow)).ok();
        assert_eq!(s.narrow_holds, solved.map(|pt| holds(&pt)));
    }
}

#[test]
fn the_complete_contact_line_is_pbar_equal_a_over_m() {
    // one 1-D wave at t = 0: p_cc = pbar - A/M (docs/physics/spatial.md section 4), so contact is
    // complete below the line A/M = pbar, straight in (A, pbar)
    let p = preset("wave-thick-layer.toml");
    let spec = MapSpec {
        x: axis(
            &p,
            "spatial.harmonics.0.amplitude",
            [1e-6, 1e-5],
            5,
            Spacing::Linear,
        ),
        y: axis(&p, "spatial.mean_pressure", [1e7, 1e8], 5, Spacing::Linear),
        quantity: QuantityKey::parse("mu_star", &p).unwrap(),
    };
    let map = map_of(&p, &spec);
    let q = QuantityKey::parse("harmonics.0.pressure_per_amplitude", &p).unwrap();
    let per_amplitude = q.value(&solve_at(&p, &[], &[], None).unwrap()).unwrap();
    let segments = line(&map, LineKind::CompleteContact);
    assert!(!segments.is_empty());
    for [a, pbar] in segments.iter().flatten().copied() {
        assert!((a * per_amplitude - pbar).abs() < 1e-9 * pbar, "{a} {pbar}");
    }
}

#[test]
fn the_map_is_coarse_first_the_sweeps_numbers_and_stops_when_cancelled() {
    let p = preset("wear-dominated.toml");
    let spec = MapSpec {
        x: axis(&p, "friction.coefficient", [0.0, 1.0], 33, Spacing::Linear),
        y: axis(&p, "plane.load", [1e2, 1e5], 17, Spacing::Log),
        quantity: QuantityKey::parse("mu_star", &p).unwrap(),
    };
    let mut passes = Vec::new();
    let map = regime_map(&p, &spec, &AtomicBool::new(false), &mut |m| {
        passes.push((m.stride, m.samples.iter().flatten().count()));
        // even a coarse map answers every grid point, from its nearest computed one
        assert!((0..33).all(|i| (0..17).all(|j| m.sample(i, j).is_some())));
    })
    .unwrap();
    // strides 16, 8, 4, 2, 1; the first pass has three points along x (0, 16, 32) and two along
    // y (0, 16)
    assert_eq!(
        passes.iter().map(|p| p.0).collect::<Vec<_>>(),
        [16, 8, 4, 2, 1]
    );
    assert_eq!(passes[0].1, 3 * 2);
    assert_eq!(passes[4].1, 33 * 17);
    // the numbers are the sweep's (the same pipeline), bit for bit
    let rows = sweep::run(&p, &[spec.y, spec.x], &[spec.quantity], &|| {});
    for row in &rows {
        let (i, j) = (
            map.x.iter().position(|x| *x == row.at[1]).unwrap(),
            map.y.iter().position(|y| *y == row.at[0]).unwrap(),
        );
        let s = map.sample(i, j).unwrap();
        assert_eq!(
            s.value.as_ref().unwrap().to_bits(),
            row.values[0].as_ref().unwrap().to_bits()
        );
    }
    // cancelled after the first pass: no map
    let cancel = AtomicBool::new(false);
    let mut seen = 0;
    let done = regime_map(&p, &spec, &cancel, &mut |_| {
        seen += 1;
        cancel.store(true, Ordering::Relaxed);
    });
    assert!(done.is_none());
    assert_eq!(seen, 1);
}

#[test]
fn a_curve_locates_where_each_model_stops_holding() {
    let p = preset("coating-thickness-sweep.toml");
    let spec = CurveSpec {
        axis: axis(&p, "material.thickness", [1e-6, 1e-2], 9, Spacing::Log),
        quantity: QuantityKey::parse("validity.contact_width_over_thickness", &p).unwrap(),
        models: vec![Model::Wide, Model::Narrow],
    };
    let c = curve(&p, &spec, &AtomicBool::new(false)).unwrap();
    assert_eq!(c.current, 1e-4);
    // the wide model holds above the change, Winkler below its own
    for (series, after) in c.series.iter().zip([true, false]) {
        assert_eq!(series.changes.len(), 1, "{:?}", series.model);
        let change = series.changes[0];
        assert_eq!(change.holds_after, after);
        let model = series.model;
        let verdict = |h: f64| holds(&solve_at(&p, &[spec.axis], &[h], model).unwrap());
        assert_eq!(verdict(change.at * (1.0 + 1e-6)), after);
        assert_eq!(verdict(change.at * (1.0 - 1e-6)), !after);
    }
}

#[test]
fn the_strip_sweep_meets_the_wide_model_and_winkler() {
    // docs/physics/plane.md section 6: the wide model's error in mu* - mu is about 0.09 (L/h)^2;
    // at large L/h the contact width tends to L_Winkler - 0.22 h (nu = 0.3)
    let base = preset("coating-thickness-sweep.toml");
    let h = axis(&base, "material.thickness", [1e-6, 1e-2], 9, Spacing::Log);
    let outputs: Vec<QuantityKey> = ["mu_star_minus_mu", "contact_width"]
        .iter()
        .map(|q| QuantityKey::parse(q, &base).unwrap())
        .collect();
    let run = |model: &str| {
        let p = base
            .with_settings(&[format!("plane.model={model}")])
            .unwrap();
        sweep::run(&p, &[h], &outputs, &|| {})
            .into_iter()
            .map(|r| [r.values[0].clone(), r.values[1].clone()])
            .collect::<Vec<_>>()
    };
    // each model answers where it is compared (the wide model's contact leaves the punch tip on
    // the thinnest coatings: no answer there)
    let (strip, wide, narrow) = (run("strip"), run("wide"), run("narrow"));
    let strip: Vec<[f64; 2]> = strip
        .iter()
        .map(|v| [v[0].clone().unwrap(), v[1].clone().unwrap()])
        .collect();
    let hs = h.values();
    let mut checked = [0, 0];
    for i in 0..hs.len() {
        let l_over_h = strip[i][1] / hs[i];
        if l_over_h < 0.1 {
            let error = (wide[i][0].clone().unwrap() - strip[i][0]).abs() / strip[i][0].abs();
            let estimate = 0.09 * l_over_h * l_over_h;
            assert!(
                (0.5..1.5).contains(&(error / estimate)),
                "L/h = {l_over_h}: {error} vs {estimate}"
            );
            checked[0] += 1;
        }
        if l_over_h > 15.0 {
            let offset = (narrow[i][1].clone().unwrap() - strip[i][1]) / hs[i];
            assert!(
                (offset - 0.22).abs() < 0.03,
                "L/h = {l_over_h}: offset {offset} h"
            );
            checked[1] += 1;
        }
    }
    assert_eq!(checked, [2, 2]);
}

#[test]
fn every_number_has_a_default_range_around_its_value() {
    for file in [
        "polymer-coating.toml",
        "hertz-check.toml",
        "dispersion.toml",
    ] {
        let p = preset(file);
        for key in wearlab::preset::Key::all(&p) {
            let param = key.param();
            let axis = Axis::default_for(&p, key);
            if param.choices().is_some() || param.is_whole() {
                assert!(axis.is_err(), "{file} {key}");
                continue;
            }
            let r = axis.unwrap_or_else(|e| panic!("{file} {key}: {e}")).range;
            let v = p.get(key).unwrap();
            if v.is_finite() && v > 0.0 {
                assert!(r.min <= v && v <= r.max, "{file} {key}: {v} in {r:?}");
            }
        }
    }
}

#[test]
fn along_an_h_sweep_the_group_is_the_contact_width_over_h_of_the_same_solution() {
    // the x axis of the dimensionless view: (a+b)/h at each point, against the contact width
    // a + b of the solution at that point divided by the h swept there
    let p = preset("coating-thickness-sweep.toml");
    let spec = CurveSpec {
        axis: axis(&p, "material.thickness", [1e-5, 1e-3], 4, Spacing::Log),
        quantity: QuantityKey::parse("mu_star", &p).unwrap(),
        models: vec![Model::Wide, Model::Narrow],
    };
    let c = curve(&p, &spec, &AtomicBool::new(false)).unwrap();
    assert_eq!(c.group.unwrap().symbol(), "(a+b)/h");
    let width = QuantityKey::parse("contact_width", &p).unwrap();
    for s in &c.series {
        for (k, h) in c.x.iter().enumerate() {
            let point = solve_at(&p, &[spec.axis], &[*h], s.model).unwrap();
            let expected = width.value(&point).unwrap() / h;
            let got = s.group[k].unwrap();
            assert!(
                (got - expected).abs() <= 1e-14 * expected,
                "{got} vs {expected}"
            );
        }
        // "now" on the group axis: the width of the preset's own operating point (h = 100 um,
        // between the sweep points 46 and 215 um) over its h, not a value interpolated between them
        let mut own = p.clone();
        own.plane.model = s.model.unwrap();
        let here = wearlab::sweeps::point::solve(&own).unwrap();
        let expected = width.value(&here).unwrap() / p.get(spec.axis.key).unwrap();
        let got = s.current_group.unwrap();
        assert!(
            (got - expected).abs() <= 1e-14 * expected,
            "now: {got} vs {expected}"
        );
        // and the curve's value there is the operating point's own mu*
        assert_eq!(s.current_y, Some(spec.quantity.value(&here).unwrap()));
    }
    // an input without a group keeps its dimensional axis
    let e = CurveSpec {
        axis: axis(&p, "material.youngs_modulus", [1e9, 1e10], 3, Spacing::Log),
        ..spec
    };
    let c = curve(&p, &e, &AtomicBool::new(false)).unwrap();
    assert!(c.group.is_none() && c.series[0].group.iter().all(Option::is_none));
    assert!(c.series[0].current_group.is_none());
}
