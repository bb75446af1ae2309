//! Readings of a net (`row,col,x,y,z`) and of rasters (CSV grid, ESRI ASCII
//! grid, `.npy`): every rule with its place, stations in any order, the
//! blocks of a raster, and the data files of a net read back.

use t2spline::fit::{fuzzify_number, FuzzifyRule, FuzzyData};
use t2spline_io::job::MAX_PROBLEMS;
use t2spline_io::{
    data_json, fuzzify_net, fuzzify_readings, parse_ascii_grid, parse_data, parse_grid_csv,
    parse_net_readings, parse_npy, parse_readings, RasterGeometry, ReadingsError, ReadingsOptions,
};

fn lines(text: &str) -> Vec<String> {
    parse_net_readings(text, "n.csv").unwrap_err().lines()
}

/// A net of `rows × columns` stations with `n` readings each, in net order;
/// the readings of station (i, j) scatter around (10 j, 10 i, i + j).
fn net_rows(rows: usize, columns: usize, n: usize) -> Vec<String> {
    let mut out = Vec::new();
    for i in 0..rows {
        for j in 0..columns {
            for k in 0..n {
                let d = (k as f64 - 1.5) * 0.01 * (1 + (i * 7 + j * 3 + k * 5) % 4) as f64;
                out.push(format!(
                    "{i},{j},{},{},{}",
                    10.0 * j as f64 + d,
                    10.0 * i as f64 - d / 2.0,
                    (i + j) as f64 + d * 3.0
                ));
            }
        }
    }
    out
}

fn options(degree: u64) -> ReadingsOptions {
    ReadingsOptions::new(None, None, [Some(degree), None], [None, None], None).unwrap()
}

#[test]
fn stations_in_any_order_give_what_the_sorted_file_gives() {
    let sorted = net_rows(3, 4, 5);
    // A log in time order: every station's readings interleaved, by a fixed
    // permutation (a stride coprime to the count), headers in any case.
    let n = sorted.len();
    let shuffled: Vec<String> = (0..n).map(|k| sorted[(k * 7 + 3) % n].clone()).collect();
    let a =
        parse_net_readings(&format!("row,col,x,y,z\n{}\n", sorted.join("\n")), "n.csv").unwrap();
    let b = parse_net_readings(
        &format!(" Row ,COL,X,y,Z\r\n{}\r\n", shuffled.join("\r\n")),
        "n.csv",
    )
    .unwrap();
    assert_eq!(a.shape, [3, 4]);
    assert_eq!(a.readings(), 60);
    // The readings of a station are kept in file order, so they may differ
    // in order; the fuzzy numbers (order statistics) may not.
    let (da, db) = (
        fuzzify_net(&a, &options(2)).unwrap(),
        fuzzify_net(&b, &options(2)).unwrap(),
    );
    assert_eq!(data_json(&da), data_json(&db));
    assert_eq!((da.degree, da.degree_v), (2, Some(2)));
}

#[test]
fn a_semicolon_file_reads_decimal_commas() {
    let text = "row;col;x;y;z\n0;0;0,5;1;2\n0;0;\"1,5\";1;3\n0;1;2;1;2\n0;1;3;1;3\n";
    let net = parse_net_readings(text, "n.csv").unwrap();
    assert_eq!(net.stations[0], [[0.5, 1.0, 2.0], [1.5, 1.0, 3.0]]);
}

