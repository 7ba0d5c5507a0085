//! The last line of defence of the reports: every number a report holds must be finite. JSON has
//! no NaN or infinity (serde_json writes them as null, which the contract reserves for "no such
//! value"), so a report is walked before it is printed and the first non-finite number is an
//! error that names where it is (e.g. `sweep.load[3] = NaN`).

use std::fmt;

use serde::Serialize;
use serde::ser;

/// Where a non-finite number sits in a report, and its value.
#[derive(Clone, Debug, PartialEq)]
pub struct NonFinite {
    /// The path of the value, e.g. `profile.pressure[7]`.
    pub path: String,
    /// The value (NaN or +-inf).
    pub value: f64,
}

impl fmt::Display for NonFinite {
    fn fmt(&self, out: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            out,
            "the result holds a number that is not finite: {} = {}",
            self.path, self.value
        )
    }
}

/// Ok when every floating-point number in `value` is finite.
pub fn check(value: &impl Serialize) -> Result<(), NonFinite> {
    let mut walker = Walker { path: Vec::new() };
    match value.serialize(&mut walker) {
        Ok(()) => Ok(()),
        Err(Found(Some(found))) => Err(found),
        // a serializer error from the value itself (not a number): nothing numeric to blame
        Err(Found(None)) => Ok(()),
    }
}

/// Ok when every cell of a table of `rows` rows and `header.len()` columns is finite, `cell(row,
/// column)` its value: the check of [`check_csv`] on the table before it is written as text (a
/// finite number is written as one), naming the same cell.
pub fn check_table(
    header: &[&str],
    rows: usize,
    cell: impl Fn(usize, usize) -> f64,
) -> Result<(), NonFinite> {
    for row in 0..rows {
        for (col, name) in header.iter().enumerate() {
            let value = cell(row, col);
            if !value.is_finite() {
                return Err(NonFinite {
                    path: format!("{name}[{row}]"),
                    value,
                });
            }
        }
    }
    Ok(())
}

/// Ok when no cell of the CSV text is a non-finite number (`NaN`, `inf`, `-inf`).
pub fn check_csv(text: &str) -> Result<(), NonFinite> {
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or("").split(',').collect();
    for (row, line) in lines.enumerate() {
        for (col, cell) in line.split(',').enumerate() {
            if let Ok(value) = cell.parse::<f64>()
                && !value.is_finite()
            {
                return Err(NonFinite {
                    path: format!("{}[{row}]", header.get(col).unwrap_or(&"column")),
                    value,
                });
            }
        }
    }
    Ok(())
}

#[derive(Debug)]
struct Found(Option<NonFinite>);

impl fmt::Display for Found {
    fn fmt(&self, out: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Some(found) => found.fmt(out),
            None => out.write_str("not a report"),
        }
    }
}

impl std::error::Error for Found {}

impl ser::Error for Found {
    fn custom<T: fmt::Display>(_: T) -> Self {
        Found(None)
    }
}

struct Walker {
    path: Vec<String>,
}

impl Walker {
    fn number(&mut self, v: f64) -> Result<(), Found> {
        if v.is_finite() {
            Ok(())
        } else {
            Err(Found(Some(NonFinite {
                path: self.path.concat().trim_start_matches('.').to_string(),
                value: v,
            })))
        }
    }

    fn at<T: Serialize + ?Sized>(&mut self, step: String, value: &T) -> Result<(), Found> {
        self.path.push(step);
        value.serialize(&mut *self)?;
        self.path.pop();
        Ok(())
    }
}

/// A sequence or map being walked: the index of the next element, the key of the next value.
struct Compound<'a> {
    walker: &'a mut Walker,
    index: usize,
    key: String,
}

macro_rules! ignore {
    ($($name:ident: $ty:ty),*) => {
        $(fn $name(self, _: $ty) -> Result<(), Found> { Ok(()) })*
    };
}

impl<'a> ser::Serializer for &'a mut Walker {
    type Ok = ();
    type Error = Found;
    type SerializeSeq = Compound<'a>;
    type SerializeTuple = Compound<'a>;
    type SerializeTupleStruct = Compound<'a>;
    type SerializeTupleVariant = Compound<'a>;
    type SerializeMap = Compound<'a>;
    type SerializeStruct = Compound<'a>;
    type SerializeStructVariant = Compound<'a>;

