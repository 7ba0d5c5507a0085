//! The text of a data file as a table: `#` notes, the header's cells as `name [unit]`, and the
//! rows of cells with their line numbers, read through a size bound so that a huge file is
//! refused without being read.

use std::fs::File;
use std::io::{BufRead, BufReader, Read};
use std::path::Path;

use super::DataError;

/// Largest data file read [bytes]: 16 MiB holds about half a million rows of three columns,
/// far more than a lab's measurement.
pub const MAX_FILE_BYTES: u64 = 16 * 1024 * 1024;

/// Most rows of a data file: each row is one solve of the model per evaluation of a fit.
pub const MAX_ROWS: usize = 100_000;

/// A header cell: the name and the unit as written (`[-]` for a number without unit).
#[derive(Clone, Debug, PartialEq)]
pub struct Heading {
    /// The quantity's name, trimmed.
    pub name: String,
    /// The unit between the brackets, trimmed.
    pub unit: String,
}

/// A data file split into its parts.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// The text of each `#` line, without the `#`.
    pub notes: Vec<String>,
    /// The header line's number and cells.
    pub header: (usize, Vec<Heading>),
    /// Each row's line number and cells, trimmed.
    pub rows: Vec<(usize, Vec<String>)>,
}

fn heading(cell: &str, column: usize) -> Result<Heading, String> {
    let cell = cell.trim();
    let unit_missing = || {
        format!(
            "column {column}, '{cell}', has no unit: write `name [unit]`, e.g. `load [N/m]` or \
             `mu [-]` for a number without unit"
        )
    };
    let (name, rest) = cell.split_once('[').ok_or_else(unit_missing)?;
    let unit = rest.strip_suffix(']').ok_or_else(unit_missing)?;
    if name.trim().is_empty() {
        return Err(format!(
            "column {column}, '{cell}', has no name before its unit"
        ));
    }
    Ok(Heading {
        name: name.trim().to_string(),
        unit: unit.trim().to_string(),
    })
}

/// The refusal of a file of `size` bytes, larger than a data file may be.
fn too_large(path: &Path, size: u64) -> DataError {
    DataError::new(
        path,
        0,
        format!(
            "the file is {size} bytes, more than the {MAX_FILE_BYTES} a data file may have \
             ({MAX_ROWS} rows at most): thin the measurement or split the file"
        ),
    )
}

/// Reads `path` into a table: at least a header and one row, every row as wide as the header.
pub fn read(path: &Path) -> Result<Table, DataError> {
    let file =
        File::open(path).map_err(|e| DataError::new(path, 0, format!("cannot be read: {e}")))?;
    let size = file.metadata().map(|m| m.len()).unwrap_or(0);
    if size > MAX_FILE_BYTES {
        return Err(too_large(path, size));
    }
    lines(path, BufReader::new(file.take(MAX_FILE_BYTES + 1)))
}

/// A data file's text read into a table as `read` reads the file (`path` names it in
/// messages): a bundled data file.
pub fn read_text(path: &Path, text: &str) -> Result<Table, DataError> {
    if text.len() as u64 > MAX_FILE_BYTES {
        return Err(too_large(path, text.len() as u64));
    }
    lines(path, text.as_bytes())
}

/// The table of the lines `reader` gives, at most `MAX_FILE_BYTES` of them.
fn lines(path: &Path, mut reader: impl BufRead) -> Result<Table, DataError> {
    let error = |line: usize, reason: String| DataError::new(path, line, reason);
    let mut notes = Vec::new();
    let mut header: Option<(usize, Vec<Heading>)> = None;
    let mut rows = Vec::new();
    let mut text = String::new();
    let mut number = 0;
    let mut bytes = 0u64;
    loop {
        text.clear();
        let read = reader
            .read_line(&mut text)
            .map_err(|e| error(number + 1, format!("cannot be read as text: {e}")))?;
        if read == 0 {
            break;
        }
        number += 1;
        bytes += read as u64;
        if bytes > MAX_FILE_BYTES {
            return Err(error(
                number,
                format!("the file grows past the {MAX_FILE_BYTES} bytes a data file may have"),
            ));
        }
        // a byte-order mark, as spreadsheets write one, is no part of the first name
        let line = text.trim().trim_start_matches('\u{feff}');
        if let Some(note) = line.strip_prefix('#') {
            notes.push(note.trim().to_string());
            continue;
        }
        if line.is_empty() {
            continue;
        }
        let cells = line.split(',');
        match &header {
            None => {
                let cells = cells
                    .enumerate()
                    .map(|(i, c)| heading(c, i + 1))
                    .collect::<Result<Vec<_>, _>>()
                    .map_err(|why| error(number, why))?;
                if cells.len() < 2 {
                    return Err(error(
                        number,
                        "the header names one column: a data file has the x column and at \
                         least one measured column, e.g. `load [N/m],mu [-]`"
                            .into(),
                    ));
                }
                header = Some((number, cells));
            }
            Some((_, names)) => {
                let cells: Vec<String> = cells.map(|c| c.trim().to_string()).collect();
                if cells.len() != names.len() {
                    return Err(error(
                        number,
                        format!(
                            "{} values, but the header names {} columns",
                            cells.len(),
                            names.len()
                        ),
                    ));
                }
                if rows.len() == MAX_ROWS {
                    return Err(error(
                        number,
                        format!("more than {MAX_ROWS} rows: thin the measurement"),
                    ));
                }
                rows.push((number, cells));
            }
        }
    }
    let Some(header) = header else {
        return Err(error(
            number.max(1),
            "empty: a data file has a header `quantity [unit],...` (e.g. `load [N/m],mu [-]`) \
             and one row per measurement"
                .into(),
        ));
    };
    if rows.is_empty() {
        return Err(error(
            header.0,
            "the header is not followed by any row of measurements".into(),
        ));
    }
    Ok(Table {
        notes,
        header,
        rows,
    })
}
