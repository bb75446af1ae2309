//! The level alpha from the command line or the job file.

use anyhow::bail;
use std::path::Path;
use t2spline::Alpha;
use t2spline_io::{Error, Job};

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

/// `--alpha` if given, else the job's alpha, else an error naming the file.
pub fn required(option: Option<Alpha>, job: &Job, path: &Path) -> anyhow::Result<Alpha> {
    let Some(alpha) = option.or(job.alpha) else {
        bail!(
            "{}: alpha: missing: give it in the job file or with --alpha",
            crate::output::job_name(path)
        );
    };
    Ok(alpha)
}
