//! The readings of a curve: stations, one reading per row (the format this
//! folder's face describes), read into a [`ReadingsFile`].

use std::collections::HashMap;
use std::path::Path;

use t2spline::fit::{Readings, MIN_READINGS};

use super::fields::{self, shorten, MAX_ROWS};
use super::tokens;
use crate::error::{Error, Problem};
use crate::limits::{MAX_POINTS, MAX_PROBLEMS_FOUND};
use crate::read::read_text;

/// A validated readings file.
#[derive(Clone, Debug, PartialEq)]
pub struct ReadingsFile {
    /// The file name used in messages.
    pub source: String,
    /// The station names, in the order of their first row.
    pub stations: Vec<String>,
    /// The line of each station's first row.
    pub first_lines: Vec<usize>,
    /// The readings of every station, in that order.
    pub readings: Readings,
}

/// Whether a data file given to `fit` is a readings file rather than JSON:
/// by its extension (`.csv`, `.txt`, `.tsv` are readings; `.json` is not),
/// otherwise by its first character (`{` starts JSON).
///
/// # Examples
/// ```
/// # use std::path::Path;
/// use t2spline_io::is_readings;
/// assert!(is_readings(Path::new("beach.csv"), "station,x,y\n"));
/// assert!(!is_readings(Path::new("beach.json"), "station,x,y\n"));
/// assert!(is_readings(Path::new("-"), "\u{feff}station;x;y\n"));
/// assert!(!is_readings(Path::new("-"), "  {\"degree\": 3}"));
/// ```
#[must_use]
pub fn is_readings(path: &Path, text: &str) -> bool {
    let extension = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match extension.as_deref() {
        Some("csv" | "txt" | "tsv") => true,
        Some("json") => false,
        _ => !text
            .trim_start_matches('\u{feff}')
            .trim_start()
            .starts_with('{'),
    }
}

/// Reads and validates a readings file.
///
/// # Errors
/// The errors of [`read_text`] (a file that cannot be read, is too large or is
/// not UTF-8) and of [`parse_readings`].
pub fn read_readings(path: &Path) -> Result<ReadingsFile, Error> {
    let text = read_text(path)?;
    parse_readings(&text, &path.display().to_string())
}

/// Parses and validates readings from text; `source` names the file in
/// messages.
///
/// # Errors
/// [`Error::Invalid`] listing every problem (at most
/// [`MAX_PROBLEMS`](crate::job::MAX_PROBLEMS), then a count), each with its
/// line and column: a wrong header, a missing or extra column, a value that is
/// not a finite number or beyond the range, a station with fewer than two
/// readings, unclosed quotes, more
/// than [`MAX_ROWS`] rows or [`MAX_POINTS`](crate::job::MAX_POINTS) stations.
///
/// # Examples
/// ```
/// let text = "station;x;y\r\nA;0;1,5\r\nB;0,5;2\r\nC;3;x\r\nA;1;1\r\n";
/// let e = t2spline_io::parse_readings(text, "r.csv").unwrap_err();
/// assert_eq!(e.lines(), [
///     "r.csv:4:5: y (column 3): `x` is not a number",
///     "r.csv:3:1: station `B`: 1 reading(s); percentiles need at least 2",
///     "r.csv:4:1: station `C`: 1 reading(s); percentiles need at least 2",
/// ]);
/// // The rows of a station may stand anywhere: as if sorted by station.
/// let ok = t2spline_io::parse_readings("station,x,y\nA,0,1\nB,5,5\nA,1,2\nB,6,6\n", "r.csv")?;
/// let sorted = t2spline_io::parse_readings("station,x,y\nA,0,1\nA,1,2\nB,5,5\nB,6,6\n", "r.csv")?;
/// assert_eq!(ok.stations, ["A", "B"]);
/// assert_eq!(ok.readings, sorted.readings);
/// # Ok::<(), t2spline_io::Error>(())
/// ```
pub fn parse_readings(text: &str, source: &str) -> Result<ReadingsFile, Error> {
    parse_readings_within(text, source, MAX_ROWS)
}

