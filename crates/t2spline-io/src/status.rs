//! What became of a job in a run of many: the words of a summary's
//! `status` column, and which failure each error of this crate is. The
//! command line's exit codes and Python's `run_table` both read them here.

use crate::error::Error;
use crate::prepared::RunError;

/// How a job of a run of many ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// It ran and its outputs were written.
    Ok,
    /// The job (or an option) breaks a rule.
    Invalid,
    /// The job could not be read.
    Unreadable,
    /// An output could not be written.
    Unwritable,
    /// A bug: a result that is not finite.
    Internal,
}

impl Status {
    /// The word in a summary: `ok`, `invalid`, `unreadable`, `unwritable`,
    /// `internal`.
    #[must_use]
    pub fn word(self) -> &'static str {
        match self {
            Status::Ok => "ok",
            Status::Invalid => "invalid",
            Status::Unreadable => "unreadable",
            Status::Unwritable => "unwritable",
            Status::Internal => "internal",
        }
    }

    /// The failure an error of this crate is: a file not read, an output
    /// not written, a result not finite (a bug), else a job that breaks a
    /// rule.
    #[must_use]
    pub fn of_error(e: &Error) -> Status {
        match e {
            Error::Read { .. } => Status::Unreadable,
            Error::Write { .. } => Status::Unwritable,
            Error::NotFinite { .. } => Status::Internal,
            _ => Status::Invalid,
        }
    }

    /// The failure a run's error is ([`Status::of_error`] for a file's;
    /// a setting or the core refusing the job: invalid).
    #[must_use]
    pub fn of_run(e: &RunError) -> Status {
        match e {
            RunError::File(e) => Status::of_error(e),
            RunError::Setting { .. } | RunError::Core(_) => Status::Invalid,
        }
    }
}
