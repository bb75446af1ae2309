//! Readings of a raster: a grid of single readings of height, whose `K × K`
//! blocks of cells are the repeated readings of the stations of a net.
//!
//! Three formats:
//! - a CSV file with the header `x,y,z` (comma or semicolon, as readings
//!   files), one cell per row: the cells' centres `x`, `y` on a regular
//!   grid and the reading `z`, empty or `nan` where there is none. The
//!   raster's columns are its distinct `x` in the order of their first row,
//!   its rows the distinct `y` likewise, so a file written row by row or
//!   column by column is stored as written; each must be evenly spaced, and
//!   every cell given once;
//! - an ESRI ASCII grid (`.asc`): the header `ncols`, `nrows`, `xllcorner`
//!   or `xllcenter`, `yllcorner` or `yllcenter`, `cellsize` and optionally
//!   `NODATA_value` (any case, any order), then `nrows × ncols` values, row 0
//!   the north edge;
//! - a numpy `.npy` array ([`npy`](super::npy)), with the centre of cell
//!   `(0, 0)` and the spacing given ([`RasterGeometry`]).
//!
//! A cell without data (empty, NaN, or the `NODATA_value`) is left out of
//! its block. The net's station `(i, j)` is the block of raster rows
//! `i·K..(i+1)·K` and columns `j·K..(j+1)·K`, as stored: u runs down the
//! raster's rows (north to south for an ESRI grid), v along its columns.
//! Its `x`, `y` are the block's centre, crisp; its `z` readings the cells'
//! values. Rows and columns past the last whole block are left out, and
//! said ([`Raster::blocks`]).

use t2spline::MAX_MAGNITUDE;

use super::fields::{self, shorten};
use super::net::{NetReadings, StationSource};
use crate::error::{Error, Problem};
use crate::limits::{MAX_POINTS, MAX_PROBLEMS_FOUND};

/// A line and a character column, from 1.
type At = (usize, usize);

/// The most cells a raster may have: 16 777 216 (`4096 × 4096`), 128 MiB of
/// 64-bit floats.
pub const MAX_RASTER_CELLS: usize = 1 << 24;

/// Where the cells of an array lie: the centre of cell `(0, 0)` and the
/// step from cell to cell.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterGeometry {
    /// `[x0, y0]`: the centre of the cell at row 0, column 0.
    pub origin: [f64; 2],
    /// `[dx, dy]`: `x` grows by `dx` per column, `y` by `dy` per row (`dy`
    /// negative when row 0 is the north edge).
    pub spacing: [f64; 2],
}

/// A raster as read: `z` per cell (NaN: no data), row by row as stored, and
/// the centre of each column and row.
#[derive(Clone, Debug, PartialEq)]
pub struct Raster {
    /// The file name used in messages.
    pub source: String,
    /// `[rows, columns]` as stored.
    pub shape: [usize; 2],
    /// The readings, row by row; NaN where a cell holds no data.
    pub values: Vec<f64>,
    /// The `x` of each column's centres.
    pub x: Vec<f64>,
    /// The `y` of each row's centres.
    pub y: Vec<f64>,
}