/// [`parse_readings`] with at most `max_rows` readings.
fn parse_readings_within(text: &str, source: &str, max_rows: usize) -> Result<ReadingsFile, Error> {
    let invalid = |problems: Vec<Problem>| Error::Invalid {
        file: source.to_owned(),
        problems,
    };
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let delimiter = fields::delimiter(text);
    // Readings are counted as they are split (the header and readings, not
    // blank lines), and splitting stops past the limit.
    let records =
        fields::records(text, delimiter, max_rows).map_err(|problem| invalid(vec![problem]))?;
    let Some((header, rows)) = records.split_first() else {
        return Err(invalid(vec![Problem::new(
            "the file is empty; expected the header `station,x,y` or `station,x,y,z` and one reading per row",
        )]));
    };
    let names = fields::names(header);
    let dimension = match names.iter().map(String::as_str).collect::<Vec<_>>()[..] {
        ["station", "x", "y"] => 2,
        ["station", "x", "y", "z"] => 3,
        _ => {
            let given = fields::given(header, delimiter);
            return Err(invalid(vec![Problem {
                line_column: header.fields.first().map(|f| (f.line, f.column)),
                message: format!(
                    "expected the header `station,x,y` or `station,x,y,z` (comma or semicolon separated), got `{}`",
                    given
                ),
            }]));
        }
    };
    let mut reader = Rows::new(delimiter, dimension);
    for row in rows {
        reader.row(row);
        if reader.problems.len() > MAX_PROBLEMS_FOUND || reader.over_limit {
            break;
        }
    }
    reader
        .finish()
        .map_err(invalid)
        .map(|(stations, first_lines, readings)| ReadingsFile {
            source: source.to_owned(),
            stations,
            first_lines,
            readings,
        })
}

/// The state of reading rows: stations so far and every problem found.
struct Rows {
    delimiter: char,
    dimension: usize,
    columns: [&'static str; 4],
    names: Vec<String>,
    first_line: Vec<usize>,
    index: HashMap<String, usize>,
    values: Vec<Vec<[f64; 3]>>,
    /// Rows per station, good or not (the rule of at least two readings
    /// counts rows, so that a bad value is reported once).
    rows: Vec<usize>,
    problems: Vec<Problem>,
    /// Too many stations: reading stops there.
    over_limit: bool,
}

impl Rows {
    fn new(delimiter: char, dimension: usize) -> Self {
        Rows {
            delimiter,
            dimension,
            columns: ["station", "x", "y", "z"],
            names: Vec::new(),
            first_line: Vec::new(),
            index: HashMap::new(),
            values: Vec::new(),
            rows: Vec::new(),
            problems: Vec::new(),
            over_limit: false,
        }
    }

    fn problem(&mut self, at: (usize, usize), message: String) {
        self.problems.push(Problem {
            line_column: Some(at),
            message,
        });
    }

    /// The header's columns of a row of this file, `station,x,y`.
    fn header(&self) -> String {
        let width = self.dimension + 1;
        let columns: Vec<&str> = self.columns.iter().take(width).copied().collect();
        columns.join(&self.delimiter.to_string())
    }

