//! The validity part of the plane status: whether the shown model holds (the reasons in a few
//! words when it does not), which effect dominates (`plane::dominance`), and how far the model is
//! from the exact strip model, measured by the engine after the operating point
//! (`plane::strip_check::StripCheck`). Every word and number comes from the library; this module
//! only lays them out.

use crate::phrase::Phrase;
use crate::physics::plane::OperatingPoint;
use crate::physics::plane::dominance::Dominance;
use crate::physics::plane::strip_check::StripCheck;
use crate::physics::plane::validity::Reason;
use crate::physics::plane::yield_onset::YieldCheck;
use ratatui::text::Line;

use crate::tui::view::status_values::{number, prose};
use crate::tui::view::theme::RenderOptions;
use crate::tui::view::wrap_within;
use crate::tui::view::wrapping::{lines_of, more, pack, pack_giving_up};

/// The validity lines of a plane operating point, wrapped to `width`, in at most `room` lines:
/// the verdict when the model holds, which effect dominates (after the verdict, so that a
/// crowded status keeps the verdict; under a model that does not hold, after the reasons), the
/// check against the strip model once it has come (how far off), then every warning in a few
/// words (why), each after "! "; what does not fit is counted on a line after the `room` ones
/// with the key that shows it ("+2 more: i"; the status writes it in its border), never cut (in
/// a single row left, the first warning alone); a verdict
/// or check that does not fit ends in "…" after its last whole clause or word (`wrap_within`).
pub fn lines(
    p: &OperatingPoint,
    check: Option<&StripCheck>,
    style: RenderOptions,
    width: usize,
    room: usize,
) -> Vec<Line<'static>> {
    judged(p, check, None, style, width, room)
}

/// As `lines`, with the yield check's line after the verdict where the preset gives Y or H (in
/// the error style where the strip yields).
fn judged(
    p: &OperatingPoint,
    check: Option<&StripCheck>,
    yielding: Option<&YieldCheck>,
    style: RenderOptions,
    width: usize,
    room: usize,
) -> Vec<Line<'static>> {
    let (mut lines, hidden) = within(p, (check, yielding), style, width, room);
    if hidden.is_empty() {
        return lines;
    }
    let look = if hidden.iter().any(|&warning| warning) {
        style.error()
    } else {
        ratatui::style::Style::default()
    };
    lines.push(Line::styled(count(hidden.len()), look));
    lines
}

/// The count of the validity lines left out, with the key that shows them ("+2 more: i").
fn count(n: usize) -> String {
    format!("+{n} more: {}", crate::tui::view::legend::IN_FULL_KEY)
}

/// Whether `line` is the count of the validity lines left out that `lines` gives after its rows.
pub fn is_count(line: &Line) -> bool {
    let text = line.to_string();
    let n = text.strip_prefix('+').and_then(|t| t.split(' ').next());
    n.and_then(|n| n.parse().ok())
        .is_some_and(|n| text == count(n))
}

/// Every validity phrase of a plane operating point, in the order `lines` shows them: the
/// verdict, the yield check, which effect dominates, the check against the strip model, the
/// reasons why the model does not hold (for the `i` window: a crowded status counts some).
pub fn in_full(
    p: &OperatingPoint,
    (check, yielding): (Option<&StripCheck>, Option<&YieldCheck>),
) -> Vec<Phrase> {
    let mut out = Vec::new();
    if p.validity.ok {
        out.push(holds(p));
    }
    out.extend(yielding.map(YieldCheck::phrase));
    out.push(Dominance::of(&p.solution).describe());
    out.extend(check.map(|c| c.describe(p.solution.model)));
    out.extend(p.validity.reasons.iter().map(reason));
    out
}

/// "valid: (a+b)/h = 0.5; wide model holds" (or on a half-plane "h = inf").
fn holds(p: &OperatingPoint) -> Phrase {
    let where_ = if p.solution.inputs.material.thickness.is_finite() {
        let ratio = p.validity.contact_width_over_thickness;
        let ratio = number("validity.contact_width_over_thickness", ratio);
        Phrase::words("valid:").then(format!("(a+b)/h = {ratio};"))
    } else {
        Phrase::words("valid: half-plane,").then("h = inf;")
    };
    where_.then_words(&format!("{} model holds", p.solution.model.name()))
}

