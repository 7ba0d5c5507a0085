//! Ticks of logarithmic and symmetric-log axes: decades, 1-2-5 or 1-3 within them on log axes;
//! zero and c 10^k on both sides on symmetric-log axes.

use super::{BARE_END, Scale, Ticks, nice_step, with_labels};

/// The whole numbers in [a, b] that are multiples of the fewest of 1, 2, 3, 5, 10, 20, ...
/// giving between 2 and `max` of them; else the two ends.
fn strided(a: f64, b: f64, max: usize) -> Vec<i32> {
    let (d0, d1) = ((a - 1e-9).ceil() as i32, (b + 1e-9).floor() as i32);
    [1, 2, 3, 5, 10, 20, 30, 50, 100]
        .into_iter()
        .map(|s| (d0..=d1).filter(|d| d % s == 0).collect::<Vec<_>>())
        .find(|v| v.len() >= 2 && v.len() <= max)
        .unwrap_or_else(|| if d1 > d0 { vec![d0, d1] } else { Vec::new() })
}

pub(super) fn logarithmic([a, b]: [f64; 2], label: &str, unit: &str, max: usize) -> Ticks {
    let title = match unit {
        "" => format!("{label} (log)"),
        u => format!("{label} [{u}] (log)"),
    };
    let decades = strided(a, b, max);
    let within = |mantissas: &[f64]| -> Vec<f64> {
        (a.floor() as i32 - 1..=b.ceil() as i32)
            .flat_map(|d| mantissas.iter().map(move |m| m * 10f64.powi(d)))
            .filter(|v| (a - 1e-9..=b + 1e-9).contains(&v.log10()))
            .collect()
    };
    // 1-2-5 within the decades when they fit (easier to read off than bare decades), else 1-3
    // (half decades) or 1-2-3-5 over at most two decades, or 1-2-3-5-7 within one, where that
    // gives more than the decades;
    // of those that fit, the first reaching within BARE_END of both ends of the range (else the
    // nearest); else decades, else 1-2-3-5-7 within less than a decade
    let bare = |v: &[f64]| match (v.first(), v.last()) {
        (Some(f), Some(l)) => ((f.log10() - a).max(b - l.log10()) / (b - a)).max(BARE_END),
        _ => 1.0,
    };
    let sets = [
        (3.0, within(&[1.0, 2.0, 5.0])),
        (2.0, within(&[1.0, 3.0])),
        (2.0, within(&[1.0, 2.0, 3.0, 5.0])),
        (1.0, within(&[1.0, 2.0, 3.0, 5.0, 7.0])),
    ];
    let fits = |(span, v): &(f64, Vec<f64>)| b - a <= *span && v.len() >= 2 && v.len() <= max;
    let best = (sets.iter().filter(|s| fits(s)))
        .filter(|s| s.0 == 3.0 || s.1.len() > decades.len().max(1))
        .min_by(|x, y| bare(&x.1).total_cmp(&bare(&y.1)));
    let values = if let Some((_, v)) = best {
        v.clone()
    } else if decades.len() >= 2 {
        decades.iter().map(|&d| 10f64.powi(d)).collect()
    } else if let Some(v) = [&[1.0, 2.0, 5.0][..], &[1.0, 2.0, 3.0, 5.0, 7.0][..]]
        .into_iter()
        .map(within)
        .find(|v| v.len() >= 2 && v.len() <= max)
    {
        v
    } else {
        // less than a decade: nice steps of the values themselves
        let (lo, hi) = (10f64.powf(a), 10f64.powf(b));
        let (step, _, _, ks) = nice_step(lo, hi, max);
        ks.iter().map(|k| k * step).collect()
    };
    // over two to three decades where 1-2-5 is too dense and the decades leave an end bare
    // (100 N/m to 60 kN/m labelled to 10k leaves 0.28 of it): half decades, where they fit
    let half = within(&[1.0, 3.0]);
    let values = if bare(&values) > BARE_END
        && b - a <= 3.0
        && half.len() <= max
        && bare(&half) < bare(&values)
    {
        half
    } else {
        values
    };
    Ticks {
        ticks: with_labels(Scale::Log, values, unit),
        title,
    }
}

pub(super) fn symlog([a, b]: [f64; 2], c: f64, label: &str, unit: &str, max: usize) -> Ticks {
    let title = match unit {
        "" => format!("{label} (symlog)"),
        u => format!("{label} [{u}] (symlog)"),
    };
    let scale = Scale::SymLog(c);
    let inside = |p: f64| (a - 1e-9..=b + 1e-9).contains(&p);
    // the core's edge (plot coordinate of c)
    let core = 2f64.log10();
    let reach = |p: f64| (scale.value_at(p).abs() / c).log10().max(0.0).ceil() as i32;
    let top = reach(a).max(reach(b));
    // zero first, then on each side c 10^k from the outermost inwards, each kept when it is
    // clear of those kept by `gap`; a side with values beyond the linear core that gets none:
    // 1-2-5 times c 10^k, then half as clear
    let pick = |gap: f64| -> Vec<f64> {
        let mut kept: Vec<(f64, f64)> = Vec::new();
        if inside(0.0) {
            kept.push((0.0, 0.0));
        }
        for (sign, wide) in [(-1.0, a < -core), (1.0, b > core)] {
            let before = kept.len();
            let tries = [
                (&[1.0][..], gap),
                (&[1.0, 2.0, 5.0], gap),
                (&[1.0, 2.0, 5.0], gap / 2.0),
            ];
            for (mantissas, clear) in tries {
                for k in (0..=top).rev() {
                    for m in mantissas.iter().rev() {
                        let v = sign * m * c * 10f64.powi(k);
                        let Some(p) = scale.to_plot(v).filter(|p| inside(*p)) else {
                            continue;
                        };
                        if kept.iter().all(|q| (q.0 - p).abs() >= clear) {
                            kept.push((p, v));
                        }
                    }
                }
                if !wide || kept.len() > before {
                    break;
                }
            }
        }
        kept.sort_by(|x, y| x.0.total_cmp(&y.0));
        kept.into_iter().map(|q| q.1).collect()
    };
    // ticks at least a max-th of the range apart (each on a row of its own), or a (max-1)-th
    // when that gives too many
    let mut values = Some(pick((b - a) / max as f64))
        .filter(|v| v.len() <= max)
        .unwrap_or_else(|| pick((b - a) / (max - 1) as f64));
    // still too many (both sides kept one half as clear): the innermost go
    while values.len() > max {
        let inner = (0..values.len())
            .filter(|&i| values[i] != 0.0)
            .min_by(|&i, &j| values[i].abs().total_cmp(&values[j].abs()));
        values.remove(inner.unwrap_or(0));
    }
    let values = if values.len() >= 2 {
        values
    } else {
        // within the linear core: nice steps of the values themselves
        let (lo, hi) = (scale.value_at(a), scale.value_at(b));
        let (step, _, _, ks) = nice_step(lo, hi, max);
        ks.iter().map(|k| k * step).collect()
    };
    Ticks {
        ticks: with_labels(scale, values, unit),
        title,
    }
}
