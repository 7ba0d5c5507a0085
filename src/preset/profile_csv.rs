//! A measured punch profile (`plane.shape = { kind = "table", file = ... }`, `docs/presets.md`):
//! a CSV file with the header `x [m],g [m]`, one point a row, `#` comments and blank lines
//! skipped; each refusal is `path:line: reason`.

use std::path::Path;

use crate::physics::plane::spline::Spline;
use crate::preset::{PresetError, disk};

/// The header a profile file starts with (spaces around the commas allowed).
pub const HEADER: &str = "x [m],g [m]";

/// Reads the profile at `path` and fits its natural cubic spline.
pub fn read(path: &Path) -> Result<Spline, PresetError> {
    parse(&disk::read_text(path)?, path)
}

/// Parses profile text; `path` is only used in messages.
pub fn parse(text: &str, path: &Path) -> Result<Spline, PresetError> {
    let refuse = |line: Option<usize>, reason: String| PresetError {
        path: path.to_path_buf(),
        line,
        reason,
    };
    let mut rows = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let squeeze = |l: &str| l.split(',').map(str::trim).collect::<Vec<_>>().join(",");
    match rows.next() {
        Some((_, l)) if squeeze(l) == HEADER => {}
        Some((n, l)) => {
            return Err(refuse(
                Some(n),
                format!("the first row is '{l}': a profile starts with the header '{HEADER}'"),
            ));
        }
        None => {
            return Err(refuse(
                None,
                format!(
                    "the file is empty: a profile starts with the header '{HEADER}', then one x,g row per point"
                ),
            ));
        }
    }
    let (mut x, mut g, mut lines) = (Vec::new(), Vec::new(), Vec::new());
    for (n, l) in rows {
        let cells: Vec<&str> = l.split(',').map(str::trim).collect();
        let number = |cell: &str| cell.parse::<f64>().ok().filter(|v| v.is_finite());
        match cells.as_slice() {
            [a, b] => match (number(a), number(b)) {
                (Some(xv), Some(gv)) => {
                    x.push(xv);
                    g.push(gv);
                    lines.push(n);
                }
                _ => {
                    return Err(refuse(
                        Some(n),
                        format!("'{l}' is not two finite numbers x,g in metres"),
                    ));
                }
            },
            _ => {
                return Err(refuse(
                    Some(n),
                    format!("'{l}' has {} cells: a row is x,g in metres", cells.len()),
                ));
            }
        }
    }
    if let Some(i) = (1..x.len()).find(|&i| x[i] <= x[i - 1]) {
        return Err(refuse(
            Some(lines[i]),
            format!(
                "x = {} m does not exceed the previous row's x = {} m: x must increase strictly",
                x[i],
                x[i - 1]
            ),
        ));
    }
    Spline::new(x, g).map_err(|e| {
        refuse(
            lines.last().copied(),
            e.to_string().trim_start_matches("invalid input: ").into(),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(text: &str) -> String {
        parse(text, Path::new("p.csv")).unwrap_err().to_string()
    }

    #[test]
    fn reads_rows_under_the_header_and_skips_comments() {
        let s = parse(
            "# worn pin\nx [m], g [m]\n-1e-3,5e-6\n\n0,0\n# tip\n1e-3,5e-6\n",
            Path::new("p.csv"),
        )
        .unwrap();
        assert_eq!(s.range(), (-1e-3, 1e-3));
        assert_eq!(s.eval(0.0).0, 0.0);
    }

    #[test]
    fn refusals_name_the_file_and_the_line() {
        assert!(err("x,g\n0,0\n").starts_with("p.csv:1: the first row is 'x,g'"));
        assert!(err("x [m],g [m]\n0,0\n1,nan\n").starts_with("p.csv:3: '1,nan' is not"));
        assert!(err("x [m],g [m]\n0,0\n1,2,3\n").starts_with("p.csv:3: '1,2,3' has 3 cells"));
        assert!(err("x [m],g [m]\n0,0\n1,0\n1,1\n").starts_with("p.csv:4: x = 1 m"));
        assert!(err("x [m],g [m]\n0,0\n").contains("at least 3"));
        assert!(err("").contains("the file is empty"));
    }
}
