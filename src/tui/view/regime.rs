//! The regime map: a quantity over two parameters as a heatmap (the quantised viridis map, shades
//! without colour), its y ticks on the left, x ticks under it, a colour bar with ticks on the
//! right, and the library's lines drawn over it as letters, the same with and without colour:
//! `0` theta = 0, `W` and `N` where the wide and the narrow model's validity check changes, `C`
//! where complete contact is lost, `Y` where the contact starts to yield; `+` the preset's own
//! point, `X` the cursor. While the map is
//! coarse, each cell shows the nearest computed point.

use crate::physics::Spacing;
use crate::sweeps::map::{Map, MapSpec};
use crate::units::format_si;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};

use crate::tui::charts::Scale;
pub use crate::tui::charts::map_lines::line_key;
use crate::tui::charts::palette::level;
use crate::tui::charts::range::bounds;
use crate::tui::charts::ticks::ticks;
use crate::tui::view::status_values;
use crate::tui::view::theme::RenderOptions;

/// Columns of the y tick labels.
const LEFT: u16 = 8;
/// Columns of the bar and its labels.
const BAR: u16 = 10;

/// The fraction of an axis at which a value lies.
fn frac(spacing: Spacing, [lo, hi]: [f64; 2], v: f64) -> f64 {
    match spacing {
        Spacing::Log => (v / lo).ln() / (hi / lo).ln(),
        Spacing::Linear => (v - lo) / (hi - lo),
    }
}

fn scale(spacing: Spacing) -> Scale {
    match spacing {
        Spacing::Log => Scale::Log,
        Spacing::Linear => Scale::Linear,
    }
}

/// The quantity at grid point (i, j), the nearest computed one while coarse.
fn value(map: &Map, i: usize, j: usize) -> f64 {
    map.sample(i, j)
        .and_then(|s| s.value.as_ref().ok().copied())
        .unwrap_or(f64::NAN)
}

