//! Engineering values: parse "3 GPa", "50mm", "1e-9", "inf"; format with SI prefixes.

/// SI prefixes from 1e-15 to 1e12 with their powers of ten (u stands for micro).
const PREFIXES: [(&str, i32); 10] = [
    ("f", -15),
    ("p", -12),
    ("n", -9),
    ("u", -6),
    ("m", -3),
    ("", 0),
    ("k", 3),
    ("M", 6),
    ("G", 9),
    ("T", 12),
];

/// Other units a quantity may be typed in, each with the power of ten that takes it to the
/// quantity's SI unit: a wear coefficient is quoted in the literature and on tribometer reports as
/// a specific wear rate in mm^3/(N m) (worn volume per normal force and sliding distance), which is
/// 1e-9 m^2/N = 1e-9 1/Pa; m^2/N is 1/Pa itself.
const ALTERNATIVES: [(&str, &str, i32); 6] = [
    ("1/Pa", "mm3/Nm", -9),
    ("1/Pa", "mm^3/Nm", -9),
    ("1/Pa", "mm3/(N m)", -9),
    ("1/Pa", "mm^3/(N m)", -9),
    ("1/Pa", "m2/N", 0),
    ("1/Pa", "m^2/N", 0),
];

/// The other units `unit` may be typed in, for messages ("mm3/Nm, m2/N").
fn alternatives(unit: &str) -> String {
    let mut names: Vec<&str> = Vec::new();
    for (u, alias, _) in ALTERNATIVES {
        if u == unit && !alias.contains(['^', '(']) {
            names.push(alias);
        }
    }
    names.join(", ")
}

/// value * 10^exp, dividing for negative powers so that "2.5 u" is exactly 2.5e-6.
fn scale(value: f64, exp: i32) -> f64 {
    if exp < 0 {
        value / 10f64.powi(-exp)
    } else {
        value * 10f64.powi(exp)
    }
}

/// Formats `value` with three significant digits and an SI prefix on `unit`, e.g. "3.00 GPa",
/// "50.0 mm", "-3.10 kPa", "-275 nm/s". Units that read badly with prefixes ("", "1/Pa", "rad/m")
/// are given in plain or scientific notation instead.
pub fn format_si(value: f64, unit: &str) -> String {
    if !value.is_finite() {
        return if value.is_nan() {
            "-".into()
        } else if value > 0.0 {
            "inf".into()
        } else {
            "-inf".into()
        };
    }
    if !prefixable(unit) {
        let text = if value == 0.0 {
            "0".to_string()
        } else if (1e-2..1e4).contains(&value.abs()) {
            format!("{}", round_sig(value, 4))
        } else {
            format!("{value:.3e}")
        };
        return if unit.is_empty() {
            text
        } else {
            format!("{text} {unit}")
        };
    }
    if value == 0.0 {
        return format!("0 {unit}");
    }
    let mag = value.abs();
    // the power of ten, a multiple of 3, that leaves 1 <= |scaled| < 1000 after rounding
    let exp = 3 * ((mag / 0.9995).log10() / 3.0).floor() as i32;
    let scaled = scale(value, -exp);
    let digits = if scaled.abs() >= 99.95 {
        0
    } else if scaled.abs() >= 9.995 {
        1
    } else {
        2
    };
    match prefix(exp) {
        Some(prefix) => format!("{scaled:.digits$} {prefix}{unit}"),
        // past the prefixes: engineering notation, so the text stays short
        None => format!("{scaled:.digits$}e{exp} {unit}"),
    }
}

fn round_sig(value: f64, sig: i32) -> f64 {
    let mag = value.abs().log10().floor() as i32;
    let factor = 10f64.powi(sig - 1 - mag);
    (value * factor).round() / factor
}

/// Significant digits kept by `clean`: far more than any input is known to, far fewer than the
/// 15-17 of an f64, so the last-bit noise of float arithmetic (3e9 * 1.1 = 3300000000.0000005)
/// is rounded away.
pub const CLEAN_DIGITS: usize = 12;

