//! The charts as data: each problem's charts are an enum (`crate::views`, which holds their
//! titles), and each chart has a help text and a pure builder from an engine answer to the figure
//! it draws. The view draws that figure and `e` exports it, so what is exported is by
//! construction what is drawn. A new chart is one variant and its title in `views`, and one arm
//! of its problem's `spec` here (help, builder).

pub mod contact;
pub mod export;
mod gaps;
pub mod map_lines;
pub mod overlay;
pub mod palette;
mod plane;
pub mod range;
pub mod readout;
mod spatial;
mod surface;
pub mod svg;
pub mod sweep;
pub mod ticks;

use crate::engine::{Answer, Output, PlaneOutput, SpatialOutput};
use crate::preset::Preset;

use crate::views::View;
pub use crate::views::{Chart, PlaneChart, SpatialChart};

pub use ticks::Scale;

/// One axis of a plot.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    /// What is along it ("x", "P", "mu*").
    pub label: String,
    /// SI unit of the values ("" for none); the axis title carries it with a prefix.
    pub unit: &'static str,
    /// How values are placed along it (the chart's default; `y` toggles the y axis).
    pub scale: Scale,
}

/// A labelled value on an axis: a vertical line at an x (labelled on the x axis), or a
/// horizontal line at a y (named in the legend).
#[derive(Clone, Debug, PartialEq)]
pub struct Mark {
    /// Where, in data coordinates.
    pub at: f64,
    /// What it is ("-a", "tip", "mu = 0.3").
    pub label: String,
}

/// A range of x drawn shaded and named in the legend (where a chart has no curve, and why).
#[derive(Clone, Debug, PartialEq)]
pub struct Shade {
    /// From this x (data coordinates).
    pub from: f64,
    /// To this x.
    pub to: f64,
    /// Why ("no complete contact").
    pub label: String,
}

/// A named set of points in data coordinates (SI units, never log-transformed).
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Legend text.
    pub name: String,
    /// (x, y) pairs.
    pub points: Vec<(f64, f64)>,
}

/// Measured points drawn over a plot (a data file's column against its x column), each with its
/// standard deviation where the file gives one, drawn as an error bar of +- one sd.
#[derive(Clone, Debug, PartialEq)]
pub struct Measured {
    /// Legend text ("data: friction.csv").
    pub name: String,
    /// (x, y) pairs in the axes' SI units.
    pub points: Vec<(f64, f64)>,
    /// One standard deviation of each y (the y unit), when the file gives them.
    pub sd: Option<Vec<f64>>,
}

impl Measured {
    /// The ends of each point's error bar, (x, y - sd) and (x, y + sd); none without sd.
    pub fn bars(&self) -> Vec<[(f64, f64); 2]> {
        let Some(sd) = &self.sd else {
            return Vec::new();
        };
        self.points
            .iter()
            .zip(sd)
            .map(|(&(x, y), s)| [(x, y - s), (x, y + s)])
            .collect()
    }
}

