//! The status of a contact solved on the period cell: partial or complete, the
//! contact fraction (`units::format_fraction`, as the charts' cursor reads it), p_max, mu* and psi of the state shown, and where the running-in stands
//! (stepping, with the simulated time reached, or the simulated time to complete contact).

use crate::engine::{CellOutput, Progress};
use crate::phrase::Phrase;
use crate::physics::spatial::partial::running_in::{HORIZON_DECAY_TIMES, MAX_STEPS};
use crate::units::{format_fraction, format_si};
use ratatui::text::Line;

use crate::tui::view::status_values::mu_star;
use crate::tui::view::theme::RenderOptions;
use crate::tui::view::wrap;
use crate::tui::view::wrapping::{lines_of, pack};

/// The head of the status for the state on the cell, and whether the harmonics' closed-form
/// rates do not hold now (the state shown is partial: they hold after complete contact; a
/// nonlinear wear law, whose words end the head: they hold for n = 1 only) and whether `then`
/// was said: with `then`, the time of complete contact ends in ", then:", heading the
/// harmonics' rows (without, where no row fits under it). `mu` is the sliding friction
/// coefficient, `wear_rate` k V [m/(Pa s)] of the inputs.
pub fn head(
    c: &CellOutput,
    mu: f64,
    wear_rate: f64,
    style: RenderOptions,
    width: usize,
    then: bool,
) -> (Vec<Line<'static>>, bool, bool) {
    let state = match &c.state {
        Ok(state) => state,
        Err(why) => {
            let lines = wrap(&why.to_string(), width)
                .into_iter()
                .map(|l| Line::styled(l, style.error()))
                .collect();
            return (lines, false, false);
        }
    };
    let o = &state.outputs;
    let (verdict, verdict_style) = if o.complete {
        ("complete contact".to_string(), style.ok())
    } else {
        // as the running-in chart's cursor reads it
        let partial = format!(
            "partial contact (fraction {})",
            format_fraction(o.contact_fraction)
        );
        (partial, ratatui::style::Style::default())
    };
    // the verdict and the time, then the values (packed apart, so that a longer time never
    // moves a value to another line while time plays)
    let first = [verdict, format!("t = {}", format_si(state.time, "s"))];
    let mut values = vec![format!("p_max = {}", format_si(o.max_pressure, "Pa"))];
    if o.complete {
        values.push(format!(
            "p_min = {} (nodes)",
            format_si(o.min_pressure_complete, "Pa")
        ));
    }
    values.extend([
        mu_star(o.mu_star, mu),
        format!("psi = {}", format_si(o.psi, "Pa")),
    ]);
    let mut lines: Vec<Line> = pack(&first, width, "")
        .into_iter()
        .map(|l| Line::styled(l, verdict_style))
        .collect();
    lines.extend(pack(&values, width, "").into_iter().map(Line::from));
    let running = match c.progress {
        Progress::Running {
            reached,
            towards: Some(t),
        } => Phrase::words("running in:")
            .then(format!("t = {}", format_si(reached, "s")))
            .then("of")
            .then(format_si(t, "s")),
        Progress::Running {
            reached,
            towards: None,
        } => Phrase::words("running in to complete contact:")
            .then(format!("t = {}", format_si(reached, "s"))),
        Progress::Done { reached } => done(c, wear_rate, reached, true),
    };
    let complete_at = c.history.as_deref().ok().and_then(|h| h.time_to_complete);
    let done_at = match c.progress {
        Progress::Done { reached } => Some(reached),
        Progress::Running { .. } => None,
    };
    // a nonlinear wear law: the harmonics' closed form never holds, so nothing follows "then"
    let said =
        then && !o.complete && done_at.is_some() && complete_at.is_some() && c.simulated.is_none();
    let then = if said { ", then:" } else { "" };
    let mut running = running.ending(then);
    // the time-step error only where the line keeps to one row (the harmonics' rows under it
    // need the room)
    if let Some(reached) = done_at.filter(|_| running.to_string().chars().count() > width) {
        running = done(c, wear_rate, reached, false).ending(then);
    }
    // a nonlinear wear law says why it is simulated right after where it stands
    if let Some(note) = &c.simulated {
        running = running.ending(";").then_words(note);
    }
    lines.extend(
        lines_of(&running, width)
            .into_iter()
            .map(|l| Line::styled(l, style.heading())),
    );
    (lines, !o.complete || c.simulated.is_some(), said)
}

/// The end of the running-in (its last stepped state at `reached` [s]), in words, with the
/// estimate of its time-stepping error when `error` (relative: the values shown are that close
/// to the exact running-in on this grid).
fn done(c: &CellOutput, wear_rate: f64, reached: f64, error: bool) -> Phrase {
    let history = c.history.as_deref().ok();
    let complete_at = history.and_then(|h| h.time_to_complete);
    let error = history.and_then(|h| h.time_error).filter(|_| error);
    // "(simulated" or "steps" closed by ")", or followed by the error estimate
    let closing = |p: Phrase| match error {
        Some(e) => p
            .ending(",")
            .then_words("time-step")
            .then(format!("error < {e:.1e})")),
        None => p.ending(")"),
    };
    if c.complete_from_start {
        // a height map in complete contact from the start (harmonics show their closed form then)
        return Phrase::words("complete from t = 0: every mode wears by its closed form");
    }
    match complete_at {
        Some(t) => closing(
            Phrase::words("complete after")
                .then(format!("t = {}", format_si(t, "s")))
                .then("(simulated"),
        ),
        None if wear_rate == 0.0 => Phrase::words("no wear: the contact stays as it is"),
        // a nonlinear wear law complete from t = 0, stepped to the end of its stepping
        None if c.simulated.is_some()
            && !c
                .history
                .as_deref()
                .is_ok_and(|h| h.min_pressure_complete.first().is_some_and(|m| *m < 0.0)) =>
        {
            let to = Phrase::words("simulated to").then(format!("t = {}", format_si(reached, "s")));
            match error {
                Some(e) => to
                    .then_words("(time-step")
                    .then(format!("error < {e:.1e})")),
                None => to,
            }
        }
        None => closing(
            Phrase::words("still partial at")
                .then(format!("t = {}:", format_si(reached, "s")))
                .then_words(&format!(
                    "complete contact not reached within the running-in's bound \
                     ({HORIZON_DECAY_TIMES} decay times 1/beta of the slowest harmonic, at most \
                     {MAX_STEPS} steps"
                )),
        ),
    }
}
