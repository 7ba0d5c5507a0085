//! The general plane solver (physics::plane::general) on the strip of any thickness against the
//! strip solver (docs/physics/plane.md section 6) and the wide-strip limit of its kernels, its
//! energy identity and node counts, and load sweeps through the general solver.

use wearlab::physics::plane::energy::energy;
use wearlab::physics::plane::general::{Problem, Solution, solve};
use wearlab::physics::plane::laws::FrictionLaw;
use wearlab::physics::plane::{Model, PlaneInputs, Shape, WearLaw};

use super::plane_general::{general, laws, material, parabola, plane_inputs, power, rel};

#[test]
fn a_load_sweep_takes_the_general_solver_too() {
    use wearlab::physics::plane::sweep::sweep;
    use wearlab::physics::{Spacing, SweepRange};
    let k = 0.5 / material(1.0).plane_modulus();
    let range = SweepRange {
        min: 1e3,
        max: 1e4,
        points: 3,
        spacing: Spacing::Log,
    };
    for (model, cap) in [(Model::Wide, 2e6), (Model::Strip, f64::INFINITY)] {
        let inputs = plane_inputs(power(0.05, 3.0), 1e-3, laws(0.3, 0.0, cap, k, 2.0), 1e4);
        let s = sweep(&inputs, model, &range);
        for (p, mu_star) in s.load.iter().zip(&s.mu_star) {
            // the wide sweep starts each load from the previous one: the same discrete problem,
            // the same answer within the width's tolerance (tests/plane/plane_general_sweep.rs)
            let point = wearlab::physics::plane::solve(&inputs.with_load(*p), model).unwrap();
            let gap = (mu_star.unwrap() - point.mu_star).abs() / point.mu_star;
            assert!(
                gap < 1e-12,
                "{model:?} P = {p}: {mu_star:?} vs {}",
                point.mu_star
            );
        }
    }
}

/// The general solver on the strip of any thickness with these kernels.
fn on_strip(
    shape: &Shape,
    kernels: &dyn wearlab::physics::plane::strip::Kernels,
    thickness: f64,
    (friction, wear): (FrictionLaw, WearLaw),
    load: f64,
    nodes: usize,
) -> Solution {
    let problem = Problem {
        material: material(thickness),
        friction,
        wear,
        shape,
        load,
        strip: Some(kernels),
    };
    solve(&problem, nodes).unwrap_or_else(|e| panic!("{shape:?}: {e}"))
}

#[test]
fn on_the_strip_the_general_solver_joins_the_strip_solver_and_the_wide_limit() {
    use wearlab::physics::plane::strip::{self, WideLimit, kernels_for};
    let m = material(1.0).plane_modulus();
    let exact = kernels_for(0.3);
    // parabola with the linear laws: today's strip solver (docs/physics/plane.md section 6), at
    // (a+b)/h from about 0.5 to 20
    for (h, load) in [(1e-3, 1e4), (1e-4, 1e4), (1e-5, 1e4)] {
        for (mu, tau0, km) in [(0.3, 0.0, 0.5), (0.5, 1e5, 0.1)] {
            let law = laws(mu, tau0, f64::INFINITY, km / m, 1.0);
            let g = on_strip(&parabola(0.05), exact.as_ref(), h, law, load, 64);
            let want = strip::solve(&PlaneInputs::parabolic(
                material(h),
                law.0.coulomb,
                km / m,
                0.05,
                load,
            ))
            .unwrap();
            let gap = rel(g.a, want.a)
                .max(rel(g.b, want.b))
                .max(rel(g.mu_star - mu, want.mu_star - mu));
            println!(
                "strip h = {h}, (a+b)/h = {:.2}, mu {mu}, tau0 {tau0}: largest gap {gap:.2e}",
                (g.a + g.b) / h
            );
            assert!(gap < 1e-8, "h {h} mu {mu}: {gap}");
        }
    }
    // any shape and law: the wide-strip limit of the kernels is the wide model
    let k = 0.5 / m;
    let law = laws(0.3, 1e5, f64::INFINITY, k, 2.0);
    let limit = WideLimit::new(0.3);
    let shape = power(0.05, 3.0);
    let s = on_strip(&shape, &limit, 1e-3, law, 1e4, 64);
    let w = general(&shape, 1e-3, law, 1e4, 64);
    let gap = rel(s.a, w.a)
        .max(rel(s.b, w.b))
        .max(rel(s.mu_star, w.mu_star));
    println!("power 3, n = 2 on the strip's wide limit against the wide model: {gap:.2e}");
    assert!(gap < 1e-10, "{gap}");
}

#[test]
fn on_the_strip_other_shapes_and_laws_keep_the_energy_identity_and_converge() {
    let k = 0.5 / material(1.0).plane_modulus();
    for (h, load) in [(1e-3, 1e4), (1e-4, 1e4)] {
        let inputs = plane_inputs(
            power(0.05, 3.0),
            h,
            laws(0.3, 1e5, f64::INFINITY, k, 2.0),
            load,
        );
        let sol = wearlab::physics::plane::solve(&inputs, Model::Strip).unwrap();
        let e = energy(&sol).unwrap();
        let kernels = wearlab::physics::plane::strip::kernels_for(0.3);
        let law = laws(0.3, 1e5, f64::INFINITY, k, 2.0);
        let fine = on_strip(&power(0.05, 3.0), kernels.as_ref(), h, law, load, 128);
        let gap = rel(sol.a, fine.a)
            .max(rel(sol.b, fine.b))
            .max(rel(sol.mu_star, fine.mu_star));
        println!(
            "strip power 3, n = 2, h = {h}: (a+b)/h {:.2} mu* {:.8e} residual {:.2e} contact residual {:.2e}, N vs N = 128 {gap:.2e}",
            (sol.a + sol.b) / h,
            sol.mu_star,
            e.residual,
            e.contact_residual
        );
        assert!(e.residual < 1e-8 && e.contact_residual < 1e-7, "{e:?}");
        assert!(gap < 1e-6, "{gap}");
    }
}
