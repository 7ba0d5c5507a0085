use std::io::Write;

use super::*;
use crate::preset::default_preset;

fn file(text: &str) -> tempfile::NamedTempFile {
    let mut f = tempfile::NamedTempFile::new().unwrap();
    f.write_all(text.as_bytes()).unwrap();
    f
}

fn read_text(text: &str) -> Result<DataSet, DataError> {
    let f = file(text);
    read(f.path(), &default_preset())
}

fn refusal(text: &str) -> DataError {
    read_text(text).expect_err("refused")
}

#[test]
fn reads_columns_in_si_units_with_notes_and_sd() {
    let set = read_text(
        "# synthetic: made by the model\n\
         load [kN/m],mu [-],mu sd [-],contact width [mm]\n\
         \n\
         1,0.30,0.002,1.5\n\
         2.5,0.29,0.002,2\n",
    )
    .unwrap();
    assert_eq!(set.notes, vec!["synthetic: made by the model"]);
    assert_eq!(set.x.key.to_string(), "plane.load");
    // "2.5 kN/m" is read as one decimal: exactly the literal 2500
    assert_eq!(set.x.values, vec![1000.0, 2500.0]);
    assert_eq!(set.measured.len(), 2);
    assert_eq!(set.measured[0].quantity.to_string(), "mu_star");
    assert_eq!(set.measured[0].values, vec![0.30, 0.29]);
    assert_eq!(set.measured[0].sd, Some(vec![0.002, 0.002]));
    assert_eq!(set.measured[1].quantity.to_string(), "contact_width");
    assert_eq!(set.measured[1].values, vec![1.5e-3, 2e-3]);
    assert_eq!(set.measured[1].sd, None);
    assert_eq!(set.lines, vec![4, 5]);
}

#[test]
fn names_keys_symbols_and_words_alike() {
    for x in ["plane.load", "P", "load", "normal load"] {
        for y in ["mu_star", "mu*", "mu", "friction coefficient", "mu star"] {
            let set = read_text(&format!("{x} [N/m],{y} [-]\n1e3,0.3\n")).unwrap();
            assert_eq!(set.x.key.to_string(), "plane.load", "{x}");
            assert_eq!(set.measured[0].quantity.to_string(), "mu_star", "{y}");
        }
    }
}

#[test]
fn ragged_rows_name_their_line() {
    let e = refusal("load [N/m],mu [-]\n1e3,0.3\n2e3\n");
    assert_eq!(e.line, 3);
    assert!(e.reason.contains("1 values, but the header names 2"), "{e}");
    assert!(
        e.to_string()
            .ends_with(":3: 1 values, but the header names 2 columns"),
        "{e}"
    );
}

#[test]
fn unknown_units_are_refused_at_the_header() {
    let e = refusal("# a note\nload [N/m],contact width [furlong]\n1e3,0.3\n");
    assert_eq!(e.line, 2);
    assert!(e.reason.contains("unknown unit [furlong]"), "{e}");
    assert!(e.reason.contains("write [m]"), "{e}");
    let e = refusal("load [N],mu [-]\n1e3,0.3\n");
    assert!(e.reason.contains("unknown unit [N] for 'load'"), "{e}");
    let e = refusal("load [N/m],mu [um]\n1e3,0.3\n");
    assert!(e.reason.contains("write [-]"), "{e}");
    let e = refusal("load [k],mu [-]\n1e3,0.3\n");
    assert!(e.reason.contains("unknown unit [k]"), "{e}");
    let e = refusal("load,mu [-]\n1e3,0.3\n");
    assert!(e.reason.contains("has no unit"), "{e}");
}