    fn row(&mut self, row: &tokens::Record) {
        let width = self.dimension + 1;
        let fields = &row.fields;
        if fields.len() < width {
            let missing: Vec<&str> = self
                .columns
                .iter()
                .take(width)
                .skip(fields.len())
                .copied()
                .collect();
            let message = format!(
                "missing column(s) {}: every row needs {width} values ({})",
                missing.join(", "),
                self.header()
            );
            self.problem(row.end, message);
            return;
        }
        if let Some(extra) = fields.get(width) {
            if fields.iter().skip(width).any(|f| !f.text.trim().is_empty()) {
                let message = format!(
                    "extra column {}: every row has {width} values ({})",
                    width + 1,
                    self.header()
                );
                self.problem((extra.line, extra.column), message);
                return;
            }
        }
        // At least `width` fields (checked above): the station, then values.
        let Some((first, values)) = fields.split_first() else {
            return;
        };
        let mut point = [0.0; 3];
        let mut good = true;
        for ((axis, field), (coordinate, name)) in values
            .iter()
            .take(self.dimension)
            .enumerate()
            .zip(point.iter_mut().zip(self.columns.iter().skip(1)))
        {
            match fields::number(self.delimiter, &field.text) {
                Ok(x) => *coordinate = x,
                Err(message) => {
                    self.problems.push(Problem {
                        line_column: Some((field.line, field.column)),
                        message: format!("{name} (column {}): {message}", axis + 2),
                    });
                    good = false;
                }
            }
        }
        let name = first.text.trim();
        let at = (first.line, first.column);
        if name.is_empty() {
            self.problem(
                at,
                "station (column 1): empty; every row names its station".into(),
            );
            return;
        }
        let station = match self.index.get(name) {
            Some(&s) => s,
            None => {
                if self.names.len() == MAX_POINTS {
                    self.problem(
                        at,
                        format!(
                            "station `{}`: more than the limit of {MAX_POINTS} stations",
                            shorten(name)
                        ),
                    );
                    self.over_limit = true;
                    return;
                }
                self.index.insert(name.to_owned(), self.names.len());
                self.names.push(name.to_owned());
                self.first_line.push(at.0);
                self.values.push(Vec::new());
                self.rows.push(0);
                self.names.len() - 1
            }
        };
        // `station` indexes the lists, which grow together.
        if let Some(rows) = self.rows.get_mut(station) {
            *rows += 1;
        }
        if let (true, Some(values)) = (good, self.values.get_mut(station)) {
            values.push(point);
        }
    }

    /// The stations and their readings, or every problem.
    fn finish(mut self) -> Result<(Vec<String>, Vec<usize>, Readings), Vec<Problem>> {
        for ((name, &count), &line) in self.names.iter().zip(&self.rows).zip(&self.first_line) {
            if count < MIN_READINGS && self.problems.len() <= MAX_PROBLEMS_FOUND {
                self.problems.push(Problem {
                    line_column: Some((line, 1)),
                    message: format!(
                        "station `{}`: {count} reading(s); percentiles need at least {MIN_READINGS}",
                        shorten(name)
                    ),
                });
            }
        }
        if self.names.is_empty() && self.problems.is_empty() {
            self.problems.push(Problem::new(
                "no readings: after the header, one reading per row is needed",
            ));
        }
        if !self.problems.is_empty() {
            return Err(fields::capped(self.problems));
        }
        let readings = if self.dimension == 2 {
            Readings::Planar(
                self.values
                    .iter()
                    .map(|s| s.iter().map(|&[x, y, _]| [x, y]).collect())
                    .collect(),
            )
        } else {
            Readings::Spatial(self.values)
        };
        Ok((self.names, self.first_line, readings))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn problems(text: &str, max_rows: usize) -> Vec<String> {
        match parse_readings_within(text, "r.csv", max_rows) {
            Ok(_) => Vec::new(),
            Err(e) => e.lines(),
        }
    }

    #[test]
    fn the_limit_counts_readings_not_lines() {
        // Four readings and the header, with blank lines around them: within a
        // limit of four readings, whatever the line count.
        let text = "station,x,y\n\nA,0,1\nA,1,2\n\r\n   \nB,2,3\nB,3,4\n\n\n";
        assert_eq!(problems(text, 4), Vec::<String>::new());
        assert_eq!(
            problems(text, 3),
            ["r.csv: more than the limit of 3 readings (rows after the header; blank lines do not count)"]
        );
        // Lone carriage returns end rows for the limit as for reading.
        assert_eq!(
            problems("station,x,y\rA,0,1\rA,1,2\rB,2,3\rB,3,4\r", 3).len(),
            1
        );
    }
}
