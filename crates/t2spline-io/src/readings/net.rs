//! Readings of a net of stations, one reading per row, as a surveyor's log
//! of a grid survey exports them.
//!
//! ```text
//! row,col,x,y,z
//! 0,0,0.012,-0.004,1.503
//! 1,2,10.021,19.987,1.734      (stations in any order: a log in time order)
//! 0,0,-0.008,0.011,1.497
//! …
//! ```
//!
//! Rules, each reported with its line and column (every problem at once, at
//! most [`MAX_PROBLEMS`](crate::limits::MAX_PROBLEMS), then a count):
//! - the header is `row,col,x,y,z` (any case, spaces around names ignored),
//!   comma or semicolon separated, with a decimal comma in a semicolon file,
//!   as for the readings of a curve ([`parse_readings`](super::curve::parse_readings));
//! - `row` and `col` are whole numbers from 0, the station `(row, col)`:
//!   row `i` lies along u, column `j` along v (`points[i][j]`);
//! - the rows of a station may stand anywhere in the file; a station's
//!   readings keep their file order;
//! - the net is rows `0..R`, columns `0..C` (`R`, `C` one past the largest
//!   given), every station present: a missing station, a row shorter than
//!   the longest (ragged) and a station with fewer than
//!   [`MIN_READINGS`] readings are refused, naming the station;
//! - limits before memory: [`MAX_ROWS`](super::fields::MAX_ROWS) readings and
//!   [`MAX_POINTS`] stations, the net's `R × C` among them.

use std::collections::HashMap;

use t2spline::fit::{fuzzify_number, FuzzifyRule, FuzzyData, MIN_READINGS};
use t2spline::{Alpha, Axis, Nt2Number, Nt2Point, Num, Place};

use super::fields::{self, shorten};
use super::tokens;
use crate::error::{Error, Problem};
use crate::fit_data::FitData;
use crate::limits::{MAX_POINTS, MAX_PROBLEMS_FOUND};

/// The columns of a net's readings file.
pub(super) const NET_HEADER: [&str; 5] = ["row", "col", "x", "y", "z"];

/// Where the readings of a station came from, for messages.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum StationSource {
    /// The line of the station's first reading in a net's readings file.
    Line(usize),
    /// The cells of a raster, `rows` and `columns` half-open ranges of the
    /// raster as stored.
    Cells {
        /// The raster rows of the block, `start..end`.
        rows: [usize; 2],
        /// The raster columns of the block, `start..end`.
        columns: [usize; 2],
    },
}

/// Validated readings of the stations of a net: a readings file with the
/// header `row,col,x,y,z` ([`parse_net_readings`]) or the blocks of a raster
/// ([`parse_grid_csv`](crate::parse_grid_csv), [`parse_ascii_grid`](crate::parse_ascii_grid), [`parse_npy`](crate::parse_npy), then
/// [`Raster::blocks`](crate::Raster::blocks)).
#[derive(Clone, Debug, PartialEq)]
pub struct NetReadings {
    /// The file name used in messages.
    pub source: String,
    /// `[R, C]`: the rows of the net (along u) and the stations per row
    /// (along v).
    pub shape: [usize; 2],
    /// The readings `[x, y, z]` of every station, row by row: station
    /// `(i, j)` is `stations[i·C + j]`.
    pub stations: Vec<Vec<[f64; 3]>>,
    /// Where each station's readings came from, in the same order.
    pub sources: Vec<StationSource>,
    /// For the blocks of a raster, each station's crisp `[x, y]` (the
    /// block's centre; its readings then give `z` only); `None` for a net's
    /// readings file, whose `x`, `y` and `z` are all read.
    pub centres: Option<Vec<[f64; 2]>>,
    /// What the stations are, for the data file's description: empty for
    /// the stations of a net's readings file, `3 × 3 blocks of a raster of
    /// 9 × 12 cells` for a raster.
    pub what: String,
}

