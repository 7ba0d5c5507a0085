//! The verdict over the loads a lab uses, 1e2 to 1e6 N/m, on every bundled plane preset and for
//! each model it allows: the status has exactly one verdict (the model holds, or why not), the
//! one `wearlab solve` reports for the same point (`operating_point`'s verdict), and every
//! threshold the verdict's message names is where the verdict changes (found by bisection in
//! the load). The status's validity lines are laid out at every load; the whole screen is
//! rendered at three, with the engine stopped once the strip check has come (its sweeps are not
//! part of the status).

use std::sync::Arc;

use super::validity::status;
use super::*;
use crate::engine::{Output, Request};
use crate::physics::plane::criteria::{MU_STAR_TOLERANCE, WIDTH_TOLERANCE};
use crate::physics::plane::shape_validity::SLOPE_BOUND;
use crate::physics::plane::strip_check::{StripCheck, strip_check, verdict};
use crate::physics::plane::validity::{Validity, estimate};
use crate::physics::plane::{Model, PlaneSolution, operating_point::operating_point, solve};
use crate::preset::{BUNDLED, Problem};
use crate::tui::view::validity_status;

/// Loads from 1e2 to 1e6 N/m: 13, three to a decade, for the parabola with the linear law and no
/// cap; 5, one to a decade, for other shapes and laws, whose solves take up to a second each
/// (the strip's) and whose turns are found by bisection all the same.
fn loads(classical: bool) -> Vec<f64> {
    let per_decade = if classical { 3 } else { 1 };
    (0..=4 * per_decade)
        .map(|i| 10f64.powf(2.0 + i as f64 / per_decade as f64))
        .collect()
}

/// The bundled plane presets with each model they allow (the narrow and the strip model need a
/// finite thickness).
fn cases() -> Vec<(&'static str, Preset, Model)> {
    let mut out = Vec::new();
    for b in BUNDLED {
        let p = b.load().unwrap();
        if p.problem != Problem::Plane {
            continue;
        }
        for model in Model::ALL.iter().copied() {
            if !model.needs_finite_thickness() || !p.material.is_half_space() {
                let mut q = p.clone();
                q.plane.model = model;
                out.push((b.file, q, model));
            }
        }
    }
    out
}

/// The verdict lines among a status's rows: "... model holds" or "! why".
fn verdict_lines(s: &str) -> (usize, Vec<&str>) {
    let holds = s.lines().filter(|l| l.contains("model holds")).count();
    let why = s
        .lines()
        .map(|l| l.trim_matches(['│', ' ']))
        .filter(|l| l.starts_with("! "))
        .collect();
    (holds, why)
}

/// The status says the verdict `v` once: one "holds" line when it holds, else no "holds" line
/// and its first reason; and the check against the strip model does not contradict it.
fn says_once(s: &str, v: &Validity, what: &str) {
    let (holds, why) = verdict_lines(s);
    if v.ok {
        assert!(holds == 1 && why.is_empty(), "{what}: holds\n{s}");
        // a measurement outside the tolerances beside "holds" would contradict it (an estimate,
        // "est. off", is the study's and within them where the verdict holds)
        let off = s.contains("off the exact strip solution by")
            || s.lines()
                .any(|l| l.trim_matches(['│', ' ']).starts_with("off exact strip"));
        assert!(!off, "{what}: holds, and the check says off\n{s}");
    } else {
        let first = v.reasons[0].text.to_string();
        let start: String = first.chars().take(24).collect();
        assert!(holds == 0 && !why.is_empty(), "{what}: {first}\n{s}");
        assert!(why[0].contains(&start), "{what}: {first}\n{s}");
        if v.measured_error.is_some_and(|d| !d.within_tolerance()) {
            assert!(!s.contains("of the exact strip solution") || s.contains("off"));
        }
    }
}

/// The app on `preset`, its point and strip check delivered, the sweeps not computed.
fn point_shown(preset: &Preset) -> App {
    let mut app = App::new(preset.clone(), None, Places::default());
    let commands = app.start();
    let mut engine = Engine::new();
    for c in commands {
        let Command::Solve(generation, request) = c else {
            continue;
        };
        let request: Arc<Request> = Arc::new((*request).clone());
        let mut answers = Vec::new();
        engine.run_staged(&request, |output, complete| {
            let more =
                matches!(&output, Output::Plane(o) if o.point.is_ok() && o.strip_check.is_none());
            answers.push(Answer {
                generation,
                request: request.clone(),
                output,
                complete,
            });
            more
        });
        for a in answers {
            update(&mut app, Msg::Answer(Box::new(a)));
        }
    }
    app
}

/// How far each warning of `v` (on `sol`) is from the threshold it names, as the ratio of the
/// quantity to it (1 at the threshold); None for a warning with no threshold in the load.
fn against_thresholds(v: &Validity, sol: &PlaneSolution) -> Vec<(String, Option<f64>)> {
    let l = sol.contact_width();
    v.warnings
        .iter()
        .map(|w| {
            let ratio = if w.contains("off the exact strip solution") {
                let d = v.measured_error.unwrap();
                Some(
                    (d.contact_width / WIDTH_TOLERANCE).max(d.mu_star_minus_mu / MU_STAR_TOLERANCE),
                )
            } else if w.contains("(a+b)/R") {
                Some(l / sol.inputs.radius() / 0.1)
            } else if let Some(limit) = named_after(w, "needs (a+b)/h ") {
                Some(v.contact_width_over_thickness / limit)
            } else if let Some(slope) = named_after(w, "reaches |g'| = ") {
                Some(slope / SLOPE_BOUND)
            } else if let (Some(count), Some(least)) = (
                named_after(w, " holds ").or(named_after(w, "] m ends ")),
                named_after(w, "fewer than "),
            ) {
                // a count: the verdict turns where it drops to one below the least
                Some((count + 1.0) / least)
            } else if w.contains("lacks the friction-induced part") {
                Some(v.estimated_error.mu_star_minus_mu / MU_STAR_TOLERANCE)
            } else {
                None
            };
            (w.clone(), ratio)
        })
        .collect()
}

