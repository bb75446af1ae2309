//! The summary of a run of many jobs: one row per job, as CSV (and as
//! Parquet with the feature `parquet`).

use std::io::{self, Write};

/// One job of a run of many: its name and file, how it ended, and its key
/// figures when it ran.
#[derive(Clone, Debug, PartialEq)]
pub struct JobSummary {
    /// The name of its outputs (the job file's name without `.json`).
    pub name: String,
    /// The job file as given.
    pub file: String,
    /// `ok`, or the kind of failure: `invalid`, `unreadable`, `unwritable`,
    /// `internal` ([`Status::word`](crate::Status::word)).
    pub status: String,
    /// The type reduction's name (`paper`, `centroid`, `nie-tan`,
    /// `alpha-planes`; docs/method.md §9), if it ran.
    pub type_reduction: Option<String>,
    /// `alpha <= h`, `alpha > h` or `mixed` (docs/method.md §3), if it ran with the
    /// paper's type reduction.
    pub regime: Option<String>,
    /// The level alpha, if it ran with the paper's type reduction (the only
    /// one that uses alpha).
    pub alpha: Option<f64>,
    /// The smallest lower height of its numbers (where the paper's
    /// reduction jumps), if it was read.
    pub h: Option<f64>,
    /// `error.max`, if it ran.
    pub error_max: Option<f64>,
    /// Where the distance is largest, if it ran: `t`, or a surface's `u`.
    pub error_max_at: Option<f64>,
    /// A surface's `v` where the distance is largest.
    pub error_max_at_v: Option<f64>,
    /// `error.rms`, if it ran.
    pub error_rms: Option<f64>,
    /// The job's description, if it ran and has one.
    pub description: Option<String>,
    /// What went wrong (the lines of the error, joined by `; `), if it failed.
    pub message: Option<String>,
}

/// The column names of a summary, in order.
pub const SUMMARY_COLUMNS: [&str; 13] = [
    "name",
    "file",
    "status",
    "type_reduction",
    "regime",
    "alpha",
    "h",
    "error_max",
    "error_max_at",
    "error_max_at_v",
    "error_rms",
    "description",
    "message",
];

/// A number in the CSV files' form.
fn number(x: Option<f64>) -> Vec<u8> {
    let mut out = Vec::new();
    if let Some(x) = x {
        // Writing to a Vec cannot fail.
        #[allow(clippy::expect_used)]
        crate::number::csv(&mut out, x).expect("in-memory write");
    }
    out
}

/// Writes the summary as CSV: a header of [`SUMMARY_COLUMNS`], then a line
/// per job; an empty field where a job has no value, text quoted where it
/// holds a comma, quote or line break (RFC 4180), numbers as in the result's
/// CSV files.
///
/// # Errors
/// The errors of `writer`.
///
/// # Examples
/// ```
/// # use t2spline_io::{write_summary_csv, JobSummary};
/// let ok = JobSummary { name: "a".into(), file: "jobs/a.json".into(), status: "ok".into(),
///     type_reduction: Some("paper".into()), regime: Some("alpha > h".into()), alpha: Some(0.8),
///     h: Some(0.6), error_max: Some(0.044), error_max_at: Some(0.25), error_max_at_v: None,
///     error_rms: Some(0.01), description: Some("a line".into()), message: None };
/// let bad = JobSummary { name: "b".into(), file: "jobs/b.json".into(), status: "invalid".into(),
///     type_reduction: None, regime: None, alpha: None, h: None, error_max: None,
///     error_max_at: None, error_max_at_v: None, error_rms: None, description: None,
///     message: Some("jobs/b.json:3:5: alhpa: unknown key".into()) };
/// let mut out = Vec::new();
/// write_summary_csv(&mut out, &[ok, bad])?;
/// assert_eq!(String::from_utf8(out)?, "name,file,status,type_reduction,regime,alpha,h,error_max,error_max_at,error_max_at_v,error_rms,description,message\n\
///     a,jobs/a.json,ok,paper,alpha > h,0.8,0.6,0.044,0.25,,0.01,a line,\n\
///     b,jobs/b.json,invalid,,,,,,,,,,jobs/b.json:3:5: alhpa: unknown key\n");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_summary_csv<W: Write>(writer: W, jobs: &[JobSummary]) -> io::Result<()> {
    let mut w = csv::Writer::from_writer(writer);
    w.write_record(SUMMARY_COLUMNS)?;
    for job in jobs {
        w.write_record([
            job.name.as_bytes(),
            job.file.as_bytes(),
            job.status.as_bytes(),
            job.type_reduction.as_deref().unwrap_or_default().as_bytes(),
            job.regime.as_deref().unwrap_or_default().as_bytes(),
            &number(job.alpha),
            &number(job.h),
            &number(job.error_max),
            &number(job.error_max_at),
            &number(job.error_max_at_v),
            &number(job.error_rms),
            job.description.as_deref().unwrap_or_default().as_bytes(),
            job.message.as_deref().unwrap_or_default().as_bytes(),
        ])?;
    }
    w.flush()
}