/// One x-y plot.
#[derive(Clone, Debug, PartialEq)]
pub struct Plot {
    /// The horizontal axis.
    pub x: Axis,
    /// The vertical axis.
    pub y: Axis,
    /// The curves, drawn as lines.
    pub series: Vec<Series>,
    /// How many of the first curves set the y range; the others are overlays, clipped, so that a
    /// model far outside the range does not flatten the one being explored.
    pub focus: usize,
    /// Marked points (the operating point, the current time, the harmonics), drawn as blocks.
    pub markers: Option<Series>,
    /// Vertical lines at x values ("-a", "tip", "b").
    pub x_marks: Vec<Mark>,
    /// Horizontal lines at y values ("mu = 0.3").
    pub y_marks: Vec<Mark>,
    /// Shaded x ranges.
    pub shaded: Vec<Shade>,
    /// Parts of curves drawn dim (where the model's own validity check fails), each with the
    /// index of the curve whose colour it takes; named once in the legend by `dim_label`, or
    /// where curves are told apart by their marks (no colour) each curve's by the name of its
    /// parts ("wide fails").
    pub dim: Vec<(usize, Series)>,
    /// The legend's name of the dim parts.
    pub dim_label: String,
    /// The dim parts are verdicts the validity study does not give (a punch or laws it does not
    /// cover), not failures: a curve dim throughout is "not judged", not "fails".
    pub unjudged: bool,
    /// Measured points drawn over the curves (an overlaid data file), setting the ranges with
    /// the focus curves.
    pub data: Vec<Measured>,
    /// Differences of y below this (absolute, the y unit) are round-off: y values that differ by
    /// no more are drawn as the one value they round to (0: only equal values are).
    pub resolution: f64,
    /// The y values are the contact fraction: the cursor reads them as the status writes it
    /// (`units::format_fraction`), not to six digits as mu*.
    pub fraction: bool,
    /// The curves that have no value at some of the points they were computed at: said in their
    /// legend entries, the points named in the CSV.
    pub unanswered: Vec<Unanswered>,
}

/// Where a curve has no value among the points it was computed at (its model has no solution
/// there).
#[derive(Clone, Debug, PartialEq)]
pub struct Unanswered {
    /// The curve's index in `Plot::series`.
    pub curve: usize,
    /// In words, for the legend: "no answer at P >= 1.70 kN/m (11 of 40 loads)".
    pub words: String,
    /// The x of those points (the x axis' unit).
    pub at: Vec<f64>,
}

impl Plot {
    /// A plot of curves, all of which set the y range, with nothing marked.
    pub fn new(x: Axis, y: Axis, series: Vec<Series>) -> Plot {
        Plot {
            x,
            y,
            focus: series.len(),
            series,
            markers: None,
            x_marks: Vec::new(),
            y_marks: Vec::new(),
            shaded: Vec::new(),
            dim: Vec::new(),
            dim_label: String::new(),
            unjudged: false,
            data: Vec::new(),
            resolution: 0.0,
            fraction: false,
            unanswered: Vec::new(),
        }
    }

    /// A plot of mu* (or mu* - mu): the line at mu, and differences under `MU_STAR_RESOLUTION`
    /// taken as round-off.
    fn against_mu(&mut self, mu: f64) {
        self.y_marks = vec![mu_line(mu)];
        self.resolution = MU_STAR_RESOLUTION;
    }
}

/// mu* is a number of the order of mu (0.01 to 10) computed to about 12 significant digits
/// (`units::CLEAN_DIGITS`): differences under 1e-12 are round-off, not physics (mu* of a
/// frictionless punch in partial contact scatters by 1e-20 around 0).
pub const MU_STAR_RESOLUTION: f64 = 1e-12;

/// A scalar field over a rectangle, drawn as a heatmap.
#[derive(Clone, Debug, PartialEq)]
pub struct Map {
    /// What the values are ("pressure").
    pub name: &'static str,
    /// Grid x [m], increasing.
    pub x: Vec<f64>,
    /// Grid y [m], increasing.
    pub y: Vec<f64>,
    /// Values, row-major: index j * x.len() + i for (x_i, y_j).
    pub values: Vec<f64>,
    /// Unit of the values.
    pub unit: &'static str,
    /// The line under the map.
    pub caption: String,
    /// Values exactly 0 are drawn apart from the colour scale and named so in its legend ("no
    /// contact"); None: 0 is a value like any other.
    pub empty: Option<&'static str>,
}

/// What a chart draws.
#[derive(Clone, Debug, PartialEq)]
pub enum Figure {
    /// One or more plots stacked vertically.
    Plots(Vec<Plot>),
    /// A heatmap.
    Map(Map),
}

/// Why a chart has nothing to draw.
#[derive(Clone, Debug, PartialEq)]
pub enum NoFigure {
    /// The stage it needs has not arrived yet.
    Solving,
    /// The solver could not answer; the reason.
    Error(String),
}

