//! Height-map files (docs/physics/spatial-surface.md section 1): the CSV grid (one row per y line,
//! the first at y = 0; one column per x line, the first at x = 0; `#` comment lines) and the
//! three-column `x y z` export of profilometers on a regular grid. Heights in metres. A file is
//! read through a size bound, so a huge file is refused without being read into memory.

use std::fmt;
use std::fs::File;
use std::io::{BufRead, BufReader, Read};
use std::path::Path;

use super::{MAX_HEIGHT, MAX_SIDE_1D, MAX_SIDE_2D, Surface, height_reason};

/// Largest file read [bytes]: a 1024 x 1024 map in `x y z` columns at 17 significant digits
/// takes about 75 MB.
pub const MAX_FILE_BYTES: u64 = 128 * 1024 * 1024;

/// Why a height-map file was refused: `path:line: reason` (line 0: the file as a whole).
#[derive(Clone, Debug, PartialEq)]
pub struct ReadError {
    /// The file as given.
    pub path: String,
    /// 1-based line, or 0 for the whole file.
    pub line: usize,
    /// What is wrong, for the user.
    pub reason: String,
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "{}: {}", self.path, self.reason)
        } else {
            write!(f, "{}:{}: {}", self.path, self.line, self.reason)
        }
    }
}

impl std::error::Error for ReadError {}

/// Where the lines come from: a file on disk, or a text already in memory (a bundled file),
/// named by `path` in messages.
#[derive(Clone, Copy)]
enum Source<'a> {
    Disk,
    Text(&'a str),
}

/// The data lines of a file (1-based number, text), comments and blank lines skipped, each
/// handed to `take` until it fails.
fn each_line(
    path: &Path,
    source: Source,
    take: impl FnMut(usize, &str) -> Result<(), String>,
) -> Result<usize, ReadError> {
    let error = |line: usize, reason: String| ReadError {
        path: path.display().to_string(),
        line,
        reason,
    };
    if let Source::Text(text) = source {
        return lines_of(text.as_bytes(), path, take);
    }
    let file = File::open(path).map_err(|e| error(0, format!("cannot be read: {e}")))?;
    let size = file.metadata().map(|m| m.len()).unwrap_or(0);
    if size > MAX_FILE_BYTES {
        return Err(error(
            0,
            format!(
                "the file is {size} bytes, more than the {MAX_FILE_BYTES} a largest grid \
                 ({MAX_SIDE_2D} x {MAX_SIDE_2D}) needs"
            ),
        ));
    }
    lines_of(BufReader::new(file.take(MAX_FILE_BYTES)), path, take)
}

/// The data lines of `reader`, as [`each_line`].
fn lines_of(
    mut reader: impl BufRead,
    path: &Path,
    mut take: impl FnMut(usize, &str) -> Result<(), String>,
) -> Result<usize, ReadError> {
    let error = |line: usize, reason: String| ReadError {
        path: path.display().to_string(),
        line,
        reason,
    };
    let mut text = String::new();
    let mut number = 0;
    loop {
        text.clear();
        let read = reader
            .read_line(&mut text)
            .map_err(|e| error(number + 1, format!("cannot be read as text: {e}")))?;
        if read == 0 {
            return Ok(number);
        }
        number += 1;
        let line = text.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        take(number, line).map_err(|reason| error(number, reason))?;
    }
}

/// A number of the file, checked as a height when `height` is set.
fn number(cell: &str, height: bool) -> Result<f64, String> {
    let value: f64 = cell
        .trim()
        .parse()
        .map_err(|_| format!("'{}' is not a number", cell.trim()))?;
    if !value.is_finite() || (height && value.abs() > MAX_HEIGHT) {
        return Err(format!("{}: {}", cell.trim(), height_reason(value)));
    }
    Ok(value)
}

/// The surface of a CSV grid over an lx x ly cell [m] (ly unused for a single row).
pub fn read_csv(path: &Path, lx: f64, ly: f64) -> Result<Surface, ReadError> {
    csv(path, Source::Disk, lx, ly)
}

/// As [`read_csv`], from the file's text in memory (`path` names it in messages).
pub fn parse_csv(text: &str, path: &Path, lx: f64, ly: f64) -> Result<Surface, ReadError> {
    csv(path, Source::Text(text), lx, ly)
}

