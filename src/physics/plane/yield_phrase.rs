//! The yield check in one short phrase for a status line (`wearlab solve` writes the long form,
//! `YieldCheck::describe`): "yields: von Mises 6.40 MPa at 126 um depth > Y = 5.00 MPa", or
//! "below yield: von Mises 3.00 MPa = 0.60 Y at the surface".

use crate::phrase::Phrase;
use crate::physics::plane::yield_onset::YieldCheck;
use crate::units::format_si;

impl YieldCheck {
    /// The check in a few words: whether the strip yields, the largest von Mises stress and
    /// where, against Y (named "H/3" where it comes from the hardness).
    pub fn phrase(&self) -> Phrase {
        let y = format_si(self.strength, "Pa");
        let y = if self.basis == "yield_strength" {
            format!("Y = {y}")
        } else {
            format!("Y = H/3 = {y}")
        };
        let (Some(stress), Some(ratio), Some(depth)) = (self.von_mises_max, self.ratio, self.depth)
        else {
            return match self.yields {
                Some(true) => {
                    Phrase::words("yields at the sharp corners (the pressure is unbounded there)")
                }
                _ => Phrase::words("yield not judged under the narrow model"),
            };
        };
        let place = if depth == 0.0 {
            "at the surface".to_string()
        } else {
            format!("at {} depth", format_si(depth, "m"))
        };
        let stress = format!("von Mises {}", format_si(stress, "Pa"));
        if ratio >= 1.0 {
            Phrase::words("yields:")
                .then(stress)
                .then(place)
                .then(format!("> {y}"))
        } else {
            Phrase::words("below yield:")
                .then(format!("{stress} = {ratio:.2} Y"))
                .then(place)
        }
    }
}
