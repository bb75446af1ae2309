//! `t2spline.fuzzify`: repeated readings of stations turned into the data of
//! a fit by the rules of ``t2spline fuzzify``, as the dict of the data file
//! it writes. The readings come as a file (readings of a curve's or a net's
//! stations, a raster file), as arrays (the readings of a net, a raster) or
//! as a long table of a net's readings; the binding only converts them into
//! the I/O crate's `NetReadings` or `Raster`, whose functions
//! (`fuzzify_readings`, `Raster::blocks`, `fuzzify_net`) compute as the
//! command does.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use t2spline_io::job::MAX_POINTS;
use t2spline_io::{
    data_json_text, fuzzify_net, fuzzify_readings, parse_ascii_grid, parse_data, parse_grid_csv,
    parse_npy, read_npy, FitData, NetReadings, Raster, RasterGeometry, ReadingsError,
    ReadingsOptions, MAX_ROWS,
};

use crate::arrays::{floats, floats_or_nan, shape_text, Floats};
use crate::errors::{internal_error, io_error, without_gil};
use crate::json::loads;
use crate::keyword;

/// How messages name readings given as arrays, as a table, as a raster.
const ARRAY_SOURCE: &str = "<array>";
const TABLE_SOURCE: &str = "<table>";
const RASTER_SOURCE: &str = "<raster>";

/// The columns of a long table of a net's readings.
const TABLE_COLUMNS: [&str; 5] = ["row", "col", "x", "y", "z"];

/// The kinds of raster file, by extension (as the command tells them).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum RasterFile {
    Csv,
    Ascii,
    Npy,
}

/// The readings, converted and ready for the I/O crate.
enum Given {
    /// A readings file (a curve's or a net's stations).
    File(PathBuf),
    /// A raster file, cut into blocks of `block` cells.
    RasterFile(PathBuf, RasterFile),
    /// The readings of a net's stations (from arrays or a table).
    Net(NetReadings),
    /// A raster as the bytes of a `.npy` file, named `<raster>`.
    Raster(Vec<u8>),
}

