//! The regime map's lines as the terminal and the SVG both name them: the letter each is drawn
//! with and what it means.

use crate::sweeps::map::LineKind;

/// The letter of a line and what it means.
pub fn line_key(kind: LineKind) -> (char, &'static str) {
    match kind {
        LineKind::ThetaZero => ('0', "theta = 0 line (mu* - mu = 0 on a half-plane)"),
        LineKind::MuStarEqualsMu => ('=', "mu* = mu line: wear dominates where mu* > mu"),
        LineKind::Validity(m) if m.name() == "wide" => ('W', "wide model's validity limit"),
        LineKind::Validity(_) => ('N', "narrow (Winkler) model's validity limit"),
        LineKind::CompleteContact => ('C', "complete contact lost"),
        LineKind::Yield => ('Y', "yield onset: largest von Mises stress = Y"),
    }
}