type Build<O> = fn(&Preset, &O) -> Result<Figure, NoFigure>;

/// A chart's definition.
struct ChartSpec<O> {
    help: &'static str,
    overlays: bool,
    build: Build<O>,
}

impl PlaneChart {
    fn spec(self) -> ChartSpec<PlaneOutput> {
        match self {
            Self::Pressure => ChartSpec {
                help: "Pressure q2(x) and shear q1 = mu q2 + tau0 over the contact [-a, b]; b is the leading edge. A peak behind the tip (a > b) means friction dominates, ahead of it wear.",
                overlays: false,
                build: plane::pressure,
            },
            Self::Wear => ChartSpec {
                help: "Wear per pass: the depth a strip point loses while the punch passes over it (the integral of the wear rate from x to b). Wear rate F(q2) = k q2 (q2/p0)^(n-1), k q2 for the linear law n = 1: depth per unit sliding distance.",
                overlays: false,
                build: plane::wear,
            },
            Self::Punch => ChartSpec {
                help: "The punch's shape g(x) (its tip at x = 0, heights away from the strip), the strip surface v(x) under load ('strip v(x)'), placed where it meets the punch at the leading edge b (nothing is worn there yet), and below them the wear groove: the depth a strip point loses in one pass. In contact the loaded strip takes the punch's shape and lies above it by the layer worn away, so v - g is the groove (the contact condition, (1.11)).",
                overlays: false,
                build: plane::punch,
            },
            Self::MuStar => ChartSpec {
                help: "Total friction coefficient mu* against load: mu* = mu + [(1 + mu^2) psi + mu Delta_g tau0]/P. The 'now' marker is the current load; the other models are overlaid for comparison (the preset's model sets the scale).",
                overlays: true,
                build: plane::mu_star,
            },
            Self::Edges => ChartSpec {
                help: "Contact edges a (trailing) and b (leading) against load, for the preset's model.",
                overlays: false,
                build: plane::edges,
            },
            Self::Energy => ChartSpec {
                help: "Where the work of the tangential force goes, against load: the friction loss Q1 + I (2.5) and the wear loss psi - J (2.7) as shares of T, the power per unit sliding speed. They add up to 1 when I = J (2.9): the status's I-J residual says how well that holds at the current load, marked 'now'. Without wear all of T is lost to friction; more wear (k) moves the split towards wear. Computed while this chart is visible.",
                overlays: false,
                build: plane::energy,
            },
        }
    }
}

impl SpatialChart {
    fn spec(self) -> ChartSpec<SpatialOutput> {
        match self {
            Self::PressureMap => ChartSpec {
                help: "Contact pressure over one period cell in bands of a round step, one colour (or shade) each; the bar labels every band's edges, the words beside it give the unit and the step. In partial contact the zones out of contact (p = 0) are drawn apart, in grey (without colour, · or ~), named beside the bar. The layer slides towards -x; friction on it points to +x. The bands are coarse: x shows a cursor X (from the middle), [ ] move it along x, { } along y, and the status reads x, y and p there.",
                overlays: false,
                build: spatial::pressure_map,
            },
            Self::Line => ChartSpec {
                help: "Pressure and shape along the middle line y = const: the pressure leads the shape by the phase lead phi.",
                overlays: false,
                build: spatial::line,
            },
            Self::History => ChartSpec {
                help: "Complete contact: the harmonic amplitudes A_n(t) decaying by wear, and the run-in of mu*(t) towards mu. Partial contact at t = 0: the running-in simulated by wear on the period cell, the contact fraction and mu*(t), with the time at which contact becomes complete marked. The blocks mark the current time; the time slider (Left/Right on t) and space play it.",
                overlays: false,
                build: spatial::history,
            },
            Self::MuStar => ChartSpec {
                help: "mu* against the mean pressure pbar for the punch as it is at time t, one curve: partial contact below the complete-contact load (marked 'complete'), complete contact above. The 'now' marker is the preset's pbar. Below the complete-contact load the contact set gains or loses whole grid nodes, so mu* moves in small steps: they are the grid's resolution (the grid row of the form), not physics. Solved on the period cell while this chart is visible (without a period cell: only where contact is complete).",
                overlays: true,
                build: spatial::mu_star,
            },
            Self::Spectrum => ChartSpec {
                help: "The power spectral density C(q) of a height-map punch's surface, radially averaged over log bins of the wavenumber q = |(qx, qy)|, on log-log axes: as given (t = 0) and at the state shown. A self-affine surface falls as q^(-2(1+H)) between its roll-off and cutoff (a profile as q^(-(1+2H))). Wear takes the short waves (large q) first: the curve at t drops most at the right. A punch of harmonics has a line spectrum: each harmonic's amplitude A against |k|, as given (the line) and at t (the blocks).",
                overlays: false,
                build: spatial::spectrum,
            },
            Self::Dispersion => ChartSpec {
                help: "Drift velocity c of a wave against kh (k for a half-space) for wave vectors at 0, 45 and 75 degrees to the sliding line; the punch's harmonics are marked. c > 0 is along +x, with the friction on the layer; for nu > 1/4, waves with kh < X* drift backwards (X* marked where c changes sign). Where the three directions differ by less than a line width the legend says so ('one line') and a second plot draws the 45 and 75 degree curves' differences from the 0 degree one.",
                overlays: false,
                build: spatial::dispersion,
            },
        }
    }
}

