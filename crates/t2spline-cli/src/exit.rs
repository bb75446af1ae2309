//! Exit codes: one per kind of failure, so that a script running many jobs can
//! tell a bad job (fix it, go on) from a broken environment (stop).
//!
//! | code | meaning |
//! |---|---|
//! | 0 | success; also when the reader of standard output closed the pipe early |
//! | 1 | internal error: a bug (a result that is not finite); nothing was written |
//! | 2 | invalid input: a usage error (clap), an option value that breaks a rule, or a job or data file that breaks a rule or a limit (JSON syntax, keys, SPEC rules, size, encoding); also any error of another layer (the options of `fit`, a figure `plot` cannot draw), which are about the input |
//! | 3 | the job cannot be read (missing, not permitted, a folder, an I/O error) |
//! | 4 | an output cannot be written (missing folder, not permitted, disk full, standard output failing); existing outputs are untouched |
//!
//! A panic (which would be a bug too) exits with Rust's 101.

use t2spline_io::Error;

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
    /// in its chain. Errors of other layers (the options of `fit`, a point
    /// index `plot` cannot draw) are about the input: 2.
    pub fn of(e: &anyhow::Error) -> Exit {
        match e.chain().find_map(|c| c.downcast_ref::<Error>()) {
            Some(Error::Read { .. }) => Exit::Read,
            Some(Error::Write { .. }) => Exit::Write,
            Some(Error::NotFinite { .. }) => Exit::Internal,
            _ => Exit::Invalid,
        }
    }

    /// The code as a byte.
    pub fn code(self) -> u8 {
        self as u8
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

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
        let option = crate::cmd::settings::OptionError {
            option: "--alpha",
            message: "m".into(),
        };
        assert_eq!(Exit::of(&anyhow::Error::new(option)), Exit::Invalid);
    }
}