/// The number after `lead` and a comparison sign ("needs (a+b)/h < 0.26 at ...": 0.26).
fn named_after(text: &str, lead: &str) -> Option<f64> {
    let rest = &text[text.find(lead)? + lead.len()..];
    let number = rest
        .trim_start_matches(['<', '>', ' '])
        .split([' ', ',', ':'])
        .next()?;
    number.parse().ok()
}

#[test]
fn every_plane_preset_and_model_says_one_verdict_from_1e2_to_1e6_n_per_m() {
    let mut turns = Vec::new();
    let mut wrong = Vec::new();
    for (file, p, model) in cases() {
        let judge = |load: f64| -> Result<(PlaneSolution, Validity), String> {
            let sol = solve(&p.plane_inputs().with_load(load), model).map_err(|e| e.to_string())?;
            let v = verdict(&sol);
            Ok((sol, v))
        };
        let mut last: Option<(f64, bool)> = None;
        let classical = p.plane_inputs().is_classical();
        for load in loads(classical) {
            let what = format!("{file} {} at {load:.3e} N/m", model.name());
            // what `wearlab solve` reports, and the status laid out from the same point
            let point = match operating_point(&p.plane_inputs().with_load(load), model, 11) {
                Ok(point) => point,
                Err(e) => {
                    // no point: the explorer shows the error instead of a verdict
                    last = None;
                    let _ = e;
                    continue;
                }
            };
            // the check against the strip model, as the status shows it (measured for the
            // parabola with the linear law: other shapes' strip solves are the screen test's)
            let check = if classical {
                strip_check(&point.solution)
            } else {
                StripCheck::Exact
            };
            let shown = classical.then_some(&check);
            let lines: String = validity_status::lines(&point, shown, PLAIN, 78, 6)
                .iter()
                .map(|l| format!("{l}\n"))
                .collect();
            says_once(&lines, &point.validity, &what);
            // a measurement is the verdict wherever the study doubts the model; other shapes and
            // laws are not judged by it (their strip solve takes up to seconds a point, too slow
            // for a sweep), though the explorer shows it
            if let StripCheck::Measured(d) = &check {
                let v = &point.validity;
                let classical = point.solution.inputs.is_classical();
                assert!(v.ok || d.within_tolerance() || !classical || v.measured_error.is_some());
                assert!(
                    v.measured_error.is_some() || estimate(&point.solution).ok || !classical,
                    "{what}: measured, not in the verdict: {v:?}\n{lines}"
                );
            }
            // where the verdict changes between two loads, the message names that point
            if let Some((before, was)) = last
                && was != point.validity.ok
            {
                let at = bisect(before, load, |x| judge(x).map(|(_, v)| v.ok).unwrap_or(was));
                let (lo, hi) = (judge(at / 1.005), judge(at * 1.005));
                let failing = [lo, hi].into_iter().flatten().find(|(_, v)| !v.ok);
                let (sol, v) = failing.expect("a failing side");
                let named = against_thresholds(&v, &sol);
                let nearest = named
                    .iter()
                    .filter_map(|(_, r)| *r)
                    .map(|r| (r - 1.0).abs())
                    .fold(f64::INFINITY, f64::min);
                turns.push(format!("{what}: turns at {at:.4e}: {named:?}"));
                if nearest >= 0.02 {
                    wrong.push(format!("{what}: turns at {at:.4e} N/m, but {named:?}"));
                }
            }
            last = Some((load, point.validity.ok));
        }
    }
    println!("{}", turns.join("\n"));
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// Where `f` changes between `lo` and `hi` (f(lo) != f(hi)), by bisection in log load to 1e-2:
/// the load to 0.5 %, a quantity growing like a power p of it to 0.5 p %.
fn bisect(lo: f64, hi: f64, f: impl Fn(f64) -> bool) -> f64 {
    let (mut lo, mut hi) = (lo.ln(), hi.ln());
    let first = f(lo.exp());
    while hi - lo > 1e-2 {
        let mid = 0.5 * (lo + hi);
        if f(mid.exp()) == first {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (0.5 * (lo + hi)).exp()
}

#[test]
fn the_screen_says_the_verdict_solve_reports_at_light_middle_and_heavy_loads() {
    for (file, p, model) in cases() {
        for load in [1e2, 1e4, 1e6] {
            let what = format!("{file} {} at {load:.0e} N/m", model.name());
            let mut q = p.clone();
            q.plane.load = load;
            let app = point_shown(&q);
            let s = status(&app, 80, 24);
            match operating_point(&q.plane_inputs(), model, 11) {
                Ok(point) => says_once(&s, &point.validity, &what),
                Err(e) => {
                    let (holds, _) = verdict_lines(&s);
                    assert_eq!(holds, 0, "{what}: {e}\n{s}");
                }
            }
        }
    }
}
