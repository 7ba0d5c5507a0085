//! The yield check in words: the long form that `wearlab solve` writes (`YieldCheck::describe`),
//! and a short phrase for a status line (`YieldCheck::phrase`): "yields: von Mises 6.40 MPa at
//! 126 um depth > Y = 5.00 MPa", or "below yield: von Mises 3.00 MPa = 0.60 Y at the surface";
//! where both a yield strength and a hardness are given, each says which one is used.

use crate::phrase::Phrase;
use crate::physics::plane::yield_onset::{NotJudged, YieldCheck};
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
            return match self.note {
                Some(NotJudged::SharpCorners) => {
                    Phrase::words("yields at the sharp corners (the pressure is unbounded there)")
                }
                Some(NotJudged::BelowLayer { depth, thickness }) => {
                    // short enough for two rows of the status at 80x24; `describe` says that
                    // the stress is the half-plane's
                    Phrase::words("yield not judged: peak stress")
                        .then(format!("{} deep,", format_si(depth, "m")))
                        .then_words("below")
                        .then(format!("h = {}", format_si(thickness, "m")))
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
        let verdict = if ratio >= 1.0 {
            Phrase::words("yields:")
                .then(stress)
                .then(place)
                .then(format!("> {y}"))
        } else {
            let basis = (self.basis != "yield_strength").then_some("(Y = H/3)");
            Phrase::words("below yield:")
                .then(format!("{stress} = {ratio:.2} Y"))
                .then(place)
                .then(basis.unwrap_or_default())
        };
        // both given: which one the check takes
        if self.hardness_unused {
            verdict.then_words("(Y as given; H not used)")
        } else {
            verdict
        }
    }

    /// The check in words: whether the strip yields, the largest stress against Y and where it
    /// is ("at the surface" or its depth).
    pub fn describe(&self) -> String {
        let unused = if self.hardness_unused {
            "; the hardness given is not used"
        } else {
            ""
        };
        let y = format!(
            "Y = {} ({}{unused})",
            format_si(self.strength, "Pa"),
            self.basis
        );
        let (Some(stress), Some(ratio), Some(depth)) = (self.von_mises_max, self.ratio, self.depth)
        else {
            let why = self.note.map(NotJudged::reason).unwrap_or_default();
            return match self.yields {
                Some(true) => format!("the strip yields: {why}"),
                _ => format!("yield not judged: {why}"),
            };
        };
        let place = if depth == 0.0 {
            "at the surface".to_string()
        } else {
            format!("{} below the surface", format_si(depth, "m"))
        };
        let stress = format_si(stress, "Pa");
        if ratio >= 1.0 {
            format!("the strip yields: von Mises stress {stress} {place} exceeds {y}")
        } else {
            format!("no yield: largest von Mises stress {stress} = {ratio:.2} Y {place}, {y}")
        }
    }
}
