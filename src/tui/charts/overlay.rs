//! A data file over the charts (`d`): each measured column is drawn on every plot whose axes are
//! the file's x column and the column's quantity, matched as the axes are titled (symbol and
//! unit), and named in the legend by the file ("data: friction.csv"). The figure is built from
//! the answer as always and the measured points are added to it, so that the view, the cursor
//! readout and both exports draw the same points; nothing is computed from them here.

use std::path::Path;

use crate::data::{DataSet, Measured as Column};
use crate::engine::Answer;
use crate::preset::Problem;
use crate::tui::charts::{Axis, Chart, Figure, Measured, NoFigure, Plot};

/// A data file shown over the charts.
#[derive(Clone, Debug, PartialEq)]
pub struct Overlay {
    /// The legend's name ("data: friction.csv").
    pub name: String,
    /// The data read.
    pub set: DataSet,
}

/// Whether an axis is titled as the quantity `symbol` in `unit` (SI).
fn titled(axis: &Axis, symbol: &str, unit: &str) -> bool {
    axis.label == symbol && axis.unit == unit
}

impl Overlay {
    /// The overlay of a data set, named by its file.
    pub fn new(set: DataSet) -> Overlay {
        let file = Path::new(&set.path)
            .file_name()
            .map_or_else(|| set.path.clone(), |f| f.to_string_lossy().into_owned());
        Overlay {
            name: format!("data: {file}"),
            set,
        }
    }

    /// Whether a measured column belongs on a plot: the plot's x axis is the file's x column
    /// and its y axis the column's quantity.
    fn fits(&self, plot: &Plot, column: &Column) -> bool {
        let key = self.set.x.key;
        let q = column.quantity;
        titled(&plot.x, &key.symbol(), key.param().unit)
            && titled(&plot.y, &q.symbol(), q.quantity().unit)
    }

    /// The measured columns of the file that belong on a plot, as drawn.
    pub fn over(&self, plot: &Plot) -> Vec<Measured> {
        let xs = &self.set.x.values;
        let named = self.set.measured.len() > 1;
        (self.set.measured.iter())
            .filter(|c| self.fits(plot, c))
            .map(|c| Measured {
                name: if named {
                    format!("{}, {}", self.name, c.heading)
                } else {
                    self.name.clone()
                },
                points: xs.iter().copied().zip(c.values.iter().copied()).collect(),
                sd: c.sd.clone(),
            })
            .collect()
    }

    /// Adds the measured points to every plot of a figure they belong on; returns how many
    /// plots took some.
    pub fn add(&self, figure: &mut Figure) -> usize {
        let Figure::Plots(plots) = figure else {
            return 0;
        };
        let mut took = 0;
        for plot in plots.iter_mut() {
            let data = self.over(plot);
            took += usize::from(!data.is_empty());
            plot.data.extend(data);
        }
        took
    }

    /// What the file measures, in the axes' words: "mu* against P".
    pub fn measures(&self) -> String {
        let x = self.set.x.key.symbol();
        let ys: Vec<String> = (self.set.measured.iter())
            .map(|c| c.quantity.symbol())
            .collect();
        format!("{} against {x}", ys.join(", "))
    }
}

/// The figure of `chart` from `answer`, with the overlay's points on the plots they belong on.
pub fn figure(
    chart: Chart,
    answer: &Answer,
    overlay: Option<&Overlay>,
) -> Result<Figure, NoFigure> {
    let mut figure = chart.build(answer)?;
    if let Some(o) = overlay {
        o.add(&mut figure);
    }
    Ok(figure)
}

/// Where an overlay goes among the charts of a problem, from an answer of that problem: the
/// charts it is drawn on (by title), and the axes of every plot of the charts ("mu* against P")
/// for the message when it is drawn on none.
pub fn placed(overlay: &Overlay, answer: &Answer, problem: Problem) -> (Vec<String>, Vec<String>) {
    let mut drawn = Vec::new();
    let mut axes: Vec<String> = Vec::new();
    for chart in Chart::all(problem) {
        let Ok(Figure::Plots(plots)) = chart.build(answer) else {
            continue;
        };
        if plots.iter().any(|p| !overlay.over(p).is_empty()) {
            drawn.push(chart.title().to_string());
        }
        for p in &plots {
            let pair = format!("{} against {}", p.y.label, p.x.label);
            if !axes.contains(&pair) {
                axes.push(pair);
            }
        }
    }
    (drawn, axes)
}