impl Raster {
    /// The readings of the net whose station `(i, j)` is the `block × block`
    /// cells from row `i·block`, column `j·block`, with a note for the rows
    /// and columns left out at the far edges (`None` when none are).
    ///
    /// # Errors
    /// [`Error::Invalid`] for a raster smaller than one block, more than
    /// [`MAX_POINTS`] blocks, or blocks with fewer than two cells holding
    /// data, each named (every one, at most
    /// [`MAX_PROBLEMS`](crate::limits::MAX_PROBLEMS)).
    ///
    /// # Examples
    /// ```
    /// let text = "ncols 4\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3 4\n5 6 7 8\n";
    /// let raster = t2spline_io::parse_ascii_grid(text, "g.asc")?;
    /// let (net, note) = raster.blocks(2)?;
    /// assert_eq!(net.shape, [1, 2]);
    /// assert_eq!(net.centres, Some(vec![[1.0, 1.0], [3.0, 1.0]]));
    /// assert_eq!(net.stations[1].iter().map(|r| r[2]).collect::<Vec<_>>(), [3.0, 4.0, 7.0, 8.0]);
    /// assert_eq!(note, None);
    /// # Ok::<(), t2spline_io::Error>(())
    /// ```
    pub fn blocks(&self, block: usize) -> Result<(NetReadings, Option<String>), Error> {
        let invalid = |problems: Vec<Problem>| Error::Invalid {
            file: self.source.clone(),
            problems,
        };
        let [rows, columns] = self.shape;
        let k = block.max(1);
        let (r, c) = (rows / k, columns / k);
        if r == 0 || c == 0 {
            return Err(invalid(vec![Problem::new(format!(
                "a raster of {rows} × {columns} cells holds no whole block of {k} × {k} cells"
            ))]));
        }
        let Some(count) = r.checked_mul(c).filter(|&n| n <= MAX_POINTS) else {
            return Err(invalid(vec![Problem::new(format!(
                "{r} × {c} blocks of {k} × {k} cells: more than the limit of {MAX_POINTS} stations; give a larger block"
            ))]));
        };
        let mut stations = Vec::with_capacity(count);
        let mut sources = Vec::with_capacity(count);
        let mut centres = Vec::with_capacity(count);
        let mut problems = Vec::new();
        for i in 0..r {
            let rows_of = [i * k, (i + 1) * k];
            let y = centre(&self.y, rows_of);
            for j in 0..c {
                let columns_of = [j * k, (j + 1) * k];
                let x = centre(&self.x, columns_of);
                let readings: Vec<[f64; 3]> = (rows_of[0]..rows_of[1])
                    .flat_map(|row| {
                        self.values
                            .get(row * columns + columns_of[0]..row * columns + columns_of[1])
                            .unwrap_or(&[])
                    })
                    .filter(|z| !z.is_nan())
                    .map(|&z| [x, y, z])
                    .collect();
                if readings.len() < t2spline::fit::MIN_READINGS
                    && problems.len() <= MAX_PROBLEMS_FOUND
                {
                    problems.push(Problem::new(format!(
                        "block ({i}, {j}) (cell rows {}..{}, columns {}..{}): {} reading(s) with data; percentiles need at least {}",
                        rows_of[0],
                        rows_of[1],
                        columns_of[0],
                        columns_of[1],
                        readings.len(),
                        t2spline::fit::MIN_READINGS
                    )));
                }
                stations.push(readings);
                sources.push(StationSource::Cells {
                    rows: rows_of,
                    columns: columns_of,
                });
                centres.push([x, y]);
            }
        }
        if !problems.is_empty() {
            return Err(invalid(fields::capped(problems)));
        }
        let (left_rows, left_columns) = (rows - r * k, columns - c * k);
        let note = (left_rows > 0 || left_columns > 0).then(|| {
            let mut parts = Vec::new();
            if left_rows > 0 {
                parts.push(format!("the last {left_rows} row(s) (rows {}..{rows})", r * k));
            }
            if left_columns > 0 {
                parts.push(format!(
                    "the last {left_columns} column(s) (columns {}..{columns})",
                    c * k
                ));
            }
            format!(
                "{}: {} of the raster as stored fill no whole block of {k} × {k} cells and were left out",
                crate::printable(&self.source),
                parts.join(" and ")
            )
        });
        Ok((
            NetReadings {
                source: self.source.clone(),
                shape: [r, c],
                stations,
                sources,
                centres: Some(centres),
                what: format!("{k} × {k} blocks of a raster of {rows} × {columns} cells"),
            },
            note,
        ))
    }
}

/// The centre of the cells `range` of `at` (their first and last centre's
/// midpoint, exact for a regular grid).
fn centre(at: &[f64], range: [usize; 2]) -> f64 {
    let first = at.get(range[0]).copied().unwrap_or(0.0);
    let last = at.get(range[1].saturating_sub(1)).copied().unwrap_or(first);
    first + (last - first) / 2.0
}

