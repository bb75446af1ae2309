//! Exit codes: one per kind of failure, so that a script running many jobs can
//! tell a bad job (fix it, go on) from a broken environment (stop).
//!
//! | code | meaning |
//! |---|---|
//! | 0 | success; also when the reader of standard output closed the pipe early |
//! | 1 | internal error: a bug (a result that is not finite); nothing was written |
//! | 2 | invalid input: a usage error (clap), an option value that breaks a rule, an output that would overwrite an input or another output of the run, or a job or data file that breaks a rule or a limit (JSON syntax, keys, the method's rules, size, encoding); also any error of another layer (the options of `fit`, a figure `plot` cannot draw), which are about the input |
//! | 3 | the job cannot be read (missing, not permitted, a folder, an I/O error) |
//! | 4 | an output cannot be written (missing folder, not permitted, disk full, standard output closed or failing, a file with several hard links); existing outputs are untouched |
//!
//! A run of many jobs (`t2spline run a.json b.json …`, `--jobs DIR`) goes on
//! past a failing job and exits with the code of its most serious failure:
//! 1 (a bug) before 4 (outputs) before 3 (inputs) before 2 (a bad job); 0
//! when every job was written. `summary.csv` has each job's status.
//!
//! A panic (which would be a bug too) exits with Rust's 101; Ctrl-C and
//! `SIGTERM` end the program by their signal, after removing its temporary
//! files.

use std::path::PathBuf;

use t2spline_io::{Error, Status};

/// A command-line option whose value breaks a rule: `--alpha: …`. Exit code 2.
#[derive(Debug)]
pub struct OptionError {
    /// The option, e.g. `--alpha`.
    pub option: &'static str,
    /// The value and the rule.
    pub message: String,
}

impl std::fmt::Display for OptionError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.option, self.message)
    }
}

impl std::error::Error for OptionError {}

/// What a failure means for the caller.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Exit {
    /// Success.
    Ok = 0,
    /// A bug.
    Internal = 1,
    /// The input breaks a rule (also clap's code for usage errors).
    Invalid = 2,
    /// The job cannot be read.
    Read = 3,
    /// An output cannot be written.
    Write = 4,
}

impl Exit {
    /// The exit code for an error: the kind of the first [`t2spline_io::Error`]
    /// in its chain (or the code a run of many jobs chose). Errors of other
    /// layers (the options of `fit`, a point index `plot` cannot draw) are
    /// about the input: 2.
    pub fn of(e: &anyhow::Error) -> Exit {
        if let Some(failed) = e.downcast_ref::<JobsFailed>() {
            return failed.exit;
        }
        match e.chain().find_map(|c| c.downcast_ref::<Error>()) {
            Some(e) => Exit::of_status(Status::of_error(e)),
            None => Exit::Invalid,
        }
    }

    /// The exit of a job's [`Status`].
    pub fn of_status(status: Status) -> Exit {
        match status {
            Status::Ok => Exit::Ok,
            Status::Invalid => Exit::Invalid,
            Status::Unreadable => Exit::Read,
            Status::Unwritable => Exit::Write,
            Status::Internal => Exit::Internal,
        }
    }

    /// The code as a byte.
    pub fn code(self) -> u8 {
        self as u8
    }

    /// How serious a failure is: a bug, then outputs, then inputs, then a
    /// bad job.
    fn rank(self) -> u8 {
        match self {
            Exit::Ok => 0,
            Exit::Invalid => 1,
            Exit::Read => 2,
            Exit::Write => 3,
            Exit::Internal => 4,
        }
    }

    /// The more serious of two.
    pub fn worst(self, other: Exit) -> Exit {
        if other.rank() > self.rank() {
            other
        } else {
            self
        }
    }

    /// The word for a job's status in a summary ([`Status::word`]).
    pub fn status(self) -> &'static str {
        let status = match self {
            Exit::Ok => Status::Ok,
            Exit::Internal => Status::Internal,
            Exit::Invalid => Status::Invalid,
            Exit::Read => Status::Unreadable,
            Exit::Write => Status::Unwritable,
        };
        status.word()
    }
}

/// Some jobs of a run of many failed (each already reported): the last line
/// of the run, whose exit code is that of the most serious failure.
#[derive(Debug)]
pub struct JobsFailed {
    /// How many failed.
    pub failed: usize,
    /// How many jobs there were.
    pub total: usize,
    /// The code to exit with.
    pub exit: Exit,
    /// The summary file written.
    pub summary: PathBuf,
}

impl std::fmt::Display for JobsFailed {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let written = if self.failed == self.total {
            "no job's results were written"
        } else {
            "the others were written"
        };
        write!(
            f,
            "{} of {} jobs failed, {written} (see {})",
            self.failed,
            self.total,
            t2spline_io::printable(&self.summary.display().to_string())
        )
    }
}

impl std::error::Error for JobsFailed {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_kind_has_its_code() {
        let io = || std::io::Error::other("x");
        let cases = [
            (
                Error::Invalid {
                    file: "j".into(),
                    problems: vec![],
                },
                2,
            ),
            (
                Error::Read {
                    path: PathBuf::from("j"),
                    source: io(),
                },
                3,
            ),
            (
                Error::Write {
                    path: PathBuf::from("o"),
                    source: io(),
                },
                4,
            ),
            (
                Error::NotFinite {
                    key: "k".into(),
                    value: f64::NAN,
                },
                1,
            ),
        ];
        for (e, code) in cases {
            assert_eq!(Exit::of(&anyhow::Error::new(e)).code(), code);
        }
        // Wrapped in context, the kind is still found.
        let wrapped = anyhow::Error::new(Error::Read {
            path: PathBuf::from("j"),
            source: io(),
        })
        .context("while reading");
        assert_eq!(Exit::of(&wrapped), Exit::Read);
        assert_eq!(
            Exit::of(&anyhow::anyhow!("a bad option of fit")),
            Exit::Invalid
        );
        let option = OptionError {
            option: "--alpha",
            message: "m".into(),
        };
        assert_eq!(Exit::of(&anyhow::Error::new(option)), Exit::Invalid);
    }

    #[test]
    fn many_jobs_exit_with_their_worst_failure() {
        use Exit::*;
        let worst = |codes: &[Exit]| codes.iter().fold(Ok, |w, &c| w.worst(c));
        assert_eq!(worst(&[]), Ok);
        assert_eq!(worst(&[Invalid, Read, Invalid]), Read);
        assert_eq!(worst(&[Invalid, Write, Read]), Write);
        assert_eq!(worst(&[Write, Internal, Invalid]), Internal);
        let failed = JobsFailed {
            failed: 2,
            total: 5,
            exit: Read,
            summary: PathBuf::from("out/summary.csv"),
        };
        assert_eq!(
            failed.to_string(),
            "2 of 5 jobs failed, the others were written (see out/summary.csv)"
        );
        assert_eq!(Exit::of(&anyhow::Error::new(failed)), Read);
        let all = JobsFailed {
            failed: 3,
            total: 3,
            exit: Invalid,
            summary: PathBuf::from("out/summary.csv"),
        };
        assert_eq!(
            all.to_string(),
            "3 of 3 jobs failed, no job's results were written (see out/summary.csv)"
        );
    }
}