/// `value` rounded to `CLEAN_DIGITS` significant digits, as the nearest f64 to that decimal (so
/// 3e9 * 1.1 gives exactly the literal 3.3e9). Changes a value by at most half a unit in its
/// twelfth digit (5e-12 relative); 0, infinities and NaN are returned as they are.
pub fn clean(value: f64) -> f64 {
    significant(value, CLEAN_DIGITS)
}

/// `value` rounded to `digits` (at least 1) significant digits, as the nearest f64 to that
/// decimal; 0, infinities and NaN are returned as they are.
pub fn significant(value: f64, digits: usize) -> f64 {
    if !value.is_finite() || value == 0.0 {
        return value;
    }
    // Rust's `{:.Ne}` rounds the exact binary value correctly; parsing gives the nearest f64
    let digits = digits.max(1) - 1;
    format!("{value:.digits$e}").parse().unwrap_or(value)
}

/// `value` to the digits an uncertainty of `half_width` (> 0) supports: rounded at the place of
/// the half-width's second significant digit (0.2997514 with +-0.00085 gives 0.29975), at least
/// one significant digit kept and at most `CLEAN_DIGITS`. The value moves by at most 5 % of the
/// half-width.
pub fn supported(value: f64, half_width: f64) -> f64 {
    if !value.is_finite() || value == 0.0 || !(half_width.is_finite() && half_width > 0.0) {
        return clean(value);
    }
    let place = half_width.log10().floor() as i64 - 1;
    let top = value.abs().log10().floor() as i64;
    let digits = (top - place + 1).clamp(1, CLEAN_DIGITS as i64) as usize;
    significant(value, digits)
}

/// Formats `value` with an SI prefix on `unit` like `format_si`, but with every significant
/// digit of `clean(value)` and no trailing zeros ("3.3 GPa", "200 pPa", "2e-10 1/Pa",
/// "0.31"), for text that is read back with `parse_si` (the ranges of the sweep form).
pub fn format_si_exact(value: f64, unit: &str) -> String {
    let value = clean(value);
    if !value.is_finite() || value == 0.0 {
        return format_si(value, unit);
    }
    let with_unit = |text: String| {
        if unit.is_empty() {
            text
        } else {
            format!("{text} {unit}")
        }
    };
    if !prefixable(unit) {
        return with_unit(if (1e-3..1e6).contains(&value.abs()) {
            format!("{value}")
        } else {
            format!("{value:e}")
        });
    }
    let mut exp = 3 * (value.abs().log10() / 3.0).floor() as i32;
    // log10 may land a hair off a power of ten: keep 1 <= |scaled| < 1000
    if clean(scale(value.abs(), -exp)) >= 1000.0 {
        exp += 3;
    } else if clean(scale(value.abs(), -exp)) < 1.0 {
        exp -= 3;
    }
    let scaled = clean(scale(value, -exp));
    match prefix(exp) {
        Some(prefix) => format!("{scaled} {prefix}{unit}"),
        None => format!("{scaled}e{exp} {unit}"),
    }
}

/// A fraction of a whole (0..1: the contact fraction) as `format_si` writes a pure number, four
/// significant digits ("0.5781"), except that a fraction short of 1 never reads "1" (a partial
/// contact of 0.99996 reads "0.9999"; one above 0 reads in scientific notation, never "0").
pub fn format_fraction(value: f64) -> String {
    let text = format_si(value, "");
    if value < 1.0 && text == "1" {
        "0.9999".into()
    } else {
        text
    }
}

/// Whether a unit takes SI prefixes ("Pa", "m", "N/m"); "", "1/Pa" and "rad/m" read badly with
/// them and do not.
pub fn prefixable(unit: &str) -> bool {
    !unit.is_empty() && !unit.starts_with("1/") && !unit.starts_with("rad")
}