/// The validity lines in at most `room` lines, and for each phrase left out whether it is a
/// warning (a reason why the model does not hold).
fn within(
    p: &OperatingPoint,
    (check, yielding): (Option<&StripCheck>, Option<&YieldCheck>),
    style: RenderOptions,
    width: usize,
    room: usize,
) -> (Vec<Line<'static>>, Vec<bool>) {
    let model = p.solution.model;
    let v = &p.validity;
    let mut hidden = Vec::new();
    let mut head = Vec::new();
    if v.ok {
        head.push((holds(p), style.ok()));
    }
    head.extend(yielding.map(|y| {
        let look = if y.yields == Some(true) {
            style.error()
        } else {
            style.ok()
        };
        (y.phrase(), look)
    }));
    // which effect dominates, read from the shown model's solution: beside a verdict that it
    // holds, before the check; where it does not hold, only in a row left after the reasons
    let dominance = (
        Dominance::of(&p.solution).describe(),
        ratatui::style::Style::default(),
    );
    let mut last = None;
    if v.ok {
        head.push(dominance);
    } else {
        last = Some(dominance);
    }
    let warnings: Vec<Vec<Line>> = v
        .reasons
        .iter()
        .map(|r| prose(&reason(r), width, style.error()))
        .collect();
    let total: usize = warnings.iter().map(Vec::len).sum();
    // how far off, then why: every warning in a few words; the short form of how far off when
    // the long one would crowd the warnings out
    if let Some(check) = check {
        let off = matches!(check, StripCheck::Measured(d) if !d.within_tolerance());
        let look = if off { style.error() } else { style.ok() };
        let long = check.describe(model);
        let crowded = head.len() + prose(&long, width, look).len() + total > room;
        let text = match check.describe_short() {
            Some(short) if crowded => short,
            _ => long,
        };
        head.push((text, look));
    }
    // each line of the head in the rows left, ended by "…" where it does not fit whole; where
    // the model does not hold, the rows of its first reason are kept, so that the verdict is
    // never pushed out by the check or the yield line
    let kept = match warnings.first() {
        Some(first) if !v.ok => room.min(first.len()),
        _ => 0,
    };
    let mut lines: Vec<Line> = Vec::new();
    for (text, look) in head {
        let rows = room.saturating_sub(kept).saturating_sub(lines.len());
        let wrapped = wrap_within(&text, width, rows, style);
        if wrapped.is_empty() {
            hidden.push(false);
        }
        lines.extend(wrapped.into_iter().map(|l| Line::styled(l, look)));
    }
    let room = room.saturating_sub(lines.len());
    // whole warnings in the rows left
    let mut used = 0;
    let shown = warnings
        .iter()
        .take_while(|w| {
            used += w.len();
            used <= room
        })
        .count();
    // no room for the first reason whole: it alone, so that the verdict stays, ended by "…"
    if shown == 0
        && let Some(first) = v.reasons.first()
    {
        lines.extend(
            wrap_within(&reason(first), width, room, style)
                .into_iter()
                .map(|l| Line::styled(l, style.error())),
        );
        hidden.extend(std::iter::repeat_n(true, v.reasons.len() - 1));
        hidden.extend(last.map(|_| false));
        return (lines, hidden);
    }
    hidden.extend(std::iter::repeat_n(true, warnings.len() - shown));
    let used: usize = warnings.iter().take(shown).map(Vec::len).sum();
    lines.extend(warnings.into_iter().take(shown).flatten());
    if let Some((text, look)) = last {
        let fits = prose(&text, width, look);
        if fits.len() <= room - used {
            lines.extend(fits);
        } else {
            hidden.push(false);
        }
    }
    (lines, hidden)
}

/// A reason the model does not hold, after "! ".
fn reason(r: &Reason) -> Phrase {
    Phrase::words("!").then_phrase(r.text.clone())
}

/// The rows the verdict takes at `width`: one for "... model holds" (ended by "…" where it is
/// wider), else those of the first reason why not.
pub fn verdict_rows(p: &OperatingPoint, width: usize) -> usize {
    match p.validity.reasons.first() {
        Some(first) if !p.validity.ok => lines_of(&reason(first), width).len().max(1),
        _ => 1,
    }
}

/// The rows a plane status never gives up to a cursor's readout: `items` but those at the
/// indices `give_up` names (counted, "+2 more"), packed into lines, and the verdict.
pub fn kept_rows<P: Clone + Into<Phrase>>(
    (items, give_up): (&[P], &[usize]),
    p: &OperatingPoint,
    width: usize,
) -> usize {
    let mut kept: Vec<Phrase> = (items.iter().enumerate())
        .filter(|(i, _)| !give_up.contains(i))
        .map(|(_, item)| item.clone().into())
        .collect();
    if !give_up.is_empty() {
        kept.push(Phrase::whole(more(give_up.len())));
    }
    pack(&kept, width, "").len() + verdict_rows(p, width)
}

/// A plane status: `items` packed into lines, then the validity lines in the room left (the
/// dimensional status and the dimensionless view share it). The verdict is the last to go:
/// where the items and the verdict do not both fit, the items give up rows (those at the indices
/// `give_up` names first, then the last ones; counted, "+2 more") and the verdict keeps its own.
pub fn with_validity<P: Clone + Into<Phrase>>(
    (items, give_up): (&[P], &[usize]),
    p: &OperatingPoint,
    (check, yielding): (Option<&StripCheck>, Option<&YieldCheck>),
    style: RenderOptions,
    width: usize,
    height: usize,
) -> Vec<Line<'static>> {
    let verdict = verdict_rows(p, width).min(height);
    let mut out: Vec<Line> = pack(items, width, "").into_iter().map(Line::from).collect();
    if out.len() + verdict > height {
        out = pack_giving_up(items, width, height - verdict, give_up)
            .into_iter()
            .map(Line::from)
            .collect();
    }
    let room = height.saturating_sub(out.len());
    out.extend(judged(p, check, yielding, style, width, room));
    out
}