impl NetReadings {
    /// The number of readings of all stations.
    #[must_use]
    pub fn readings(&self) -> usize {
        self.stations.iter().map(Vec::len).sum()
    }
}

/// A station as read so far.
struct Station {
    /// Its readings with good values.
    values: Vec<[f64; 3]>,
    /// Its rows, good or not (at least two readings counts rows, so that a
    /// bad value is reported once).
    rows: usize,
    /// The line of its first row.
    line: usize,
}

/// Parses and validates the readings of a net from text whose header (in
/// lower case, trimmed) is `row,col,x,y,z`; `source` names the file.
///
/// # Errors
/// [`Error::Invalid`] listing every problem with its line and column: a
/// missing or extra column, a row or column that is not a whole number from
/// 0, a value that is not a finite number within the range, a station with
/// fewer than two readings, a missing station or a ragged row of the net,
/// more than [`MAX_ROWS`](super::fields::MAX_ROWS) readings or
/// [`MAX_POINTS`] stations.
///
/// # Examples
/// ```
/// let text = "row,col,x,y,z\n0,1,1,0,5\n0,0,0,0,4\n0,1,1,0,6\n0,0,0,0,5\n";
/// let net = t2spline_io::parse_net_readings(text, "net.csv")?;
/// assert_eq!(net.shape, [1, 2]);
/// assert_eq!(net.stations[1], [[1.0, 0.0, 5.0], [1.0, 0.0, 6.0]]);
/// let text = "row,col,x,y,z\n0,0,0,0,1\n0,1,1,0,1\n1,1,1,1,1\n0,0,0,0,2\n0,1,1,0,2\n1,1,1,1,2\n";
/// let e = t2spline_io::parse_net_readings(text, "n.csv").unwrap_err();
/// assert_eq!(e.lines(), ["n.csv: station (1, 0): missing; the net is rows 0..2, columns 0..2, every station needs readings"]);
/// # Ok::<(), t2spline_io::Error>(())
/// ```
pub fn parse_net_readings(text: &str, source: &str) -> Result<NetReadings, Error> {
    parse_within(text, source, super::fields::MAX_ROWS)
}

/// [`parse_net_readings`] with at most `max_rows` readings.
pub(super) fn parse_within(
    text: &str,
    source: &str,
    max_rows: usize,
) -> Result<NetReadings, Error> {
    let invalid = |problems: Vec<Problem>| Error::Invalid {
        file: source.to_owned(),
        problems,
    };
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let delimiter = fields::delimiter(text);
    let records =
        fields::records(text, delimiter, max_rows).map_err(|problem| invalid(vec![problem]))?;
    let Some((header, rows)) = records.split_first() else {
        return Err(invalid(vec![Problem::new(
            "the file is empty; expected the header `row,col,x,y,z` and one reading per row",
        )]));
    };
    if fields::names(header) != NET_HEADER {
        return Err(invalid(vec![Problem {
            line_column: header.fields.first().map(|f| (f.line, f.column)),
            message: format!(
                "expected the header `row,col,x,y,z` (comma or semicolon separated), got `{}`",
                fields::given(header, delimiter)
            ),
        }]));
    }
    let mut reader = Reader {
        delimiter,
        index: HashMap::new(),
        stations: Vec::new(),
        problems: Vec::new(),
        over_limit: false,
    };
    for row in rows {
        reader.row(row);
        if reader.problems.len() > MAX_PROBLEMS_FOUND || reader.over_limit {
            break;
        }
    }
    reader.finish(source).map_err(invalid)
}

/// The state of reading rows: the stations so far and every problem.
struct Reader {
    delimiter: char,
    /// `(row, col)` → index into `stations`.
    index: HashMap<(usize, usize), usize>,
    stations: Vec<((usize, usize), Station)>,
    problems: Vec<Problem>,
    over_limit: bool,
}

impl Reader {
    fn problem(&mut self, at: (usize, usize), message: String) {
        self.problems.push(Problem {
            line_column: Some(at),
            message,
        });
    }