/// The data of a fit from repeated readings, as ``t2spline fuzzify`` makes
/// it: per station and coordinate, crisp = the median, lower = the 25th–75th
/// percentiles (at ``lower_height``), primary = the 10th–90th, upper = the
/// extremes widened by ``tolerance`` (percentiles by linear interpolation,
/// type 7). The same code as the command reads the readings and computes,
/// so the numbers are the command's on the equivalent file, bit for bit.
///
/// Parameters
/// ----------
/// readings : str, os.PathLike, array, table or 2-D array
///     One of:
///
///     - the path of a readings file: a header ``station,x,y`` or
///       ``station,x,y,z`` (the stations of a curve) or ``row,col,x,y,z``
///       (the stations of a net), one reading per row, the rows of a station
///       in any order; or of a raster file (``.asc``, ``.npy`` or, with
///       ``block``, a CSV ``x,y,z``), as ``t2spline fuzzify --block K``;
///     - the readings of a net as an array of shape ``(rows, cols, readings,
///       3)``: ``readings[i, j, k]`` is the ``k``-th reading ``(x, y, z)`` of
///       station ``(i, j)`` (``i`` along u, ``j`` along v); a reading with NaN
///       in any coordinate is missing and left out, so stations may have
///       different numbers of readings (at least 2 each);
///     - the readings of a net as a long table with the columns ``row``,
///       ``col``, ``x``, ``y``, ``z``, one reading per row, stations in any
///       order (a dict of columns, a pandas DataFrame, a pyarrow Table:
///       anything whose ``table["x"]`` numpy reads); ``row`` and ``col`` are
///       whole numbers from 0, every station of the net present; a reading
///       with NaN is left out;
///     - a raster as a 2-D array of ``z`` (NaN: no data), with ``block``,
///       ``origin`` and ``spacing``: each ``block × block`` cells are the
///       readings of one station, ``x`` and ``y`` its centre (crisp).
/// tolerance : float, optional
///     The instrument's accuracy ``T`` (default 0).
/// lower_height : float, optional
///     The height of the lower membership function (default 0.5).
/// degree, order : int or (int, int), optional
///     The degree (or order) of the curve to fit (default degree 3); for a
///     net, one for both directions or a pair ``(p, q)`` along u and v.
/// alpha : float, optional
///     The level alpha to carry into the data (and so into the fitted job).
/// block : int, optional
///     For a raster: the side ``K >= 2`` of the blocks of cells.
/// origin : (float, float), optional
///     For a raster array or ``.npy`` file: ``(x0, y0)``, the centre of the
///     cell at row 0, column 0.
/// spacing : (float, float), optional
///     For a raster array or ``.npy`` file: ``(dx, dy)``, the step per column
///     and per row (``dy`` negative when row 0 is the north edge).
///
/// Returns
/// -------
/// dict
///     The data file's keys, in its order (``description``, ``degree`` or
///     ``order``, ``alpha`` if given, ``lower_height``, ``points``), as
///     ``t2spline fuzzify`` writes them: ``json.dumps`` of it is a data file
///     that ``t2spline fit`` takes, and ``fit_job`` fits it. A net's
///     ``points`` are rows of points and its degree a pair. The description
///     names arrays ``<array>``, a table ``<table>`` and a raster array
///     ``<raster>``. Rows and columns of a raster past its last whole block
///     are left out with a ``UserWarning``.
///
/// Raises
/// ------
/// JobError
///     For readings that break a rule (``file:line:column: rule``; a station
///     with fewer than 2 readings, named by ``(row, col)`` or its block).
/// ValueError
///     For an option out of its range, named: ``tolerance: …``, and for
///     arrays of a wrong shape or a table without its columns, naming
///     ``readings``.
/// TypeError
///     For readings of no kind above.
/// OSError
///     For a file that cannot be read.
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> rng = np.random.default_rng(1)
/// >>> i, j = np.meshgrid(np.arange(3), np.arange(4), indexing="ij")
/// >>> station = np.stack([i, j, i + j], axis=-1)[:, :, None, :]     # (3, 4, 1, 3)
/// >>> readings = station + rng.normal(0, 0.01, (3, 4, 5, 3))          # 5 readings each
/// >>> data = fuzzify(readings, degree=(2, 1))
/// >>> data["degree"], len(data["points"]), len(data["points"][0])
/// ([2, 1], 3, 4)
/// >>> raster = np.arange(36.0).reshape(6, 6)
/// >>> data = fuzzify(raster, block=3, origin=(0.0, 10.0), spacing=(1.0, -1.0), degree=1)
/// >>> data["points"][0][1]["x"]["crisp"], data["points"][0][1]["z"]["crisp"]
/// (4.0, 10.0)
#[pyfunction]
#[pyo3(signature = (readings, *, tolerance=None, lower_height=None, degree=None, order=None, alpha=None, block=None, origin=None, spacing=None))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn fuzzify<'py>(
    py: Python<'py>,
    readings: &Bound<'py, PyAny>,
    tolerance: Option<&Bound<'py, PyAny>>,
    lower_height: Option<&Bound<'py, PyAny>>,
    degree: Option<&Bound<'py, PyAny>>,
    order: Option<&Bound<'py, PyAny>>,
    alpha: Option<&Bound<'py, PyAny>>,
    block: Option<&Bound<'py, PyAny>>,
    origin: Option<&Bound<'py, PyAny>>,
    spacing: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let non_negative = |v: Option<i64>, name: &str| -> PyResult<Option<u64>> {
        v.map(|n| {
            u64::try_from(n).map_err(|_| PyValueError::new_err(format!("{name}: {n} is negative")))
        })
        .transpose()
    };
    let split = |arg, name: &str| -> PyResult<(Option<u64>, Option<u64>)> {
        Ok(match keyword::opt_per_direction(arg, name)? {
            None => (None, None),
            Some(keyword::PerDirection::One(p)) => (non_negative(Some(p), name)?, None),
            Some(keyword::PerDirection::Two(p, q)) => (
                non_negative(Some(p), &format!("{name}[0]"))?,
                non_negative(Some(q), &format!("{name}[1]"))?,
            ),
        })
    };
    let (degree, degree_v) = split(degree, "degree")?;
    let (order, order_v) = split(order, "order")?;
    let options = ReadingsOptions::new(
        keyword::opt_real(tolerance, "tolerance")?,
        keyword::opt_real(lower_height, "lower_height")?,
        [degree, degree_v],
        [order, order_v],
        keyword::opt_real(alpha, "alpha")?,
    )
    .map_err(|e| readings_error(py, e))?;
    let block = keyword::opt_int(block, "block")?
        .map(|k| {
            usize::try_from(k).ok().filter(|&k| k >= 2).ok_or_else(|| {
                PyValueError::new_err(format!(
                    "block: {k}: a block of K × K cells needs K of at least 2, for at least 2 readings per station"
                ))
            })
        })
        .transpose()?;
    let origin = opt_pair(origin, "origin")?;
    let spacing = opt_pair(spacing, "spacing")?;
    if spacing.is_some_and(|s| s.contains(&0.0)) {
        return Err(PyValueError::new_err(
            "spacing: the steps dx and dy must not be 0",
        ));
    }
    let given = given(py, readings, block, origin.is_some() || spacing.is_some())?;
    let geometry = match &given {
        Given::Raster(_) | Given::RasterFile(_, RasterFile::Npy) => {
            let missing = |name: &str, what: &str| {
                PyValueError::new_err(format!(
                    "{name}: a raster given as an array (or a .npy file) needs {name}={what}: the cells' places are not in the array"
                ))
            };
            Some(RasterGeometry {
                origin: origin.ok_or_else(|| {
                    missing(
                        "origin",
                        "(x0, y0), the centre of the cell at row 0, column 0",
                    )
                })?,
                spacing: spacing.ok_or_else(|| {
                    missing("spacing", "(dx, dy), the step per column and per row")
                })?,
            })
        }
        _ => None,
    };
    let block = block.unwrap_or(2);
    let (json, note) = without_gil(py, move || -> Result<_, ReadingsError> {
        let (data, note) = fit_data(given, block, geometry, &options)?;
        Ok((data_json_text(&data), note))
    })?
    .map_err(|e| readings_error(py, e))?;
    if let Some(note) = note {
        crate::reduction::warn(py, &note)?;
    }
    // The last guard, as the command's: what is given is a valid data file.
    parse_data(&json, "<fuzzify>")
        .map_err(|e| internal_error(&format!("the data file does not validate: {e}")))?;
    loads(py, &json)
}