/// Reads a raster of the CSV format (`x,y,z`, one cell per row); `source`
/// names the file in messages.
///
/// # Errors
/// [`Error::Invalid`] listing every problem with its line and column: a
/// wrong header, a missing or extra column, an `x` or `y` that is not a
/// number, a `z` that is neither a number nor empty nor `nan`, a cell given
/// twice, cells missing from the grid, uneven spacing, more than
/// [`MAX_ROWS`](super::fields::MAX_ROWS) rows.
///
/// # Examples
/// ```
/// let text = "x,y,z\n0,10,1\n1,10,2\n0,9,nan\n1,9,4\n";
/// let raster = t2spline_io::parse_grid_csv(text, "g.csv")?;
/// assert_eq!(raster.shape, [2, 2]);
/// assert_eq!((raster.x.clone(), raster.y.clone()), (vec![0.0, 1.0], vec![10.0, 9.0]));
/// assert!(raster.values[2].is_nan());
/// # Ok::<(), t2spline_io::Error>(())
/// ```
pub fn parse_grid_csv(text: &str, source: &str) -> Result<Raster, Error> {
    let invalid = |problems: Vec<Problem>| Error::Invalid {
        file: source.to_owned(),
        problems,
    };
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let delimiter = fields::delimiter(text);
    let records = fields::records(
        text,
        delimiter,
        super::fields::MAX_ROWS.min(MAX_RASTER_CELLS),
    )
    .map_err(|p| invalid(vec![p]))?;
    let Some((header, rows)) = records.split_first() else {
        return Err(invalid(vec![Problem::new(
            "the file is empty; expected the header `x,y,z` and one cell per row",
        )]));
    };
    if fields::names(header) != ["x", "y", "z"] {
        return Err(invalid(vec![Problem {
            line_column: header.fields.first().map(|f| (f.line, f.column)),
            message: format!(
                "expected the header `x,y,z` of a raster (comma or semicolon separated), got `{}`",
                fields::given(header, delimiter)
            ),
        }]));
    }
    let mut problems = Vec::new();
    let mut cells: Vec<([f64; 2], f64, usize)> = Vec::with_capacity(rows.len());
    for row in rows {
        if problems.len() > MAX_PROBLEMS_FOUND {
            break;
        }
        let f = &row.fields;
        if f.len() < 3 {
            let missing: Vec<&str> = ["x", "y", "z"].iter().skip(f.len()).copied().collect();
            problems.push(Problem {
                line_column: Some(row.end),
                message: format!(
                    "missing column(s) {}: every row needs 3 values (x,y,z)",
                    missing.join(", ")
                ),
            });
            continue;
        }
        if let Some(extra) = f.iter().skip(3).find(|f| !f.text.trim().is_empty()) {
            problems.push(Problem {
                line_column: Some((extra.line, extra.column)),
                message: "extra column 4: every row has 3 values (x,y,z)".into(),
            });
            continue;
        }
        let mut xy = [0.0; 2];
        let mut good = true;
        for (axis, (field, name)) in f.iter().zip(["x", "y"]).enumerate() {
            match fields::number(delimiter, &field.text) {
                Ok(v) => {
                    if let Some(c) = xy.get_mut(axis) {
                        *c = v;
                    }
                }
                Err(m) => {
                    problems.push(Problem {
                        line_column: Some((field.line, field.column)),
                        message: format!("{name} (column {}): {m}", axis + 1),
                    });
                    good = false;
                }
            }
        }
        let z = match f.get(2) {
            Some(field) => {
                let t = field.text.trim();
                if t.is_empty() || t.eq_ignore_ascii_case("nan") {
                    Some(f64::NAN)
                } else {
                    match fields::number(delimiter, t) {
                        Ok(v) => Some(v),
                        Err(m) => {
                            problems.push(Problem {
                                line_column: Some((field.line, field.column)),
                                message: format!(
                                    "z (column 3): {m}; a cell without data is empty or `nan`"
                                ),
                            });
                            None
                        }
                    }
                }
            }
            None => None,
        };
        if let (true, Some(z)) = (good, z) {
            cells.push((xy, z, row.end.0));
        }
    }
    if !problems.is_empty() {
        return Err(invalid(fields::capped(problems)));
    }
    let xs = axis_values(cells.iter().map(|(p, _, _)| p[0]));
    let ys = axis_values(cells.iter().map(|(p, _, _)| p[1]));
    for (name, values) in [("x", &xs), ("y", &ys)] {
        if let Some(message) = uneven(name, values) {
            problems.push(Problem::new(message));
        }
    }
    if cells.is_empty() {
        problems.push(Problem::new(
            "no cells: after the header, one cell per row is needed",
        ));
    }
    if !problems.is_empty() {
        return Err(invalid(problems));
    }
    let (rows_n, columns_n) = (ys.len(), xs.len());
    let Some(count) = rows_n
        .checked_mul(columns_n)
        .filter(|&n| n <= MAX_RASTER_CELLS)
    else {
        return Err(invalid(vec![Problem::new(format!(
            "a grid of {rows_n} × {columns_n} cells is more than the limit of {MAX_RASTER_CELLS}"
        ))]));
    };
    let column_of = index_of(&xs);
    let row_of = index_of(&ys);
    let mut values = vec![f64::NAN; count];
    let mut line_of: Vec<usize> = vec![0; count];
    for ([x, y], z, line) in &cells {
        let (Some(j), Some(i)) = (column_of(*x), row_of(*y)) else {
            continue;
        };
        let k = i * columns_n + j;
        match line_of.get(k).copied() {
            Some(0) => {
                if let (Some(v), Some(l)) = (values.get_mut(k), line_of.get_mut(k)) {
                    *v = *z;
                    *l = *line;
                }
            }
            Some(first) if problems.len() <= MAX_PROBLEMS_FOUND => {
                problems.push(Problem {
                    line_column: Some((*line, 1)),
                    message: format!(
                        "cell (x {}, y {}): given again (first at line {first}); every cell once",
                        t2spline::Num(*x),
                        t2spline::Num(*y)
                    ),
                });
            }
            Some(_) | None => {}
        }
    }
    for (k, &line) in line_of.iter().enumerate() {
        if line == 0 && problems.len() <= MAX_PROBLEMS_FOUND {
            let (x, y) = (
                xs.get(k % columns_n).copied().unwrap_or(0.0),
                ys.get(k / columns_n).copied().unwrap_or(0.0),
            );
            problems.push(Problem::new(format!(
                "cell (x {}, y {}): missing; every cell of the grid needs a row (a cell without data: `z` empty or `nan`)",
                t2spline::Num(x),
                t2spline::Num(y)
            )));
        }
    }
    if !problems.is_empty() {
        return Err(invalid(fields::capped(problems)));
    }
    Ok(Raster {
        source: source.to_owned(),
        shape: [rows_n, columns_n],
        values,
        x: xs,
        y: ys,
    })
}