    fn row(&mut self, row: &tokens::Record) {
        let width = NET_HEADER.len();
        let fields = &row.fields;
        if fields.len() < width {
            let missing: Vec<&str> = NET_HEADER.iter().skip(fields.len()).copied().collect();
            let message = format!(
                "missing column(s) {}: every row needs {width} values (row,col,x,y,z)",
                missing.join(", ")
            );
            self.problem(row.end, message);
            return;
        }
        if let Some(extra) = fields.get(width) {
            if fields.iter().skip(width).any(|f| !f.text.trim().is_empty()) {
                let message = format!(
                    "extra column {}: every row has {width} values (row,col,x,y,z)",
                    width + 1
                );
                self.problem((extra.line, extra.column), message);
                return;
            }
        }
        let mut place = [0usize; 2];
        let mut good_place = true;
        for (column, (field, index)) in fields.iter().zip(&mut place).enumerate() {
            match whole(&field.text) {
                Ok(i) => *index = i,
                Err(message) => {
                    let name = NET_HEADER.get(column).copied().unwrap_or("row");
                    self.problem(
                        (field.line, field.column),
                        format!("{name} (column {}): {message}", column + 1),
                    );
                    good_place = false;
                }
            }
        }
        let mut point = [0.0; 3];
        let mut good = true;
        for (axis, field) in fields.iter().skip(2).take(3).enumerate() {
            match fields::number(self.delimiter, &field.text) {
                Ok(x) => {
                    if let Some(c) = point.get_mut(axis) {
                        *c = x;
                    }
                }
                Err(message) => {
                    let name = NET_HEADER.get(axis + 2).copied().unwrap_or("x");
                    self.problem(
                        (field.line, field.column),
                        format!("{name} (column {}): {message}", axis + 3),
                    );
                    good = false;
                }
            }
        }
        if !good_place {
            return;
        }
        let at = fields.first().map_or(row.end, |f| (f.line, f.column));
        let [i, j] = place;
        let key = (i, j);
        let station = match self.index.get(&key) {
            Some(&s) => s,
            None => {
                if self.stations.len() == MAX_POINTS {
                    self.problem(
                        at,
                        format!(
                            "station ({}, {}): more than the limit of {MAX_POINTS} stations",
                            key.0, key.1
                        ),
                    );
                    self.over_limit = true;
                    return;
                }
                self.index.insert(key, self.stations.len());
                self.stations.push((
                    key,
                    Station {
                        values: Vec::new(),
                        rows: 0,
                        line: at.0,
                    },
                ));
                self.stations.len() - 1
            }
        };
        if let Some((_, s)) = self.stations.get_mut(station) {
            s.rows += 1;
            if good {
                s.values.push(point);
            }
        }
    }

