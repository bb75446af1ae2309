//! `t2spline fuzzify` of a net's readings and of rasters: the built binary on
//! a shuffled log (byte for byte the sorted file's data), an ESRI ASCII grid,
//! a numpy `.npy` array, a CSV grid with a `nan`, and the refusals (exit code
//! 2, one line per problem, nothing written).

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use serde_json::Value;

fn t2spline() -> Command {
    let mut c = Command::cargo_bin("t2spline").unwrap();
    c.env("SOURCE_DATE_EPOCH", "0");
    c
}

fn write(dir: &Path, name: &str, bytes: impl AsRef<[u8]>) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

/// Runs `fuzzify` with `args` in `dir`, expecting success with `stderr`;
/// returns the data file written to standard output, as text.
fn fuzzify(dir: &Path, args: &[&str], stderr: &str) -> String {
    let out = t2spline()
        .current_dir(dir)
        .arg("fuzzify")
        .args(args)
        .assert()
        .code(0)
        .stderr(stderr.to_owned())
        .get_output()
        .stdout
        .clone();
    String::from_utf8(out).unwrap()
}

/// A 4 × 5 net with 6 readings per station, in net order.
fn net_rows() -> Vec<String> {
    let mut rows = Vec::new();
    for i in 0..4 {
        for j in 0..5 {
            for k in 0..6 {
                let d = f64::from((k * 7 + i * 3 + j) % 5) * 0.003 - 0.006;
                rows.push(format!(
                    "{i},{j},{},{},{}",
                    f64::from(j) * 10.0 + d,
                    f64::from(i) * 10.0 - d,
                    1.0 + 0.1 * f64::from(i) + d * 2.0
                ));
            }
        }
    }
    rows
}

#[test]
fn a_shuffled_log_gives_the_sorted_files_data_byte_for_byte() {
    let (a, b) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    let sorted = net_rows();
    let n = sorted.len();
    let shuffled: Vec<String> = (0..n).map(|k| sorted[(k * 11 + 5) % n].clone()).collect();
    write(
        a.path(),
        "net.csv",
        format!("row,col,x,y,z\n{}\n", sorted.join("\n")),
    );
    write(
        b.path(),
        "net.csv",
        format!(
            "ROW;Col;x;y;z\r\n{}\r\n",
            shuffled.join("\r\n").replace(',', ";")
        ),
    );
    let args = [
        "net.csv",
        "--tolerance",
        "0.01",
        "--degree",
        "3,2",
        "--alpha",
        "0.5",
    ];
    let (one, two) = (fuzzify(a.path(), &args, ""), fuzzify(b.path(), &args, ""));
    assert_eq!(one, two);
    let data: Value = serde_json::from_str(&one).unwrap();
    assert_eq!(data["degree"], serde_json::json!([3, 2]));
    assert_eq!(data["alpha"], 0.5);
    let rows = data["points"].as_array().unwrap();
    assert_eq!((rows.len(), rows[0].as_array().unwrap().len()), (4, 5));
    // `--order` keeps its key; one value is both directions.
    let data: Value =
        serde_json::from_str(&fuzzify(a.path(), &["net.csv", "--order", "3"], "")).unwrap();
    assert_eq!(data["order"], serde_json::json!([3, 3]));
}

#[test]
fn an_ascii_grid_in_blocks_with_a_note_for_the_cells_left_out() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "dem.asc",
        "ncols 5\nnrows 4\nxllcorner 100\nyllcorner 200\ncellsize 2\nNODATA_value -9999\n\
         1 2 3 4 5\n2 -9999 4 5 6\n3 4 5 6 7\n4 5 6 7 8\n",
    );
    let out = fuzzify(
        dir.path(),
        &["dem.asc", "--block", "2", "--degree", "1"],
        "t2spline fuzzify: dem.asc: the last 1 column(s) (columns 4..5) of the raster as stored fill no whole block of 2 × 2 cells and were left out\n",
    );
    let data: Value = serde_json::from_str(&out).unwrap();
    let p = &data["points"][0][0];
    assert_eq!(p["x"]["crisp"], 102.0);
    assert_eq!(p["y"]["upper"], serde_json::json!([206.0, 206.0]));
    assert_eq!(p["z"]["crisp"], 2.0);
    assert_eq!(data["points"][1][1]["z"]["crisp"], 6.0);
}

/// The bytes of a version 1.0 `.npy` file of a C-order `'<f8'` array.
fn npy(rows: usize, columns: usize, values: &[f64]) -> Vec<u8> {
    let header =
        format!("{{'descr': '<f8', 'fortran_order': False, 'shape': ({rows}, {columns}), }}");
    let width = (10 + header.len() + 1).div_ceil(64) * 64 - 10 - 1;
    let padded = format!("{header:<width$}\n");
    let mut out = b"\x93NUMPY\x01\x00".to_vec();
    out.extend(u16::try_from(padded.len()).unwrap().to_le_bytes());
    out.extend(padded.as_bytes());
    out.extend(values.iter().flat_map(|v| v.to_le_bytes()));
    out
}