impl Chart {
    /// The chart a preset opens on: its lesson's, else its problem's first.
    pub fn opening(preset: &Preset) -> Chart {
        match preset.lesson.as_ref().and_then(|l| l.view) {
            Some(View::Chart(c)) if c.problem() == preset.problem => c,
            _ => Chart::first(preset.problem),
        }
    }

    /// What the chart means, for the help.
    pub fn help(self) -> &'static str {
        match self {
            Chart::Plane(c) => c.spec().help,
            Chart::Spatial(c) => c.spec().help,
        }
    }

    /// True when the chart draws the other plane models (the engine computes them only then).
    pub fn draws_overlays(self) -> bool {
        match self {
            Chart::Plane(c) => c.spec().overlays,
            Chart::Spatial(c) => c.spec().overlays,
        }
    }

    /// True when the chart draws the energy losses along the load sweep (the engine computes
    /// them only then).
    pub fn draws_energies(self) -> bool {
        self == Chart::Plane(PlaneChart::Energy)
    }

    /// The figure for an answer, from the inputs the answer carries (never from the form).
    pub fn build(self, answer: &Answer) -> Result<Figure, NoFigure> {
        let preset = &answer.request.preset;
        match (self, &answer.output) {
            (Chart::Plane(c), Output::Plane(out)) => (c.spec().build)(preset, out),
            (Chart::Spatial(c), Output::Spatial(Ok(out))) => (c.spec().build)(preset, out),
            (Chart::Spatial(_), Output::Spatial(Err(e))) => Err(NoFigure::Error(e.to_string())),
            (Chart::Spatial(c), Output::Surface(Ok(out))) => surface::build(c, preset, out),
            (Chart::Spatial(_), Output::Surface(Err(e))) => Err(NoFigure::Error(e.to_string())),
            // the answer is for the other problem: the chart's own is on its way
            _ => Err(NoFigure::Solving),
        }
    }
}

/// An axis.
fn axis(label: &str, unit: &'static str, scale: Scale) -> Axis {
    Axis {
        label: label.into(),
        unit,
        scale,
    }
}

/// The line at the sliding friction coefficient mu on a mu* chart.
fn mu_line(mu: f64) -> Mark {
    Mark {
        at: mu,
        label: format!("mu = {}", ticks::plain(mu)),
    }
}

/// x-y pairs from two columns.
fn zip(x: &[f64], y: &[f64]) -> Vec<(f64, f64)> {
    x.iter().copied().zip(y.iter().copied()).collect()
}