/// Whether `text` is an SI prefix alone ("k", "u"), without a unit.
pub fn is_prefix(text: &str) -> bool {
    PREFIXES.iter().any(|(p, _)| !p.is_empty() && *p == text)
}

/// The SI prefix of a power of ten that is a multiple of 3 from -15 to 12 ("u" for micro).
pub fn prefix(exp: i32) -> Option<&'static str> {
    PREFIXES.iter().find(|(_, e)| *e == exp).map(|(p, _)| *p)
}

/// The decimal number `text` times 10^exp, read as one decimal ("2.5" and -6 read as "2.5e-6"),
/// so that the result is the f64 nearest to the value typed, as the same value written in SI
/// units gives: "2 mm" is the literal 2e-3 bit for bit. None when the exponent does not fit.
pub(crate) fn shifted(text: &str, exp: i32) -> Option<f64> {
    let (mantissa, own) = match text.find(['e', 'E']) {
        Some(i) => (&text[..i], text[i + 1..].parse::<i32>().ok()?),
        None => (text, 0),
    };
    format!("{mantissa}e{}", own.checked_add(exp)?).parse().ok()
}

/// Parses a number with an optional SI prefix and unit: "3e9", "3 GPa", "50mm", "0.3", "inf",
/// "2.5 um". The unit, when given, must be `unit` (with or without a prefix).
pub fn parse_si(text: &str, unit: &str) -> Result<f64, String> {
    let t = text.trim();
    if t.is_empty() {
        return Err("empty: type a number, e.g. 3e9 or 3 GPa".into());
    }
    if t.eq_ignore_ascii_case("inf") {
        return Ok(f64::INFINITY);
    }
    // the longest prefix of t that parses as a number
    let split = (1..=t.len())
        .rev()
        .filter(|&i| t.is_char_boundary(i))
        .find(|&i| t[..i].trim().parse::<f64>().is_ok() && !t[..i].ends_with(['e', 'E']))
        .ok_or_else(|| format!("'{t}' is not a number"))?;
    let number: f64 = t[..split]
        .trim()
        .parse()
        .map_err(|_| format!("'{t}' is not a number"))?;
    let rest = t[split..].trim();
    if rest.is_empty() {
        return Ok(number);
    }
    if let Some((_, _, exp)) = ALTERNATIVES
        .iter()
        .find(|(u, alias, _)| *u == unit && rest.eq_ignore_ascii_case(alias))
    {
        // the decimal the user typed: 0.02 mm3/Nm is exactly the literal 2e-11
        return Ok(shifted(t[..split].trim(), *exp).unwrap_or(scale(number, *exp)));
    }
    let rest = rest
        .strip_suffix(unit)
        .filter(|_| !unit.is_empty())
        .unwrap_or(rest);
    let rest = rest.replace('µ', "u");
    if rest.is_empty() {
        return Ok(number);
    }
    match PREFIXES.iter().find(|(p, _)| !p.is_empty() && *p == rest) {
        Some((_, exp)) => Ok(shifted(t[..split].trim(), *exp).unwrap_or(scale(number, *exp))),
        None if prefixable(unit) || unit.is_empty() => Err(format!(
            "'{t}': unknown unit; write a plain number or a prefixed {unit} (e.g. k{unit}, M{unit})"
        )),
        None => {
            let others = alternatives(unit);
            let or = if others.is_empty() {
                String::new()
            } else {
                format!(" or in {others}")
            };
            Err(format!(
                "'{t}': unknown unit; write a plain number in {unit}{or}"
            ))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fraction_short_of_one_never_reads_one() {
        // 37 of 64 nodes in contact
        assert_eq!(format_fraction(0.578125), "0.5781");
        assert_eq!(format_fraction(0.99996), "0.9999");
        assert_eq!(format_fraction(1.0), "1");
        assert_eq!(format_fraction(1.0 / 262_144.0), "3.815e-6");
        assert_eq!(format_fraction(0.0), "0");
    }

    #[test]
    fn formats_with_prefixes() {
        assert_eq!(format_si(3e9, "Pa"), "3.00 GPa");
        assert_eq!(format_si(0.05, "m"), "50.0 mm");
        assert_eq!(format_si(-3100.0, "Pa"), "-3.10 kPa");
        assert_eq!(format_si(1e-4, "m"), "100 um");
        assert_eq!(format_si(0.0, "m"), "0 m");
        assert_eq!(format_si(f64::INFINITY, "m"), "inf");
        assert_eq!(format_si(2e-11, "1/Pa"), "2.000e-11 1/Pa");
        assert_eq!(format_si(0.35, ""), "0.35");
        assert_eq!(format_si(0.999_96, "m"), "1.00 m");
        assert_eq!(format_si(-2.749e-7, "m/s"), "-275 nm/s");
        assert_eq!(format_si(5000.0, "N/m"), "5.00 kN/m");
        assert_eq!(format_si(3141.6, "rad/m"), "3142 rad/m");
        // past the prefixes (T, f): engineering notation
        assert_eq!(format_si(3e30, "Pa"), "3.00e30 Pa");
        assert_eq!(format_si(999.96e12, "Pa"), "1.00e15 Pa");
        assert_eq!(format_si(-1.5e-20, "m"), "-15.0e-21 m");
        assert_eq!(format_si(999e12, "Pa"), "999 TPa");
    }

    #[test]
    fn clean_removes_float_noise() {
        // 3e9 * 1.1 is 3300000000.0000005 in f64: one nudge of E from 3 GPa
        assert_ne!(3e9 * 1.1, 3.3e9);
        assert_eq!(clean(3e9 * 1.1), 3.3e9);
        // 31 linear steps of 0.01 (the nudge of mu) is 0.31000000000000005 in f64
        assert_eq!(clean(31.0 * 0.01), 0.31);
        assert_eq!(clean(2e-9 / 10.0), 2e-10);
        assert_eq!(clean(0.0), 0.0);
        assert_eq!(clean(f64::INFINITY), f64::INFINITY);
    }

    #[test]
    fn a_value_keeps_the_digits_its_uncertainty_supports() {
        // rounded at the second significant digit of the half-width, by hand
        assert_eq!(supported(0.299_751_391_856_090_2, 0.000_85), 0.299_75);
        assert_eq!(supported(3.001_234_5e9, 5.1e6), 3.0012e9);
        assert_eq!(supported(2.012_345_6e-11, 3.4e-13), 2.012e-11);
        assert_eq!(supported(-1.234_567, 0.12), -1.23);
        // a half-width larger than the value: one digit is kept
        assert_eq!(supported(0.000_312, 0.05), 0.0003);
        assert_eq!(
            format_si_exact(supported(0.299_751_4, 0.000_85), ""),
            "0.29975"
        );
        // no half-width to go by: 12 digits, as `clean`
        assert_eq!(supported(0.1 + 0.2, 0.0), 0.3);
    }

    #[test]
    fn exact_text_reads_back() {
        assert_eq!(format_si_exact(3e9 * 1.1, "Pa"), "3.3 GPa");
        assert_eq!(format_si_exact(2e-9 / 10.0, "m"), "200 pm");
        assert_eq!(format_si_exact(1e-9, "m"), "1 nm");
        assert_eq!(format_si_exact(1000.0, "N/m"), "1 kN/m");
        assert_eq!(format_si_exact(2e-10, "1/Pa"), "2e-10 1/Pa");
        assert_eq!(
            format_si_exact(-std::f64::consts::PI, "rad"),
            "-3.14159265359 rad"
        );
        assert_eq!(format_si_exact(0.31, ""), "0.31");
        assert_eq!(format_si_exact(f64::INFINITY, "m"), "inf");
        assert_eq!(format_si_exact(3e30, "Pa"), "3e30 Pa");
        for (v, unit) in [(3.3e9, "Pa"), (2e-10, "m"), (123.456, "N/m"), (1e13, "Pa")] {
            assert_eq!(
                parse_si(&format_si_exact(v, unit), unit),
                Ok(v),
                "{v} {unit}"
            );
        }
    }

    proptest::proptest! {
        // 256 cases in `cargo test`; run once by hand with PROPTEST_CASES=100000
        #[test]
        fn clean_moves_a_value_by_at_most_half_a_twelfth_digit(
            mantissa in 1.0f64..10.0, exp in -30i32..30, negative: bool,
        ) {
            let value = if negative { -mantissa } else { mantissa } * 10f64.powi(exp);
            let cleaned = clean(value);
            // half a unit in the 12th significant digit is 5e-12 of the leading digit's place,
            // at most 5e-12 relative; 1e-15 allows for the f64 rounding of the result
            proptest::prop_assert!(((cleaned - value) / value).abs() <= 5e-12 + 1e-15);
            proptest::prop_assert_eq!(clean(cleaned), cleaned);
        }
    }

    #[test]
    fn parses_engineering_text() {
        assert_eq!(parse_si("3e9", "Pa"), Ok(3e9));
        assert_eq!(parse_si("3 GPa", "Pa"), Ok(3e9));
        assert_eq!(parse_si("50mm", "m"), Ok(0.05));
        assert_eq!(parse_si(" 2.5 um ", "m"), Ok(2.5e-6));
        assert_eq!(parse_si("inf", "m"), Ok(f64::INFINITY));
        assert_eq!(parse_si("1e-9", "1/Pa"), Ok(1e-9));
        assert_eq!(parse_si("7 k", "Pa"), Ok(7000.0));
        assert!(parse_si("abc", "Pa").unwrap_err().contains("not a number"));
        assert!(parse_si("3 GN", "Pa").unwrap_err().contains("unknown unit"));
        assert!(parse_si("", "Pa").is_err());
    }

    #[test]
    fn prefixed_values_are_the_decimal_typed() {
        // in f64, 0.1 / 1e6 != 1e-7, 3.3 / 1e6 != 3.3e-6 and 0.07 / 1e3 != 7e-5 (the division
        // rounds twice); the text read as one decimal is the literal
        assert_ne!(0.1 / 1e6, 1e-7);
        assert_eq!(parse_si("0.1 um", "m"), Ok(1e-7));
        assert_eq!(parse_si("3.3 um", "m"), Ok(3.3e-6));
        assert_eq!(parse_si("0.07 mm", "m"), Ok(7e-5));
        assert_eq!(parse_si("6.283185307179586 km", "m"), Ok(6283.185307179586));
        assert_eq!(parse_si("1.5e2 MPa", "Pa"), Ok(1.5e8));
        assert_eq!(parse_si("-2 kN/m", "N/m"), Ok(-2000.0));
    }

    #[test]
    fn wear_coefficients_in_specific_wear_rate_units() {
        // 1 mm^3/(N m) = 1e-9 m^3/(N m) = 1e-9 m^2/N = 1e-9 1/Pa, exactly the literal 1e-9
        assert_eq!(parse_si("1 mm3/Nm", "1/Pa"), Ok(1e-9));
        assert_eq!(parse_si("3e-5 mm3/Nm", "1/Pa"), Ok(3e-5 / 1e9));
        assert_eq!(parse_si("2 mm^3/(N m)", "1/Pa"), Ok(2e-9));
        assert_eq!(parse_si("2e-11 m2/N", "1/Pa"), Ok(2e-11));
        assert_eq!(parse_si("2e-11 1/Pa", "1/Pa"), Ok(2e-11));
        // only where the quantity is a wear coefficient
        assert!(parse_si("1 mm3/Nm", "Pa").is_err());
        let why = parse_si("1 mm3/N", "1/Pa").unwrap_err();
        assert!(why.contains("mm3/Nm, m2/N"), "{why}");
    }
}
