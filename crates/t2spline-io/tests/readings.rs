//! Readings files: every rule with its line and column, spreadsheet dialects,
//! limits before allocation, and the numbers against numpy's percentiles.

use t2spline::fit::{FuzzifyRule, FuzzyData, Readings};
use t2spline_io::{parse_readings, MAX_ROWS};

fn lines(text: &str) -> Vec<String> {
    parse_readings(text, "r.csv").unwrap_err().lines()
}

#[test]
fn every_rule_is_reported_with_its_place() {
    let text = "station,x,y\n\
                A,0,1\n\
                A,0.5,abc\n\
                A,1\n\
                A,1,2,3\n\
                B,2,inf\n\
                B,2,1e200\n\
                C,4,4\n\
                A,5,5\n\
                ,1,1\n";
    assert_eq!(
        lines(text),
        [
            "r.csv:3:7: y (column 3): `abc` is not a number",
            "r.csv:4:4: missing column(s) y: every row needs 3 values (station,x,y)",
            "r.csv:5:7: extra column 4: every row has 3 values (station,x,y)",
            "r.csv:6:5: y (column 3): `inf` is not a number",
            "r.csv:7:5: y (column 3): 1e200 is outside [-1e150, 1e150]",
            "r.csv:10:1: station (column 1): empty; every row names its station",
            "r.csv:8:1: station `C`: 1 reading(s); percentiles need at least 2",
        ]
    );
}

#[test]
fn a_number_beyond_the_range_of_a_float_is_out_of_range() {
    // `1e309` reads as infinite: a number all the same, beyond the limit.
    assert_eq!(
        lines("station,x,y\nA,1e309,1\nA,0,-1E400\nA,0,infinity\n"),
        [
            "r.csv:2:3: x (column 2): 1e309 is outside [-1e150, 1e150]",
            "r.csv:3:5: y (column 3): -1E400 is outside [-1e150, 1e150]",
            "r.csv:4:5: y (column 3): `infinity` is not a number",
        ]
    );
}

#[test]
fn headers_are_checked() {
    assert_eq!(
        lines("name,x,y\nA,1,2\n"),
        ["r.csv:1:1: expected the header `station,x,y` or `station,x,y,z` (comma or semicolon separated), got `name,x,y`"]
    );
    assert_eq!(
        lines(""),
        ["r.csv: the file is empty; expected the header `station,x,y` or `station,x,y,z` and one reading per row"]
    );
    assert_eq!(
        lines("station,x,y\n"),
        ["r.csv: no readings: after the header, one reading per row is needed"]
    );
    // Case and spaces around names do not matter; z makes 3-D readings.
    let ok = parse_readings(" Station , X ,Y,z\nA,1,2,3\nA,2,3,4\n", "r.csv").unwrap();
    assert!(matches!(ok.readings, Readings::Spatial(_)));
}

#[test]
fn spreadsheet_dialects_read_the_same() {
    let plain = "station,x,y\nA,1.5,2\nA,2.5,-3\nB,4,5\nB,6,7\n";
    let excel =
        "\u{feff}\"station\";\"x\";\"y\"\r\n\"A\";1,5;2\r\nA;\"2,5\";-3\r\n\r\nB;4;5\r\nB;6;7\r\n";
    let a = parse_readings(plain, "a.csv").unwrap();
    let b = parse_readings(excel, "b.csv").unwrap();
    assert_eq!(a.readings, b.readings);
    assert_eq!(a.stations, ["A", "B"]);
    assert_eq!(b.first_lines, [2, 5]);
    // A station name may hold the separator when quoted.
    let q = parse_readings(
        "station,x,y\n\"dune, crest\",0,1\n\"dune, crest\",1,2\n",
        "q.csv",
    )
    .unwrap();
    assert_eq!(q.stations, ["dune, crest"]);
    assert_eq!(
        lines("station,x,y\n\"A,1,2\n"),
        ["r.csv:2:1: a quoted field is not closed"]
    );
}

#[test]
fn limits_are_checked_before_rows_are_stored() {
    // Readings are counted, not lines: blank lines past the limit are no
    // readings (the count of readings itself is a unit test of the module).
    let mut text = String::from("station,x,y\nA,0,0\nA,1,1\n");
    text.push_str(&"\n".repeat(MAX_ROWS + 2));
    let file = parse_readings(&text, "r.csv").expect("two readings and blank lines");
    assert_eq!(file.stations, ["A"]);
    // Stations: at most as many as control points.
    let mut text = String::from("station,x,y\n");
    for i in 0..=t2spline_io::job::MAX_POINTS {
        text.push_str(&format!("s{i},0,0\ns{i},1,1\n"));
    }
    let e = lines(&text);
    assert_eq!(
        e,
        ["r.csv:200002:1: station `s100000`: more than the limit of 100000 stations"]
    );
}

#[test]
fn problems_are_capped() {
    let mut text = String::from("station,x,y\n");
    for _ in 0..1500 {
        text.push_str("A,x,1\n");
    }
    let e = lines(&text);
    assert_eq!(e.len(), 21, "{e:?}");
    assert!(e[20].starts_with("r.csv: … and "), "{}", e[20]);
    assert!(
        e[20].ends_with("more problems (only the first 20 are listed)"),
        "{}",
        e[20]
    );
}

/// numpy 2.4.6 on the readings of station S01 of `examples/beach-readings.csv`:
/// `np.percentile(v, [10, 25, 50, 75, 90])` and `min - 0.02`, `max + 0.02`
/// (printed with `repr`).
#[test]
fn the_shipped_example_matches_numpy() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/beach-readings.csv"
    );
    let file = t2spline_io::read_readings(std::path::Path::new(path)).unwrap();
    assert_eq!((file.stations.len(), file.readings.readings()), (13, 260));
    let rule = FuzzifyRule::try_new(0.02, 0.5).unwrap();
    let FuzzyData::Planar(points) = file.readings.fuzzify(&rule).unwrap() else {
        panic!("2-D readings")
    };
    let x = points[0].coords()[0];
    let y = points[0].coords()[1];
    let numpy_x = [
        -0.18109999999999998,
        -0.11775000000000001,
        0.026500000000000003,
        0.0695,
        0.16640000000000013,
    ];
    let numpy_y = [5.8955, 5.92775, 5.9885, 6.04025, 6.049200000000001];
    for (n, numpy) in [(x, numpy_x), (y, numpy_y)] {
        assert_eq!(
            [
                n.primary().left(),
                n.lower().left(),
                n.crisp(),
                n.lower().right(),
                n.primary().right()
            ],
            numpy
        );
    }
    assert_eq!(
        (x.upper().left(), x.upper().right()),
        (-0.365, 0.40900000000000003)
    );
    assert_eq!(
        (y.upper().left(), y.upper().right()),
        (5.688000000000001, 6.116)
    );
}