    /// The net, or every problem: those of the rows, then those of the
    /// stations in the order of the net.
    fn finish(mut self, source: &str) -> Result<NetReadings, Vec<Problem>> {
        if self.stations.is_empty() {
            if self.problems.is_empty() {
                self.problems.push(Problem::new(
                    "no readings: after the header, one reading per row is needed",
                ));
            }
            return Err(fields::capped(self.problems));
        }
        // Not empty: the largest row and column exist.
        let rows = self
            .stations
            .iter()
            .map(|((i, _), _)| *i)
            .max()
            .unwrap_or(0);
        let columns = self
            .stations
            .iter()
            .map(|((_, j), _)| *j)
            .max()
            .unwrap_or(0);
        let (r, c) = (rows.saturating_add(1), columns.saturating_add(1));
        let Some(count) = r.checked_mul(c).filter(|&n| n <= MAX_POINTS) else {
            self.problems.push(Problem::new(format!(
                "the net is rows 0..{r}, columns 0..{c}: more than the limit of {MAX_POINTS} stations"
            )));
            return Err(fields::capped(self.problems));
        };
        // The longest extent of each row, for ragged rows.
        let mut extent: Vec<Option<usize>> = vec![None; r];
        for ((i, j), _) in &self.stations {
            if let Some(e) = extent.get_mut(*i) {
                *e = Some(e.map_or(*j, |e: usize| e.max(*j)));
            }
        }
        let longest = extent
            .iter()
            .enumerate()
            .filter_map(|(i, e)| Some((i, (*e)?)))
            .max_by_key(|&(i, e)| (e, std::cmp::Reverse(i)))
            .map_or(0, |(i, _)| i);
        let mut slots: Vec<Option<Station>> = (0..count).map(|_| None).collect();
        for ((i, j), station) in self.stations {
            if let Some(slot) = slots.get_mut(i * c + j) {
                *slot = Some(station);
            }
        }
        let mut stations = Vec::with_capacity(count);
        let mut sources = Vec::with_capacity(count);
        let mut slots = slots.into_iter();
        for i in 0..r {
            let row: Vec<Option<Station>> = slots.by_ref().take(c).collect();
            let end = extent.get(i).copied().flatten();
            match end {
                None => self.problems.push(Problem::new(format!(
                    "row {i}: no stations; the net is rows 0..{r}, columns 0..{c}, every station needs readings"
                ))),
                Some(end) if end + 1 < c => self.problems.push(Problem::new(format!(
                    "row {i}: columns 0..{}, but row {longest} has columns 0..{c}: every row of the net needs as many stations",
                    end + 1
                ))),
                Some(_) => {}
            }
            for (j, slot) in row.into_iter().enumerate() {
                match slot {
                    Some(s) => {
                        if s.rows < MIN_READINGS {
                            self.problems.push(Problem {
                                line_column: Some((s.line, 1)),
                                message: format!(
                                    "station ({i}, {j}): {} reading(s); percentiles need at least {MIN_READINGS}",
                                    s.rows
                                ),
                            });
                        }
                        stations.push(s.values);
                        sources.push(StationSource::Line(s.line));
                    }
                    // A missing station of a row that is there up to its end.
                    None if end.is_some_and(|end| j < end) => {
                        self.problems.push(Problem::new(format!(
                            "station ({i}, {j}): missing; the net is rows 0..{r}, columns 0..{c}, every station needs readings"
                        )));
                    }
                    None => {}
                }
            }
        }
        if !self.problems.is_empty() {
            return Err(fields::capped(self.problems));
        }
        Ok(NetReadings {
            source: source.to_owned(),
            shape: [r, c],
            stations,
            sources,
            centres: None,
            what: String::new(),
        })
    }
}

/// A row or column of the net: a whole number from 0 (`3`, not `3.0`).
fn whole(text: &str) -> Result<usize, String> {
    let text = text.trim();
    if text.is_empty() {
        return Err("empty; every reading names its station by row and column".into());
    }
    if !text.bytes().all(|b| b.is_ascii_digit()) {
        return Err(format!("`{}` is not a whole number from 0", shorten(text)));
    }
    text.parse::<usize>()
        .ok()
        .filter(|&n| n < MAX_POINTS)
        .ok_or_else(|| {
            format!(
                "{} is more than the limit of {MAX_POINTS} stations",
                shorten(text)
            )
        })
}

/// Whether the header of `text` is that of a net's readings, `row,col,x,y,z`.
pub(super) fn is_net(text: &str) -> bool {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let first = text.lines().find(|l| !l.trim().is_empty()).unwrap_or("");
    fields::records(first, fields::delimiter(first), 0)
        .ok()
        .and_then(|records| records.first().map(fields::names))
        .is_some_and(|names| names == NET_HEADER)
}