/// Draws the map into `area`.
pub fn draw(
    spec: &MapSpec,
    map: &Map,
    cell: Option<(usize, usize)>,
    style: RenderOptions,
    buf: &mut Buffer,
    area: Rect,
) {
    let (nx, ny) = (map.x.len(), map.y.len());
    if nx < 2 || ny < 2 || area.width < LEFT + BAR + 8 || area.height < 6 {
        return;
    }
    let lines_used: Vec<&crate::sweeps::map::Line> = map
        .lines
        .iter()
        .filter(|l| !l.segments.is_empty())
        .collect();
    // each line's meaning wrapped beside its letter (never cut mid-word on a narrow chart)
    let text_width = (area.width as usize).saturating_sub(2);
    let meanings: Vec<(char, Vec<String>)> = lines_used
        .iter()
        .map(|l| {
            let (glyph, what) = line_key(l.kind);
            (glyph, crate::tui::view::wrap(what, text_width))
        })
        .collect();
    let legend = 1 + meanings.iter().map(|(_, w)| w.len() as u16).sum::<u16>();
    let h = area.height.saturating_sub(2 + legend).max(3);
    let w = area.width - LEFT - BAR - 1;
    let (x0, y0) = (area.x + LEFT, area.y);
    let xr = [map.x[0], map.x[nx - 1]];
    let yr = [map.y[0], map.y[ny - 1]];
    let [lo, hi] = bounds(
        (0..ny)
            .flat_map(|j| (0..nx).map(move |i| (i, j)))
            .map(|(i, j)| value(map, i, j)),
    );
    let t = |v: f64| (v - lo) / (hi - lo);
    let node = |col: u16, row: u16| -> (usize, usize) {
        let i = ((col as f64 + 0.5) / w as f64 * (nx - 1) as f64).round() as usize;
        let j = ((1.0 - (row as f64 + 0.5) / h as f64) * (ny - 1) as f64).round() as usize;
        (i.min(nx - 1), j.min(ny - 1))
    };
    for row in 0..h {
        for col in 0..w {
            let (i, j) = node(col, row);
            let v = t(value(map, i, j));
            let c = &mut buf[(x0 + col, y0 + row)];
            if style.color {
                c.set_char(' ')
                    .set_style(Style::default().bg(style.heat(level(v))));
            } else {
                c.set_char(style.shade(v));
            }
        }
    }
    let ink = if style.color {
        Style::default()
            .fg(Color::White)
            .bg(Color::Black)
            .add_modifier(Modifier::BOLD)
    } else {
        Style::default().add_modifier(Modifier::BOLD)
    };
    let at = |x: f64, y: f64| -> Option<(u16, u16)> {
        let (fx, fy) = (
            frac(spec.x.range.spacing, xr, x),
            frac(spec.y.range.spacing, yr, y),
        );
        if !(0.0..=1.0).contains(&fx) || !(0.0..=1.0).contains(&fy) {
            return None;
        }
        let col = ((fx * w as f64) as u16).min(w - 1);
        let row = (((1.0 - fy) * h as f64) as u16).min(h - 1);
        Some((x0 + col, y0 + row))
    };
    for line in &lines_used {
        let (glyph, _) = line_key(line.kind);
        for [a, b] in &line.segments {
            for k in 0..=16 {
                let u = k as f64 / 16.0;
                // in the axes' own spacing, so a segment on a log axis stays straight
                let x = crate::sweeps::locate::between(spec.x.range.spacing, a[0], b[0], u);
                let y = crate::sweeps::locate::between(spec.y.range.spacing, a[1], b[1], u);
                if let Some(p) = at(x, y) {
                    buf[p].set_char(glyph).set_style(ink);
                }
            }
        }
    }
    // the preset's own point ('+' is no shade: `theme::ASCII_SHADES`)
    let own = '+';
    let now = at(map.current[0], map.current[1]);
    if let Some(p) = now {
        buf[p].set_char(own).set_style(ink);
    }
    if let Some((i, j)) = cell {
        if let Some(p) = at(map.x[i.min(nx - 1)], map.y[j.min(ny - 1)]) {
            buf[p].set_char('X').set_style(ink.fg(if style.color {
                Color::Yellow
            } else {
                Color::Reset
            }));
        }
    }
    // y ticks
    let yt = ticks(
        [yr[0], yr[1]].map(|v| scale(spec.y.range.spacing).to_plot(v).unwrap_or(v)),
        scale(spec.y.range.spacing),
        &spec.y.key.symbol(),
        spec.y.key.param().unit,
        (h as usize / 2).max(2),
    );
    let ypl = yt.ticks.iter().map(|(p, l)| (p, l));
    let yplot = [yr[0], yr[1]].map(|v| scale(spec.y.range.spacing).to_plot(v).unwrap_or(v));
    for (p, label) in ypl {
        let fy = (p - yplot[0]) / (yplot[1] - yplot[0]);
        let row = (((1.0 - fy) * h as f64) as u16).min(h - 1);
        buf.set_stringn(
            area.x,
            y0 + row,
            format!("{label:>7}┤"),
            LEFT as usize,
            Style::default(),
        );
    }
    // x ticks and both titles under the map
    let xplot = [xr[0], xr[1]].map(|v| scale(spec.x.range.spacing).to_plot(v).unwrap_or(v));
    let xt = ticks(
        xplot,
        scale(spec.x.range.spacing),
        &spec.x.key.symbol(),
        spec.x.key.param().unit,
        (w as usize / 10).max(2),
    );
    let mut free = x0;
    for (p, label) in &xt.ticks {
        let fx = (p - xplot[0]) / (xplot[1] - xplot[0]);
        let col = x0 + ((fx * w as f64) as u16).min(w - 1);
        let start = col
            .saturating_sub(label.chars().count() as u16 / 2)
            .max(free);
        if start + label.chars().count() as u16 > area.x + area.width {
            continue;
        }
        buf.set_string(start, y0 + h, label, Style::default());
        free = start + label.chars().count() as u16 + 1;
    }
    let titles = format!("x: {}   y: {}", xt.title, yt.title);
    buf.set_stringn(
        area.x,
        y0 + h + 1,
        titles,
        area.width as usize,
        Style::default(),
    );
    // the bar
    let bx = x0 + w + 1;
    for row in 0..h {
        let v = 1.0 - row as f64 / (h - 1).max(1) as f64;
        let c = &mut buf[(bx, y0 + row)];
        if style.color {
            c.set_char(' ')
                .set_style(Style::default().bg(style.heat(level(v))));
        } else {
            c.set_char(style.shade(v));
        }
    }
    let q = spec.quantity;
    let bt = ticks(
        [lo, hi],
        Scale::Linear,
        &q.symbol(),
        q.quantity().unit,
        (h as usize / 2).max(2),
    );
    for (v, label) in &bt.ticks {
        let row = ((1.0 - (v - lo) / (hi - lo)) * (h - 1) as f64).round() as u16;
        buf.set_stringn(
            bx + 1,
            y0 + row,
            format!("{}{label}", style.bar_tick()),
            (BAR - 2) as usize,
            Style::default(),
        );
    }
    // the legend: the colour's quantity, then each line drawn
    let mut y = y0 + h + 2;
    // the preset's own point may lie outside the ranges (mu = 0 on a log axis)
    let where_now = if now.is_some() { "" } else { ": off the map" };
    // without colour the map is drawn in shades
    let drawn_in = if style.color { "colour" } else { "shade" };
    let mut words = format!("{drawn_in}: {}   {own} now{where_now}", bt.title);
    // the cursor's mark, named where it fits whole
    let cursor = "   X cursor";
    if cell.is_some() && words.chars().count() + cursor.len() <= area.width as usize {
        words.push_str(cursor);
    }
    buf.set_stringn(area.x, y, words, area.width as usize, Style::default());
    for (glyph, wrapped) in &meanings {
        for (k, text) in wrapped.iter().enumerate() {
            y += 1;
            if y >= area.y + area.height {
                return;
            }
            if k == 0 {
                buf.set_string(area.x, y, glyph.to_string(), ink);
            }
            buf.set_stringn(area.x + 2, y, text, text_width, Style::default());
        }
    }
}