/// The distinct values of one coordinate, in the order they first appear.
fn axis_values(values: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut seen = std::collections::HashSet::new();
    // `+ 0.0` makes -0 and 0 one value.
    values
        .map(|v| v + 0.0)
        .filter(|v| seen.insert(v.to_bits()))
        .collect()
}

/// The index of a value among `values` (distinct).
fn index_of(values: &[f64]) -> impl Fn(f64) -> Option<usize> {
    let map: std::collections::HashMap<u64, usize> = values
        .iter()
        .enumerate()
        .map(|(i, v)| (v.to_bits(), i))
        .collect();
    move |v| map.get(&(v + 0.0).to_bits()).copied()
}

/// Why `values` (in order) are not evenly spaced, if they are not: every
/// step within a millionth of the first.
fn uneven(name: &str, values: &[f64]) -> Option<String> {
    let (&first, &second) = (values.first()?, values.get(1)?);
    let step = second - first;
    values.iter().enumerate().find_map(|(i, &v)| {
        let expected = first + step * i as f64;
        ((v - expected).abs() > 1e-6 * step.abs()).then(|| {
            format!(
                "the {name} of the cells are not evenly spaced: in the order of their first row they begin {}, {}, so the {}th would be {}, but it is {}; a raster is a regular grid",
                t2spline::Num(first),
                t2spline::Num(second),
                i + 1,
                t2spline::Num(expected),
                t2spline::Num(v)
            )
        })
    })
}