#[test]
fn every_rule_of_a_net_is_reported_with_its_place() {
    let text = "row,col,x,y,z\n\
                0,0,1,1,1\n\
                0,0,1,1,2\n\
                0,2,1,1,1\n\
                1,0,1,x,1\n\
                1,0,1,2\n\
                2,1,1,1,1,9\n\
                -1,0,0,0,0\n\
                1.5,0,0,0,0\n\
                ,0,0,0,0\n\
                2,1,1,1,1e200\n\
                2,1,1,1,1\n";
    assert_eq!(
        lines(text),
        [
            "n.csv:5:7: y (column 4): `x` is not a number",
            "n.csv:6:8: missing column(s) z: every row needs 5 values (row,col,x,y,z)",
            "n.csv:7:11: extra column 6: every row has 5 values (row,col,x,y,z)",
            "n.csv:8:1: row (column 1): `-1` is not a whole number from 0",
            "n.csv:9:1: row (column 1): `1.5` is not a whole number from 0",
            "n.csv:10:1: row (column 1): empty; every reading names its station by row and column",
            "n.csv:11:9: z (column 5): 1e200 is outside [-1e150, 1e150]",
            "n.csv: station (0, 1): missing; the net is rows 0..3, columns 0..3, every station needs readings",
            "n.csv:4:1: station (0, 2): 1 reading(s); percentiles need at least 2",
            "n.csv: row 1: columns 0..1, but row 0 has columns 0..3: every row of the net needs as many stations",
            "n.csv:5:1: station (1, 0): 1 reading(s); percentiles need at least 2",
            "n.csv: row 2: columns 0..2, but row 0 has columns 0..3: every row of the net needs as many stations",
            "n.csv: station (2, 0): missing; the net is rows 0..3, columns 0..3, every station needs readings",
        ]
    );
    assert_eq!(
        lines("row,col,x,y,z\n1,0,0,0,1\n1,0,0,0,2\n"),
        ["n.csv: row 0: no stations; the net is rows 0..2, columns 0..1, every station needs readings"]
    );
    assert_eq!(
        lines("row,col,x,y\n0,0,1,1\n"),
        ["n.csv:1:1: expected the header `row,col,x,y,z` (comma or semicolon separated), got `row,col,x,y`"]
    );
    assert_eq!(
        lines("row,col,x,y,z\n"),
        ["n.csv: no readings: after the header, one reading per row is needed"]
    );
}

#[test]
fn limits_are_checked_before_the_net_is_stored() {
    // A station index at the limit of stations, and a net whose rows × columns
    // pass it although only two stations are given.
    assert_eq!(
        lines("row,col,x,y,z\n0,100000,0,0,0\n"),
        ["n.csv:2:3: col (column 2): 100000 is more than the limit of 100000 stations"]
    );
    assert_eq!(
        lines("row,col,x,y,z\n999,0,0,0,0\n0,999,0,0,0\n"),
        ["n.csv: the net is rows 0..1000, columns 0..1000: more than the limit of 100000 stations"]
    );
}

#[test]
fn problems_are_capped_and_counted() {
    // Every station of a 1 × 1500 net has one reading.
    let mut text = String::from("row,col,x,y,z\n");
    for j in 0..1500 {
        text += &format!("0,{j},0,0,0\n");
    }
    let got = lines(&text);
    assert_eq!(got.len(), MAX_PROBLEMS + 1);
    assert_eq!(
        got[0],
        "n.csv:2:1: station (0, 0): 1 reading(s); percentiles need at least 2"
    );
    // The reader stops collecting at 1000 problems, so the count is a bound.
    assert_eq!(
        got[MAX_PROBLEMS],
        format!(
            "n.csv: … and at least {} more problems (only the first {MAX_PROBLEMS} are listed)",
            1500 - MAX_PROBLEMS
        )
    );
}

#[test]
fn equal_readings_give_a_crisp_number_and_the_tolerance_widens_only_the_upper_feet() {
    let mut r = vec![2.5; 4];
    let x = fuzzify_number(&mut r, &FuzzifyRule::try_new(0.0, 0.5).unwrap()).unwrap();
    let feet = |x: &t2spline::Nt2Number| {
        [
            x.upper().left(),
            x.primary().left(),
            x.lower().left(),
            x.crisp(),
            x.lower().right(),
            x.primary().right(),
            x.upper().right(),
        ]
    };
    assert_eq!(feet(&x), [2.5; 7]);
    let x = fuzzify_number(&mut r, &FuzzifyRule::try_new(0.1, 0.5).unwrap()).unwrap();
    assert_eq!(feet(&x), [2.4, 2.5, 2.5, 2.5, 2.5, 2.5, 2.6]);
}

