//! A changed value written as its author wrote the value it replaces: in the same unit and
//! prefix ("2 mm" edited to 3e-3 is "3 mm", "4e-5 mm3/Nm" edited to 5e-14 is "5e-5 mm3/Nm"), as
//! a decimal that `units::parse_si` reads back to exactly the new value.

use crate::units::shifted;

/// The number and what follows it (the unit, with the space before it) of a value text:
/// ("2", " mm") for "2 mm"; None when the text does not start with a number.
fn split(text: &str) -> Option<(&str, &str)> {
    let t = text.trim();
    // the longest start of the text that reads as a number, as `parse_si` splits it
    let end = (1..=t.len())
        .rev()
        .filter(|&i| t.is_char_boundary(i))
        .find(|&i| t[..i].trim().parse::<f64>().is_ok() && !t[..i].ends_with(['e', 'E']))?;
    let number = t[..end].trim_end();
    Some((number, &t[number.len()..]))
}

/// `value` as a text in the unit of `text`, which reads as `was` (both SI); None when `text` has
/// no unit, when its unit's power of ten cannot be told from it (a zero, inf) or when no text in
/// that unit reads back to exactly `value`.
pub(super) fn in_unit_of(text: &str, was: f64, value: f64) -> Option<String> {
    let (number, unit) = split(text)?;
    if unit.trim().is_empty() || !value.is_finite() {
        return None;
    }
    let n: f64 = number.parse().ok()?;
    if !(n != 0.0 && n.is_finite() && was.is_finite() && was != 0.0) {
        return None;
    }
    // every unit `parse_si` reads is a power of ten times the SI unit
    let exp = (was / n).abs().log10().round() as i32;
    if shifted(number, exp) != Some(was) {
        return None;
    }
    let (mantissa, own) = format!("{value:e}")
        .split_once('e')
        .map(|(m, e)| (m.to_string(), e.parse::<i32>().ok()))?;
    let scientific = number.contains(['e', 'E']);
    let digits = decimal(&mantissa, own? - exp, scientific);
    (shifted(&digits, exp) == Some(value)).then(|| format!("{digits}{unit}"))
}

/// The decimal `mantissa` x 10^exp (`mantissa` as Rust's `{:e}` writes it, "-1.25"), written out
/// in full ("0.0125", "1250") unless `scientific` (as the author wrote the old value) or long,
/// then as "1.25e-7".
fn decimal(mantissa: &str, exp: i32, scientific: bool) -> String {
    if scientific || !(-5..=15).contains(&exp) {
        return format!("{mantissa}e{exp}");
    }
    let (sign, unsigned) = match mantissa.strip_prefix('-') {
        Some(rest) => ("-", rest),
        None => ("", mantissa),
    };
    let digits: String = unsigned.chars().filter(|c| *c != '.').collect();
    // the point sits after the first digit; exp moves it
    let point = 1 + exp;
    let text = if point <= 0 {
        format!("0.{}{digits}", "0".repeat((-point) as usize))
    } else if point as usize >= digits.len() {
        format!("{digits}{}", "0".repeat(point as usize - digits.len()))
    } else {
        format!(
            "{}.{}",
            &digits[..point as usize],
            &digits[point as usize..]
        )
    };
    format!("{sign}{text}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::units::parse_si;

    #[test]
    fn a_new_value_keeps_the_unit_it_replaces() {
        assert_eq!(in_unit_of("2 mm", 2e-3, 3e-3).as_deref(), Some("3 mm"));
        assert_eq!(in_unit_of("2mm", 2e-3, 2.5e-4).as_deref(), Some("0.25mm"));
        assert_eq!(
            in_unit_of("0.5 GPa", 5e8, 7.25e9).as_deref(),
            Some("7.25 GPa")
        );
        // the author's notation: an exponent where the old value had one
        assert_eq!(
            in_unit_of("4e-5 mm3/Nm", 4e-14, 5e-14).as_deref(),
            Some("5e-5 mm3/Nm")
        );
        assert_eq!(
            in_unit_of("0.04 mm3/Nm", 4e-11, 5e-14).as_deref(),
            Some("0.00005 mm3/Nm")
        );
        assert_eq!(in_unit_of("3e3 Pa", 3e3, 4e3).as_deref(), Some("4e3 Pa"));
        assert_eq!(
            in_unit_of("10 kN/m", 1e4, -1.5e12).as_deref(),
            Some("-1500000000 kN/m")
        );
        assert_eq!(
            in_unit_of("40 nm", 4e-8, 1.234e-20).as_deref(),
            Some("1.234e-11 nm")
        );
        // each text reads back to exactly the value
        for (text, unit, value) in [("0.25 mm", "m", 2.5e-4), ("7.25 GPa", "Pa", 7.25e9)] {
            assert_eq!(parse_si(text, unit), Ok(value));
        }
    }

    #[test]
    fn without_a_unit_that_can_be_told_the_value_is_written_in_si() {
        assert_eq!(in_unit_of("0.3", 0.3, 0.4), None);
        assert_eq!(in_unit_of("0 mm", 0.0, 1e-3), None);
        assert_eq!(in_unit_of("inf", f64::INFINITY, 1e-3), None);
        assert_eq!(in_unit_of("2 mm", 2e-3, f64::INFINITY), None);
        assert_eq!(in_unit_of("mm", 2e-3, 1e-3), None);
    }
}
