//! The explorer's views by name, for files that name one (a preset's `[lesson]` opens on a view):
//! each problem's charts in Tab order with their titles, and the sweep chart and the regime map
//! of a preset's `[explore]` section. The explorer draws them (`tui::charts`); the titles live
//! here once, so that the library can check a name without the terminal code.

use strum::VariantArray;

use crate::preset::{Preset, Problem};

/// The charts of the plane problem, in Tab order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, VariantArray)]
pub enum PlaneChart {
    /// q2 and q1 against x.
    Pressure,
    /// Wear per pass and wear rate against x.
    Wear,
    /// mu* against load, the other models overlaid.
    MuStar,
    /// a and b against load.
    Edges,
    /// The punch's shape, the strip surface and the wear groove against x.
    Punch,
    /// The friction and wear losses' shares of T against load.
    Energy,
}

impl PlaneChart {
    /// The title drawn above the chart.
    pub fn title(self) -> &'static str {
        match self {
            Self::Pressure => "pressure and shear",
            Self::Wear => "wear",
            Self::Punch => "punch and strip surface",
            Self::MuStar => "mu* against load",
            Self::Edges => "contact edges against load",
            Self::Energy => "energy losses against load",
        }
    }
}

/// The charts of the spatial problem, in Tab order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, VariantArray)]
pub enum SpatialChart {
    /// p(x, y) over the period cell.
    PressureMap,
    /// p and U along the middle line.
    Line,
    /// A_n(t) and mu*(t).
    History,
    /// mu* against pbar.
    MuStar,
    /// c against kh.
    Dispersion,
    /// The PSD of a height-map punch, as given and at t.
    Spectrum,
}

impl SpatialChart {
    /// The title drawn above the chart.
    pub fn title(self) -> &'static str {
        match self {
            Self::PressureMap => "pressure map",
            Self::Line => "pressure and shape along a line",
            Self::History => "time history",
            Self::MuStar => "mu* against mean pressure",
            Self::Dispersion => "dispersion: drift velocity",
            Self::Spectrum => "surface spectrum (PSD)",
        }
    }
}

/// A chart of either problem.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Chart {
    /// A plane chart.
    Plane(PlaneChart),
    /// A spatial chart.
    Spatial(SpatialChart),
}

impl Chart {
    /// The charts of a problem, in Tab order.
    pub fn all(problem: Problem) -> Vec<Chart> {
        match problem {
            Problem::Plane => PlaneChart::VARIANTS
                .iter()
                .copied()
                .map(Chart::Plane)
                .collect(),
            Problem::Spatial => (SpatialChart::VARIANTS.iter().copied())
                .map(Chart::Spatial)
                .collect(),
        }
    }

    /// The first chart of a problem.
    pub fn first(problem: Problem) -> Chart {
        Chart::all(problem)[0]
    }

    /// The problem the chart belongs to.
    pub fn problem(self) -> Problem {
        match self {
            Chart::Plane(_) => Problem::Plane,
            Chart::Spatial(_) => Problem::Spatial,
        }
    }

    /// Position (from 1) and count within its problem, for "2/4".
    pub fn position(self) -> (usize, usize) {
        let all = Chart::all(self.problem());
        let i = all.iter().position(|c| *c == self).expect("listed");
        (i + 1, all.len())
    }

    /// The chart `step` places further in Tab order (wrapping).
    pub fn step(self, step: isize) -> Chart {
        let all = Chart::all(self.problem());
        let (i, n) = self.position();
        all[(i as isize - 1 + step).rem_euclid(n as isize) as usize]
    }

    /// The title.
    pub fn title(self) -> &'static str {
        match self {
            Chart::Plane(c) => c.title(),
            Chart::Spatial(c) => c.title(),
        }
    }
}

/// The name of the sweep chart of a preset's `[explore]` section (one axis).
pub const SWEEP: &str = "sweep";
/// The name of the regime map of a preset's `[explore]` section (two axes).
pub const MAP: &str = "regime map";

/// A view the explorer can open on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// One of the problem's charts.
    Chart(Chart),
    /// The sweep chart of the `[explore]` section.
    Sweep,
    /// The regime map of the `[explore]` section.
    Map,
}

impl View {
    /// The view's name: a chart's title, `SWEEP` or `MAP`.
    pub fn name(self) -> &'static str {
        match self {
            View::Chart(c) => c.title(),
            View::Sweep => SWEEP,
            View::Map => MAP,
        }
    }

    /// The views a preset can open on: its problem's charts, and the sweep or the map of its
    /// `[explore]` section when it has one.
    pub fn all(preset: &Preset) -> Vec<View> {
        let mut views: Vec<View> = Chart::all(preset.problem)
            .into_iter()
            .map(View::Chart)
            .collect();
        match preset.explore.as_ref().map(|e| e.axes.len()) {
            Some(1) => views.push(View::Sweep),
            Some(_) => views.push(View::Map),
            None => {}
        }
        views
    }

    /// The view of a preset with this name; Err lists the names there are.
    pub fn parse(name: &str, preset: &Preset) -> Result<View, String> {
        let views = View::all(preset);
        views
            .iter()
            .copied()
            .find(|v| v.name() == name.trim())
            .ok_or_else(|| {
                let names: Vec<String> = views.iter().map(|v| format!("\"{}\"", v.name())).collect();
                let explore = if preset.explore.is_none() {
                    format!(
                        " (\"{SWEEP}\" and \"{MAP}\" need an [explore] section with one or two axes)"
                    )
                } else {
                    String::new()
                };
                format!(
                    "view = \"{}\" is not a view of a {} preset: the views are {}{explore}",
                    name.trim(),
                    preset.problem.name(),
                    names.join(", ")
                )
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::preset::bundled;

    #[test]
    fn every_view_is_found_by_its_name_and_an_unknown_one_lists_them() {
        for b in crate::preset::BUNDLED {
            let preset = bundled(b.file).unwrap().unwrap();
            for v in View::all(&preset) {
                assert_eq!(View::parse(v.name(), &preset), Ok(v));
            }
        }
        let hertz = bundled("hertz-check.toml").unwrap().unwrap();
        let why = View::parse("mu against load", &hertz).unwrap_err();
        assert!(why.contains("\"mu* against load\""), "{why}");
        assert!(why.contains("need an [explore] section"), "{why}");
    }
}
