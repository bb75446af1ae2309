//! The levels a command answers at: `--alpha A` (one level), `--levels N`
//! (N equally spaced from 0 to 1), or neither: the job's `alpha`, else the
//! command's default count (`measure` and `section`: 11; `region` has none
//! and asks for one). Checked before the job is read; resolved with it.

use t2spline::job::Job;
use t2spline::Alpha;

use super::prepare::OptionError;
use crate::cli::LevelsArg;

/// Levels at most, of every command that takes `--levels`.
pub const MAX_LEVELS: u64 = 1001;

/// The levels asked for, checked; [`Levels::resolve`] gives them for a job.
#[derive(Debug, Clone, PartialEq)]
pub enum Levels {
    /// `--alpha A`.
    One(Alpha),
    /// `--levels N`.
    Uniform(u64),
    /// Neither: the job's alpha, else `fallback` uniform levels (none: the
    /// command needs a level).
    FromJob { fallback: Option<u64> },
}

fn invalid(option: &'static str, message: String) -> anyhow::Error {
    OptionError { option, message }.into()
}

impl Levels {
    /// The levels of `arg`, each flag checked and named; `fallback` the
    /// count used when neither flag is given and the job has no alpha.
    ///
    /// # Errors
    /// `--alpha` outside [0, 1]; `--levels` outside 2 ..= `max`.
    pub fn from_arg(arg: &LevelsArg, fallback: Option<u64>, max: u64) -> anyhow::Result<Levels> {
        match (arg.alpha, arg.levels) {
            (Some(a), _) => Alpha::try_new(a)
                .map(Levels::One)
                .map_err(|e| invalid("--alpha", e.to_string())),
            (None, Some(n)) if (2..=max).contains(&n) => Ok(Levels::Uniform(n)),
            (None, Some(n)) => Err(invalid("--levels", format!("{n} is outside 2 ..= {max}"))),
            (None, None) => Ok(Levels::FromJob { fallback }),
        }
    }

    /// The levels for `job`, in increasing order.
    ///
    /// # Errors
    /// Neither flag, no alpha in the job and no fallback.
    pub fn resolve(&self, job: &Job) -> anyhow::Result<Vec<Alpha>> {
        match *self {
            Levels::One(a) => Ok(vec![a]),
            Levels::Uniform(n) => Ok(uniform(n)),
            Levels::FromJob { fallback } => match (job.alpha, fallback) {
                (Some(a), _) => Ok(vec![a]),
                (None, Some(n)) => Ok(uniform(n)),
                (None, None) => Err(invalid(
                    "--alpha",
                    "the job has no alpha: give the level with --alpha A, or --levels N".to_owned(),
                )),
            },
        }
    }
}

/// `n` (at least 2) levels equally spaced from 0 to 1.
pub fn uniform(n: u64) -> Vec<Alpha> {
    let last = n.saturating_sub(1).max(1) as f64;
    (0..n)
        .filter_map(|k| Alpha::try_new(k as f64 / last).ok())
        .collect()
}
