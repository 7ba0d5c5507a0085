//! The quantity registry (`sweeps::quantity`): the report's quantities are the report's keys with
//! the report's values; the derived ones against independent routes.

use crate::common;

use serde_json::Value;
use wearlab::preset::{BUNDLED, Preset, Problem, bundled};
use wearlab::report;
use wearlab::sweeps::point::{Point, solve};
use wearlab::sweeps::quantity::{self, Origin, QuantityKey};

fn preset(file: &str) -> Preset {
    bundled(file).unwrap().unwrap()
}

fn plane_point(p: &Preset) -> wearlab::sweeps::point::PlanePoint {
    match solve(p).unwrap() {
        Point::Plane(pp) => *pp,
        Point::Spatial(_) => unreachable!("a plane preset"),
    }
}

/// The JSON value at a dotted name (`harmonics.0.decay_rate`).
fn at<'a>(v: &'a Value, name: &str) -> &'a Value {
    name.split('.')
        .fold(v, |v, part| match part.parse::<usize>() {
            Ok(n) => &v[n],
            Err(_) => &v[part],
        })
}

#[test]
fn every_report_quantity_is_the_report_key_with_the_reports_value() {
    let mut compared = 0;
    for b in BUNDLED {
        let p = b.load().unwrap();
        let json = match p.problem {
            Problem::Plane => report::to_json(&report::plane_report(&p, 2).unwrap()),
            Problem::Spatial => report::to_json(
                &wearlab::spatial_report::spatial_report(&p, None, &[], false).unwrap(),
            ),
        };
        let json: Value = serde_json::from_str(&json).unwrap();
        let point = solve(&p).unwrap();
        for q in QuantityKey::all(&p) {
            if q.quantity().origin != Origin::Report {
                continue;
            }
            let reported = at(&json, &q.to_string());
            match q.value(&point) {
                Ok(v) if q.quantity().flag => assert_eq!(reported.as_bool(), Some(v == 1.0)),
                Ok(v) => assert_eq!(
                    reported.as_f64().map(f64::to_bits),
                    Some(v.to_bits()),
                    "{} {q}",
                    b.file
                ),
                // an optional key of the report (null there) has no value here
                Err(why) => assert!(reported.is_null(), "{} {q}: {why}", b.file),
            }
            compared += 1;
        }
    }
    assert!(compared > 100, "{compared}");
}

#[test]
fn names_are_unique_and_every_quantity_has_a_value_at_the_bundled_presets() {
    let mut names: Vec<(&str, &str)> = Vec::new();
    for b in BUNDLED {
        let p = b.load().unwrap();
        if p.spatial.harmonics.is_empty() {
            continue;
        }
        let point = solve(&p).unwrap();
        for q in QuantityKey::all(&p) {
            let entry = (p.problem.name(), q.quantity().name);
            if !names.contains(&entry) {
                names.push(entry);
            }
            if let Ok(v) = q.value(&point) {
                assert!(v.is_finite(), "{} {q}", b.file);
            }
        }
    }
    let mut sorted = names.clone();
    sorted.sort();
    sorted.dedup();
    assert_eq!(sorted.len(), names.len());
    assert!(quantity::defaults(&preset("dispersion.toml")).len() > 8);
}

#[test]
fn the_largest_pressure_is_at_the_closed_form_maximum() {
    // docs/physics/plane.md section 3: the wide pressure peaks at x = (1/2 - theta) b - (1/2 + theta) a
    for file in [
        "wear-dominated.toml",
        "friction-half-plane.toml",
        "hertz-check.toml",
    ] {
        let p = plane_point(&preset(file));
        let s = &p.solution;
        let theta = s.theta.unwrap();
        let x = (0.5 - theta) * s.b - (0.5 + theta) * s.a;
        let exact = s.pressure(x);
        let got = p.max_pressure();
        assert!(
            (got - exact).abs() <= 1e-12 * exact,
            "{file}: {got} vs {exact}"
        );
    }
    // Hertz: q2(0) = 2P/(pi a) (Johnson 1985, eq. 4.45)
    let p = plane_point(&preset("hertz-check.toml"));
    let hertz = 2.0 * p.solution.inputs.load / (std::f64::consts::PI * p.solution.a);
    assert!(common::rel(p.max_pressure(), hertz) < 1e-12);
}

#[test]
fn the_wear_at_the_tip_is_half_the_wear_of_a_symmetric_contact() {
    // without friction, and with wear too weak to tilt it (k m = 4e-9, theta ~ 1e-9), the
    // pressure is symmetric about the tip: k times half of Q2
    let p = preset("hertz-check.toml")
        .with_settings(&["wear.coefficient=1e-20"])
        .unwrap();
    let pp = plane_point(&p);
    let half = 1e-20 * pp.solution.normal_force / 2.0;
    assert!(
        common::rel(pp.tip_wear(), half) < 1e-8,
        "{} vs {half}",
        pp.tip_wear()
    );
    // and at the trailing edge (the whole pass) the profile's wear per pass, by its own quadrature
    let wide = preset("wear-dominated.toml");
    let point = plane_point(&wide);
    let profile = wearlab::physics::plane::profile::profile(&point.solution, 201);
    let tip = profile.x.iter().position(|x| *x >= 0.0).unwrap();
    // the profile's point nearest the tip from the leading side; the quadratures differ by 1e-8
    let k = wide.wear;
    let between: f64 = {
        let rule = wearlab::physics::quadrature::gauss_legendre(20);
        k * rule.integrate(0.0, profile.x[tip], |x| point.solution.pressure(x))
    };
    assert!(common::rel(point.tip_wear(), profile.wear[tip] + between) < 1e-8);
}

#[test]
fn the_cli_page_lists_every_output() {
    let page = std::fs::read_to_string("docs/cli.md").unwrap();
    for file in ["hertz-check.toml", "dispersion.toml"] {
        for q in QuantityKey::all(&preset(file)) {
            let name = q.quantity().name;
            let listed = match name.strip_prefix("harmonics.N.") {
                Some(field) => {
                    page.contains(&format!("`harmonics.N.{field}`"))
                        || page.contains(&format!("`.{field}`"))
                }
                None => page.contains(&format!("`{name}`")),
            };
            assert!(listed, "docs/cli.md does not list the output {name}");
        }
    }
}