/// The status's readout at the cursor, most telling first (a crowded status keeps the first):
/// both parameters with units, the quantity, which effect dominates, the verdicts there, theta.
pub fn readout(spec: &MapSpec, map: &Map, (i, j): (usize, usize)) -> Option<Vec<String>> {
    let (i, j) = (i.min(map.x.len() - 1), j.min(map.y.len() - 1));
    let s = map.sample(i, j)?;
    let q = spec.quantity;
    let value = match &s.value {
        // mu* with six decimals, as the status gives it (0.299802, not 0.2998 beside mu = 0.3)
        Ok(v) if q.quantity().name == "mu_star" => format!("{v:.6}"),
        Ok(v) => format_si(*v, q.quantity().unit),
        Err(why) => format!("none ({why})"),
    };
    let mut items = vec![
        format!(
            "cursor {} = {}",
            spec.x.key.symbol(),
            format_si(map.x[i], spec.x.key.param().unit)
        ),
        format!(
            "{} = {}:",
            spec.y.key.symbol(),
            format_si(map.y[j], spec.y.key.param().unit)
        ),
    ];
    // the words on which effect dominates give mu* - mu themselves: the map's value beside them
    // only where it is another quantity
    if s.dominance.is_none() || q.quantity().name != "mu_star_minus_mu" {
        items.push(format!("{} = {value}", q.symbol()));
    }
    items.extend(s.dominance.map(|d| d.describe().to_string()));
    let verdict = |ok: bool| if ok { "holds" } else { "fails" };
    items.extend(s.wide_holds.map(|h| format!("wide {}", verdict(h))));
    items.extend(s.narrow_holds.map(|h| format!("narrow {}", verdict(h))));
    items.extend(
        s.yields
            .map(|y| if y { "yields" } else { "no yield" }.to_string()),
    );
    items.extend(s.complete.map(|c| {
        if c {
            "contact complete".to_string()
        } else {
            "contact partial".to_string()
        }
    }));
    if map.stride > 1 {
        items.push("(coarse: nearest computed point)".into());
    }
    // theta last: where the status has no room for every item, the words and verdicts stay
    items.extend(
        s.theta
            .map(|t| format!("theta = {}", status_values::number("theta", t))),
    );
    Some(items)
}
