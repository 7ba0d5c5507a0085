//! Where a key of the main screen applies (`keys::Binding::only`): every preset, one problem, or
//! a punch that is a generated rough surface; the footer shows a key there only, and elsewhere
//! the key says why it does nothing.

use crate::preset::{Preset, Problem, surface_from_file};

/// Where a binding applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scope {
    /// Every preset.
    All,
    /// One problem.
    Problem(Problem),
    /// A spatial preset whose punch is a generated rough surface (`spatial.surface` with
    /// kind = "self-affine").
    GeneratedSurface,
}

/// What is open, as far as the keys care: the problem, and whether the punch is a generated
/// rough surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Open {
    /// The problem solved.
    pub problem: Problem,
    /// True when the punch is a generated surface.
    pub generated_surface: bool,
}

impl Open {
    /// What `preset` opens.
    pub fn of(preset: &Preset) -> Open {
        Open {
            problem: preset.problem,
            generated_surface: preset.problem == Problem::Spatial
                && preset.spatial.surface.is_some()
                && !surface_from_file(preset),
        }
    }
}

impl From<Problem> for Open {
    /// A problem with a punch that is not a generated surface.
    fn from(problem: Problem) -> Open {
        Open {
            problem,
            generated_surface: false,
        }
    }
}

impl Scope {
    /// Whether a binding of this scope applies to what is open.
    pub fn applies(self, open: Open) -> bool {
        match self {
            Scope::All => true,
            Scope::Problem(p) => p == open.problem,
            Scope::GeneratedSurface => open.generated_surface,
        }
    }

    /// Where it applies, in words ("the plane problem"); None for every preset.
    pub fn place(self) -> Option<String> {
        match self {
            Scope::All => None,
            Scope::Problem(p) => Some(format!("the {} problem", p.name())),
            Scope::GeneratedSurface => Some("a generated rough surface".into()),
        }
    }
}