#[test]
fn a_net_too_small_for_its_degree_is_refused_naming_the_direction() {
    let text = format!("row,col,x,y,z\n{}\n", net_rows(2, 5, 2).join("\n"));
    let net = parse_net_readings(&text, "n.csv").unwrap();
    let refused = |o: ReadingsOptions| match fuzzify_net(&net, &o) {
        Err(ReadingsError::Option { option, message }) => format!("{option}: {message}"),
        other => panic!("{other:?}"),
    };
    assert_eq!(
        refused(ReadingsOptions::new(None, None, [None; 2], [None; 2], None).unwrap()),
        "degree: n.csv: a net of 2 × 5 stations has 2 row(s), but degree 3 along u needs at least 4; give a lower degree"
    );
    let o = ReadingsOptions::new(None, None, [None, None], [Some(2), Some(7)], None).unwrap();
    assert_eq!(
        refused(o),
        "order: n.csv: a net of 2 × 5 stations has 5 station(s) per row, but degree 6 along v needs at least 7; give a lower degree"
    );
    // A degree out of its range is refused when the options are made.
    match ReadingsOptions::new(None, None, [Some(1), Some(0)], [None, None], None) {
        Err(ReadingsError::Option { option, message }) => assert_eq!(
            format!("{option}: {message}"),
            "degree: a fit needs degree 1 to 31 (order 2 to 32) in each direction"
        ),
        other => panic!("{other:?}"),
    }
    // Orders keep their key in the data file.
    let o = ReadingsOptions::new(None, None, [None, None], [Some(2), Some(3)], None).unwrap();
    let json = data_json(&fuzzify_net(&net, &o).unwrap());
    assert_eq!(json["order"], serde_json::json!([2, 3]));
}

#[test]
fn a_pair_of_degrees_is_refused_for_the_stations_of_a_curve() {
    let o = ReadingsOptions::new(None, None, [Some(1), Some(2)], [None, None], None).unwrap();
    match fuzzify_readings("station,x,y\nA,0,0\nA,1,1\nB,2,0\nB,3,1\n", "r.csv", &o) {
        Err(ReadingsError::Option { message, .. }) => assert_eq!(
            message,
            "a pair P,Q is for a net (the header row,col,x,y,z, or a raster); the stations of a curve take one degree"
        ),
        other => panic!("{other:?}"),
    }
}

#[test]
fn the_readings_of_a_curve_may_interleave_stations() {
    let log = "station,x,y\nA,0,0\nB,5,5\nA,1,1\nC,9,9\nB,6,6\nC,8,8\nA,2,0\n";
    let sorted = "station,x,y\nA,0,0\nA,1,1\nA,2,0\nB,5,5\nB,6,6\nC,9,9\nC,8,8\n";
    let (a, b) = (
        parse_readings(log, "r.csv").unwrap(),
        parse_readings(sorted, "r.csv").unwrap(),
    );
    assert_eq!(a.stations, ["A", "B", "C"]);
    assert_eq!(a.first_lines, [2, 3, 5]);
    assert_eq!(a.readings, b.readings);
}

