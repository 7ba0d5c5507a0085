//! The state of the sweep chart and the regime map (part of the model): which view is shown,
//! the sweep and the map chosen, the dimensionless view, the map's cursor, the requests sent to
//! the sweep worker and its newest answer; and the state of the `v`/`M` form.

use crate::engine::sweep_worker::{SweepAnswer, SweepRequest};
use crate::physics::Spacing;
use crate::preset::{Key, Preset};
use crate::sweeps::curve::CurveSpec;
use crate::sweeps::map::MapSpec;
use crate::sweeps::{Axis, Opening, QuantityKey, opening};
use crate::tui::text_field::TextField;
use crate::units::format_si_exact;

/// What the chart area shows instead of the charts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// A quantity against one parameter.
    Sweep,
    /// A quantity over two parameters.
    Map,
}

/// The explorer's state.
#[derive(Clone, Debug, Default)]
pub struct Explore {
    /// The view shown (None: the charts).
    pub view: Option<View>,
    /// The sweep chosen with `v` (None: the default of the preset).
    pub curve: Option<CurveSpec>,
    /// The map chosen with `M`.
    pub map: Option<MapSpec>,
    /// Status, axes and choices in the problem's dimensionless groups (`D`).
    pub dimensionless: bool,
    /// The map's cursor (grid column, row), when on.
    pub cell: Option<(usize, usize)>,
    /// The generation of the newest request.
    pub generation: u64,
    /// The newest request sent.
    pub requested: Option<SweepRequest>,
    /// The newest answer received.
    pub shown: Option<SweepAnswer>,
    /// `E` waits for the view's whole answer.
    pub export_waiting: bool,
}

impl Explore {
    /// The state for a newly opened preset: on its `[explore]` section's view, if it has one,
    /// unless its lesson opens on a chart.
    pub fn opened(preset: &Preset) -> Explore {
        let on_chart = matches!(
            preset.lesson.as_ref().and_then(|l| l.view),
            Some(crate::views::View::Chart(_))
        );
        Explore {
            view: match opening(preset) {
                _ if on_chart => None,
                Some(Ok(Opening::Curve(_))) => Some(View::Sweep),
                Some(Ok(Opening::Map(_))) => Some(View::Map),
                _ => None,
            },
            ..Explore::default()
        }
    }
}

/// One axis as typed.
#[derive(Clone, Debug, PartialEq)]
pub struct Draft {
    /// The parameter.
    pub key: Key,
    /// The first value, as typed (the parameter's unit when none is typed).
    pub from: TextField,
    /// The last value.
    pub to: TextField,
    /// The number of points.
    pub points: TextField,
    /// Log spacing (else linear).
    pub log: bool,
}

impl Draft {
    /// The draft of an axis as it stands.
    pub fn of(axis: &Axis) -> Draft {
        Draft {
            key: axis.key,
            from: TextField::proposed(format_si_exact(axis.range.min, axis.key.param().unit)),
            to: TextField::proposed(format_si_exact(axis.range.max, axis.key.param().unit)),
            points: TextField::proposed(axis.range.points.to_string()),
            log: axis.range.spacing == Spacing::Log,
        }
    }
}

/// A row of the form.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Field {
    /// The parameter of axis n (←→ choose).
    Param(usize),
    /// Its first value (typed).
    From(usize),
    /// Its last value (typed).
    To(usize),
    /// Its number of points (typed).
    Points(usize),
    /// Log or linear (←→).
    Scale(usize),
    /// The quantity shown (←→).
    Quantity,
}

/// The form's state.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepForm {
    /// A sweep (one axis) or a map (two).
    pub view: View,
    /// The axes.
    pub axes: Vec<Draft>,
    /// The quantity.
    pub quantity: QuantityKey,
    /// The selected row.
    pub row: usize,
}

impl SweepForm {
    /// The rows, in order.
    pub fn fields(&self) -> Vec<Field> {
        (0..self.axes.len())
            .flat_map(|n| {
                [
                    Field::Param(n),
                    Field::From(n),
                    Field::To(n),
                    Field::Points(n),
                    Field::Scale(n),
                ]
            })
            .chain([Field::Quantity])
            .collect()
    }

    /// The selected row.
    pub fn field(&self) -> Field {
        let fields = self.fields();
        fields[self.row.min(fields.len() - 1)]
    }
}