fn csv(path: &Path, source: Source, lx: f64, ly: f64) -> Result<Surface, ReadError> {
    let mut heights = Vec::new();
    let (mut nx, mut ny) = (0, 0);
    let last = each_line(path, source, |_, line| {
        let start = heights.len();
        for cell in line.split(',') {
            heights.push(number(cell, true)?);
            if heights.len() - start > MAX_SIDE_1D {
                return Err(format!("a row of more than {MAX_SIDE_1D} heights"));
            }
        }
        let width = heights.len() - start;
        if ny > 0 && width != nx {
            return Err(format!(
                "this row has {width} values and the first row {nx}: every row needs one value per x grid line"
            ));
        }
        nx = width;
        ny += 1;
        if ny > 1 && (nx > MAX_SIDE_2D || ny > MAX_SIDE_2D) {
            return Err(format!(
                "a map larger than {MAX_SIDE_2D} x {MAX_SIDE_2D} (rows of {nx} values, {ny} rows so far)"
            ));
        }
        Ok(())
    })?;
    if ny == 0 {
        return Err(whole(
            path,
            "no heights (the file is empty or only comments)",
        ));
    }
    Surface::new(nx, ny, lx, ly, heights).map_err(|reason| ReadError {
        path: path.display().to_string(),
        line: last,
        reason,
    })
}

/// The surface of an `x y z` file (columns separated by spaces, tabs or commas, in metres) whose
/// points fill a regular grid, each node once, in any order. The cell is nx dx x ny dy.
pub fn read_xyz(path: &Path) -> Result<Surface, ReadError> {
    let mut points: Vec<[f64; 3]> = Vec::new();
    let limit = MAX_SIDE_2D * MAX_SIDE_2D;
    let last = each_line(path, Source::Disk, |_, line| {
        let cells: Vec<&str> = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|c| !c.is_empty())
            .collect();
        if cells.len() != 3 {
            return Err(format!("{} columns; an x y z line has 3", cells.len()));
        }
        points.push([
            number(cells[0], false)?,
            number(cells[1], false)?,
            number(cells[2], true)?,
        ]);
        if points.len() > limit {
            return Err(format!(
                "more than {limit} points ({MAX_SIDE_2D} x {MAX_SIDE_2D})"
            ));
        }
        Ok(())
    })?;
    if points.is_empty() {
        return Err(whole(
            path,
            "no points (the file is empty or only comments)",
        ));
    }
    let fail = |reason: String| ReadError {
        path: path.display().to_string(),
        line: last,
        reason,
    };
    let (x0, dx, nx) = axis(points.iter().map(|p| p[0])).map_err(|r| fail(format!("x: {r}")))?;
    let (y0, dy, ny) = axis(points.iter().map(|p| p[1])).map_err(|r| fail(format!("y: {r}")))?;
    super::check_grid(nx, ny).map_err(&fail)?;
    if nx * ny != points.len() {
        return Err(fail(format!(
            "{} points do not fill the {nx} x {ny} grid of their coordinates once each",
            points.len()
        )));
    }
    let mut heights = vec![f64::NAN; nx * ny];
    for p in &points {
        let i = ((p[0] - x0) / dx).round() as usize;
        let j = if ny > 1 {
            ((p[1] - y0) / dy).round() as usize
        } else {
            0
        };
        let slot = &mut heights[j * nx + i];
        if !slot.is_nan() {
            return Err(fail(format!(
                "the node x = {}, y = {} is given twice",
                p[0], p[1]
            )));
        }
        *slot = p[2];
    }
    let ly = if ny > 1 { ny as f64 * dy } else { 0.0 };
    Surface::new(nx, ny, nx as f64 * dx, ly, heights).map_err(fail)
}

/// The first coordinate, the spacing and the node count of one axis of a regular grid.
fn axis(values: impl Iterator<Item = f64>) -> Result<(f64, f64, usize), String> {
    let mut sorted: Vec<f64> = values.collect();
    sorted.sort_by(f64::total_cmp);
    let (first, last) = (sorted[0], sorted[sorted.len() - 1]);
    let tolerance = 1e-9 * (last - first).abs().max(first.abs()).max(f64::MIN_POSITIVE);
    sorted.dedup_by(|a, b| (*a - *b).abs() <= tolerance);
    let n = sorted.len();
    if n == 1 {
        return Ok((first, 1.0, 1));
    }
    let step = (last - first) / (n - 1) as f64;
    match sorted
        .windows(2)
        .find(|w| ((w[1] - w[0]) - step).abs() > 1e-6 * step)
    {
        Some(w) => Err(format!(
            "the coordinates are not on a regular grid (a step of {} beside the mean step {step})",
            w[1] - w[0]
        )),
        None => Ok((first, step, n)),
    }
}

fn whole(path: &Path, reason: &str) -> ReadError {
    ReadError {
        path: path.display().to_string(),
        line: 0,
        reason: reason.into(),
    }
}