#[test]
fn data_files_of_a_net_read_back_and_keep_their_rules() {
    let text = format!("row,col,x,y,z\n{}\n", net_rows(3, 4, 4).join("\n"));
    let o = ReadingsOptions::new(None, None, [Some(2), Some(3)], [None, None], Some(0.5)).unwrap();
    let data = fuzzify_readings(&text, "n.csv", &o).unwrap();
    let json = data_json(&data);
    let back = parse_data(&json.to_string(), "d.json").unwrap();
    assert_eq!(back.points, data.points);
    assert_eq!(
        (back.degree, back.degree_v, back.degree_key),
        (2, Some(3), "degree")
    );
    let FuzzyData::Net(rows) = &back.points else {
        panic!("a net: {:?}", back.points)
    };
    assert_eq!((rows.len(), rows[0].len()), (3, 4));
    // Too few rows and columns, a degree 0, a pair of samples, the keys
    // the fit makes: each named at its place.
    let mut bad = json.clone();
    bad["degree"] = serde_json::json!([3, 0]);
    bad["samples"] = serde_json::json!([5, 5]);
    bad["weights"] = serde_json::json!([[1]]);
    let e = parse_data(&serde_json::to_string_pretty(&bad).unwrap(), "d.json").unwrap_err();
    let got: Vec<String> = e
        .lines()
        .into_iter()
        .map(|l| l.split_once(": ").map_or(l.clone(), |(_, m)| m.to_owned()))
        .collect();
    assert_eq!(
        got,
        [
            "weights: not allowed in a data file: the fit makes the weights (all 1) and the knots",
            "samples: a data file of a net takes one number of samples, for both directions of the fitted surface",
            "degree[1]: degree 0 cannot be fitted: a piecewise-constant curve does not pass through its data; give degree 1 or more",
        ]
    );
    let mut bad = json.clone();
    bad["degree"] = serde_json::json!([3, 4]);
    let e = parse_data(&bad.to_string(), "d.json").unwrap_err();
    let got: Vec<String> = e
        .lines()
        .into_iter()
        .map(|l| l.split_once(": ").map_or(l.clone(), |(_, m)| m.to_owned()))
        .collect();
    assert_eq!(
        got,
        [
            "points: 3 row(s), but a net of degree 3 along u needs at least 4",
            "points: 4 point(s) per row, but a net of degree 4 along v needs at least 5",
        ]
    );
    // A ragged net is the surface job's message.
    let mut bad = json;
    bad["points"][1].as_array_mut().unwrap().pop();
    let e = parse_data(&bad.to_string(), "d.json").unwrap_err();
    assert!(
        e.to_string().contains(
            "points[1]: 3 columns, row 0 has 4: every row of the net needs as many points"
        ),
        "{e}"
    );
}

#[test]
fn a_net_is_fitted_as_a_surface_with_the_same_options_in_both_directions() {
    let text = format!("row,col,x,y,z\n{}\n", net_rows(3, 4, 3).join("\n"));
    let data = fuzzify_readings(&text, "n.csv", &options(1)).unwrap();
    let outcome = data
        .points
        .fit(
            &t2spline::fit::FitOptions::interpolation(1).unwrap(),
            t2spline::fit::FuzzyFitMode::Valid,
        )
        .unwrap();
    assert_eq!(
        outcome.summary.net.map(|n| (n.data, n.control)),
        Some(([3, 4], [3, 4]))
    );
    assert_eq!(data.points.len(), 12);
}

#[test]
fn the_text_of_a_data_file_is_that_of_its_tree_of_values() {
    // A net with the order key, and a data file whose numbers mix lower
    // heights (each written where it differs from the top-level one).
    let text = format!("row,col,x,y,z\n{}\n", net_rows(3, 4, 4).join("\n"));
    let o = ReadingsOptions::new(
        Some(0.01),
        None,
        [None, None],
        [Some(3), Some(2)],
        Some(0.25),
    )
    .unwrap();
    let net = fuzzify_readings(&text, "n.csv", &o).unwrap();
    let mixed = parse_data(
        r#"{"degree": 1, "lower_height": 0.5, "samples": 7, "points": [
          {"x": {"crisp": 0, "upper": [-1, 1], "primary": [-0.5, 0.5], "lower": [-0.2, 0.2], "lower_height": 0.3},
           "y": {"crisp": 0, "upper": [-1, 2], "primary": [-0.5, 1], "lower": [-0.2, 0.5]}},
          {"x": {"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]},
           "y": {"crisp": 1, "upper": [0, 3], "primary": [0.5, 2], "lower": [0.8, 1.5], "lower_height": 1}}
        ]}"#,
        "d.json",
    )
    .unwrap();
    for data in [&net, &mixed] {
        let text = t2spline_io::data_json_text(data);
        assert_eq!(text, t2spline_io::to_json_pretty(&data_json(data)));
        assert_eq!(parse_data(&text, "again.json").unwrap().points, data.points);
    }
}

const ASC: &str =
    "ncols 5\nnrows 4\nxllcorner 100\nyllcorner 200\ncellsize 2\nNODATA_value -9999\n\
                   1 2 3 4 5\n2 -9999 4 5 6\n3 4 5 6 7\n4 5 6 7 8\n";