    ignore!(serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
        serialize_i64: i64, serialize_u8: u8, serialize_u16: u16, serialize_u32: u32,
        serialize_u64: u64, serialize_char: char, serialize_str: &str, serialize_bytes: &[u8],
        serialize_unit_struct: &'static str);

    fn serialize_f32(self, v: f32) -> Result<(), Found> {
        self.number(v.into())
    }
    fn serialize_f64(self, v: f64) -> Result<(), Found> {
        self.number(v)
    }
    fn serialize_none(self) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<(), Found> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        value: &T,
    ) -> Result<(), Found> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<(), Found> {
        self.at(format!(".{variant}"), value)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Compound<'a>, Found> {
        Ok(self.compound())
    }
    fn serialize_tuple(self, _: usize) -> Result<Compound<'a>, Found> {
        Ok(self.compound())
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, Found> {
        Ok(self.compound())
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, Found> {
        Ok(self.compound())
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Compound<'a>, Found> {
        Ok(self.compound())
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, Found> {
        Ok(self.compound())
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, Found> {
        Ok(self.compound())
    }
}

impl Walker {
    fn compound(&mut self) -> Compound<'_> {
        Compound {
            walker: self,
            index: 0,
            key: String::new(),
        }
    }
}

impl Compound<'_> {
    fn element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
        let step = format!("[{}]", self.index);
        self.index += 1;
        self.walker.at(step, value)
    }
    fn field<T: Serialize + ?Sized>(&mut self, key: &str, value: &T) -> Result<(), Found> {
        self.walker.at(format!(".{key}"), value)
    }
}

macro_rules! sequence {
    ($($trait:ident: $method:ident),*) => {$(
        impl ser::$trait for Compound<'_> {
            type Ok = ();
            type Error = Found;
            fn $method<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
                self.element(value)
            }
            fn end(self) -> Result<(), Found> {
                Ok(())
            }
        }
    )*};
}
sequence!(SerializeSeq: serialize_element, SerializeTuple: serialize_element,
    SerializeTupleStruct: serialize_field, SerializeTupleVariant: serialize_field);

macro_rules! fields {
    ($($trait:ident),*) => {$(
        impl ser::$trait for Compound<'_> {
            type Ok = ();
            type Error = Found;
            fn serialize_field<T: Serialize + ?Sized>(
                &mut self,
                key: &'static str,
                value: &T,
            ) -> Result<(), Found> {
                self.field(key, value)
            }
            fn end(self) -> Result<(), Found> {
                Ok(())
            }
        }
    )*};
}
fields!(SerializeStruct, SerializeStructVariant);

impl ser::SerializeMap for Compound<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), Found> {
        self.key = match serde_json::to_value(key) {
            Ok(serde_json::Value::String(text)) => text,
            Ok(other) => other.to_string(),
            Err(_) => "key".into(),
        };
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
        let key = std::mem::take(&mut self.key);
        self.field(&key, value)
    }
    fn end(self) -> Result<(), Found> {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Serialize)]
    struct Sweep {
        load: Vec<f64>,
        mu_star: Vec<Option<f64>>,
    }

    #[derive(Serialize)]
    struct Report {
        problem: &'static str,
        a: f64,
        theta: Option<f64>,
        sweep: Sweep,
    }

    fn report(load: f64) -> Report {
        Report {
            problem: "plane",
            a: 1.0,
            theta: None,
            sweep: Sweep {
                load: vec![1.0, 2.0, load],
                mu_star: vec![None, Some(0.3)],
            },
        }
    }

    #[test]
    fn names_the_first_non_finite_number() {
        assert_eq!(check(&report(3.0)), Ok(()));
        let err = check(&report(f64::NAN)).unwrap_err();
        assert_eq!(err.path, "sweep.load[2]");
        assert!(err.value.is_nan());
        let mut map = std::collections::BTreeMap::new();
        map.insert("p", f64::NEG_INFINITY);
        assert_eq!(check(&map).unwrap_err().path, "p");
    }

    #[test]
    fn csv_cells() {
        assert_eq!(check_csv("x,p\n1e0,2e0\n"), Ok(()));
        let err = check_csv("x,p\n1e0,2e0\n2e0,NaN\n").unwrap_err();
        assert_eq!(err.path, "p[1]");
        assert_eq!(check_csv("x,p\n1e0,inf\n").unwrap_err().path, "p[0]");
    }
}
