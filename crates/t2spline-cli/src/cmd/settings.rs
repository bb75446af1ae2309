//! The settings of a run from the command line: the core's checks, with
//! messages that name the option (`--alpha`, `--samples`, `--derivatives`),
//! and the note for an alpha that the type reduction does not use.

use std::io::Write as _;
use std::path::Path;

use t2spline::job::{Job, Overrides, Setting, Settings};
use t2spline_io::job::locate;
use t2spline_io::{Error, Problem};

use crate::output::job_name;

pub use crate::exit::OptionError;

/// The option that sets `setting`.
pub fn option_name(setting: Setting) -> &'static str {
    match setting {
        Setting::Alpha => "--alpha",
        Setting::Samples => "--samples",
        Setting::Derivatives => "--derivatives",
        Setting::Points => "--points",
        Setting::Threads => "--threads",
    }
}

/// A core error about a setting, as an error about its option; other errors
/// unchanged.
pub fn about_option(e: t2spline::Error) -> anyhow::Error {
    match e {
        t2spline::Error::Setting { setting, message } => OptionError {
            option: option_name(setting),
            message,
        }
        .into(),
        other => other.into(),
    }
}

/// The settings of a run of `job` (read from `path`, whose `text` places a
/// missing `alpha` at the job's top-level object) with the options given.
pub fn settings(
    job: &Job,
    overrides: &Overrides,
    path: &Path,
    text: &str,
) -> anyhow::Result<Settings> {
    job.settings(overrides).map_err(|e| match e {
        t2spline::Error::MissingAlpha => Error::Invalid {
            file: job_name(path),
            problems: vec![Problem {
                line_column: Some(locate(text, "alpha")),
                message: "alpha: missing: give it in the job file or with --alpha".into(),
            }],
        }
        .into(),
        other => about_option(other),
    })
}

/// That the type reduction does not use the alpha given (`--alpha` if
/// `from_option`, else the job file's), and what that alpha still does
/// (`effect`); `None` if every alpha given is used.
pub fn unused_alpha(settings: &Settings, from_option: bool, effect: &str) -> Option<String> {
    let a = settings.unused_alpha?;
    let source = if from_option {
        "--alpha"
    } else {
        "the job's alpha"
    };
    Some(format!(
        "note: type reduction {} does not use alpha; {source} {} {effect}",
        settings.type_reduction,
        a.get()
    ))
}

/// Says [`unused_alpha`] on standard error, in one line, for `command`.
pub fn note_unused_alpha(command: &str, settings: &Settings, from_option: bool, effect: &str) {
    if let Some(note) = unused_alpha(settings, from_option, effect) {
        // A closed standard error must not stop the command.
        let _ = writeln!(std::io::stderr().lock(), "t2spline {command}: {note}");
    }
}

/// A derivative beyond the range of a float is the input's doing, not a bug:
/// an error about `--derivatives`. Other errors unchanged.
pub fn about_derivatives(e: t2spline::Error) -> anyhow::Error {
    match e {
        t2spline::Error::DerivativeOverflow { .. }
        | t2spline::Error::NotFinite {
            what: "curves.arc_length.crisp" | "curves.arc_length.defuzzified",
            ..
        } => OptionError {
            option: "--derivatives",
            message: e.to_string(),
        }
        .into(),
        other => other.into(),
    }
}