#[test]
fn nan_and_text_are_refused_where_they_stand() {
    let e = refusal("load [N/m],mu [-]\n1e3,NaN\n2e3,NaN\n");
    assert_eq!(
        (e.line, e.reason.as_str()),
        (2, "mu = NaN is not a measurement (a finite number)")
    );
    let e = refusal("load [N/m],mu [-]\n1e3,0.3\n2e3,inf\n");
    assert_eq!(e.line, 3);
    let e = refusal("load [N/m],mu [-]\n1e3,abc\n");
    assert_eq!(
        (e.line, e.reason.as_str()),
        (2, "mu = 'abc' is not a number")
    );
    let e = refusal("load [N/m],mu [-]\n1e3,\n");
    assert!(e.reason.contains("'' is not a number"), "{e}");
}

#[test]
fn empty_files_and_headers_alone_are_refused() {
    let e = refusal("");
    assert_eq!(e.line, 1);
    assert!(e.reason.starts_with("empty"), "{e}");
    let e = refusal("# only notes\n\n");
    assert!(e.reason.starts_with("empty"), "{e}");
    let e = refusal("# a note\nload [N/m],mu [-]\n");
    assert_eq!(e.line, 2);
    assert!(e.reason.contains("not followed by any row"), "{e}");
    let e = refusal("load [N/m]\n1e3\n");
    assert!(e.reason.contains("names one column"), "{e}");
}

#[test]
fn quantities_the_program_does_not_compute_are_named_with_those_it_does() {
    let e = refusal("load [N/m],colour [-]\n1e3,0.3\n");
    assert_eq!(e.line, 1);
    assert!(e.reason.contains("'colour' matches no quantity"), "{e}");
    assert!(e.reason.contains("mu (mu_star)"), "{e}");
    assert!(e.reason.contains("contact width (contact_width)"), "{e}");
    let e = refusal("sliding distance [m],mu [-]\n1,0.3\n");
    assert!(
        e.reason.contains("names no parameter the program can vary"),
        "{e}"
    );
    assert!(e.reason.contains("load (plane.load)"), "{e}");
    let e = refusal("plane.model [-],mu [-]\n1,0.3\n");
    assert!(
        e.reason.contains("not a number the program can vary"),
        "{e}"
    );
}

#[test]
fn sd_columns_belong_to_a_measured_column_and_are_positive() {
    let e = refusal("load [N/m],a [m],mu sd [-]\n1e3,1e-3,0.002\n");
    assert!(e.reason.contains("which no column measures"), "{e}");
    let e = refusal("load [N/m],mu [-],mu sd [-]\n1e3,0.3,0\n");
    assert_eq!(e.line, 2);
    assert!(e.reason.contains("a standard deviation is > 0"), "{e}");
    let e = refusal("load [N/m],mu [-],mu* [-]\n1e3,0.3,0.3\n");
    assert!(e.reason.contains("two columns measure mu_star"), "{e}");
}

#[test]
fn x_values_outside_the_parameter_range_are_refused() {
    let e = refusal("load [N/m],mu [-]\n1e3,0.3\n-5,0.3\n");
    assert_eq!(e.line, 3);
    assert!(e.reason.contains("load = plane.load"), "{e}");
}

#[test]
fn a_huge_file_is_refused_without_reading_it() {
    let f = file("load [N/m],mu [-]\n1e3,0.3\n");
    // a sparse 1 GB file: refused from its size
    f.as_file().set_len(1 << 30).unwrap();
    let start = std::time::Instant::now();
    let e = read(f.path(), &default_preset()).unwrap_err();
    assert_eq!(e.line, 0);
    assert!(e.reason.contains("1073741824 bytes, more than the"), "{e}");
    assert!(start.elapsed().as_secs_f64() < 1.0);
}

#[test]
fn a_missing_file_says_so() {
    let e = read(Path::new("/nonexistent/data.csv"), &default_preset()).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("/nonexistent/data.csv: cannot be read"),
        "{e}"
    );
}

#[test]
fn a_byte_order_mark_is_no_part_of_the_first_name() {
    let set = read_text("\u{feff}load [N/m],mu [-]\n1e3,0.3\n").unwrap();
    assert_eq!(set.x.key.to_string(), "plane.load");
}
