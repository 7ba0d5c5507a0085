//! The status in the problem's dimensionless groups (the dimensionless view, `D`): every number is
//! a group the library computes (`sweeps::groups`), never a dimensional value, and the panel's
//! title says "groups". `?` defines each group.

use crate::engine::{Output, SpatialOutput};
use crate::phrase::Phrase;
use crate::physics::plane::OperatingPoint;
use crate::sweeps::groups::{self, Group};
use ratatui::text::Line;

use crate::tui::app::App;
use crate::tui::charts::contact;
use crate::tui::view::status_values::{Checks, mu_star, number, per_output, prose, table_within};
use crate::tui::view::surface_status;
use crate::tui::view::theme::RenderOptions;
use crate::tui::view::validity_status::with_validity;
use crate::tui::view::wrapping::pack;

/// The status panel's title: it says when the values are groups.
pub fn title(app: &App) -> &'static str {
    if app.explore.dimensionless {
        "operating point in dimensionless groups"
    } else {
        "operating point"
    }
}

/// "symbol = value", mu* with six decimals and the preset's mu beside it.
fn item(g: &Group, mu: f64) -> String {
    match g.name {
        // as in the dimensional status: its difference from mu is often a few 1e-5
        "mu_star" => mu_star(g.value, mu),
        _ => format!("{} = {}", g.symbol, number(g.name, g.value)),
    }
}

/// The status lines of the shown output in groups, wrapped to `width`, at most `height` harmonic
/// rows counted as in the dimensional status (the selected harmonic kept in view).
pub fn lines(
    output: &Output,
    selected: Option<usize>,
    style: RenderOptions,
    width: usize,
    height: usize,
) -> Vec<Line<'static>> {
    per_output(
        output,
        style,
        |p, checks| plane(p, checks, style, width, height),
        |out| spatial(out, selected, style, width, height),
        // a height map has no harmonics whose groups could be listed: its values as they are
        |out| surface_status::lines(out, style, width),
    )
}

fn plane(
    p: &OperatingPoint,
    checks: Checks,
    style: RenderOptions,
    width: usize,
    height: usize,
) -> Vec<Line<'static>> {
    with_validity((&plane_items(p), &GIVE_UP), p, checks, style, width, height)
}

/// In a crowded status, (a+b)/R and P/(m R) (the indices of `plane_items`) give way before
/// (a+b)/h, the material's numbers, theta, mu* and mu* - mu.
pub const GIVE_UP: [usize; 2] = [1, 2];

/// The groups of a plane operating point, in the order the status shows them.
pub fn plane_items(p: &OperatingPoint) -> Vec<String> {
    let s = &p.solution;
    let mu = s.inputs.friction.coefficient;
    (groups::plane(s, &p.validity).iter())
        .map(|g| item(g, mu))
        .collect()
}

fn spatial(
    out: &SpatialOutput,
    selected: Option<usize>,
    style: RenderOptions,
    width: usize,
    height: usize,
) -> Vec<Line<'static>> {
    let s = &out.state.solution;
    let mu = s.inputs.friction.coefficient;
    let items: Vec<String> = groups::spatial(s).iter().map(|g| item(g, mu)).collect();
    let mut lines: Vec<Line> = pack(&items, width, "")
        .into_iter()
        .map(Line::from)
        .collect();
    // the groups are the closed form's: say so when the contact is not complete all along
    let (verdict, look) = match (contact::stepped(out), out.state.contact.complete) {
        (Some(_), _) => (
            "contact partial at first (running in): these are the closed form's groups, for \
             complete contact; D off shows the running-in",
            style.error(),
        ),
        (None, true) => ("complete contact", style.ok()),
        (None, false) => (
            "contact lost: these are the closed form's groups, for complete contact; D off says \
             why",
            style.error(),
        ),
    };
    lines.extend(prose(&Phrase::words(verdict), width, look));
    let Some((header, blocks)) = harmonic_table(out) else {
        return lines;
    };
    let room = height.saturating_sub(lines.len() + 1);
    if room == 0 {
        // no row fits: a header over nothing is left out (the dimensional status does the same)
        return lines;
    }
    lines.extend(table_within(&header, &blocks, selected, room, width, style));
    lines
}

/// The harmonics' table in groups: its header (n and each group's symbol) and one row per
/// harmonic; None without harmonics.
pub fn harmonic_table(out: &SpatialOutput) -> Option<(String, Vec<Vec<String>>)> {
    let s = &out.state.solution;
    let rows: Vec<Vec<Group>> = s.harmonics.iter().map(|h| groups::harmonic(s, h)).collect();
    let first = rows.first()?;
    // each column as wide as its symbol or its widest value, two spaces apart
    let cells: Vec<Vec<String>> = rows
        .iter()
        .map(|row| row.iter().map(|g| number(g.name, g.value)).collect())
        .collect();
    let widths: Vec<usize> = (first.iter().enumerate())
        .map(|(i, g)| {
            (cells.iter().map(|c| c[i].chars().count())).fold(g.symbol.chars().count(), usize::max)
        })
        .collect();
    let line = |n: &str, texts: Vec<&str>| {
        let mut line = format!("{n:>3}");
        for (text, width) in texts.iter().zip(&widths) {
            line.push_str(&format!("  {text:<width$}"));
        }
        line.trim_end().to_string()
    };
    let header = line("n", first.iter().map(|g| g.symbol).collect());
    let blocks: Vec<Vec<String>> = (cells.iter().enumerate())
        .map(|(n, c)| {
            vec![line(
                &(n + 1).to_string(),
                c.iter().map(String::as_str).collect(),
            )]
        })
        .collect();
    Some((header, blocks))
}