/// The I/O crate's error as Python's: a file's problems as its exception,
/// an option's as `ValueError` naming the keyword.
fn readings_error(py: Python<'_>, e: ReadingsError) -> PyErr {
    match e {
        ReadingsError::File(e) => io_error(py, e),
        ReadingsError::Option { option, message } => {
            PyValueError::new_err(format!("{option}: {message}"))
        }
    }
}

/// A pair of finite reals, or `None`.
fn opt_pair(arg: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<[f64; 2]>> {
    let Some(arg) = arg.filter(|a| !a.is_none()) else {
        return Ok(None);
    };
    let (a, b) = keyword::real_pair(arg, name)?;
    for (k, v) in [a, b].into_iter().enumerate() {
        if !v.is_finite() {
            return Err(PyValueError::new_err(format!(
                "{name}[{k}]: {v} is not a finite number"
            )));
        }
    }
    Ok(Some([a, b]))
}

/// The data of a fit from the converted readings, by the I/O crate's
/// functions, with the note of a raster's rows and columns left out.
fn fit_data(
    given: Given,
    block: usize,
    geometry: Option<RasterGeometry>,
    options: &ReadingsOptions,
) -> Result<(FitData, Option<String>), ReadingsError> {
    let raster: Raster = match given {
        Given::File(path) => {
            let text = t2spline_io::job::read_text(&path)?;
            let source = path.display().to_string();
            return Ok((fuzzify_readings(&text, &source, options)?, None));
        }
        Given::Net(net) => return Ok((fuzzify_net(&net, options)?, None)),
        Given::Raster(bytes) => {
            let geometry = geometry.ok_or_else(|| missing_geometry(RASTER_SOURCE))?;
            parse_npy(&bytes, RASTER_SOURCE, &geometry)?
        }
        Given::RasterFile(path, kind) => {
            let source = path.display().to_string();
            match kind {
                RasterFile::Npy => {
                    let geometry = geometry.ok_or_else(|| missing_geometry(&source))?;
                    read_npy(&path, &geometry)?
                }
                RasterFile::Ascii => {
                    parse_ascii_grid(&t2spline_io::job::read_text(&path)?, &source)?
                }
                RasterFile::Csv => parse_grid_csv(&t2spline_io::job::read_text(&path)?, &source)?,
            }
        }
    };
    let (net, note) = raster.blocks(block)?;
    Ok((fuzzify_net(&net, options)?, note))
}

/// Never made: the geometry of an array or `.npy` raster is checked first.
fn missing_geometry(source: &str) -> ReadingsError {
    ReadingsError::File(t2spline_io::Error::Invalid {
        file: source.to_owned(),
        problems: vec![t2spline_io::Problem {
            line_column: None,
            message: "a raster array needs its origin and spacing".to_owned(),
        }],
    })
}

/// What `readings` is, converted: a path (of readings or of a raster), the
/// arrays of a net's readings, a table of them, or a raster array.
fn given(
    py: Python<'_>,
    readings: &Bound<'_, PyAny>,
    block: Option<usize>,
    geometry: bool,
) -> PyResult<Given> {
    let only_raster = |name: &str| {
        PyValueError::new_err(format!(
            "{name}: only for a raster (a 2-D array, or a raster file); these readings are the stations' own"
        ))
    };
    let only_npy = || {
        PyValueError::new_err(
            "origin, spacing: only for a raster given as an array or a .npy file; a CSV grid and an ESRI ASCII grid say where their cells are",
        )
    };
    if readings.is_instance_of::<PyString>() || readings.hasattr("__fspath__")? {
        let path: PathBuf = py
            .import("os")?
            .call_method1("fspath", (readings,))?
            .extract()?;
        let kind = match (extension(&path).as_deref(), block) {
            (Some("asc"), _) => Some(RasterFile::Ascii),
            (Some("npy"), _) => Some(RasterFile::Npy),
            (_, Some(_)) => Some(RasterFile::Csv),
            (_, None) => None,
        };
        if kind.is_some() && block.is_none() {
            return Err(PyValueError::new_err(format!(
                "block: {}: a raster's cells are single readings; give block=K for the K × K cells that are the readings of one station",
                path.display()
            )));
        }
        if geometry && kind != Some(RasterFile::Npy) {
            return Err(only_npy());
        }
        return Ok(match kind {
            Some(kind) => Given::RasterFile(path, kind),
            None => Given::File(path),
        });
    }
    let table = readings.is_instance_of::<PyDict>()
        || readings.hasattr("column_names")?
        || readings.hasattr("columns")?;
    if table {
        if block.is_some() {
            return Err(only_raster("block"));
        }
        if geometry {
            return Err(only_npy());
        }
        return table_net(readings).map(Given::Net);
    }
    if readings.hasattr("__len__")? || readings.hasattr("__array__")? {
        let values = floats_or_nan(readings, "readings")?;
        return match values.shape[..] {
            [_, _, _, 3] => {
                if block.is_some() {
                    return Err(only_raster("block"));
                }
                if geometry {
                    return Err(only_npy());
                }
                array_net(&values).map(Given::Net)
            }
            [rows, columns] => {
                if block.is_none() {
                    return Err(PyValueError::new_err(format!(
                        "block: a 2-D array of shape {} is a raster, whose cells are single readings; give block=K for the K × K cells that are the readings of one station",
                        shape_text(&values.shape)
                    )));
                }
                Ok(Given::Raster(npy_bytes(&values.data, rows, columns)))
            }
            _ => Err(PyValueError::new_err(format!(
                "readings: expected shape (rows, cols, readings, 3): the readings (x, y, z) of the stations of a net, or a 2-D raster with block=K, got {}",
                shape_text(&values.shape)
            ))),
        };
    }
    Err(PyTypeError::new_err(format!(
        "readings: expected the path of a readings file (str or os.PathLike), an array of shape (rows, cols, readings, 3), a table with the columns row, col, x, y, z, or a 2-D raster array, got {}",
        readings.get_type().name()?
    )))
}

/// A path's extension in lower case.
fn extension(path: &Path) -> Option<String> {
    path.extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
}

/// The readings of a net from an array `(rows, cols, readings, 3)`: each
/// station's readings in order, those with NaN left out.
fn array_net(values: &Floats) -> PyResult<NetReadings> {
    let [rows, columns, count, 3] = values.shape[..] else {
        return Err(internal_error("the readings of a net are not 4-D"));
    };
    let stations_count = rows.checked_mul(columns).filter(|&n| n <= MAX_POINTS);
    if stations_count.is_none() {
        return Err(PyValueError::new_err(format!(
            "readings: a net of {rows} × {columns} stations: more than the limit of {MAX_POINTS} stations"
        )));
    }
    if values.data.len() / 3 > MAX_ROWS {
        return Err(PyValueError::new_err(format!(
            "readings: {} readings: more than the limit of {MAX_ROWS}",
            values.data.len() / 3
        )));
    }
    let stations = values
        .data
        .chunks_exact(3 * count.max(1))
        .map(|station| {
            station
                .chunks_exact(3)
                .filter(|r| r.iter().all(|v| !v.is_nan()))
                .map(|r| [r[0], r[1], r[2]])
                .collect()
        })
        .collect::<Vec<Vec<[f64; 3]>>>();
    let stations = if count == 0 {
        vec![Vec::new(); rows * columns]
    } else {
        stations
    };
    Ok(net_readings(ARRAY_SOURCE, [rows, columns], stations))
}

/// A net's readings with no lines to name.
fn net_readings(source: &str, shape: [usize; 2], stations: Vec<Vec<[f64; 3]>>) -> NetReadings {
    NetReadings {
        source: source.to_owned(),
        shape,
        stations,
        sources: Vec::new(),
        centres: None,
        what: String::new(),
    }
}

/// The readings of a net from a long table of the columns `row`, `col`,
/// `x`, `y`, `z`: every station of the net present, its readings in the
/// table's order, those with NaN left out.
fn table_net(table: &Bound<'_, PyAny>) -> PyResult<NetReadings> {
    let mut columns = Vec::with_capacity(5);
    for name in TABLE_COLUMNS {
        let column = table.get_item(name).map_err(|_| {
            PyValueError::new_err(format!(
                "readings: the table has no column `{name}`; the readings of a net are the columns row, col, x, y, z, one reading per row"
            ))
        })?;
        let label = format!("readings[{name:?}]");
        let values = if matches!(name, "row" | "col") {
            floats(&column, &label)?
        } else {
            floats_or_nan(&column, &label)?
        };
        if values.shape.len() != 1 {
            return Err(PyValueError::new_err(format!(
                "{label}: expected one value per reading, shape (n,), got {}",
                shape_text(&values.shape)
            )));
        }
        columns.push((label, values.data));
    }
    let n = columns[0].1.len();
    if let Some((label, c)) = columns.iter().find(|(_, c)| c.len() != n) {
        return Err(PyValueError::new_err(format!(
            "{label}: {} values, but readings[\"row\"] has {n}: every column has one value per reading",
            c.len()
        )));
    }
    if n == 0 {
        return Err(PyValueError::new_err(
            "readings: the table has no readings; one reading per row is needed",
        ));
    }
    if n > MAX_ROWS {
        return Err(PyValueError::new_err(format!(
            "readings: {n} readings: more than the limit of {MAX_ROWS}"
        )));
    }
    let mut place = vec![[0usize; 2]; n];
    for (d, (label, c)) in columns.iter().take(2).enumerate() {
        for (k, &v) in c.iter().enumerate() {
            if v < 0.0 || v.fract() != 0.0 || v >= MAX_POINTS as f64 {
                return Err(PyValueError::new_err(format!(
                    "{label}[{k}] = {v} is not a whole number from 0 (below the limit of {MAX_POINTS} stations)"
                )));
            }
            // Whole and within the limit: exact.
            place[k][d] = v as usize;
        }
    }
    let mut index: HashMap<[usize; 2], Vec<[f64; 3]>> = HashMap::new();
    for (k, at) in place.iter().enumerate() {
        let reading = [columns[2].1[k], columns[3].1[k], columns[4].1[k]];
        let station = index.entry(*at).or_default();
        if reading.iter().all(|v| !v.is_nan()) {
            station.push(reading);
        }
    }
    let rows = place.iter().map(|p| p[0]).max().unwrap_or(0) + 1;
    let cols = place.iter().map(|p| p[1]).max().unwrap_or(0) + 1;
    if rows.checked_mul(cols).is_none_or(|c| c > MAX_POINTS) {
        return Err(PyValueError::new_err(format!(
            "readings: the net is rows 0..{rows}, columns 0..{cols}: more than the limit of {MAX_POINTS} stations"
        )));
    }
    let mut stations = Vec::with_capacity(rows * cols);
    let mut missing = Vec::new();
    for i in 0..rows {
        for j in 0..cols {
            match index.remove(&[i, j]) {
                Some(s) => stations.push(s),
                None => {
                    missing.push(format!(
                        "readings: station ({i}, {j}): missing; the net is rows 0..{rows}, columns 0..{cols}, every station needs readings"
                    ));
                    stations.push(Vec::new());
                }
            }
        }
    }
    if !missing.is_empty() {
        let more = missing.len().saturating_sub(10);
        missing.truncate(10);
        if more > 0 {
            missing.push(format!("readings: {more} more station(s) missing"));
        }
        return Err(PyValueError::new_err(missing.join("\n")));
    }
    Ok(net_readings(TABLE_SOURCE, [rows, cols], stations))
}

/// The bytes of a `.npy` file (version 1.0, `'<f8'`, C order) of a
/// `rows × columns` array, as numpy's `save` writes them.
fn npy_bytes(values: &[f64], rows: usize, columns: usize) -> Vec<u8> {
    let header =
        format!("{{'descr': '<f8', 'fortran_order': False, 'shape': ({rows}, {columns}), }}");
    // Magic (6), version (2), length (2), header and newline: a multiple of 64.
    let padded = (10 + header.len() + 1).div_ceil(64) * 64 - 10;
    let mut bytes = Vec::with_capacity(padded + 10 + values.len() * 8);
    bytes.extend_from_slice(b"\x93NUMPY\x01\x00");
    bytes.extend_from_slice(&u16::try_from(padded).unwrap_or(u16::MAX).to_le_bytes());
    bytes.extend_from_slice(header.as_bytes());
    bytes.resize(bytes.len() + padded - header.len() - 1, b' ');
    bytes.push(b'\n');
    for v in values {
        bytes.extend_from_slice(&v.to_le_bytes());
    }
    bytes
}