/// Reads an ESRI ASCII grid; `source` names the file in messages.
///
/// # Errors
/// [`Error::Invalid`] with the line and column of each problem: a missing,
/// repeated or unknown header key, a header value out of its range (a
/// positive whole `ncols` and `nrows`, a positive `cellsize`), a value that
/// is not a number, more or fewer values than `nrows × ncols`, more than
/// [`MAX_RASTER_CELLS`] cells (checked before they are stored).
///
/// # Examples
/// ```
/// let text = "NCOLS 2\nNROWS 2\nXLLCENTER 100\nYLLCENTER 200\nCELLSIZE 5\nNODATA_VALUE -9999\n1 -9999\n3 4\n";
/// let raster = t2spline_io::parse_ascii_grid(text, "g.asc")?;
/// assert_eq!((raster.x.clone(), raster.y.clone()), (vec![100.0, 105.0], vec![205.0, 200.0]));
/// assert!(raster.values[1].is_nan());
/// # Ok::<(), t2spline_io::Error>(())
/// ```
pub fn parse_ascii_grid(text: &str, source: &str) -> Result<Raster, Error> {
    let invalid = |problems: Vec<Problem>| Error::Invalid {
        file: source.to_owned(),
        problems,
    };
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut words = Words::new(text);
    // The header: `key value` pairs until the first word that is a number.
    let mut header: Vec<(String, f64, At)> = Vec::new();
    let mut problems = Vec::new();
    while let Some((word, at)) = words.peek() {
        if word.parse::<f64>().is_ok() || word.eq_ignore_ascii_case("nan") {
            break;
        }
        let key = word.to_ascii_lowercase();
        words.next();
        let known = [
            "ncols",
            "nrows",
            "xllcorner",
            "xllcenter",
            "yllcorner",
            "yllcenter",
            "cellsize",
            "nodata_value",
        ];
        if !known.contains(&key.as_str()) {
            problems.push(Problem {
                line_column: Some(at),
                message: format!(
                    "`{}` is not a key of an ESRI ASCII grid's header (ncols, nrows, xllcorner or xllcenter, yllcorner or yllcenter, cellsize, NODATA_value)",
                    shorten(word)
                ),
            });
            words.next();
            continue;
        }
        match words.next() {
            Some((value, vat)) => match value.parse::<f64>() {
                Ok(v) if v.is_finite() && v.abs() <= MAX_MAGNITUDE => {
                    if let Some((_, _, first)) = header.iter().find(|(k, _, _)| *k == key) {
                        problems.push(Problem {
                            line_column: Some(at),
                            message: format!(
                                "{key}: given again (first at line {}); each key once",
                                first.0
                            ),
                        });
                    }
                    header.push((key, v, at));
                }
                _ => problems.push(Problem {
                    line_column: Some(vat),
                    message: format!("{key}: `{}` is not a finite number", shorten(value)),
                }),
            },
            None => problems.push(Problem {
                line_column: Some(at),
                message: format!("{key}: no value"),
            }),
        }
    }
    let get = |key: &str| {
        header
            .iter()
            .find(|(k, _, _)| k == key)
            .map(|(_, v, at)| (*v, *at))
    };
    let need = |keys: &[&str], problems: &mut Vec<Problem>| -> Option<(f64, At, usize)> {
        let found: Vec<(f64, At, usize)> = keys
            .iter()
            .enumerate()
            .filter_map(|(i, k)| get(k).map(|(v, at)| (v, at, i)))
            .collect();
        match found.as_slice() {
            [one] => Some(*one),
            [] => {
                problems.push(Problem::new(format!(
                    "the header has no {}",
                    keys.join(" or ")
                )));
                None
            }
            [_, (_, at, _), ..] => {
                problems.push(Problem {
                    line_column: Some(*at),
                    message: format!("give one of {}, not both", keys.join(" and ")),
                });
                None
            }
        }
    };
    let ncols = need(&["ncols"], &mut problems);
    let nrows = need(&["nrows"], &mut problems);
    let xll = need(&["xllcorner", "xllcenter"], &mut problems);
    let yll = need(&["yllcorner", "yllcenter"], &mut problems);
    let cellsize = need(&["cellsize"], &mut problems);
    let nodata = get("nodata_value").map(|(v, _)| v);
    let count = |what: &str, v: Option<(f64, At, usize)>, problems: &mut Vec<Problem>| {
        let (v, at, _) = v?;
        if v >= 1.0 && v.fract() == 0.0 && v <= MAX_RASTER_CELLS as f64 {
            Some(v as usize)
        } else {
            problems.push(Problem {
                line_column: Some(at),
                message: format!(
                    "{what} = {}: a whole number from 1 to {MAX_RASTER_CELLS}",
                    t2spline::Num(v)
                ),
            });
            None
        }
    };
    let columns = count("ncols", ncols, &mut problems);
    let rows = count("nrows", nrows, &mut problems);
    let size = cellsize.and_then(|(v, at, _)| {
        if v > 0.0 {
            Some(v)
        } else {
            problems.push(Problem {
                line_column: Some(at),
                message: format!("cellsize = {}: a positive number", t2spline::Num(v)),
            });
            None
        }
    });
    let (Some(columns), Some(rows), Some(size), Some(xll), Some(yll)) =
        (columns, rows, size, xll, yll)
    else {
        return Err(invalid(fields::capped(problems)));
    };
    if !problems.is_empty() {
        return Err(invalid(fields::capped(problems)));
    }
    let Some(cells) = rows.checked_mul(columns).filter(|&n| n <= MAX_RASTER_CELLS) else {
        return Err(invalid(vec![Problem::new(format!(
            "a grid of {rows} × {columns} cells is more than the limit of {MAX_RASTER_CELLS}"
        ))]));
    };
    // A value takes at least two characters (itself and a space): a short
    // file that claims many cells does not get their memory.
    let mut values = Vec::with_capacity(cells.min(text.len() / 2 + 1));
    let mut last = (1, 1);
    for (word, at) in words.by_ref() {
        last = at;
        if values.len() == cells {
            problems.push(Problem {
                line_column: Some(at),
                message: format!("more values than nrows × ncols = {rows} × {columns} = {cells}"),
            });
            break;
        }
        let v = if word.eq_ignore_ascii_case("nan") {
            f64::NAN
        } else {
            match word.parse::<f64>() {
                Ok(v) if v.is_finite() && v.abs() <= MAX_MAGNITUDE => v,
                Ok(v) if Some(v) == nodata => v,
                Ok(v) if v.is_finite() => {
                    problems.push(Problem {
                        line_column: Some(at),
                        message: format!("{} is outside [-1e150, 1e150]", t2spline::Num(v)),
                    });
                    f64::NAN
                }
                _ => {
                    problems.push(Problem {
                        line_column: Some(at),
                        message: format!("`{}` is not a number", shorten(word)),
                    });
                    f64::NAN
                }
            }
        };
        values.push(if Some(v) == nodata { f64::NAN } else { v });
        if problems.len() > MAX_PROBLEMS_FOUND {
            break;
        }
    }
    if values.len() < cells && problems.len() <= MAX_PROBLEMS_FOUND {
        problems.push(Problem {
            line_column: Some(last),
            message: format!(
                "{} value(s), but nrows × ncols = {rows} × {columns} = {cells}",
                values.len()
            ),
        });
    }
    if !problems.is_empty() {
        return Err(invalid(fields::capped(problems)));
    }
    // Cell centres: a corner is half a cell from the first centre; row 0
    // is the north edge, the lower-left the south-west.
    let x0 = if xll.2 == 0 {
        xll.0 + size / 2.0
    } else {
        xll.0
    };
    let y_south = if yll.2 == 0 {
        yll.0 + size / 2.0
    } else {
        yll.0
    };
    let x = (0..columns).map(|j| x0 + size * j as f64).collect();
    let y = (0..rows)
        .map(|i| y_south + size * (rows - 1 - i) as f64)
        .collect();
    Ok(Raster {
        source: source.to_owned(),
        shape: [rows, columns],
        values,
        x,
        y,
    })
}

