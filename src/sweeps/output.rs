//! The rows of a sweep as CSV or JSON (`wearlab sweep --format`). Numbers are written in the
//! shortest form that reads back to the same bits (`{:e}` in CSV, as `wearlab solve --format csv`
//! does; serde_json's in JSON, as `wearlab solve` does); flags as true/false. A field is empty
//! (JSON null) only where its row's `status` says why; `status` is "ok" otherwise. A stopped sweep
//! (`Err` among the rows) ends the writing with an error where it was stopped: the text is then
//! cut short (a JSON document left open), never a whole answer.

use std::cell::RefCell;
use std::io::{self, Write};

use serde::ser::{Error as _, Serialize, SerializeMap, SerializeSeq, Serializer};

use crate::physics::Spacing;
use crate::physics::spatial::partial::running_in::Stopped;
use crate::preset::{Preset, Problem};
use crate::sweeps::axis::Axis;
use crate::sweeps::quantity::QuantityKey;
use crate::sweeps::sweep::Row;

fn cell(q: &QuantityKey, v: &Result<f64, String>) -> String {
    match v {
        Ok(v) if q.quantity().flag => (*v != 0.0).to_string(),
        Ok(v) => format!("{v:e}"),
        Err(_) => String::new(),
    }
}

fn quoted(text: &str) -> String {
    if text.contains([',', '"', '\n']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// CSV: a header of the varied keys, the outputs and `status`, then one line per row, each
/// written as soon as `rows` gives it.
pub fn write_csv(
    out: &mut impl Write,
    axes: &[Axis],
    outputs: &[QuantityKey],
    rows: impl Iterator<Item = Result<Row, Stopped>>,
) -> io::Result<()> {
    let mut header: Vec<String> = axes.iter().map(|a| a.key.to_string()).collect();
    header.extend(outputs.iter().map(|q| q.to_string()));
    header.push("status".into());
    writeln!(out, "{}", header.join(","))?;
    for row in rows {
        let row = row.map_err(io::Error::other)?;
        let mut fields: Vec<String> = row.at.iter().map(|v| format!("{v:e}")).collect();
        fields.extend(outputs.iter().zip(&row.values).map(|(q, v)| cell(q, v)));
        fields.push(quoted(&row.status()));
        writeln!(out, "{}", fields.join(","))?;
    }
    Ok(())
}

struct JsonRow<'a> {
    axes: &'a [Axis],
    outputs: &'a [QuantityKey],
    row: &'a Row,
}

impl Serialize for JsonRow<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(None)?;
        for (axis, v) in self.axes.iter().zip(&self.row.at) {
            map.serialize_entry(&axis.key.to_string(), v)?;
        }
        for (q, v) in self.outputs.iter().zip(&self.row.values) {
            let name = q.to_string();
            match v {
                Ok(v) if q.quantity().flag => map.serialize_entry(&name, &(*v != 0.0))?,
                Ok(v) => map.serialize_entry(&name, v)?,
                Err(_) => map.serialize_entry(&name, &())?,
            }
        }
        map.serialize_entry("status", &self.row.status())?;
        map.end()
    }
}

/// The rows of a JSON document, serialized one by one as the iterator gives them.
struct JsonRows<'a, I> {
    axes: &'a [Axis],
    outputs: &'a [QuantityKey],
    rows: RefCell<I>,
}

impl<I: Iterator<Item = Result<Row, Stopped>>> Serialize for JsonRows<'_, I> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut seq = s.serialize_seq(None)?;
        for row in self.rows.borrow_mut().by_ref() {
            let row = row.map_err(S::Error::custom)?;
            seq.serialize_element(&JsonRow {
                axes: self.axes,
                outputs: self.outputs,
                row: &row,
            })?;
        }
        seq.end()
    }
}

#[derive(serde::Serialize)]
struct Vary {
    key: String,
    from: f64,
    to: f64,
    points: usize,
    scale: Spacing,
}

#[derive(serde::Serialize)]
struct Column {
    name: String,
    unit: &'static str,
    description: &'static str,
}

#[derive(serde::Serialize)]
struct Document<R> {
    problem: Problem,
    #[serde(skip_serializing_if = "Option::is_none")]
    model: Option<&'static str>,
    vary: Vec<Vary>,
    outputs: Vec<Column>,
    rows: R,
}

/// JSON: the problem (and plane model), the varied ranges, the outputs with their units and
/// descriptions, and the rows as objects keyed by the varied keys, the outputs and `status`, each
/// written as soon as `rows` gives it.
pub fn write_json(
    out: &mut impl Write,
    preset: &Preset,
    axes: &[Axis],
    outputs: &[QuantityKey],
    rows: impl Iterator<Item = Result<Row, Stopped>>,
) -> io::Result<()> {
    let doc = Document {
        problem: preset.problem,
        model: (preset.problem == Problem::Plane).then(|| preset.plane.model.name()),
        vary: axes
            .iter()
            .map(|a| Vary {
                key: a.key.to_string(),
                from: a.range.min,
                to: a.range.max,
                points: a.range.points,
                scale: a.range.spacing,
            })
            .collect(),
        outputs: outputs
            .iter()
            .map(|q| Column {
                name: q.to_string(),
                unit: q.quantity().unit,
                description: q.quantity().description,
            })
            .collect(),
        rows: JsonRows {
            axes,
            outputs,
            rows: RefCell::new(rows),
        },
    };
    serde_json::to_writer_pretty(&mut *out, &doc)?;
    writeln!(out)
}
