//! The level alpha from the command line or the job file.

use std::path::Path;

use t2spline::Alpha;
use t2spline_io::job::locate;
use t2spline_io::{Error, Job, Problem};

/// Checks `--alpha` against [0, 1].
pub fn parse_option(value: Option<f64>) -> Result<Option<Alpha>, Error> {
    value
        .map(|a| {
            Alpha::try_new(a).map_err(|e| Error::Option {
                option: "--alpha",
                message: e.to_string(),
            })
        })
        .transpose()
}

/// `--alpha` if given, else the job's alpha, else an error naming the file and
/// placing the missing key at the job's top-level object in `text`.
pub fn required(option: Option<Alpha>, job: &Job, path: &Path, text: &str) -> Result<Alpha, Error> {
    option.or(job.alpha).ok_or_else(|| Error::Invalid {
        file: crate::output::job_name(path),
        problems: vec![Problem {
            line_column: Some(locate(text, "alpha")),
            message: "alpha: missing: give it in the job file or with --alpha".into(),
        }],
    })
}
