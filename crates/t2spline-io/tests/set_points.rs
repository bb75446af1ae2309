//! Query-point files (`t2spline membership`): what they hold, and every kind of
//! problem named by its line and column.

use t2spline_io::set::{parse_points, read_points, QueryPoints};
use t2spline_io::Error;

fn problems(text: &str) -> Vec<String> {
    match parse_points(text, "p.csv") {
        Err(e @ Error::Invalid { .. }) => e.lines(),
        other => panic!("expected a problem, got {other:?}"),
    }
}

#[test]
fn points_in_file_order_in_two_and_three_dimensions() {
    let p = parse_points("x,y\n3,4\n-1.5,2e3\n0,0\n", "p.csv").unwrap();
    assert_eq!(
        p,
        QueryPoints::Plane(vec![[3.0, 4.0], [-1.5, 2000.0], [0.0, 0.0]])
    );
    assert_eq!((p.dimension(), p.len(), p.is_empty()), (2, 3, false));
    let q = parse_points("X, Y ,z\r\n1,2,3\r\n", "p.csv").unwrap();
    assert_eq!(q, QueryPoints::Space(vec![[1.0, 2.0, 3.0]]));
    assert_eq!(q.dimension(), 3);
}

#[test]
fn a_byte_order_mark_and_semicolons_with_decimal_commas_are_read() {
    let p = parse_points("\u{feff}x;y\n1,5;2,25\n3;4\n", "p.csv").unwrap();
    assert_eq!(p, QueryPoints::Plane(vec![[1.5, 2.25], [3.0, 4.0]]));
}

#[test]
fn a_word_nan_and_infinity_are_not_numbers() {
    assert_eq!(
        problems("x,y\n1,2\n3,two\nnan,4\n5,-inf\n"),
        [
            "p.csv:3:3: y (column 2): `two` is not a number",
            "p.csv:4:1: x (column 1): `nan` is not a number",
            "p.csv:5:3: y (column 2): `-inf` is not a number",
        ]
    );
}

#[test]
fn numbers_beyond_the_limit_and_empty_fields() {
    assert_eq!(
        problems("x,y\n1e151,2\n3,\n4,1e999\n"),
        [
            "p.csv:2:1: x (column 1): 1e151 is outside [-1e150, 1e150]",
            "p.csv:3:3: y (column 2): empty; every coordinate needs a number",
            "p.csv:4:3: y (column 2): `1e999` is outside [-1e150, 1e150]",
        ]
    );
}

#[test]
fn missing_and_extra_columns() {
    assert_eq!(
        problems("x,y,z\n1,2\n1,2,3,4\n"),
        [
            "p.csv:2:4: z (column 3) is missing; every row has x,y,z",
            "p.csv:3:7: column 4 is one too many; every row has x,y,z",
        ]
    );
}

#[test]
fn the_header_must_name_the_axes() {
    for header in ["x,z", "y,x", "x", "x,y,z,w", "1,2"] {
        assert_eq!(
            problems(&format!("{header}\n1,2\n")),
            [format!(
                "p.csv:1:1: the header must be x,y or x,y,z, not `{header}`"
            )],
            "{header}"
        );
    }
}

#[test]
fn an_empty_file_and_a_file_without_points() {
    assert_eq!(
        problems(""),
        ["p.csv: empty: the first line must be the header x,y (or x,y,z)"]
    );
    assert_eq!(
        problems("x,y\n"),
        ["p.csv: no points: after the header, one point per row is needed"]
    );
}

#[test]
fn an_unclosed_quote_is_named() {
    let lines = problems("x,y\n1,\"2\n");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(lines[0].starts_with("p.csv:2:3: "), "{lines:?}");
}

#[test]
fn many_problems_are_listed_up_to_twenty_then_counted() {
    let text = format!("x,y\n{}", "a,b\n".repeat(30));
    let lines = problems(&text);
    assert_eq!(lines.len(), 21, "{lines:?}");
    assert_eq!(
        lines[20],
        "p.csv: … and 40 more problems (only the first 20 are listed)"
    );
}

#[test]
fn control_characters_in_a_bad_header_are_made_printable() {
    let lines = problems("x,\u{1b}[31my\n1,2\n");
    assert_eq!(lines.len(), 1);
    assert!(!lines[0].contains('\u{1b}'), "{lines:?}");
}

#[test]
fn reading_a_missing_file_is_a_read_error() {
    let e = read_points(std::path::Path::new("no/such/points.csv")).unwrap_err();
    assert!(!matches!(e, Error::Invalid { .. }), "{e:?}");
    assert!(e.lines()[0].starts_with("no/such/points.csv: "), "{e:?}");
}
