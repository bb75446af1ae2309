//! The one error type of the I/O crate.

use std::fmt;
use std::path::PathBuf;

/// One thing wrong with a job file: where, and which rule.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Problem {
    /// Line and column (1-based) for JSON syntax errors.
    pub line_column: Option<(usize, usize)>,
    /// The place and the rule, e.g. `points[2].y: the order upper.left <= primary.left is broken: 0.7 > 0.6`.
    pub message: String,
}

impl Problem {
    /// A problem at a place named inside `message`.
    pub(crate) fn new(message: impl Into<String>) -> Self {
        Problem {
            line_column: None,
            message: message.into(),
        }
    }

    /// A problem at `key`: `"{key}: {rule}"`.
    pub(crate) fn at(key: &str, rule: impl fmt::Display) -> Self {
        Problem::new(format!("{key}: {rule}"))
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
    #[error("{}: cannot read", path.display())]
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
    #[error("{}: cannot write", path.display())]
    Write {
        /// The file or folder.
        path: PathBuf,
        /// Why.
        #[source]
        source: std::io::Error,
    },
    /// A value given on the command line breaks a rule.
    #[error("{option}: {message}")]
    Option {
        /// The option, e.g. `--alpha`.
        option: &'static str,
        /// The rule.
        message: String,
    },
}

/// Formatting of [`Error::Invalid`].
struct Invalid;

impl Invalid {
    fn lines(file: &str, problems: &[Problem]) -> String {
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