#[test]
fn an_ascii_grid_gives_blocks_of_its_cells_north_first() {
    let raster = parse_ascii_grid(ASC, "g.asc").unwrap();
    // Corners: centres half a cell in; row 0 is the north edge.
    assert_eq!(raster.x, [101.0, 103.0, 105.0, 107.0, 109.0]);
    assert_eq!(raster.y, [207.0, 205.0, 203.0, 201.0]);
    let (net, note) = raster.blocks(2).unwrap();
    assert_eq!(
        note.as_deref(),
        Some("g.asc: the last 1 column(s) (columns 4..5) of the raster as stored fill no whole block of 2 × 2 cells and were left out")
    );
    assert_eq!(net.shape, [2, 2]);
    assert_eq!(
        net.centres.clone().unwrap(),
        [
            [102.0, 206.0],
            [106.0, 206.0],
            [102.0, 202.0],
            [106.0, 202.0]
        ]
    );
    // The NODATA cell is left out of block (0, 0).
    let z: Vec<f64> = net.stations[0].iter().map(|r| r[2]).collect();
    assert_eq!(z, [1.0, 2.0, 2.0]);
    let data = fuzzify_net(&net, &options(1)).unwrap();
    let json = data_json(&data);
    let p = &json["points"][0][0];
    assert_eq!(p["x"]["upper"], serde_json::json!([102.0, 102.0]));
    assert_eq!(p["z"]["crisp"], 2.0);
    assert_eq!(p["z"]["primary"], serde_json::json!([1.2, 2.0]));
    // Centres given: the same cells, and no note for a whole grid.
    let centred = ASC
        .replace("xllcorner 100", "XLLCENTER 101")
        .replace("yllcorner 200", "YLLCenter 201")
        .replace("ncols 5", "ncols 4")
        .replace(" 5\n", "\n")
        .replace(" 6\n", "\n")
        .replace(" 7\n", "\n")
        .replace(" 8\n", "\n");
    let (again, note) = parse_ascii_grid(&centred, "g.asc")
        .unwrap()
        .blocks(2)
        .unwrap();
    assert_eq!((again.centres, note), (net.centres, None));
}

#[test]
fn every_rule_of_an_ascii_grid_is_reported_with_its_place() {
    let lines = |text: &str| parse_ascii_grid(text, "g.asc").unwrap_err().lines();
    assert_eq!(
        lines("ncols 2\nnrows 0\nxllcorner 0\nxllcenter 1\ncellsize -1\nfoo 3\n1 2\n"),
        [
            "g.asc:6:1: `foo` is not a key of an ESRI ASCII grid's header (ncols, nrows, xllcorner or xllcenter, yllcorner or yllcenter, cellsize, NODATA_value)",
            "g.asc:4:1: give one of xllcorner and xllcenter, not both",
            "g.asc: the header has no yllcorner or yllcenter",
            "g.asc:2:1: nrows = 0: a whole number from 1 to 16777216",
            "g.asc:5:1: cellsize = -1: a positive number",
        ]
    );
    assert_eq!(
        lines("ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 x\n3\n"),
        [
            "g.asc:6:3: `x` is not a number",
            "g.asc:7:1: 3 value(s), but nrows × ncols = 2 × 2 = 4",
        ]
    );
    assert_eq!(
        lines("ncols 1\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n"),
        ["g.asc:6:3: more values than nrows × ncols = 1 × 1 = 1"]
    );
    assert_eq!(
        lines("ncols 5000\nnrows 5000\nxllcorner 0\nyllcorner 0\ncellsize 1\n"),
        ["g.asc: a grid of 5000 × 5000 cells is more than the limit of 16777216"]
    );
    // Blocks with too few readings name their cells.
    let text = "ncols 4\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\nnodata_value -1\n-1 -1 1 2\n-1 5 3 4\n";
    let e = parse_ascii_grid(text, "g.asc")
        .unwrap()
        .blocks(2)
        .unwrap_err();
    assert_eq!(
        e.lines(),
        ["g.asc: block (0, 0) (cell rows 0..2, columns 0..2): 1 reading(s) with data; percentiles need at least 2"]
    );
    let e = parse_ascii_grid(text, "g.asc")
        .unwrap()
        .blocks(3)
        .unwrap_err();
    assert_eq!(
        e.lines(),
        ["g.asc: a raster of 2 × 4 cells holds no whole block of 3 × 3 cells"]
    );
}

