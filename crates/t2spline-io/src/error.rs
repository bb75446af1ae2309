//! The one error type of the I/O crate.

use crate::printable;

use std::fmt;
use std::path::PathBuf;

/// One thing wrong with a job file: where, and which rule.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Problem {
    /// Line and column (from 1; columns count characters) of the place in the
    /// file: the key of an object member or an array element; for a missing
    /// key, the member or element whose object lacks it (the root object for a
    /// top-level key). `None` for a problem with the whole file (too large, not
    /// UTF-8 at all).
    pub line_column: Option<(usize, usize)>,
    /// The place and the rule, e.g. `points[2].y: the order upper.left <= primary.left is broken: 0.7 > 0.6`.
    pub message: String,
}

impl Problem {
    /// A problem with the file as a whole, at no line and column (a fit that
    /// the data cannot give, a file too large).
    pub(crate) fn new(message: impl Into<String>) -> Self {
        Problem {
            line_column: None,
            message: message.into(),
        }
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line_column {
            Some((line, column)) => write!(f, "line {line}, column {column}: {}", self.message),
            None => f.write_str(&self.message),
        }
    }
}

/// Everything that can go wrong reading jobs and writing results.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// The job file could not be read.
    #[error("{}: cannot read", printable(&path.display().to_string()))]
    Read {
        /// The file.
        path: PathBuf,
        /// Why.
        #[source]
        source: std::io::Error,
    },
    /// The job breaks one or more rules; each problem is one line of the message.
    #[error("{}", Invalid::lines(file, problems))]
    Invalid {
        /// The file name as given (or `<stdin>` for standard input).
        file: String,
        /// Every problem found.
        problems: Vec<Problem>,
    },
    /// An output file or folder could not be written; nothing was left
    /// half-written.
    #[error("{}: cannot write", printable(&path.display().to_string()))]
    Write {
        /// The file or folder.
        path: PathBuf,
        /// Why.
        #[source]
        source: std::io::Error,
    },
    /// A computed value is NaN or infinite. Valid input never leads here (the
    /// core crate's ranges guarantee finite results); it would be a bug, and
    /// the result is not written rather than written with `null` in its place.
    #[error("internal error: {key} = {value} is not a finite number; nothing was written (please report this with the job file)")]
    NotFinite {
        /// Where in the result, e.g. `curves.defuzzified[7][1]`.
        key: String,
        /// The value.
        value: f64,
    },
}

/// Formatting of [`Error::Invalid`].
struct Invalid;

impl Invalid {
    fn lines(file: &str, problems: &[Problem]) -> String {
        let file = printable(file);
        problems
            .iter()
            .map(|p| match p.line_column {
                Some((line, column)) => format!("{file}:{line}:{column}: {}", p.message),
                None => format!("{file}: {}", p.message),
            })
            .collect::<Vec<_>>()
            .join("\n")
    }
}

impl Error {
    /// The lines of the message, one per problem: what a tool prints, each line
    /// naming the file, the place and the rule. The chain of sources (the
    /// `io::Error` of [`Error::Read`] and [`Error::Write`]) follows the message,
    /// separated by `": "`.
    ///
    /// # Examples
    /// ```
    /// # use std::path::Path;
    /// let e = t2spline_io::job::read_text(Path::new("no/such/job.json")).unwrap_err();
    /// assert_eq!(e.lines(), ["no/such/job.json: cannot read: No such file or directory (os error 2)"]);
    /// ```
    #[must_use]
    pub fn lines(&self) -> Vec<String> {
        let mut text = self.to_string();
        let mut source = std::error::Error::source(self);
        while let Some(s) = source {
            text.push_str(": ");
            text.push_str(&s.to_string());
            source = s.source();
        }
        text.lines().map(str::to_owned).collect()
    }
}
