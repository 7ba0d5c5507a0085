//! Which other measurement would determine a parameter that the data at hand do not: the
//! quantity that changes most with it, in the words of a lab.

use crate::preset::Key;

/// A measurement that would determine `key`, in words.
pub fn measurement_for(key: Key) -> String {
    match key.param().key {
        "wear.coefficient" => "wear depth against sliding distance (a wear test) would determine \
                               it: wear grows in proportion to k, friction hardly feels it"
            .into(),
        "wear.exponent" | "wear.reference_pressure" => {
            "the wear rate at several loads would determine it".into()
        }
        "friction.coefficient" => "the friction coefficient at high loads, where mu* tends to mu, \
                                   would determine it"
            .into(),
        "friction.adhesion" => "the friction coefficient at light loads, where the adhesive part \
                                tau0 (a+b)/P is largest, would determine it"
            .into(),
        "friction.shear_strength" => "the friction coefficient at loads high enough for the \
                                      shear stress to reach its cap would determine it"
            .into(),
        "material.youngs_modulus" | "material.poisson_ratio" | "plane.radius" => {
            "the contact width against load (a+b grows like sqrt(P R/E)) would determine it".into()
        }
        "material.thickness" => "the contact width or mu* at loads where the contact is as wide \
                                 as the layer is thick would determine it"
            .into(),
        _ => format!(
            "a quantity that changes with {key} over the range measured would determine it (see \
             which with wearlab sweep --vary {key}=FROM:TO)"
        ),
    }
}
