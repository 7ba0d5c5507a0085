//! Measured data files: CSV with a header naming each column's quantity and unit
//! (`load [N/m],mu [-]`), optional uncertainty columns (`mu sd [-]`, one standard deviation) and
//! `#` lines kept as notes. The first column is the x axis, a parameter the program can vary
//! (`names::parameter`); every other column a quantity it computes (`names::quantity`) or the
//! uncertainty of one. Values are read in the header's unit through `units::parse_si` and held in
//! SI units. Every refusal is `path:line: reason`.

pub mod names;
pub mod table;

use std::fmt;
use std::path::Path;

use crate::preset::{Key, Preset};
use crate::sweeps::QuantityKey;
use crate::units::{is_prefix, parse_si};

use table::Heading;

/// Why a data file was refused: `path:line: reason` (line 0: the file as a whole).
#[derive(Clone, Debug, PartialEq)]
pub struct DataError {
    /// The file as given.
    pub path: String,
    /// 1-based line, or 0 for the whole file.
    pub line: usize,
    /// What is wrong, for the user.
    pub reason: String,
}

impl DataError {
    fn new(path: &Path, line: usize, reason: String) -> DataError {
        DataError {
            path: path.display().to_string(),
            line,
            reason,
        }
    }
}

impl fmt::Display for DataError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "{}: {}", self.path, self.reason)
        } else {
            write!(f, "{}:{}: {}", self.path, self.line, self.reason)
        }
    }
}

impl std::error::Error for DataError {}

/// The x column: a parameter of the preset and its values [the parameter's SI unit].
#[derive(Clone, Debug, PartialEq)]
pub struct Abscissa {
    /// The parameter.
    pub key: Key,
    /// The header cell as written.
    pub heading: String,
    /// One value per row, in the parameter's SI unit.
    pub values: Vec<f64>,
}

/// A measured column: a quantity, its values and, where the file gives them, their standard
/// deviations (both in the quantity's SI unit).
#[derive(Clone, Debug, PartialEq)]
pub struct Measured {
    /// The quantity.
    pub quantity: QuantityKey,
    /// The header cell as written.
    pub heading: String,
    /// One value per row, in the quantity's SI unit.
    pub values: Vec<f64>,
    /// One standard deviation per row (> 0), from the `<name> sd [unit]` column.
    pub sd: Option<Vec<f64>>,
}

/// A data file read for a preset.
#[derive(Clone, Debug, PartialEq)]
pub struct DataSet {
    /// The file as given.
    pub path: String,
    /// The `#` lines, in order.
    pub notes: Vec<String>,
    /// The x column.
    pub x: Abscissa,
    /// The measured columns, in file order.
    pub measured: Vec<Measured>,
    /// The line number of each row.
    pub lines: Vec<usize>,
}

impl DataSet {
    /// The number of rows.
    pub fn len(&self) -> usize {
        self.lines.len()
    }

    /// True when the set has no row (a file read by `read` always has one).
    pub fn is_empty(&self) -> bool {
        self.lines.is_empty()
    }
}

/// Whether `written` is a unit of a quantity whose SI unit is `si` (`[-]` or `[1]` or `[]` for a
/// number without unit; a prefixed or alternative unit otherwise), and Err with what to write.
fn check_unit(written: &str, si: &str, name: &str) -> Result<(), String> {
    let plain = matches!(written, "" | "-" | "1");
    let fits = if si.is_empty() {
        plain
    } else {
        !(plain || (written != si && is_prefix(written)))
            && parse_si(&format!("1 {written}"), si).is_ok()
    };
    if fits {
        return Ok(());
    }
    Err(if si.is_empty() {
        format!("'{name}' is a number without unit: write [-], not [{written}]")
    } else {
        format!(
            "unknown unit [{written}] for '{name}', whose unit is {si}: write [{si}] or a prefixed {si}"
        )
    })
}

/// A cell read in the header's unit, in SI units; finite.
fn value(cell: &str, written: &str, si: &str) -> Result<f64, String> {
    let text = if si.is_empty() {
        cell.to_string()
    } else {
        format!("{cell} {written}")
    };
    let v = if cell.is_empty() {
        Err("empty".to_string())
    } else {
        parse_si(&text, si)
    };
    match v {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(v) => Err(format!("{v} is not a measurement (a finite number)")),
        Err(_) => Err(format!("'{cell}' is not a number")),
    }
}

/// What a column is.
enum Role {
    X(Key),
    Measured(QuantityKey),
    Sd(QuantityKey),
}