#[test]
fn a_npy_array_with_its_origin_and_spacing() {
    let dir = tempfile::tempdir().unwrap();
    let mut values: Vec<f64> = (0..24).map(f64::from).collect();
    values[7] = f64::NAN;
    write(dir.path(), "dem.npy", npy(4, 6, &values));
    let out = fuzzify(
        dir.path(),
        &[
            "dem.npy",
            "--block",
            "2",
            "--degree",
            "1,2",
            "--origin",
            "-500,-20",
            "--spacing",
            "1,-1",
        ],
        "",
    );
    let data: Value = serde_json::from_str(&out).unwrap();
    // Block (0, 1): cells rows 0..2, columns 2..4 = 2, 3, 8, 9; centre (-497.5, -20.5).
    let p = &data["points"][0][1];
    assert_eq!(
        (p["x"]["crisp"].clone(), p["y"]["crisp"].clone()),
        ((-497.5).into(), (-20.5).into())
    );
    assert_eq!(p["z"]["crisp"], 5.5);
    // Block (0, 0) without its NaN: 0, 1, 6.
    assert_eq!(data["points"][0][0]["z"]["crisp"], 1.0);
    assert_eq!(data["degree"], serde_json::json!([1, 2]));
}

#[test]
fn a_csv_grid_with_a_nan() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("x,y,z\n");
    for i in 0..4 {
        for j in 0..4 {
            let z = if (i, j) == (1, 1) {
                "nan".to_owned()
            } else {
                format!("{}", i * 4 + j)
            };
            text += &format!("{j},{},{z}\n", 10 - i);
        }
    }
    write(dir.path(), "grid.csv", text);
    let out = fuzzify(
        dir.path(),
        &["grid.csv", "--block", "2", "--degree", "1"],
        "",
    );
    let data: Value = serde_json::from_str(&out).unwrap();
    // Block (0, 0): 0, 1, 4 (the nan left out).
    assert_eq!(data["points"][0][0]["z"]["crisp"], 1.0);
    assert_eq!(data["points"][0][0]["x"]["crisp"], 0.5);
    assert_eq!(data["points"][1][0]["y"]["crisp"], 7.5);
}

/// Runs `fuzzify` with `args` in `dir` writing to `data.json`, expecting
/// exit code 2, `stderr`, and no file.
fn refused(dir: &Path, args: &[&str], stderr: &str) {
    t2spline()
        .current_dir(dir)
        .arg("fuzzify")
        .args(args)
        .args(["-o", "data.json"])
        .assert()
        .code(2)
        .stdout("")
        .stderr(stderr.to_owned());
    assert!(!dir.join("data.json").exists());
}

#[test]
fn refusals_name_every_problem_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(
        d,
        "bad.csv",
        "row,col,x,y,z\n0,0,1,1,1\n0,0,1,1,2\n0,2,1,1,1\n1,0,1,x,1\n1,0,1,2,1\n2,1,1,1,1\n2,1,1,1,2\n2,2,1,1,1\n2,2,1,1,1\n",
    );
    refused(
        d,
        &["bad.csv"],
        "t2spline: bad.csv:5:7: y (column 4): `x` is not a number\n\
         t2spline: bad.csv: station (0, 1): missing; the net is rows 0..3, columns 0..3, every station needs readings\n\
         t2spline: bad.csv:4:1: station (0, 2): 1 reading(s); percentiles need at least 2\n\
         t2spline: bad.csv: row 1: columns 0..1, but row 0 has columns 0..3: every row of the net needs as many stations\n\
         t2spline: bad.csv: station (2, 0): missing; the net is rows 0..3, columns 0..3, every station needs readings\n",
    );
    write(
        d,
        "net.csv",
        format!("row,col,x,y,z\n{}\n", net_rows().join("\n")),
    );
    refused(
        d,
        &["net.csv", "--degree", "4"],
        "t2spline: --degree: net.csv: a net of 4 × 5 stations has 4 row(s), but degree 4 along u needs at least 5; give a lower degree\n",
    );
    refused(
        d,
        &["net.csv", "--degree", "1,2,3"],
        "t2spline: --degree: one value, or a pair P,Q for a net (along u, along v)\n",
    );
    write(
        d,
        "dem.asc",
        "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n3 x\n",
    );
    refused(
        d,
        &["dem.asc"],
        "t2spline: --block: dem.asc: a raster's cells are single readings; give --block K for the K × K cells that are the readings of one station\n",
    );
    refused(
        d,
        &["dem.asc", "--block", "2"],
        "t2spline: dem.asc:7:3: `x` is not a number\n",
    );
    refused(
        d,
        &["dem.asc", "--block", "1"],
        "t2spline: --block: 1: a block of K × K cells needs K of at least 2, for at least 2 readings per station\n",
    );
    refused(
        d,
        &["dem.asc", "--block", "2", "--origin", "0,0"],
        "t2spline: --origin: only for a .npy raster; a CSV grid and an ESRI ASCII grid say where their cells are\n",
    );
    write(d, "dem.npy", npy(2, 2, &[1.0, f64::NAN, 3.0, 4.0]));
    refused(
        d,
        &["dem.npy", "--block", "2"],
        "t2spline: --origin: a .npy raster needs --origin X0,Y0 (the centre of the cell at row 0, column 0): the cells' places are not in the file\n",
    );
    write(
        d,
        "holes.npy",
        npy(
            2,
            4,
            &[1.0, f64::NAN, 3.0, 4.0, f64::NAN, f64::NAN, 5.0, 6.0],
        ),
    );
    refused(
        d,
        &["holes.npy", "--block", "2", "--origin", "0,0", "--spacing", "1,1"],
        "t2spline: holes.npy: block (0, 0) (cell rows 0..2, columns 0..2): 1 reading(s) with data; percentiles need at least 2\n",
    );
    write(d, "grid.csv", "x,y,z\n0,0,1\n1,0,2\n0,1,\n");
    refused(
        d,
        &["grid.csv", "--block", "2"],
        "t2spline: grid.csv: cell (x 1, y 1): missing; every cell of the grid needs a row (a cell without data: `z` empty or `nan`)\n",
    );
}
