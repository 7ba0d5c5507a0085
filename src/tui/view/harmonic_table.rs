//! The spatial status's table of the harmonics (a row each: n, kh, 1/beta, c, phi), and the
//! table whole for the `i` window, where a crowded status counts the rows it leaves out.

use crate::engine::Output;
use crate::engine::SpatialOutput;
use crate::units::format_si;

use crate::tui::app::App;
use crate::tui::view::groups_status;
use crate::tui::view::status_values::number;

/// The harmonics' table of the spatial status: its header (n, kh or k for a half-space, 1/beta,
/// c, phi) and one row per harmonic.
pub fn dimensional(out: &SpatialOutput) -> (String, Vec<Vec<String>>) {
    let s = &out.state.solution;
    let h = s.inputs.material.thickness;
    // one row per harmonic under a header: n, kh (k for a half-space), 1/beta, c, phi
    let k_label = if h.is_finite() { "kh" } else { "k [rad/m]" };
    let header = format!(
        "{:>3} {k_label:<10}{:<10}{:<12}{}",
        "n", "1/beta", "c", "phi"
    );
    let blocks: Vec<Vec<String>> = s
        .harmonics
        .iter()
        .enumerate()
        .map(|(n, hs)| {
            let e = &hs.evolution;
            let k = hs.initial.wavenumber();
            let kh = format_si(if h.is_finite() { k * h } else { k }, "");
            let decay = if e.decay_rate > 0.0 {
                format_si(1.0 / e.decay_rate, "s")
            } else {
                "inf".into()
            };
            let c = format_si(e.drift_velocity, "m/s");
            vec![format!(
                "{:>3} {kh:<10}{decay:<10}{c:<12}{}",
                n + 1,
                number("harmonics.N.phase_lead", e.phase_lead)
            )]
        })
        .collect();
    (header, blocks)
}

/// The harmonics' table whole, header first, as the status shows it (in groups in the
/// dimensionless view), for the `i` window where a crowded status counts rows ("+2 more: i");
/// empty for an output without harmonics.
pub fn in_full(app: &App) -> Vec<String> {
    let Some((answer, _)) = crate::tui::on_screen::on_screen(app).answer() else {
        return Vec::new();
    };
    let Output::Spatial(Ok(out)) = &answer.output else {
        return Vec::new();
    };
    let table = if app.explore.dimensionless {
        groups_status::harmonic_table(out)
    } else {
        Some(dimensional(out))
    };
    match table {
        Some((header, blocks)) if !blocks.is_empty() => std::iter::once(header)
            .chain(blocks.into_iter().flatten())
            .collect(),
        _ => Vec::new(),
    }
}