fn role(preset: &Preset, column: usize, h: &Heading) -> Result<Role, String> {
    if column == 0 {
        return names::parameter(preset, &h.name).map(Role::X);
    }
    let sd_of = h
        .name
        .strip_suffix(" sd")
        .or_else(|| h.name.strip_suffix(" SD"));
    match sd_of {
        Some(base) => names::quantity(preset, base.trim()).map(Role::Sd),
        None => names::quantity(preset, &h.name).map(Role::Measured),
    }
}

fn si_unit(role: &Role) -> &'static str {
    match role {
        Role::X(key) => key.param().unit,
        Role::Measured(q) | Role::Sd(q) => q.quantity().unit,
    }
}

/// Reads a data file for a preset: the x column a parameter of its problem, each other column a
/// quantity of its problem and model or the `sd` of one, every value finite and in its unit, the
/// x values allowed by the parameter's limit, every sd > 0.
pub fn read(path: &Path, preset: &Preset) -> Result<DataSet, DataError> {
    of_table(path, table::read(path)?, preset)
}

/// Reads a data file's text as `read` reads the file (`path` names it): a bundled data file.
pub fn read_text(path: &Path, text: &str, preset: &Preset) -> Result<DataSet, DataError> {
    of_table(path, table::read_text(path, text)?, preset)
}

/// The data set of a table read from `path`, for a preset (`read`'s checks).
fn of_table(path: &Path, t: table::Table, preset: &Preset) -> Result<DataSet, DataError> {
    let (header_line, headings) = (t.header.0, t.header.1.clone());
    let error = |line: usize, reason: String| DataError::new(path, line, reason);
    let roles = headings
        .iter()
        .enumerate()
        .map(|(i, h)| {
            let r = role(preset, i, h)?;
            check_unit(&h.unit, si_unit(&r), &h.name)?;
            Ok(r)
        })
        .collect::<Result<Vec<Role>, String>>()
        .map_err(|why| error(header_line, why))?;
    let mut columns: Vec<Vec<f64>> = vec![Vec::with_capacity(t.rows.len()); roles.len()];
    for (line, cells) in &t.rows {
        for (i, cell) in cells.iter().enumerate() {
            let h = &headings[i];
            let v = value(cell, &h.unit, si_unit(&roles[i]))
                .map_err(|why| error(*line, format!("{} = {why}", h.name)))?;
            match &roles[i] {
                Role::X(key) => {
                    if let Some(limit) = key.param().limit() {
                        limit
                            .check(&format!("{} = {key}", h.name), v)
                            .map_err(|why| error(*line, why))?;
                    }
                }
                Role::Sd(_) if v <= 0.0 => {
                    return Err(error(
                        *line,
                        format!("{} = {cell}: a standard deviation is > 0", h.name),
                    ));
                }
                _ => {}
            }
            columns[i].push(v);
        }
    }
    assemble(path, t, roles, headings, columns)
}

/// The data set from the columns read: the measured columns with their sd, each quantity once.
fn assemble(
    path: &Path,
    t: table::Table,
    roles: Vec<Role>,
    headings: Vec<Heading>,
    mut columns: Vec<Vec<f64>>,
) -> Result<DataSet, DataError> {
    let line = t.header.0;
    let error = |reason: String| DataError::new(path, line, reason);
    let Role::X(key) = roles[0] else {
        return Err(error("the first column is not the x axis".into()));
    };
    let mut measured: Vec<Measured> = Vec::new();
    for (i, r) in roles.iter().enumerate() {
        if let Role::Measured(q) = r {
            if measured.iter().any(|m| m.quantity == *q) {
                return Err(error(format!("two columns measure {q}: keep one")));
            }
            measured.push(Measured {
                quantity: *q,
                heading: headings[i].name.clone(),
                values: std::mem::take(&mut columns[i]),
                sd: None,
            });
        }
    }
    if measured.is_empty() {
        return Err(error(
            "no measured column: after the x column, a quantity such as `mu [-]`".into(),
        ));
    }
    for (i, r) in roles.iter().enumerate() {
        if let Role::Sd(q) = r {
            let m = measured
                .iter_mut()
                .find(|m| m.quantity == *q)
                .ok_or_else(|| {
                    error(format!(
                        "'{}' is the uncertainty of {q}, which no column measures",
                        headings[i].name
                    ))
                })?;
            if m.sd.is_some() {
                return Err(error(format!("two sd columns for {q}: keep one")));
            }
            m.sd = Some(std::mem::take(&mut columns[i]));
        }
    }
    Ok(DataSet {
        path: path.display().to_string(),
        notes: t.notes,
        x: Abscissa {
            key,
            heading: headings[0].name.clone(),
            values: std::mem::take(&mut columns[0]),
        },
        measured,
        lines: t.rows.iter().map(|(l, _)| *l).collect(),
    })
}

#[cfg(test)]
mod tests;
