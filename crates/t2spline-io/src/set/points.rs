//! Query points: a CSV file with the header `x,y` or `x,y,z`, one point per row.

use std::path::Path;

use t2spline::{Num, MAX_MAGNITUDE};

use crate::error::{Error, Problem};
use crate::read::read_text;
use crate::readings::tokens::{each_record, Fault, Field, Record};

/// Rows of a query-point file at most (ten million: 240 MB of coordinates).
pub const MAX_QUERY_POINTS: usize = 10_000_000;
use crate::limits::{more_problems, MAX_PROBLEMS};

/// The points of a query-point file, in file order.
#[derive(Clone, Debug, PartialEq)]
pub enum QueryPoints {
    /// Header `x,y`.
    Plane(Vec<[f64; 2]>),
    /// Header `x,y,z`.
    Space(Vec<[f64; 3]>),
}

impl QueryPoints {
    /// The number of coordinates of each point.
    #[must_use]
    pub fn dimension(&self) -> usize {
        match self {
            QueryPoints::Plane(_) => 2,
            QueryPoints::Space(_) => 3,
        }
    }

    /// How many points.
    #[must_use]
    pub fn len(&self) -> usize {
        match self {
            QueryPoints::Plane(p) => p.len(),
            QueryPoints::Space(p) => p.len(),
        }
    }

    /// Whether there are none.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Reads a query-point file.
///
/// # Errors
/// The errors of [`read_text`] and of [`parse_points`].
pub fn read_points(path: &Path) -> Result<QueryPoints, Error> {
    let text = read_text(path)?;
    parse_points(&text, &path.display().to_string())
}

/// Parses query points: a header `x,y` or `x,y,z` (comma- or
/// semicolon-separated, as spreadsheets write; with semicolons a decimal comma
/// counts as a point), then one finite number of magnitude at most 1e150 per
/// field. `source` names the file in messages.
///
/// # Errors
/// [`Error::Invalid`] listing every problem with its line and column: a wrong
/// header, a missing or extra field, a value that is not a number or is out of
/// range, unclosed quotes, no points, more than [`MAX_QUERY_POINTS`].
///
/// # Examples
/// ```
/// use t2spline_io::set::{parse_points, QueryPoints};
/// let p = parse_points("x,y\n1,2\n3.5,-1\n", "p.csv")?;
/// assert_eq!(p, QueryPoints::Plane(vec![[1.0, 2.0], [3.5, -1.0]]));
/// let e = parse_points("x,y\n1,2\n3,two\n4\n", "p.csv").unwrap_err();
/// assert_eq!(e.lines(), [
///     "p.csv:3:3: y (column 2): `two` is not a number",
///     "p.csv:4:2: y (column 2) is missing; every row has x,y",
/// ]);
/// # Ok::<(), t2spline_io::Error>(())
/// ```
pub fn parse_points(text: &str, source: &str) -> Result<QueryPoints, Error> {
    let invalid = |problems: Vec<Problem>| Error::Invalid {
        file: source.to_owned(),
        problems,
    };
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let first_line = text.lines().next().unwrap_or("");
    let delimiter = if first_line.contains(';') { ';' } else { ',' };
    // Each row is made a point as it is read: no more memory than the points
    // (24 bytes each), and the limit refuses the file at its first row past it.
    let mut reader = PointRows::default();
    let read = each_record(text, delimiter, MAX_QUERY_POINTS.saturating_add(1), |row| {
        reader.row(row, delimiter);
    });
    if let Err(fault) = read {
        return Err(invalid(vec![match fault {
            Fault::Quote(q) => Problem {
                line_column: Some((q.line, q.column)),
                message: q.message.to_owned(),
            },
            Fault::TooMany => Problem::new(format!(
                "more than {MAX_QUERY_POINTS} points; split the file"
            )),
        }]));
    }
    let PointRows {
        dimension,
        bad_header,
        points,
        mut problems,
        more,
    } = reader;
    let Some(dimension) = dimension else {
        return Err(invalid(vec![if bad_header {
            Problem {
                line_column: Some((1, 1)),
                message: format!(
                    "the header must be x,y or x,y,z, not `{}`",
                    crate::printable(first_line.trim_end())
                ),
            }
        } else {
            Problem::new("empty: the first line must be the header x,y (or x,y,z)")
        }]));
    };
    if more > 0 {
        problems.push(Problem::new(more_problems(more, false)));
    }
    if points.is_empty() && problems.is_empty() {
        problems.push(Problem::new(
            "no points: after the header, one point per row is needed",
        ));
    }
    if !problems.is_empty() {
        return Err(invalid(problems));
    }
    Ok(match dimension {
        2 => QueryPoints::Plane(points.into_iter().map(|p| [p[0], p[1]]).collect()),
        _ => QueryPoints::Space(points),
    })
}

/// The reader of a query-point file, fed one row at a time: the header
/// first (x,y or x,y,z), then one point per row.
#[derive(Debug, Default)]
struct PointRows {
    /// 2 or 3 once the header is read.
    dimension: Option<usize>,
    /// The first row is not a header; the rows are then not read.
    bad_header: bool,
    points: Vec<[f64; 3]>,
    problems: Vec<Problem>,
    /// Problems past [`MAX_PROBLEMS`], counted.
    more: usize,
}

impl PointRows {
    fn push(&mut self, line: usize, column: usize, message: String) {
        if self.problems.len() < MAX_PROBLEMS {
            self.problems.push(Problem {
                line_column: Some((line, column)),
                message,
            });
        } else {
            self.more += 1;
        }
    }