impl NetReadings {
    /// The fuzzy data points of the net, row by row: each coordinate of each
    /// station by the rule ([`fuzzify_number`]); for the blocks of a raster,
    /// `x` and `y` the block's centre, crisp (all seven values equal).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the station (and its line, for a net's
    /// readings file) for a value the rule takes beyond the range of
    /// coordinates, or a station with fewer than two readings.
    pub fn fuzzify(&self, rule: &FuzzifyRule) -> Result<Vec<Vec<Nt2Point<3>>>, Error> {
        let [_, columns] = self.shape;
        let mut points = Vec::with_capacity(self.stations.len());
        let mut column = Vec::new();
        for (k, readings) in self.stations.iter().enumerate() {
            let (i, j) = (k / columns.max(1), k % columns.max(1));
            let centre = self.centres.as_ref().and_then(|c| c.get(k));
            let mut numbers = Vec::with_capacity(3);
            for axis in [Axis::X, Axis::Y, Axis::Z] {
                let crisp = centre.and_then(|c| c.get(axis.index()));
                let number = match crisp {
                    Some(&c) => {
                        Nt2Number::try_new(c, [c, c], [c, c], [c, c], rule.lower_height().get())
                    }
                    None => {
                        column.clear();
                        column.extend(readings.iter().filter_map(|r| r.get(axis.index())));
                        fuzzify_number(&mut column, rule)
                    }
                };
                numbers.push(
                    number.map_err(|e| self.station_error(k, &e.at(Place::in_net(i, j, axis))))?,
                );
            }
            let Ok(coordinates) = <[Nt2Number; 3]>::try_from(numbers) else {
                // Three axes, three numbers.
                continue;
            };
            points.push(Nt2Point::new(coordinates));
        }
        Ok(points.chunks(columns.max(1)).map(<[_]>::to_vec).collect())
    }

    /// An error about station `k`, named by its row and column and placed at
    /// its first line (a net's readings file) or named by its cells (a
    /// raster).
    fn station_error(&self, k: usize, e: &t2spline::Error) -> Error {
        let columns = self.shape[1].max(1);
        let (i, j) = (k / columns, k % columns);
        let (line_column, name) = match self.sources.get(k) {
            Some(StationSource::Line(line)) => (Some((*line, 1)), format!("station ({i}, {j})")),
            Some(StationSource::Cells { rows, columns }) => (
                None,
                format!(
                    "block ({i}, {j}) (cell rows {}..{}, columns {}..{})",
                    rows[0], rows[1], columns[0], columns[1]
                ),
            ),
            None => (None, format!("station ({i}, {j})")),
        };
        Error::Invalid {
            file: self.source.clone(),
            problems: vec![Problem {
                line_column,
                message: format!("{name}: {e}"),
            }],
        }
    }

    /// The data of a fit from the fuzzy data points `points` of this net
    /// made with `rule`: a description of where they came from and how, the
    /// top-level `lower_height` of the rule, the degrees `[p, q]` (written as
    /// `degree` or `order` by `degree_key`) and the `alpha` to carry.
    #[must_use]
    pub fn fit_data(
        &self,
        points: Vec<Vec<Nt2Point<3>>>,
        rule: &FuzzifyRule,
        degree_key: &'static str,
        degrees: [usize; 2],
        alpha: Option<Alpha>,
    ) -> FitData {
        let [rows, columns] = self.shape;
        let coordinates = if self.centres.is_some() {
            "x, y = the block's centre (crisp); z"
        } else {
            "Per coordinate"
        };
        let what = if self.what.is_empty() {
            String::new()
        } else {
            format!("{}; ", self.what)
        };
        let description = format!(
            "Fuzzified by t2spline from {}: a net of {rows} × {columns} stations ({what}points[i][j]: row i along u, column j along v), {} readings. {coordinates}: crisp = median, lower = [25th, 75th percentile] (lower_height {}), primary = [10th, 90th percentile], upper = [min - T, max + T] with T = {} (percentiles by linear interpolation, type 7).",
            self.source,
            self.readings(),
            Num(rule.lower_height().get()),
            // `-0` is 0 (adding 0 turns -0 into +0).
            Num(rule.tolerance() + 0.0),
        );
        let [p, q] = degrees;
        FitData {
            source: self.source.clone(),
            description: Some(description),
            degree_key,
            degree: p,
            degree_v: Some(q),
            alpha,
            type_reduction: None,
            lower_height: Some(rule.lower_height().get()),
            samples: None,
            points: FuzzyData::Net(points),
        }
    }
}
