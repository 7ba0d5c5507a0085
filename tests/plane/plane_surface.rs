//! The deformed strip surface of the profile (`Profile::surface`, v(x) - v(b) + g(b) = g + wear
//! per pass by the contact condition (1.11)) against an independent route: the Winkler strip's
//! own displacement v = -beta q2 + const (Soldatenkov (2007) eq. 5.1), so that
//! surface(x) = g(b) - beta q2(x) with beta = (1 - 2 nu)(1 + nu) h/((1 - nu) E).

use wearlab::physics::plane::Model;
use wearlab::physics::plane::operating_point::operating_point;
use wearlab::preset::bundled;

#[test]
fn the_surface_is_the_winkler_displacement_under_a_parabola_and_a_rounded_flat() {
    for file in ["thin-strip-winkler.toml", "flat-pin-coating.toml"] {
        let preset = bundled(file).unwrap().unwrap();
        let inputs = preset.plane_inputs();
        assert_eq!(preset.plane.model, Model::Narrow);
        let op = operating_point(&inputs, Model::Narrow, 101).unwrap();
        let p = &op.profile;
        let mat = &inputs.material;
        let nu = mat.poisson_ratio;
        let beta =
            (1.0 - 2.0 * nu) * (1.0 + nu) * mat.thickness / ((1.0 - nu) * mat.youngs_modulus);
        let g_b = *p.shape.last().unwrap();
        let scale = p.pressure.iter().fold(0.0_f64, |m, q| m.max(beta * q));
        // the wear part is far from negligible: at least a tenth of the depth
        assert!(p.wear[0] > 0.1 * scale, "{file}: {} {scale}", p.wear[0]);
        for i in 0..p.x.len() {
            let winkler = g_b - beta * p.pressure[i];
            assert!(
                (p.surface[i] - winkler).abs() < 1e-6 * scale,
                "{file} x = {}: {} against {winkler}",
                p.x[i],
                p.surface[i]
            );
        }
    }
}