    fn row(&mut self, row: Record, delimiter: char) {
        if self.bad_header {
            return;
        }
        let Some(dimension) = self.dimension else {
            self.header(&row);
            return;
        };
        let axes = ["x", "y", "z"];
        let mut p = [0.0; 3];
        for (c, axis) in axes.iter().enumerate().take(dimension) {
            match row.fields.get(c) {
                Some(f) => match number(f, delimiter) {
                    Ok(x) => p[c] = x,
                    Err(m) => {
                        self.push(f.line, f.column, format!("{axis} (column {}): {m}", c + 1))
                    }
                },
                None => self.push(
                    row.end.0,
                    row.end.1,
                    format!(
                        "{axis} (column {}) is missing; every row has {}",
                        c + 1,
                        axes[..dimension].join(",")
                    ),
                ),
            }
        }
        if let Some(f) = row.fields.get(dimension) {
            self.push(
                f.line,
                f.column,
                format!(
                    "column {} is one too many; every row has {}",
                    dimension + 1,
                    axes[..dimension].join(",")
                ),
            );
        }
        self.points.push(p);
    }

    /// The header: x,y or x,y,z in any case.
    fn header(&mut self, header: &Record) {
        let names: Vec<String> = header
            .fields
            .iter()
            .map(|f| f.text.trim().to_ascii_lowercase())
            .collect();
        match names
            .iter()
            .map(String::as_str)
            .collect::<Vec<_>>()
            .as_slice()
        {
            ["x", "y"] => self.dimension = Some(2),
            ["x", "y", "z"] => self.dimension = Some(3),
            _ => self.bad_header = true,
        }
    }
}

/// A coordinate: a finite number of magnitude at most 1e150.
fn number(field: &Field, delimiter: char) -> Result<f64, String> {
    let text = field.text.trim();
    let decimal = if delimiter == ';' && text.contains(',') && !text.contains('.') {
        text.replacen(',', ".", 1)
    } else {
        text.to_owned()
    };
    match decimal.parse::<f64>() {
        Ok(x) if x.is_finite() && x.abs() <= MAX_MAGNITUDE => Ok(x),
        Ok(x) if x.is_finite() => Err(format!("{} is outside [-1e150, 1e150]", Num(x))),
        Ok(_)
            if !text.to_ascii_lowercase().contains("inf")
                && !text.to_ascii_lowercase().contains("nan") =>
        {
            Err(format!(
                "`{}` is outside [-1e150, 1e150]",
                crate::printable(text)
            ))
        }
        _ if text.is_empty() => Err("empty; every coordinate needs a number".into()),
        _ => Err(format!("`{}` is not a number", crate::printable(text))),
    }
}