#[test]
fn a_csv_grid_reads_empty_and_nan_as_no_data() {
    let text = "x;y;z\n0;10;1\n1;10;2\n2;10;\n0;9;nan\n1;9;4\n2;9;NaN\n0;8;1,5\n1;8;2\n2;8;3\n";
    let raster = parse_grid_csv(text, "g.csv").unwrap();
    assert_eq!(raster.shape, [3, 3]);
    assert_eq!(
        (raster.x.clone(), raster.y.clone()),
        (vec![0.0, 1.0, 2.0], vec![10.0, 9.0, 8.0])
    );
    let (net, note) = raster.blocks(2).unwrap();
    assert_eq!(
        net.stations[0].iter().map(|r| r[2]).collect::<Vec<_>>(),
        [1.0, 2.0, 4.0]
    );
    assert_eq!(net.centres.unwrap(), [[0.5, 9.5]]);
    assert_eq!(
        note.as_deref(),
        Some("g.csv: the last 1 row(s) (rows 2..3) and the last 1 column(s) (columns 2..3) of the raster as stored fill no whole block of 2 × 2 cells and were left out")
    );
    // Written column by column: the same raster.
    let by_columns =
        "x,y,z\n0,10,1\n0,9,nan\n0,8,1.5\n1,10,2\n1,9,4\n1,8,2\n2,10,\n2,9,nan\n2,8,3\n";
    let other = parse_grid_csv(by_columns, "g.csv").unwrap();
    assert_eq!((other.x, other.y), (raster.x, raster.y));
    assert_eq!(
        format!("{:?}", other.values),
        format!("{:?}", raster.values)
    );
}

#[test]
fn every_rule_of_a_csv_grid_is_reported_with_its_place() {
    let lines = |text: &str| parse_grid_csv(text, "g.csv").unwrap_err().lines();
    assert_eq!(
        lines("x,y,z\n0,0,1\n1,a,2\n0,1,b\n1,1\n1,1,1,1\n"),
        [
            "g.csv:3:3: y (column 2): `a` is not a number",
            "g.csv:4:5: z (column 3): `b` is not a number; a cell without data is empty or `nan`",
            "g.csv:5:4: missing column(s) z: every row needs 3 values (x,y,z)",
            "g.csv:6:7: extra column 4: every row has 3 values (x,y,z)",
        ]
    );
    assert_eq!(
        lines("x,y,z\n0,0,1\n1,0,2\n0,1,3\n0,0,4\n"),
        [
            "g.csv:5:1: cell (x 0, y 0): given again (first at line 2); every cell once",
            "g.csv: cell (x 1, y 1): missing; every cell of the grid needs a row (a cell without data: `z` empty or `nan`)",
        ]
    );
    assert_eq!(
        lines("x,y,z\n0,0,1\n1,0,2\n3,0,3\n"),
        ["g.csv: the x of the cells are not evenly spaced: in the order of their first row they begin 0, 1, so the 3th would be 2, but it is 3; a raster is a regular grid"]
    );
    assert_eq!(
        lines("station,x,y\nA,0,0\n"),
        ["g.csv:1:1: expected the header `x,y,z` of a raster (comma or semicolon separated), got `station,x,y`"]
    );
}

/// The bytes of a `.npy` file: `version` 1, 2 or 3, `descr`, the header's
/// other entries as given, then `data`.
fn npy(version: u8, descr: &str, rest: &str, data: &[u8]) -> Vec<u8> {
    let header = format!("{{'descr': '{descr}', {rest}, }}");
    let prefix = if version == 1 { 10 } else { 12 };
    let total = (prefix + header.len() + 1).div_ceil(64) * 64;
    let padded = format!("{header:<width$}\n", width = total - prefix - 1);
    let mut out = b"\x93NUMPY".to_vec();
    out.extend([version, 0]);
    if version == 1 {
        out.extend((padded.len() as u16).to_le_bytes());
    } else {
        out.extend((padded.len() as u32).to_le_bytes());
    }
    out.extend(padded.as_bytes());
    out.extend(data);
    out
}

