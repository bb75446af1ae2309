//! Job files (docs/jobs.md) and data files for fitting: reading, validating every
//! rule at once, and writing back.
//!
//! A job file becomes the core crate's [`Job`], which
//! [`Job::run`](t2spline::job::Job::run) computes; a data file becomes a
//! [`FitData`], whose points [`t2spline::fit::FuzzyData::fit`] fits.

// The input decides the indices here: no indexing that can panic (`get`,
// iterators, `split_first`), as ARCHITECTURE.md explains.
#![cfg_attr(not(test), deny(clippy::indexing_slicing))]

mod common;
mod non_finite;
pub(crate) mod parse;
mod place;
mod point;
mod position;
mod schema;
mod surface;
#[cfg(test)]
mod tests;
mod valid;
mod walker;
mod weights;

pub use crate::job_json::job_json;
pub use crate::limits::{
    more_problems, MAX_ARRAY, MAX_FILE_BYTES, MAX_KEYS, MAX_NESTING, MAX_ORDER, MAX_POINTS,
    MAX_PROBLEMS, MAX_SURFACE_WORK, MAX_VALUES,
};
pub use crate::read::{read_text, read_text_from};
pub use non_finite::non_finite;
pub use place::{child, element};
pub use position::{locate, LineColumn};

use std::path::Path;

use t2spline::job::Job;

use crate::error::Error;
use crate::fit_data::FitData;

/// Parses and validates a job from JSON text; `source` names the file in
/// messages.
///
/// # Errors
/// [`Error::Invalid`] listing every problem found: JSON syntax (a text that
/// is JSON but for the words `NaN`, `Infinity` or `-Infinity` names each word
/// at its place instead, as [`non_finite`] does), duplicate,
/// unknown or missing keys, wrong types, the limits of [`MAX_FILE_BYTES`] and the other `MAX_*` constants, and
/// every rule of docs/method.md §1, §6, docs/jobs.md and, for a surface job (`points` given as
/// rows of a net), docs/method.md §8. Each names its line and column (of the key or element
/// concerned; for a missing key, of the object that lacks it) and its place
/// (`points[2].y`, `weights[1]`, `knots`, and in a surface job
/// `points[2][1].y`, `weights[2][1]`, `knots.v`, ...).
///
/// # Examples
/// ```
/// let e = t2spline_io::parse_job(r#"{"order": 2, "alhpa": 0.5, "points": []}"#, "job.json").unwrap_err();
/// assert_eq!(e.lines(), [
///     "job.json:1:14: alhpa: unknown key (did you mean `alpha`?)",
///     "job.json:1:28: points: a curve of order 2 needs at least 2 control points, got 0",
/// ]);
/// let e = t2spline_io::parse_job(r#"{"order": [2, 2], "knots": {"w": []}, "points": [[], [1]]}"#, "s.json").unwrap_err();
/// assert_eq!(e.lines(), [
///     "s.json:1:54: points[1]: 1 column, row 0 has 0: every row of the net needs as many points",
///     "s.json:1:55: points[1][0]: expected a point (a JSON object), got a number",
///     "s.json:1:29: knots.w: unknown key (known keys: u, v)",
/// ]);
/// ```
pub fn parse_job(text: &str, source: &str) -> Result<Job, Error> {
    parse::parse(text).map_err(|problems| Error::Invalid {
        file: source.to_owned(),
        problems,
    })
}

/// Reads and validates a job file.
///
/// # Errors
/// The errors of [`read_text`] (a file that cannot be read, is too large or
/// is not UTF-8) and of [`parse_job`].
pub fn read_job(path: &Path) -> Result<Job, Error> {
    let text = read_text(path)?;
    parse_job(&text, &path.display().to_string())
}

/// Parses and validates a data file for fitting; `source` names it in
/// messages.
///
/// # Errors
/// [`Error::Invalid`] listing every problem: those of [`parse_job`] (without
/// the rules for weights and knots, which a data file must not give), fewer
/// than `degree + 1` points, degree 0.
///
/// # Examples
/// ```
/// let e = t2spline_io::parse_data(r#"{"degree": 2, "knots": [0, 1], "points": []}"#, "data.json").unwrap_err();
/// assert_eq!(e.lines(), [
///     "data.json:1:15: knots: not allowed in a data file: the fit makes the weights (all 1) and the knots",
///     "data.json:1:32: points: a curve of degree 2 needs at least 3 data points, got 0",
/// ]);
/// ```
pub fn parse_data(text: &str, source: &str) -> Result<FitData, Error> {
    let mut data = parse::parse_data(text).map_err(|problems| Error::Invalid {
        file: source.to_owned(),
        problems,
    })?;
    source.clone_into(&mut data.source);
    Ok(data)
}

/// Reads and validates a data file.
///
/// # Errors
/// The errors of [`read_text`] (a file that cannot be read, is too large or
/// is not UTF-8) and of [`parse_data`].
pub fn read_data(path: &Path) -> Result<FitData, Error> {
    let text = read_text(path)?;
    parse_data(&text, &path.display().to_string())
}
