//! The shaded x ranges of a chart where a sweep has no value.

use crate::tui::charts::Shade;

/// The x ranges where a sweep has no value, each from the last point with a value before it to
/// the first after it (or the sweep's end).
pub(super) fn gaps(x: &[f64], values: &[Option<f64>], label: &str) -> Vec<Shade> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < values.len() {
        if values[i].is_some() {
            i += 1;
            continue;
        }
        let j = (i..values.len())
            .find(|&j| values[j].is_some())
            .unwrap_or(values.len());
        out.push(Shade {
            from: x[i.saturating_sub(1)],
            to: x[j.min(values.len() - 1)],
            label: label.into(),
        });
        i = j;
    }
    out
}
