//! How the status panels write what they show: a failed solve in words, mu* and the
//! dimensionless numbers, a sentence wrapped to the panel, and which harmonics fit.

use crate::engine::{Output, SpatialOutput, SurfaceOutput};
use crate::phrase::Phrase;
use crate::physics::plane::OperatingPoint;
use crate::physics::plane::strip_check::StripCheck;
use crate::physics::plane::yield_onset::YieldCheck;
use crate::units::format_si;
use ratatui::text::Line;

use crate::tui::view::theme::RenderOptions;
use crate::tui::view::wrapping::{lines_of, more};

/// The checks of a plane point that the status shows: against the strip model and for yield.
pub type Checks<'a> = (Option<&'a StripCheck>, Option<&'a YieldCheck>);

/// The status lines of an output: a failed solve in words, else the lines `plane`, `spatial` or
/// `surface` make of it (the dimensional status and the dimensionless view differ only there).
pub fn per_output(
    output: &Output,
    style: RenderOptions,
    plane: impl FnOnce(&OperatingPoint, Checks) -> Vec<Line<'static>>,
    spatial: impl FnOnce(&SpatialOutput) -> Vec<Line<'static>>,
    surface: impl FnOnce(&SurfaceOutput) -> Vec<Line<'static>>,
) -> Vec<Line<'static>> {
    match output {
        Output::Plane(out) => match &out.point {
            Ok(p) => plane(p, (out.strip_check.as_ref(), out.yield_check.as_ref())),
            Err(e) => vec![Line::styled(e.to_string(), style.error())],
        },
        Output::Spatial(Err(e)) => vec![Line::styled(e.to_string(), style.error())],
        Output::Spatial(Ok(out)) => spatial(out),
        Output::Surface(Err(e)) => vec![Line::styled(e.to_string(), style.error())],
        Output::Surface(Ok(out)) => surface(out),
    }
}

/// "mu* = 0.299822 (mu 0.3)": six decimals, so that mu* - mu reads off to 1e-6 (it is often
/// a few 1e-5); mu as every number of the status (`format_si`), however many digits it was
/// typed with.
pub fn mu_star(value: f64, mu: f64) -> String {
    format!("mu* = {value:.6} (mu {})", format_si(mu, ""))
}

/// How a dimensionless quantity, named as in `sweeps::groups`, is written wherever a screen
/// shows it (the status, the groups of `D`, the map's cursor): four significant digits
/// (`format_si`), the phase lead with its sign. mu* has its own rule (`mu_star`).
pub fn number(name: &str, value: f64) -> String {
    let text = format_si(value, "");
    match name {
        "harmonics.N.phase_lead" if value > 0.0 => format!("+{text}"),
        _ => text,
    }
}

/// A sentence wrapped to the panel between its pieces, in one style.
pub fn prose(text: &Phrase, width: usize, style: ratatui::style::Style) -> Vec<Line<'static>> {
    lines_of(text, width)
        .into_iter()
        .map(|l| Line::styled(l, style))
        .collect()
}

/// A table's header and as many of its row blocks as fit in `room` lines (the selected one kept
/// in view), the count of the others after the header with the key that shows them ("+2 more:
/// i"), or, where the header has no room for it within `width`, on a line of its own after the
/// rows.
pub fn table_within(
    header: &str,
    blocks: &[Vec<String>],
    selected: Option<usize>,
    room: usize,
    width: usize,
    style: RenderOptions,
) -> Vec<Line<'static>> {
    let (mut first, mut count) = visible(blocks, selected, room);
    let mut hidden = blocks.len() - count;
    let beside = format!("{header}  {}", more(hidden));
    let mut out = Vec::new();
    let own_line = hidden > 0 && beside.chars().count() > width;
    if own_line {
        (first, count) = visible(blocks, selected, room.saturating_sub(1));
        hidden = blocks.len() - count;
    }
    let head = if hidden > 0 && !own_line {
        beside
    } else {
        header.to_string()
    };
    out.push(Line::styled(head, style.heading()));
    for block in &blocks[first..first + count] {
        out.extend(block.iter().cloned().map(Line::from));
    }
    if own_line {
        out.push(Line::styled(more(hidden), style.heading()));
    }
    out
}

/// Which harmonic blocks fit in `room` lines: (first, count), keeping the selected one in view.
pub fn visible(blocks: &[Vec<String>], selected: Option<usize>, room: usize) -> (usize, usize) {
    let fits_from = |first: usize| {
        let mut used = 0;
        blocks[first..]
            .iter()
            .take_while(|b| {
                used += b.len();
                used <= room
            })
            .count()
    };
    let want = selected.unwrap_or(0).min(blocks.len().saturating_sub(1));
    let first = (0..=want)
        .find(|&f| f + fits_from(f) > want)
        .unwrap_or(want);
    (first, fits_from(first))
}