/// The words of a text separated by white space, each with its line and
/// column.
struct Words<'t> {
    rest: std::iter::Peekable<WordIter<'t>>,
}

struct WordIter<'t> {
    text: &'t str,
    position: usize,
    line: usize,
    column: usize,
}

impl<'t> Iterator for WordIter<'t> {
    type Item = (&'t str, At);

    fn next(&mut self) -> Option<Self::Item> {
        let rest = self.text.get(self.position..)?;
        let mut start = None;
        for (offset, c) in rest.char_indices() {
            match (start, c.is_whitespace()) {
                (None, true) => {
                    if c == '\n' {
                        self.line += 1;
                        self.column = 1;
                    } else {
                        self.column += 1;
                    }
                }
                (None, false) => start = Some((offset, (self.line, self.column))),
                (Some((from, at)), true) => {
                    let word = rest.get(from..offset)?;
                    self.position += offset;
                    self.column += word.chars().count();
                    return Some((word, at));
                }
                (Some(_), false) => {}
            }
        }
        let (from, at) = start?;
        let word = rest.get(from..)?;
        self.position = self.text.len();
        Some((word, at))
    }
}

impl<'t> Words<'t> {
    fn new(text: &'t str) -> Self {
        Words {
            rest: WordIter {
                text,
                position: 0,
                line: 1,
                column: 1,
            }
            .peekable(),
        }
    }

    fn peek(&mut self) -> Option<(&'t str, At)> {
        self.rest.peek().copied()
    }
}

impl<'t> Iterator for Words<'t> {
    type Item = (&'t str, At);

    fn next(&mut self) -> Option<Self::Item> {
        self.rest.next()
    }
}