#[test]
fn npy_arrays_of_every_version_and_both_float_widths_are_read() {
    let values = [1.0, 2.0, f64::NAN, 4.0, 5.0, 6.0];
    let f8: Vec<u8> = values.iter().flat_map(|v| v.to_le_bytes()).collect();
    let f4: Vec<u8> = values
        .iter()
        .flat_map(|&v| (v as f32).to_le_bytes())
        .collect();
    let g = RasterGeometry {
        origin: [0.0, 10.0],
        spacing: [0.5, -1.0],
    };
    let shape = "'fortran_order': False, 'shape': (2, 3)";
    for bytes in [
        npy(1, "<f8", shape, &f8),
        npy(2, "<f4", shape, &f4),
        npy(3, "<f8", shape, &f8),
    ] {
        let r = parse_npy(&bytes, "g.npy", &g).unwrap();
        assert_eq!(
            (r.shape, r.x.clone(), r.y.clone()),
            ([2, 3], vec![0.0, 0.5, 1.0], vec![10.0, 9.0])
        );
        assert_eq!(format!("{:?}", r.values), format!("{values:?}"));
    }
    // Keys in another order, as other writers put them.
    let bytes = npy(1, "<f8", "'shape': (2, 3), 'fortran_order': False", &f8);
    assert_eq!(parse_npy(&bytes, "g.npy", &g).unwrap().shape, [2, 3]);
}

#[test]
fn npy_files_that_are_not_a_2d_float_array_are_refused_saying_what_they_hold() {
    let g = RasterGeometry {
        origin: [0.0, 0.0],
        spacing: [1.0, 1.0],
    };
    let refused = |bytes: &[u8]| parse_npy(bytes, "g.npy", &g).unwrap_err().lines();
    let f8 = vec![0u8; 48];
    let shape = "'fortran_order': False, 'shape': (2, 3)";
    assert_eq!(
        refused(&npy(1, ">f8", shape, &f8)),
        ["g.npy: an array of type '>f8'; rasters are read as little-endian floats, '<f8' or '<f4' (in numpy: a.astype('<f8'))"]
    );
    assert_eq!(
        refused(&npy(1, "<i4", shape, &f8))[0].split(';').next(),
        Some("g.npy: an array of type '<i4'")
    );
    assert_eq!(
        refused(&npy(1, "<f8", "'fortran_order': True, 'shape': (2, 3)", &f8)),
        ["g.npy: an array in Fortran order; rasters are read in C order (in numpy: np.save(path, np.ascontiguousarray(a)))"]
    );
    assert_eq!(
        refused(&npy(
            1,
            "<f8",
            "'fortran_order': False, 'shape': (2, 3, 1)",
            &f8
        )),
        ["g.npy: an array of 3 dimension(s); a raster is a 2-D array (rows, columns)"]
    );
    assert_eq!(
        refused(&npy(1, "<f8", shape, &f8[..40])),
        ["g.npy: 40 bytes of data, but 2 × 3 values of 8 bytes are 48"]
    );
    assert_eq!(
        refused(&npy(
            1,
            "<f8",
            "'fortran_order': False, 'shape': (5000, 5000)",
            &[]
        )),
        ["g.npy: an array of 5000 × 5000 cells, more than the limit of 16777216"]
    );
    assert_eq!(
        refused(b"PK\x03\x04"),
        ["g.npy: not a .npy file: it does not start with numpy's magic `\\x93NUMPY`"]
    );
    let mut bytes = npy(1, "<f8", shape, &f8);
    bytes[6] = 4;
    assert_eq!(
        refused(&bytes),
        ["g.npy: a .npy file of version 4.0; versions 1.0, 2.0 and 3.0 are read"]
    );
    let inf: Vec<u8> = [0.0, 0.0, f64::INFINITY, 0.0, 0.0, 0.0]
        .iter()
        .flat_map(|v| v.to_le_bytes())
        .collect();
    assert_eq!(
        refused(&npy(1, "<f8", shape, &inf)),
        ["g.npy: cell (0, 2) = inf: a reading is a finite number within [-1e150, 1e150], or NaN for no data"]
    );
}
